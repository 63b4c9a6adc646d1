"""tutorials/bendDeposition: the Stokes number's diameter against the hand
formula, the gate's verdicts on made-up rows (each limit fails when it
should), and the `ci` preset run end to end in a copy of the tutorial
(about 30 s): exit status 0, every row PASS, the counts from the mass
balance adding up to the injected particles, the pictures written."""

import json
import math
import shutil
import subprocess

import pytest

from aggloTools.runner import project_dir, tutorial_module

TUT = project_dir() / "tutorials" / "bendDeposition"
tutorial_module("bendDeposition", "bendPlots")     # the driver's sibling
driver = tutorial_module("bendDeposition", "bendDeposition")


def test_stokes_number_diameter():
    """St = rho_p d^2 U / (9 mu D): at St = 1 in air (mu = 1.8e-5 Pa s)
    at 3 m/s in a 5 mm pipe, rho_p = 2200: d = sqrt(9 mu D / (rho_p U))
    = 11.08 um."""
    assert driver.U_MEAN == pytest.approx(3.0)
    assert driver.diameter(1.0) == pytest.approx(
        math.sqrt(9 * 1.8e-5 * 5e-3 / (2200 * 3.0)), rel=1e-12)
    assert driver.diameter(1.0) == pytest.approx(11.08e-6, rel=1e-3)


def row(st, eta, n=1000, flight=0, injected=1000):
    return dict(St=st, eta=eta, sigma=math.sqrt(eta * (1 - eta) / n),
                entered=n, inFlight=flight, undecided=flight,
                injected=injected, expected=1000)


def test_gate_verdicts():
    """Each limit of the gate fails a row that breaks it, and only it."""
    good = [row(0.05, 0.03), row(0.5, 0.5), row(5.0, 0.97)]
    assert [r["verdict"] for r in driver.judge(good)] == ["PASS"] * 3
    # tracers that deposit
    bad = driver.judge([row(0.05, 0.2), row(0.5, 0.5), row(5.0, 0.97)])
    assert [r["verdict"] for r in bad] == ["FAIL", "PASS", "PASS"]
    # ballistic particles that do not
    bad = driver.judge([row(0.05, 0.03), row(0.5, 0.5), row(5.0, 0.8)])
    assert [r["verdict"] for r in bad] == ["PASS", "PASS", "FAIL"]
    # a fall beyond 2 sigma with St, but not within it
    bad = driver.judge([row(0.05, 0.03), row(0.5, 0.6), row(1.0, 0.5),
                        row(5.0, 0.97)])
    assert [r["verdict"] for r in bad] == ["PASS", "PASS", "FAIL", "PASS"]
    ok = driver.judge([row(0.05, 0.03), row(0.5, 0.6), row(1.0, 0.59),
                       row(5.0, 0.97)])
    assert all(r["verdict"] == "PASS" for r in ok)
    # particles lost or left in flight
    bad = driver.judge([row(0.05, 0.03, flight=30), row(0.5, 0.5,
                        injected=999), row(5.0, 0.97, flight=20)])
    assert [r["verdict"] for r in bad] == ["FAIL", "FAIL", "PASS"]


def test_ci_preset_end_to_end(tmp_path, foam_env):
    tut = tmp_path / "bendDeposition"
    shutil.copytree(TUT, tut, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    res = subprocess.run(["./Allrun", "-preset", "ci", "-every", "1"],
                         cwd=tut, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    out = tut / "runs/ci/report"
    summary = json.loads((out / "summary.json").read_text())
    rows = summary["rows"]
    assert [r["St"] for r in rows] == [0.02, 0.3, 5.0]
    for r in rows:
        assert r["verdict"] == "PASS", r
        counted = (r["inFlight"] + sum(r["deposited"].values())
                   + sum(r["escaped"].values()))
        assert counted == r["injected"] == 300
        assert r["entered"] == (300 - r["deposited"].get("inletPipe", 0)
                                - r["undecided"])
        assert 0 <= r["undecided"] <= r["inFlight"]
        assert r["eta"] == pytest.approx(
            r["deposited"].get("bend", 0) / r["entered"], rel=1e-12)
    for png in ("efficiency.png", "deposits.png"):
        assert (out / png).stat().st_size > 10000
    # a second call keeps the finished runs and writes the same report
    res = subprocess.run(["./Allrun", "-preset", "ci"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=300)
    assert res.returncode == 0 and "finished earlier, kept" in res.stdout
    assert json.loads((out / "summary.json").read_text())["rows"] == rows
