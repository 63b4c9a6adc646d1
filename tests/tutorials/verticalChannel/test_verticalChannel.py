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
  velocities).
The smoke runs' reports, pictures and the regime study's post-processing
of them: post/test_channelSmokeOutputs.py."""

import json
import math
import shutil

import numpy as np
import pytest

from aggloTools import cloud, fields, times
from aggloTools.runner import foam_bin, run, tutorial_module
from aggloTools.stats import read_stats
from channelTestRuns import (N_PAIRS, N_RELEASED, N_TOTAL, STEPS_AGG,
                             agg_runs, last_profiles, script)



@pytest.mark.parametrize("np_", [1, 2])
def test_statistics_complete_and_consistent(smoke_runs, np_):
    case = smoke_runs[np_]
    for (c, m), adir in agg_runs(case).items():
        st = read_stats(adir, m)
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
        dfin = cloud.read_lagrangian(times.time_dirs(adir)[-1]
                                      / "lagrangian" / m / "d")
        assert t[:, 5].mean() == pytest.approx(
            (math.pi / 6 * dfin**3).sum() / (Lx * Ly * Lz), rel=0.01)
    summary = json.loads((case / "runs/smoke/report/summary.json").read_text())
    assert not [r for r in summary["regression"] if r["status"] == "FAIL"]
    # the run's report goes beside the committed reference, never into it
    assert not (case / "results").exists()
    assert "no committed reference" in (
        case / "runs/smoke/report/comparison.txt").read_text()
    assert (case / "runs/smoke/report/particlesC1EAM.png").is_file()


@pytest.mark.parametrize("np_", [1, 2])
def test_replay_of_the_event_logs(smoke_runs, np_):
    """channel.post.replay (doc/eventLog.md): each agglomeration cloud's log
    holds its first contacts (the statistics' count); replayed with the
    run's own kernel they agglomerate as often as the run's first
    contacts did, every logged outcome reproduced; EAM at e_n 0.97 is the
    run's kernel for the EAM clouds."""
    case = smoke_runs[np_]
    rep = json.loads((case / "runs/smoke/report/replay.json").read_text())
    assert sorted(rep["ensembles"]) == ["C1 EAM", "C1 MAM", "C2 EAM",
                                        "C2 MAM"]
    for (c, m), adir in agg_runs(case).items():
        st = read_stats(adir, m)
        res = rep["ensembles"][f"{c} {m}"]
        own = res["configurations"][0]
        assert own["name"] == "run"
        assert own["events"] == st["nColFirst"][-1] > 0
        assert own["compared"] == own["matches"] == own["events"]
        assert own["agglomerations"] == st["nAggFirst"][-1]
        conf = {r["name"]: r for r in res["configurations"]}
        same = conf[f"{m}097"]
        assert same["agglomerations"] == own["agglomerations"]


@pytest.mark.parametrize("np_", [1, 2])
def test_seeded_pairs(smoke_runs, np_):
    """C1 (no random numbers): exactly the slow pairs agglomerate."""
    case = smoke_runs[np_]
    adir = agg_runs(case)[("C1", "EAM")]
    t = times.time_dirs(adir)[-1]
    for m in ("EAM", "MAM"):
        st = read_stats(adir, m)
        assert st["nCol"][-1] >= N_PAIRS
        assert st["nAgg"][-1] == N_PAIRS // 2, m
        assert st["nParticles"][-1] == N_TOTAL - N_PAIRS // 2
        cdir = t / "lagrangian" / m
        ids = cloud.read_lagrangian(cdir / "origId").astype(int)
        npri = cloud.read_lagrangian(cdir / "nPrimary").astype(int)
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
        a = read_stats(s[key], key[1])
        b = read_stats(p[key], key[1])
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
    src = agg_runs(smoke_runs[1])[("C1", "EAM")]
    case = tmp_path / "restart"
    shutil.copytree(src, case, ignore=shutil.ignore_patterns("VTK"))
    tdirs = times.time_dirs(case)
    assert len(tdirs) == 4          # branch time and 3 writes
    for t in tdirs[2:]:
        shutil.rmtree(t)
    for d in case.glob("postProcessing/*HardSphere/*"):
        if float(d.name) > float(tdirs[1].name):
            shutil.rmtree(d)
    (case / "log.aggloPimpleFoam").unlink()
    run([foam_bin("aggloPimpleFoam")], case, "log.aggloPimpleFoam")
    assert times.time_dirs(case)[-1].name == tdirs[-1].name
    for m in ("EAM", "MAM"):
        a, b = read_stats(src, m), read_stats(case, m)
        assert len(b["Time"]) == STEPS_AGG
        for col in a:
            if col != "Time":
                np.testing.assert_allclose(b[col], a[col], rtol=1e-12,
                                           atol=0, err_msg=f"{m} {col}")
        for f in ("U", "omega", "nPrimary", "origId"):
            x = cloud.read_lagrangian(src / tdirs[-1].name / "lagrangian"
                                       / m / f)
            y = cloud.read_lagrangian(case / tdirs[-1].name / "lagrangian"
                                       / m / f)
            np.testing.assert_allclose(y, x, rtol=1e-12, atol=1e-15,
                                       err_msg=f"{m} {f}")


# ----------------------------------------------------------- the release

def _particles_module():
    """channel.case.particles, with the settings module it imports."""
    return tutorial_module("verticalChannel", "channel.case.particles")


def _brute_overlaps(x, dmin, Lx, Lz):
    """Oracle: every pair, minimum image in x and z."""
    r = x[:, None, :] - x[None, :, :]
    r[..., 0] -= Lx * np.round(r[..., 0] / Lx)
    r[..., 2] -= Lz * np.round(r[..., 2] / Lz)
    close = np.einsum("ijk,ijk->ij", r, r) < dmin**2
    i, j = np.nonzero(np.triu(close, 1))
    return np.unique(np.maximum(i, j))


def test_release_places_without_overlap():
    """place(): no two centres closer than 1.001 d (oracle), every centre
    inside the walls' clearance, the same positions for the same seed."""
    ch = _particles_module()
    L = (2 * math.pi * 0.02, 0.04, math.pi * 0.02)
    dp = 1e-3               # dense: about 30 % of the first draws overlap
    a = ch.place(3000, dp, L, np.random.default_rng(3))
    b = ch.place(3000, dp, L, np.random.default_rng(3))
    assert np.array_equal(a, b)
    assert len(_brute_overlaps(a, dp * 1.001, L[0], L[2])) == 0
    assert len(_brute_overlaps(
        np.random.default_rng(3).uniform(0, 1, (3000, 3)) * L,
        dp * 1.001, L[0], L[2])) > 50
    assert a[:, 1].min() >= dp / 2 * 1.001
    assert a[:, 1].max() <= L[1] - dp / 2 * 1.001


def test_release_into_processors_is_the_serial_release(smoke_runs):
    """On 2 ranks the particles are written straight into the processor
    folders (no decomposePar): together the same particles and ids as the
    serial release, each on the rank whose cells hold it (its z inside
    that rank's slab of the mesh), with the velocity of the 2-rank run's
    own fluid (the LES on 2 ranks differs by round-off) at its cell."""
    def released(root, t):
        c = root / t / "lagrangian/particles"
        return (cloud.read_lagrangian(c / "origId").astype(int),
                cloud.read_positions(c / "positions"),
                cloud.read_lagrangian(c / "U"))
    s = smoke_runs[1] / "runs/smoke/C1/dispersion"
    p = smoke_runs[2] / "runs/smoke/C1/dispersion"
    t = times.time_dirs(s)[0].name
    ids, x, U = released(s, t)
    assert np.array_equal(ids, np.arange(N_RELEASED))
    assert not (p / "log.decomposePar").exists()
    got = {}
    for proc in sorted(p.glob("processor*")):
        i, xp, up = released(proc, t)
        assert 0 < len(i) < N_RELEASED
        z = cloud.read_lagrangian(proc / "constant/polyMesh/points")[:, 2]
        assert np.all((xp[:, 2] >= z.min()) & (xp[:, 2] <= z.max()))
        got.update({k: (a, b) for k, a, b in zip(i, xp, up)})
    assert sorted(got) == list(range(N_RELEASED))
    assert np.array_equal(np.array([got[k][0] for k in ids]), x)
    ch = _particles_module()
    grid = ch.Grid(fields.read_internal(p / t / "C"), (16, 16, 16))
    Uf = fields.read_internal(p / t / "U")
    assert np.array_equal(np.array([got[k][1] for k in ids]),
                          Uf[grid.cell(x)])
    assert not np.array_equal(Uf[grid.cell(x)], U)      # a different LES


def test_resumed_log_counts_each_step_once():
    """A run resumed with -append repeats the steps after its last write
    in the log: the u_tau check reads each step's gradients once, the
    resumed run's (channel.post.postprocess.step_values)."""
    post = script("channel.post.postprocess")
    steps = [(1, [10, 11]), (2, [20, 21]), (3, [30, 31]),     # killed
             (2, [22, 23]), (3, [32, 33]), (4, [40, 41])]     # resumed
    log = "".join(f"Time = {t}\n" + "".join(
        f"Pressure gradient source: uncorrected Ubar = 1, pressure "
        f"gradient = {g}\n" for g in gs) for t, gs in steps)
    assert post.step_values(log, r"pressure gradient = ([-0-9.eE+]+)") \
        == [10, 11, 22, 23, 32, 33, 40, 41]
