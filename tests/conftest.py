"""Shared fixtures of the test suite: paths, the OpenFOAM environment
(sourced by ./Alltest from etc/bashrc) and a helper that runs a command in
a case directory and keeps its log."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
RUNS = ROOT / "tests" / "runs"


def foam_bin(name):
    """Path of an OpenFOAM or project executable; fails clearly if absent."""
    path = shutil.which(name)
    if path is None:
        pytest.fail(
            f"'{name}' not found on PATH: run the tests through ./Alltest "
            "(it sources etc/bashrc and builds the project)"
        )
    return path


def run(cmd, cwd, log, check=True, timeout=600):
    """Run cmd in cwd, write stdout+stderr to cwd/log, return the result."""
    env = dict(os.environ, PWD=str(cwd))
    res = subprocess.run(
        cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        text=True, timeout=timeout, env=env,
    )
    (Path(cwd) / log).write_text(res.stdout)
    if check and res.returncode != 0:
        pytest.fail(
            f"{' '.join(map(str, cmd))} failed (rc {res.returncode}) in "
            f"{cwd}:\n{res.stdout[-3000:]}"
        )
    return res


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
