"""The event logs' record layouts in C++ (collisionEvent::pack,
breakupEvent::pack) and in Python (aggloTools.eventlog.DTYPE,
aggloTools.breakuplog.DTYPE) cannot drift apart unnoticed: the C++ unit
tests CollisionEventFile.WrittenForPython and
BreakupEventFile.WrittenForPython write records of known, pairwise
different values into log files (collision: its sample(5), sample(6);
break-up: layoutSample()); the Python readers must read back every field,
exactly (the wall distance as its float)."""

import math
import os
import shutil
import subprocess

import numpy as np
import pytest

from aggloTools import breakuplog, eventlog

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


def written(tmp_path, test, name):
    """The log file the C++ unit test writes into tmp_path."""
    exe = shutil.which(EXE)
    if exe is None:
        pytest.fail(f"{EXE} not found on PATH: build with ./Allwmake")
    res = subprocess.run(
        [exe, f"--gtest_filter={test}"], capture_output=True, text=True,
        timeout=120, env=dict(os.environ, AGGLO_LAYOUT_DIR=str(tmp_path)))
    assert res.returncode == 0 and "[  PASSED  ] 1 test." in res.stdout, \
        res.stdout + res.stderr
    return tmp_path / name


def compare(record, want, k):
    for name, value in want.items():
        got = record[name]
        if np.ndim(value):
            assert list(got) == list(value), (k, name)
        else:
            assert got == value, (k, name)


def test_collision_records(tmp_path, foam_env):
    f = written(tmp_path, "CollisionEventFile.WrittenForPython",
                "collisionEvents.bin")
    assert list(eventlog.read_header(f)) == ["eq21", "eq65", "caseI",
                                             "caseII"]
    records = eventlog.read_file(f)
    assert len(records) == 2
    assert set(records.dtype.names) == set(sample(5))
    for r, k in zip(records, (5, 6)):
        compare(r, sample(k), k)
    # the sign of the denormal survives (a drift by a byte would not)
    assert math.copysign(1, records[0]["omega1"][2]) == -1


def breakup_sample():
    """tests/unit/breakupKernels/testBreakupEventFile.C, layoutSample()."""
    return {
        "timeIndex": 12, "mechanism": 1, "proc": 2, "id": 31,
        "newProc": -2, "newId": 7, "dt": 1e-5,
        "nPrimary_p": 9, "nPrimary_a": 1, "nPrimary_b": 8,
        "x_p": (1e-3, 2e-3, 3e-3), "U_p": (0.1, -0.2, 0.3),
        "omega_p": (10, -20, 30), "d_p": 4e-5, "rho_p": 1100,
        "epsilon": 5.5, "nu": 1.5e-5, "rhoF": 1.2,
        "dragForce": (1e-9, 2e-9, -3e-9), "wallImpactSpeed": 0.25,
        "S": (11, 12, 13, 14, 15, 16), "values": (0.5, 1.5, 2.5, 3.5),
        "x_a": (4e-3, 5e-3, 6e-3), "U_a": (0.4, 0.5, 0.6),
        "omega_a": (40, 50, 60), "d_a": 1.2e-5, "rho_a": 2200,
        "x_b": (7e-3, 8e-3, 9e-3), "U_b": (0.7, 0.8, 0.9),
        "omega_b": (70, 80, 90), "d_b": 3.8e-5, "rho_b": 1150,
        "attempt": 3, "padding": 0,
    }


def test_breakup_records(tmp_path, foam_env):
    f = written(tmp_path, "BreakupEventFile.WrittenForPython",
                "breakupEvents.bin")
    records, header = breakuplog.read_file(f)
    assert [list(header[k]) for k in breakuplog.KEYS] == [
        ["turbulence", "drag", "rotation"], ["layoutSample"],
        ["v0", "v1", "v2", "v3"]]
    assert len(records) == 1
    want = breakup_sample()
    assert set(records.dtype.names) == set(want) | {"check"}
    compare(records[0], want, 0)
