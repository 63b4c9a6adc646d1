"""Shared fixtures of the test suite: a fresh run folder per test and the
OpenFOAM environment (sourced by ./Alltest from etc/bashrc). The helpers
the tests call (running commands, box cases, file readers) are in the
aggloTools package."""

import os
import shutil

import pytest

from aggloTools import boxcase
from aggloTools.runner import foam_bin, project_dir, run

RUNS = project_dir() / "tests" / "runs"


@pytest.fixture
def case_dir(request):
    """A fresh run directory under tests/runs/<test name>."""
    d = RUNS / request.node.name.replace("/", "_").replace("[", "_").rstrip("]")
    if d.exists():
        shutil.rmtree(d)
    d.mkdir(parents=True)
    return d


@pytest.fixture(scope="session")
def foam_env():
    """Checks that the project environment is set (etc/bashrc sourced)."""
    for var in ("WM_PROJECT_DIR", "FOAM_USER_APPBIN", "FOAM_USER_LIBBIN"):
        if not os.environ.get(var):
            pytest.fail(f"{var} is not set: run the tests through ./Alltest")
    return os.environ


@pytest.fixture(scope="session")
def raised_digits(tmp_path_factory, foam_env):
    """An uninterrupted run whose time names gain digits: dt = 1/3 s,
    timePrecision 2, to t = 17 s, a write per step (v1912 finds the start
    folder 1.667 at 17 digits only and 16.333317 not at all)."""
    parts = [dict(x=(2e-4 + 1e-4 * i, 5e-4, 5e-4), U=(0, 0, 0), id=i)
             for i in range(3)]
    whole = tmp_path_factory.mktemp("raisedDigits") / "whole"
    boxcase.box_case(whole, particles=parts, dt=1 / 3, end_time=17.0,
                     write_interval=1, hard_sphere=boxcase.kernel("EAM"))
    run([foam_bin("foamDictionary"), "-entry", "timePrecision", "-set", "2",
         "system/controlDict"], whole, "log.foamDictionary")
    boxcase.run_case(whole)
    return whole
