"""Exact equality of the cloud's runs on the agglomerating box gas
(cloudBoxCases): a restart continues as the uninterrupted run, the same
run twice, serial and 2-rank counters every step, and the parcels kept in
cell order or not (the same events and particles; the written list in
cell order, stable within a cell)."""

from pathlib import Path

import numpy as np
import pytest

from aggloTools import placement
from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.cloud import cloud_dir, read_lagrangian, read_positions
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows as stats
from aggloTools.times import last_time
from cloudBoxCases import D, agglomerating_gas, cloud_state


def final_fields(case_dir, t):
    d = Path(case_dir) / t / "lagrangian" / "kinematicCloud"
    return {f.name: f.read_text().split("\n", 16)[-1]
            for f in sorted(d.iterdir()) if f.name != "positions"}


def test_restart_equals_continuous_run(case_dir, foam_env):
    full = case_dir / "full"
    agglomerating_gas(full, 4e-3, 20)
    run_case(full)
    half = case_dir / "half"
    agglomerating_gas(half, 2e-3, 20)
    run_case(half)
    run([foam_bin("foamDictionary"), "-entry", "endTime", "-set", "0.004",
         "system/controlDict"], half, "log.foamDictionary")
    run([foam_bin("aggloPimpleFoam")], half, "log.aggloPimpleFoam.restart")
    a, b = stats(full)[-1], stats(half)[-1]
    assert a["nCol"] > 5 and a["nAgg"] > 0 and a["nWall"] > 0
    # OpenFOAM re-reads the time from the directory name on restart, so
    # the time value itself may differ in the last bit
    assert b.pop("Time") == pytest.approx(a.pop("Time"), rel=1e-12)
    assert a == b
    fa, fb = final_fields(full, "0.004"), final_fields(half, "0.004")
    assert fa.keys() == fb.keys()
    # contact times carry the same last-bit difference of the time value
    ta = read_lagrangian(cloud_dir(full, "0.004") / "lastContactTime")
    tb = read_lagrangian(cloud_dir(half, "0.004") / "lastContactTime")
    np.testing.assert_allclose(ta, tb, rtol=1e-12, atol=0)
    fa.pop("lastContactTime"), fb.pop("lastContactTime")
    assert fa == fb  # positions, U, omega, d, rho, ids, partners: exact


def test_same_run_twice_and_parallel_counts(case_dir, foam_env):
    runs = {}
    for name, procs in (("a", 0), ("b", 0), ("mpi", 2)):
        c = case_dir / name
        agglomerating_gas(c, 4e-3, 40, decompose=(2, 1, 1))
        run_case(c, parallel=procs)
        runs[name] = c
    # repetition: identical output
    assert final_fields(runs["a"], "0.004") == \
        final_fields(runs["b"], "0.004")
    assert stats(runs["a"]) == stats(runs["b"])
    # decomposition: identical counters every step
    keys = ("nParticles", "nPrimaries", "nAgglomerates", "nCol",
            "nColFirst", "nColRepeat", "nColOverlapStart", "nAgg",
            "nSuppressed", "nSkipSeparating", "nWall", "maxPrimaries")
    sa, sm = stats(runs["a"]), stats(runs["mpi"])
    assert len(sa) == len(sm) == 40
    for ra, rm in zip(sa, sm):
        assert {k: ra[k] for k in keys} == {k: rm[k] for k in keys}
        assert rm["mass"] == pytest.approx(ra["mass"], rel=1e-12)
    assert sa[-1]["nAgg"] > 0
    # mass and primaries conserved
    assert sa[-1]["nPrimaries"] == 300
    assert sa[-1]["mass"] == pytest.approx(sa[0]["mass"], rel=1e-12)
    assert sa[-1]["nParticles"] == 300 - sa[-1]["nAgg"]


def with_cell_order(case, interval):
    """Set the cloud's cellOrderInterval."""
    f = Path(case) / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    assert "solution\n{\n" in text
    f.write_text(text.replace(
        "solution\n{\n", f"solution\n{{\n    cellOrderInterval {interval};\n",
        1))


def test_cell_order_keeps_the_physics(case_dir, foam_env):
    """The agglomerating gas with the parcels sorted into cell order at
    every step and never: the same events (counters of every step), the
    same particles (every field, exact, once ordered by particle id);
    only the sums over particles of the statistics (mass, mean diameters,
    ...), added in another order, may differ in round-off."""
    runs = {}
    for name, interval in (("sorted", 1), ("unsorted", 0)):
        c = case_dir / name
        agglomerating_gas(c, 4e-3, 40)
        with_cell_order(c, interval)
        run_case(c)
        runs[name] = c
    log = (runs["sorted"] / "log.aggloPimpleFoam").read_text()
    # every step, and once more after the written step (the written
    # order is the cell order)
    assert log.count("parcels in cell order") == 40 + 1
    assert "parcels in cell order" not in \
        (runs["unsorted"] / "log.aggloPimpleFoam").read_text()
    sa, sb = stats(runs["sorted"]), stats(runs["unsorted"])
    assert len(sa) == len(sb) == 40
    counters = ("nParticles", "nPrimaries", "nAgglomerates", "nCol",
                "nColFirst", "nColRepeat", "nColOverlapStart", "nAgg",
                "nSuppressed", "nSkipSeparating", "nWall", "maxPrimaries")
    for ra, rb in zip(sa, sb):
        assert ra.keys() == rb.keys()
        assert {k: ra[k] for k in counters} == {k: rb[k] for k in counters}
        for k in ra:
            assert rb[k] == pytest.approx(ra[k], rel=1e-12, abs=1e-300), k
    assert sa[-1]["nCol"] > 5 and sa[-1]["nAgg"] > 0 and sa[-1]["nWall"] > 0
    a = cloud_state(runs["sorted"], "0.004")
    b = cloud_state(runs["unsorted"], "0.004")
    a["x"] = read_positions(cloud_dir(runs["sorted"], "0.004") / "positions")
    b["x"] = read_positions(cloud_dir(runs["unsorted"], "0.004")
                            / "positions")
    ia = np.lexsort((a["origId"], a["origProcId"]))
    ib = np.lexsort((b["origId"], b["origProcId"]))
    assert not np.array_equal(ia, ib)  # the lists are in other orders
    for k in a:
        np.testing.assert_array_equal(a[k][ia], b[k][ib], err_msg=k)


def test_cell_order_is_the_order_of_the_cells(case_dir, foam_env):
    """Particles at rest on a 6^3 mesh, placed in random order: after a
    step with cellOrderInterval 1 the written list ascends by cell (the
    cell computed from the position on the uniform mesh), in id order
    within a cell (the sort is stable); without it, the ids ascend."""
    rng = np.random.default_rng(5)
    Lb, n, N = 2e-4, 6, 200
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0),
                         (Lb, Lb - 0.6 * D, Lb), (Lb, None, Lb), rng)
    parts = [dict(x=tuple(x), U=(0, 0, 0), id=i) for i, x in enumerate(xs)]
    for interval in (1, 0):
        c = case_dir / f"i{interval}"
        box_case(c, L=(Lb,) * 3, n=(n,) * 3,
                 kinds=("cyclic", "wall", "cyclic"),
                 particles=parts, dt=1e-4, end_time=1e-4,
                 hard_sphere=kernel("EAM"))
        with_cell_order(c, interval)
        run_case(c)
        t = last_time(c)
        x = read_positions(cloud_dir(c, t) / "positions")
        ids = read_lagrangian(cloud_dir(c, t) / "origId").astype(int)
        np.testing.assert_allclose(x, xs[ids], rtol=0, atol=1e-12 * Lb)
        ijk = np.minimum((x / Lb * n).astype(int), n - 1)
        cell = ijk[:, 0] + n * (ijk[:, 1] + n * ijk[:, 2])
        if interval:
            assert (np.diff(cell) >= 0).all()
            same = np.diff(cell) == 0
            assert (np.diff(ids)[same] > 0).all()
            assert not (np.diff(ids) > 0).all()
        else:
            np.testing.assert_array_equal(ids, np.arange(N))
            assert not (np.diff(cell) >= 0).all()
