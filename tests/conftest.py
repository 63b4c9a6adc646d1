"""Shared fixtures of the test suite: a fresh run folder per test and the
OpenFOAM environment (sourced by ./Alltest from etc/bashrc). The helpers
the tests call (running commands, box cases, file readers) are in the
aggloTools package."""

import os
import shutil

import pytest

from aggloTools.runner import project_dir

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
