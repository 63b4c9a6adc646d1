"""Runs the C++ unit tests (GoogleTest program aggloUnitTests, built by
Allwmake from tests/unit) so that each C++ test case is one pytest item.

The test list comes from `aggloUnitTests --gtest_list_tests`; each item
runs the program with --gtest_filter for its own case and passes only if
GoogleTest reports it passed."""

import shutil
import subprocess

import pytest

EXE = "aggloUnitTests"


def _list_tests():
    exe = shutil.which(EXE)
    if exe is None:
        return ["<aggloUnitTests not built: run ./Alltest>"]
    out = subprocess.run(
        [exe, "--gtest_list_tests"], capture_output=True, text=True,
        check=True,
    ).stdout
    names, suite = [], None
    for line in out.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split()[0]
        else:
            names.append(suite + line.split()[0])
    return names


@pytest.mark.parametrize("name", _list_tests())
def test_cpp(name):
    exe = shutil.which(EXE)
    if exe is None:
        pytest.fail(f"{EXE} not found on PATH: build with ./Allwmake")
    res = subprocess.run(
        [exe, f"--gtest_filter={name}"], capture_output=True, text=True,
        timeout=300,
    )
    out = res.stdout + res.stderr
    assert res.returncode == 0 and "[  PASSED  ] 1 test." in out, out[-4000:]
