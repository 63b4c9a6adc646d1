"""tutorials/breakupShear: the criterion of breakupTheory against the hand
values of doc/breakup.md 1.7, the gate's verdicts and exit status, and
the `ci` preset run end to end in a copy of the tutorial (about 20 s)."""

import json
import math
import shutil
import subprocess

import pytest

from aggloTools import times
from aggloTools.runner import project_dir, tutorial_module
from aggloTools.foamfile import edit
from runLocks import lock_text

TUT = project_dir() / "tutorials" / "breakupShear"
theory = tutorial_module("breakupShear", "breakupTheory")
driver = tutorial_module("breakupShear", "breakupShear")
report = tutorial_module("breakupShear", "breakupShearReport")


def test_criterion_matches_the_spec_example():
    """doc/breakup.md 1.7: d_p = 2 um, A = 6.5e-20 J, delta0 = 0.4 nm,
    rho_p = 2500, air, N = 1000, CSM f = 0.52: F_vdW = 3.4e-8 N,
    sigma_T = 9.2 kPa with c_R = 1, d_a = 24.9 um, omega_crit = 4.3e5
    rad/s (the rotational stress rho_a omega^2 d_a^2/16 equal to it)."""
    c = theory.Criterion(2e-6, 2500, 6.5e-20, 0.4e-9, 1.5e-5, 1.2, c_r=1)
    assert c.bond_force() == pytest.approx(3.4e-8, rel=0.01)
    assert c.strength(1000) == pytest.approx(9.2e3, rel=0.01)
    assert c.diameter(1000) == pytest.approx(24.9e-6, rel=0.01)
    w = 4 / c.diameter(1000) * math.sqrt(c.strength(1000) / c.density(1000))
    assert w == pytest.approx(4.3e5, rel=0.01)
    # the shear rate that spins it at omega_crit makes sigma_r = sigma_T
    assert c.stresses(1000, 2 * w)[1] == pytest.approx(c.strength(1000),
                                                       rel=1e-12)


def test_final_size_is_the_largest_stable_size_below_n0():
    """Erosion stops at the first stable size going down from N0; a stable
    N0 stays; above the critical shear of a doublet nothing below it
    holds two primaries unless a larger size is stable."""
    c = report.criterion(driver.READING)
    for g in (3e5, 4e5, 5e5, 6e5):
        n = c.final_size(200, g)
        assert c.stable(n, g)
        assert all(not c.stable(k, g) for k in range(n + 1, 201))
    assert c.final_size(200, 1e5) == 200
    g2 = c.critical_shear(2)
    assert c.stable(2, 0.999 * g2) and not c.stable(2, 1.001 * g2)


def test_readings_in_laminar_shear():
    """doc/breakup.md 1.1 in laminar shear (eps = nu gamma^2, all of it
    resolved): total puts it into the inertial form where d_a > eta,
    subgrid leaves no turbulent stress, resolvedShear the viscous
    C_v mu gamma at any size; rotation is the same in all three."""
    g = 5e5
    c = {r: report.criterion(r) for r in theory.Criterion.READINGS}
    da = c["total"].diameter(2)
    eta = math.sqrt(report.NU / g)
    assert da > eta
    mu = report.NU * report.RHO_F
    assert c["total"].stresses(2, g)[0] == pytest.approx(
        report.RHO_F * (report.NU * g ** 2 * da) ** (2 / 3), rel=1e-12)
    assert c["subgrid"].stresses(2, g)[0] == 0
    assert c["resolvedShear"].stresses(2, g)[0] == pytest.approx(
        mu * g, rel=1e-12)
    rot = {r: c[r].stresses(2, g)[1] for r in c}
    assert len(set(rot.values())) == 1
    with pytest.raises(ValueError, match="resolvedShear"):
        report.criterion("resolved")


def row(**kw):
    r = dict(primaries=320, primaries0=320, unjustified=0,
             stillEroding=False, nMax=14, nPredicted=14)
    r.update(kw)
    return r


def test_gate_verdicts():
    """Two-sided. FAIL: primaries lost, a break-up the criterion does not
    allow (too much) or the largest above the prediction once erosion
    stopped (too little); n/r while still eroding; PASS otherwise (the
    collisions may erode below the prediction)."""
    assert report.judge(row()) == "PASS"
    assert report.judge(row(nMax=9)) == "PASS"
    assert report.judge(row(nMax=15)) == "FAIL"
    assert report.judge(row(primaries=319)) == "FAIL"
    assert report.judge(row(unjustified=1)) == "FAIL"
    assert report.judge(row(nMax=20, stillEroding=True)).startswith("n/r")
    assert report.judge(row(primaries=319, stillEroding=True)) == "FAIL"
    assert report.judge(row(unjustified=2, stillEroding=True)) == "FAIL"


def test_ci_preset_end_to_end(tmp_path, foam_env):
    """The ci preset in a copy of the tutorial: exit status 0, every row
    PASS (the largest agglomerate at or below the criterion's size once
    erosion stopped, primaries conserved) and break-ups happened; then the
    same report judged against a prediction one primary smaller fails
    with exit status 1. Progress lines every second: a fresh run printed
    none before its progress line's name was shadowed (NameError)."""
    tut = tmp_path / "breakupShear"
    shutil.copytree(TUT, tut, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    res = subprocess.run(["./Allrun", "-preset", "ci", "-every", "1"],
                         cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=600)
    assert res.returncode == 0, res.stdout[-3000:]
    rows = json.loads((tut / "runs/ci/report/summary.json").read_text())[
        "rows"]
    assert len(rows) == 4
    for r in rows:
        assert r["verdict"] == "PASS", r
        assert r["primaries"] == 8 * 40
        assert sum(r["breakups"].values()) > 0
    shear = {r["gamma"]: r for r in rows if r["series"] == "shear"}
    assert shear[5e5]["nPredicted"] == 14 and shear[5e5]["nMax"] <= 14
    for png in ("sizes.png", "distribution.png", "criterion.png"):
        assert (tut / "runs/ci/report" / png).stat().st_size > 10000

    # A write cut off by a kill: the run continues from the write before
    # it, to the same end (before, every later call ended in a traceback)
    case = tut / "runs/ci/shear-resolvedShear-gamma5e+05"
    last = times.time_dirs(case)[-1]
    (last / "U").write_bytes((last / "U").read_bytes()[:200])
    log = case / "log.aggloPimpleFoam"
    edit(log, "\nEnd\n", "\n")
    res = subprocess.run(["./Allrun", "-preset", "ci"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=600)
    assert res.returncode == 0, res.stdout[-3000:]
    assert f"write of time {last.name} was cut off" in res.stdout
    assert "finished earlier, kept" in res.stdout       # the other three
    again = json.loads((tut / "runs/ci/report/summary.json").read_text())
    assert again["rows"] == rows

    # One driver at a time: a live run's lock refuses a second driver
    holder = subprocess.Popen(["sleep", "60"])
    try:
        lock = tut / "runs/ci/.aggloRun.lock"
        lock.write_text(lock_text(holder.pid))
        res = subprocess.run(["./Allrun", "-preset", "ci"], cwd=tut,
                             capture_output=True, text=True, timeout=60)
        assert res.returncode == 1
        assert "is in use by another run" in res.stderr, res.stderr
        assert f"process {holder.pid} runs" in res.stderr
    finally:
        holder.kill()
        holder.wait()
    lock.unlink()

    # The gate: a prediction one primary below the largest agglomerate
    # seen must fail (one below the prediction no longer does: the
    # fragments' collisions erode the agglomerates below it)
    largest = max(r["nMax"] for r in rows)
    assert largest > 1
    patched = tut / "breakupTheory.py"
    edit(patched,
         "        return n\n\n    def critical_shear",
         f"        return min(n, {largest - 1})\n\n    def critical_shear")
    res = subprocess.run(["./Allrun", "-preset", "ci", "-post"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=600)
    assert res.returncode == 1, res.stdout[-3000:]
    assert "FAIL" in res.stdout

    # The other side: with bonds ten times stronger in the theory every
    # logged break-up is one the criterion does not allow
    theory_file = tut / "breakupTheory.py"
    text = theory_file.read_text()
    theory_file.write_text(text.replace(
        "        F = self.bond_force()\n",
        "        F = 10 * self.bond_force()\n"))
    assert theory_file.read_text() != text
    res = subprocess.run(["./Allrun", "-preset", "ci", "-post"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=600)
    assert res.returncode == 1, res.stdout[-3000:]
    rows = json.loads((tut / "runs/ci/report/summary.json").read_text())[
        "rows"]
    assert all(r["unjustified"] == r["checkedBreakups"] > 0 for r in rows)


def test_driver_help_and_refusals(tmp_path, foam_env):
    """-help prints the options and exits 0; -post before any run and a
    solver that fails end with one line, exit status 1, no traceback."""
    tut = tmp_path / "breakupShear"
    shutil.copytree(TUT, tut, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    res = subprocess.run(["./Allrun", "-help"], cwd=tut,
                         capture_output=True, text=True)
    assert res.returncode == 0 and "-preset" in res.stdout
    res = subprocess.run(["./Allrun", "-preset", "ci", "-post"], cwd=tut,
                         capture_output=True, text=True)
    assert res.returncode == 1 and "Traceback" not in res.stderr
    assert "no finished run of shear-resolvedShear-gamma5e+05" \
        in res.stderr
    # a solver that cannot start: its controlDict names no application
    theory = tut / "breakupShear.py"
    edit(theory,
         '    stages.run_logged([foam_bin("blockMesh")], case, '
         '"log.blockMesh")',
         '    stages.run_logged([foam_bin("blockMesh")], case, '
         '"log.blockMesh")\n        (case / "system/fvSolution").unlink()')
    res = subprocess.run(["./Allrun", "-preset", "ci"], cwd=tut,
                         capture_output=True, text=True, timeout=300)
    assert res.returncode == 1, res.stdout[-2000:]
    assert "Traceback" not in res.stderr + res.stdout
    assert "Allrun: a run failed" in res.stderr
    assert "aggloPimpleFoam failed, see" in res.stdout
