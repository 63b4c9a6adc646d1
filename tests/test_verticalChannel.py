"""tutorials/verticalChannel, smoke preset (doc/cases.md A.11), serial and on 2
MPI ranks: every stage (unladen, release, dispersion, agglomeration) of
configuration C1 (EAM and MAM as two clouds of one run) and C2 (sub-models:
one cloud per run), through the tutorial's own ./Allrun in a copy.

Checks against independent expectations:
- the 50 seeded head-on pairs of C1: the 25 at 0.3 mm/s agglomerate and the
  25 at 20 mm/s rebound under both models (below and above the critical
  velocities 2.34 / 0.86 mm/s of doc/models.md 12.5), identified by their ids
  in the final cloud; N_col >= 50, N_agg = 25, N_p = 2100 - 25;
- the statistics files are complete (one row per agglomeration step) and
  consistent: counters non-decreasing, particle mass conserved to
  round-off, primaries conserved, N_p = N - N_agg;
- serial and 2-rank runs: identical C1 counters (no random numbers after
  the release), C2 counters within their Poisson noise (random SGS
  velocities)."""

import json
import math
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, RUNS

TUTORIAL = ROOT / "tutorials" / "verticalChannel"
STEPS_AGG = 30          # smoke: 0.6 T* at dt* = 0.02
N_RELEASED, N_PAIRS = 2000, 50
N_TOTAL = N_RELEASED + 2 * N_PAIRS

import sys  # noqa: E402
sys.path.insert(0, str(ROOT / "tools"))
from aggloTools import foamio  # noqa: E402


def run_smoke(tmp, np_):
    case = tmp / f"verticalChannel_np{np_}"
    if case.exists():
        shutil.rmtree(case)
    case.mkdir(parents=True)
    for name in ("0.orig", "constant", "system", "presets", "channel.py",
                 "channelPost.py", "Allrun", "Allclean"):
        src = TUTORIAL / name
        (shutil.copytree if src.is_dir() else shutil.copy2)(src, case / name)
    res = subprocess.run(
        ["./Allrun", "-preset", "smoke", "-configs", "C1 C2", "-np",
         str(np_), "-every", "600"], cwd=case, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, text=True, timeout=900,
        env=dict(os.environ, PWD=str(case)))
    (case / "log.Allrun").write_text(res.stdout)
    assert res.returncode == 0, res.stdout[-4000:]
    return case


@pytest.fixture(scope="module")
def smoke_runs(foam_env):
    tmp = RUNS / "test_verticalChannel"
    return {n: run_smoke(tmp, n) for n in (1, 2)}


def agg_runs(case):
    base = case / "runs" / "smoke"
    return {("C1", "EAM"): base / "C1/agglomeration",
            ("C1", "MAM"): base / "C1/agglomeration",
            ("C2", "EAM"): base / "C2/agglomeration-EAM",
            ("C2", "MAM"): base / "C2/agglomeration-MAM"}


def last_profiles(adir, cloud):
    files = sorted((adir / "postProcessing" / f"{cloud}HardSphere").glob(
        "*/profiles.dat"), key=lambda f: float(f.parent.name))
    text = files[-1].read_text()
    return text, np.loadtxt(files[-1])


@pytest.mark.parametrize("np_", [1, 2])
def test_statistics_complete_and_consistent(smoke_runs, np_):
    case = smoke_runs[np_]
    for (c, m), adir in agg_runs(case).items():
        st = foamio.read_stats(adir, m)
        assert len(st["Time"]) == STEPS_AGG, (c, m)
        assert np.all(np.diff(st["Time"]) > 0)
        for col in ("nCol", "nColFirst", "nAgg", "nWall", "nSuppressed"):
            assert np.all(np.diff(st[col]) >= 0), (c, m, col)
        assert np.all(st["nPrimaries"] == N_TOTAL), (c, m)
        assert np.all(st["nParticles"] == N_TOTAL - st["nAgg"]), (c, m)
        assert np.max(np.abs(st["mass"] / st["mass"][0] - 1)) < 1e-12
        # mass of N_TOTAL quartz spheres of 12 um
        m0 = N_TOTAL * 2200 * math.pi / 6 * (12e-6)**3
        assert st["mass"][0] == pytest.approx(m0, rel=1e-12)
        # agglomerates and primaries bound in them are consistent
        assert np.all(st["nPrimariesInAgglomerates"]
                      >= 2 * st["nAgglomerates"])
        # profiles (Eq. 86): the counts per slab volume add up to the
        # counters; the slab-averaged volume fraction is the global one
        prof = last_profiles(adir, m)
        assert "slab volumes: cell volumes split by overlap" in prof[0]
        t = prof[1]
        Lx, Ly, Lz = 2 * math.pi * 0.02, 0.04, math.pi * 0.02
        Vslab = Ly / len(t) * Lx * Lz
        assert (t[:, 1] * Vslab).sum() == pytest.approx(st["nCol"][-1],
                                                        rel=1e-9)
        assert (t[:, 3] * Vslab).sum() == pytest.approx(st["nAgg"][-1],
                                                        rel=1e-9)
        # (agglomerates count with their CSM envelope volume; the seeded
        # pairs merge in the first step)
        dfin = foamio.read_lagrangian(foamio.time_dirs(adir)[-1]
                                      / "lagrangian" / m / "d")
        assert t[:, 5].mean() == pytest.approx(
            (math.pi / 6 * dfin**3).sum() / (Lx * Ly * Lz), rel=0.01)
    summary = json.loads((case / "results/smoke/summary.json").read_text())
    assert not [r for r in summary["regression"] if r["status"] == "FAIL"]


@pytest.mark.parametrize("np_", [1, 2])
def test_seeded_pairs(smoke_runs, np_):
    """C1 (no random numbers): exactly the slow pairs agglomerate."""
    case = smoke_runs[np_]
    adir = agg_runs(case)[("C1", "EAM")]
    t = foamio.time_dirs(adir)[-1]
    for m in ("EAM", "MAM"):
        st = foamio.read_stats(adir, m)
        assert st["nCol"][-1] >= N_PAIRS
        assert st["nAgg"][-1] == N_PAIRS // 2, m
        assert st["nParticles"][-1] == N_TOTAL - N_PAIRS // 2
        cdir = t / "lagrangian" / m
        ids = foamio.read_lagrangian(cdir / "origId").astype(int)
        npri = foamio.read_lagrangian(cdir / "nPrimary").astype(int)
        by_id = dict(zip(ids, npri))
        for k in range(N_PAIRS):
            a, b = N_RELEASED + 2 * k, N_RELEASED + 2 * k + 1
            if k % 2 == 0:      # 0.3 mm/s: one agglomerate of two
                assert (a in by_id) != (b in by_id), (m, k)
                assert by_id.get(a, by_id.get(b)) == 2, (m, k)
            else:               # 20 mm/s: both rebound
                assert by_id.get(a) == 1 and by_id.get(b) == 1, (m, k)
        # no released particle agglomerated in 30 steps
        assert (npri > 1).sum() == N_PAIRS // 2
        # the VTK output of the last time (foamToVTK, ParaView) holds the
        # same particles
        import pyvista as pv
        vtp = sorted((adir / "VTK/lagrangian" / m).glob("*_*.vtp"))[-1]
        mesh = pv.read(vtp)
        assert mesh.n_points == N_TOTAL - N_PAIRS // 2
        assert int(np.asarray(mesh.point_data["nPrimary"]).sum()) == N_TOTAL


def test_serial_and_parallel_agree(smoke_runs):
    s, p = agg_runs(smoke_runs[1]), agg_runs(smoke_runs[2])
    for key in s:
        a = foamio.read_stats(s[key], key[1])
        b = foamio.read_stats(p[key], key[1])
        np.testing.assert_allclose(a["Time"], b["Time"], rtol=1e-12)
        for col in ("nCol", "nAgg", "nWall", "nParticles"):
            if key[0] == "C1":
                assert np.array_equal(a[col], b[col]), (key, col)
            else:
                x, y = a[col][-1], b[col][-1]
                assert abs(x - y) <= 3 * math.sqrt(max(x, y, 1)), (key, col)


def test_restart_reproduces_the_agglomeration_stage(smoke_runs, tmp_path):
    """doc/cases.md A.11: C1 (no random numbers after the release) restarted
    from its first write of the agglomeration stage (10 of 30 steps)
    reproduces the counters and the particles of the uninterrupted run."""
    from conftest import foam_bin, run
    src = agg_runs(smoke_runs[1])[("C1", "EAM")]
    case = tmp_path / "restart"
    shutil.copytree(src, case, ignore=shutil.ignore_patterns("VTK"))
    times = foamio.time_dirs(case)
    assert len(times) == 4          # branch time and 3 writes
    for t in times[2:]:
        shutil.rmtree(t)
    for d in case.glob("postProcessing/*HardSphere/*"):
        if float(d.name) > float(times[1].name):
            shutil.rmtree(d)
    (case / "log.aggloPimpleFoam").unlink()
    run([foam_bin("aggloPimpleFoam")], case, "log.aggloPimpleFoam")
    assert foamio.time_dirs(case)[-1].name == times[-1].name
    for m in ("EAM", "MAM"):
        a, b = foamio.read_stats(src, m), foamio.read_stats(case, m)
        assert len(b["Time"]) == STEPS_AGG
        for col in a:
            if col != "Time":
                np.testing.assert_allclose(b[col], a[col], rtol=1e-12,
                                           atol=0, err_msg=f"{m} {col}")
        for f in ("U", "omega", "nPrimary", "origId"):
            x = foamio.read_lagrangian(src / times[-1].name / "lagrangian"
                                       / m / f)
            y = foamio.read_lagrangian(case / times[-1].name / "lagrangian"
                                       / m / f)
            np.testing.assert_allclose(y, x, rtol=1e-12, atol=1e-15,
                                       err_msg=f"{m} {f}")
