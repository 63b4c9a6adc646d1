"""The collision log's record layout in C++ (collisionEvent::pack) and in
Python (aggloTools.eventlog.DTYPE) cannot drift apart unnoticed: the C++
unit test CollisionEventFile.WrittenForPython writes two records of
known values (its sample(5), sample(6): the fields' values differ) into a log file; the Python
reader must read back every field of both, exactly (the wall distance
as its float)."""

import math
import os
import shutil
import subprocess

import numpy as np
import pytest

from aggloTools import eventlog

EXE = "aggloUnitTests"
TINY = np.nextafter(0, 1)          # the smallest denormal double


def sample(k):
    """tests/unit/collisionKernels/testCollisionEvent.C, sample(k)."""
    return {
        "timeIndex": 100 + k // 3, "category": k % 3,
        "branch": 0 if k % 2 else 3, "agglomerates": k % 2, "type": 1,
        "time": 0.1 + 1e-7 * k + 1.0 / 3.0,
        "proc1": k % 4, "proc2": 3, "id1": k, "id2": 2147483000 + k,
        "x1": (1.0 / 7.0, -2e-300, 5e-7 * k), "U1": (1e-3, -0.5, 1.0 / 3.0),
        "omega1": (1e5, 0, -TINY), "d1": 12e-6, "rho1": 2200.0 / 3.0,
        "nPrimary1": 1,
        "x2": (0.25, 0.5, 0.75), "U2": (-1e-3, 0.5, 1e3),
        "omega2": (0, 1, 2), "d2": 24e-6 * (1 + k), "rho2": 2200,
        "nPrimary2": 8 + k,
        "wallDistance": np.float32(3.5e-5),
    }


def test_python_reads_what_cpp_writes(tmp_path, foam_env):
    exe = shutil.which(EXE)
    if exe is None:
        pytest.fail(f"{EXE} not found on PATH: build with ./Allwmake")
    res = subprocess.run(
        [exe, "--gtest_filter=CollisionEventFile.WrittenForPython"],
        capture_output=True, text=True, timeout=120,
        env=dict(os.environ, AGGLO_LAYOUT_DIR=str(tmp_path)))
    assert res.returncode == 0, res.stdout + res.stderr
    f = tmp_path / "collisionEvents.bin"
    assert list(eventlog.read_header(f)) == ["eq21", "eq65", "caseI",
                                             "caseII"]
    records = eventlog.read_file(f)
    assert len(records) == 2
    assert set(records.dtype.names) == set(sample(5))
    for r, k in zip(records, (5, 6)):
        for name, want in sample(k).items():
            got = r[name]
            if np.ndim(want):
                assert list(got) == list(want), (k, name)
            else:
                assert got == want, (k, name)
    # the sign of the denormal survives (a drift by a byte would not)
    assert math.copysign(1, records[0]["omega1"][2]) == -1
