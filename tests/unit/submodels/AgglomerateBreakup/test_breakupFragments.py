"""The fragments of the stressThreshold model (doc/breakup.md): they never
stick again in still fluid (V6), the break time does not depend on the
time step (V7), and mass, momentum and angular momentum are conserved on
10^4 parents, serially and on 2 ranks (V4)."""

import math
import re

import numpy as np
import pytest
from scipy.spatial import cKDTree

from aggloTools import boxcase, breakuplog
from aggloTools.stats import read_stats
from aggloTools.times import last_time
from breakupCases import (BREAKUP, DP, GAP, H, NU_F, RHO_F, breakup, by_id,
                          kernel, omega_crit, size_density, state,
                          tensile_strength, totals)


def test_fragments_never_re_stick_in_still_fluid(case_dir, foam_env):
    """V6: a doublet split by its spin in still fluid (no forces) leaves
    two primaries whose relative velocity is perpendicular to their
    separation: they are made after the step's collisions and then move
    apart as sqrt(s^2 + v^2 t^2), so no collision or agglomeration ever
    follows."""
    n = 2
    da, rho = size_density(n, "CSM")
    w = 1.01 * omega_crit(n, "CSM")
    part = [dict(x=(1e-3, 0.5e-3, 0.5e-3), U=(0, 0, 0), d=da, rho=rho,
                 nPrimary=n, omega=(0, 0, w))]
    hs = kernel()
    boxcase.box_case(case_dir, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                     particles=part, dt=1e-7, end_time=2e-6,
                     write_interval=5, hard_sphere=hs, cloud=BREAKUP)
    boxcase.run_case(case_dir)
    stats = read_stats(case_dir)
    assert stats["nBreakupRotation"][-1] == 1
    assert stats["nCol"][-1] == 0 and stats["nAgg"][-1] == 0

    s0 = DP + GAP * DP                     # the split's separation
    ts = sorted((p.name for p in case_dir.iterdir()
                 if p.name.startswith(("5e-", "1e-", "1.5e-", "2e-"))),
                key=float)
    assert len(ts) == 4
    v = None
    for t in ts:
        c, x, _ = state(case_dir, t)
        assert len(c["d"]) == 2 and list(c["nPrimary"]) == [1, 1]
        if v is None:
            v = np.linalg.norm(c["U"][0] - c["U"][1])
            assert v > 0
        # moving apart since the end of the first step (t - dt)
        dt = float(t) - 1e-7
        assert np.linalg.norm(x[0] - x[1]) == pytest.approx(
            math.hypot(s0, v * dt), rel=1e-9)


@pytest.mark.parametrize("refine", [10, 20, 40])
def test_break_time_independent_of_the_time_step(case_dir, foam_env,
                                                 refine):
    """V7: an agglomerate released without spin in frozen Couette flow
    spins up under the fluid torque (Stokes regime, Re_R < 32) as
    omega(t) = gamma/2 (1 - exp(-t/tau)), tau = rho_a d_a^2/(60 mu),
    exactly per step; bonds weakened so that omega_crit = 0.8 gamma/2 it
    breaks at t_b = tau ln 5, in the first step that ends after t_b, for
    dt = tau/10, tau/20 and tau/40."""
    n, gamma = 10, 2e4
    da, rho = size_density(n, "CSM")
    mu = NU_F * RHO_F
    tau = rho * da ** 2 / (60 * mu)
    assert RHO_F * (gamma / 2) * da ** 2 / mu < 32      # Re_R, Stokes
    w_crit = 0.8 * gamma / 2
    # sigma_T (proportional to H) for this omega_crit
    h_weak = H * rho * (w_crit * da / 4) ** 2 / tensile_strength(n, "CSM")
    t_b = tau * math.log(5)
    dt = tau / refine
    k_b = math.floor(t_b / dt) + 1                      # the break step
    y0 = 0.52e-3
    part = [dict(x=(0.5e-3, y0, 0.25e-3),
                 U=(gamma * (y0 - 0.5e-3), 0, 0), d=da, rho=rho,
                 nPrimary=n, omega=(0, 0, 0))]
    hs = kernel(h_weak)
    Lb, nb = (1e-3, 1e-3, 0.5e-3), (5, 10, 2)
    uw = gamma * Lb[1] / 2
    boxcase.box_case(case_dir, L=Lb, n=nb,
                     kinds=("cyclic", "wall", "cyclic"), particles=part,
                     dt=dt, end_time=(k_b + 3) * dt, nu=NU_F, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     hard_sphere=hs, cloud=breakup(rotation=True))
    boxcase.write_internal_U(case_dir, Lb, nb,
                             lambda x, y, z: (gamma * (y - Lb[1] / 2), 0,
                                              0))
    boxcase.run_case(case_dir)
    log = (case_dir / "log.aggloPimpleFoam").read_text()
    events = [int(m) for m in re.findall(r"Break-up: (\d+) events", log)]
    assert len(events) == k_b + 3
    assert events.index(1) + 1 == k_b, (events, k_b)
    assert sum(events) == 1
    # the break lies within one time step after t_b
    assert 0 < k_b * dt - t_b <= dt


def many_parents(case, mode, decompose=(1, 1, 1)):
    """10^4 CSM agglomerates of 2-20 primaries on a 100 um lattice
    (22 x 22 x 21), spinning about random axes at 1.05-2 omega_crit,
    moving at random velocities below 1 mm/s: every one breaks in the
    first step (rotation), erosion or binary split, the parents at the
    processor plane x = 1.1 mm included."""
    rng = np.random.default_rng(7)
    parts = []
    for i in range(22):
        for j in range(22):
            for k in range(21):
                n = int(rng.integers(2, 21))
                da, rho = size_density(n, "CSM")
                axis = rng.normal(size=3)
                axis /= np.linalg.norm(axis)
                w = rng.uniform(1.05, 2) * omega_crit(n, "CSM")
                parts.append(dict(
                    x=(50e-6 + 100e-6 * i, 50e-6 + 100e-6 * j,
                       50e-6 + 100e-6 * k),
                    U=tuple(rng.uniform(-1e-3, 1e-3, 3)), d=da, rho=rho,
                    nPrimary=n, omega=tuple(w * axis)))
    assert len(parts) == 10164
    hs = kernel()
    brk = breakup(fragmentation={"mode": mode}, eventLog=True)
    boxcase.box_case(case, L=(2.2e-3, 2.2e-3, 2.1e-3), n=(11, 11, 10),
                     particles=parts, dt=1e-7, end_time=1e-7,
                     hard_sphere=hs, cloud=brk, decompose=decompose,
                     write_format="binary")
    return parts


@pytest.mark.parametrize("mode", ["erosion", "binary"])
def test_conservation_on_ten_thousand_parents_and_two_ranks(case_dir,
                                                            foam_env, mode):
    """V4 in the cloud: 10^4 parents break in one step; the primaries are
    kept exactly, the mass to 1e-12, the momentum and the angular
    momentum about the origin to 1e-12 of the sum of their magnitudes
    (the totals of random spins and velocities nearly cancel); on 2 ranks
    the same fragments with the same ids and states."""
    serial, par = case_dir / "serial", case_dir / "parallel"
    many_parents(serial, mode)
    many_parents(par, mode, decompose=(2, 1, 1))
    boxcase.run_case(serial)
    boxcase.run_case(par, parallel=2)
    c0, x0, m0 = state(serial, 0)
    t = last_time(serial)
    c1, x1, m1 = state(serial, t)
    assert len(m1) == 2 * len(m0)               # every parent broke
    N0, M0, P0, L0 = totals(c0, x0, m0)
    N1, M1, P1, L1 = totals(c1, x1, m1)
    assert N1 == N0
    assert M1 == pytest.approx(M0, rel=1e-12)
    p_scale = np.sum(m0 * np.linalg.norm(c0["U"], axis=1)) + np.sum(
        m1 * np.linalg.norm(c1["U"], axis=1))
    assert np.linalg.norm(P1 - P0) < 1e-12 * p_scale
    spin = (0.1 * m0 * c0["d"] ** 2) * np.linalg.norm(c0["omega"], axis=1)
    orbit = m0 * np.linalg.norm(np.cross(x0, c0["U"]), axis=1)
    assert np.linalg.norm(L1 - L0) < 1e-12 * np.sum(spin + orbit)

    cs, xs = by_id(c1, x1)
    cp, xp = by_id(*state(par, t)[:2])
    for k in ("origProcId", "origId", "nPrimary"):
        assert np.array_equal(cs[k], cp[k]), k
    for k in ("d", "rho", "U", "omega"):
        assert np.allclose(cs[k], cp[k], rtol=1e-12, atol=0), k
    assert np.max(np.abs(xs - xp)) < 1e-12 * 2.2e-3

    # The break-up logs: one record per parent, the same on 2 ranks (two
    # files), each reproduced by the run's kernel
    es = breakuplog.read_breakup_events(serial)
    ep = breakuplog.read_breakup_events(par)
    assert len(es) == len(m0) == len(ep)
    assert len(list(breakuplog.folder(par).glob("events*.bin"))) == 2
    for k in ("timeIndex", "mechanism", "proc", "id", "newProc", "newId",
              "nPrimary_a", "nPrimary_b"):
        assert np.array_equal(es[k], ep[k]), k
    for k in ("U_a", "U_b", "omega_a", "omega_b", "d_a"):
        assert np.allclose(es[k], ep[k], rtol=1e-12, atol=0), k
    for c in (serial, par):
        res = breakuplog.replay_breakups(c, check=True)
        assert res["configurations"][0]["reproduced"] == len(m0)


def crowded_parents(case, mode, decompose=(1, 1, 1)):
    """1,452 spinning CSM agglomerates of 2-20 primaries at 1.05-2
    omega_crit, all at rest, on a 100 um lattice (11 x 11 x 12) of a box
    cyclic in x and z, shifted so that the first plane of parents lies
    5 um from the cyclic faces; each with 4 primaries around it in the
    plane perpendicular to its spin (where a split by rotation puts its
    fragments), 1-30 % of the contact distance away, some of them through
    the cyclic faces; every seventh with a second agglomerate beside it
    that breaks in the same step. Nothing moves but the spins: no
    collision, every agglomerate breaks (rotation) in the first step where
    its fragments find room."""
    rng = np.random.default_rng(11)
    L = (1.1e-3, 1.1e-3, 1.2e-3)
    parts, parents = [], []

    def wrap(x):
        return (x[0] % L[0], x[1], x[2] % L[2])

    def agglomerate(x, axis):
        n = int(rng.integers(2, 21))
        da, rho = size_density(n, "CSM")
        w = rng.uniform(1.05, 2) * omega_crit(n, "CSM")
        parts.append(dict(x=wrap(x), U=(0, 0, 0), d=da, rho=rho,
                          nPrimary=n, omega=tuple(w * axis)))
        parents.append(len(parts) - 1)
        return da

    for i in range(11):
        for j in range(11):
            for k in range(12):
                c = np.array([5e-6 + 100e-6 * i, 50e-6 + 100e-6 * j,
                              5e-6 + 100e-6 * k])
                axis = rng.normal(size=3)
                axis /= np.linalg.norm(axis)
                da = agglomerate(c, axis)
                # two unit vectors perpendicular to the spin
                u = np.cross(axis, rng.normal(size=3))
                u /= np.linalg.norm(u)
                v = np.cross(axis, u)
                phis = rng.uniform(0, 2 * math.pi) + np.arange(4) * (
                    math.pi / 2) + rng.uniform(-0.4, 0.4, 4)
                for m, phi in enumerate(phis):
                    e = math.cos(phi) * u + math.sin(phi) * v
                    if m == 0 and len(parents) % 7 == 0:
                        # a second parent beside it
                        n2 = int(rng.integers(2, 21))
                        d2 = size_density(n2, "CSM")[0]
                        s = 0.5 * (da + d2) * rng.uniform(1.01, 1.3)
                        if 0.5 * da + s + d2 < 50e-6:
                            agglomerate(c + s * e, axis)
                            continue
                    s = 0.5 * (da + DP) * rng.uniform(1.01, 1.3)
                    parts.append(dict(x=wrap(c + s * e), U=(0, 0, 0),
                                      d=DP, rho=2200.0, nPrimary=1,
                                      omega=(0, 0, 0)))
    hs = kernel()
    brk = breakup(fragmentation={"mode": mode}, eventLog=True)
    boxcase.box_case(case, L=L, n=(11, 11, 12),
                     kinds=("cyclic", "wall", "cyclic"), particles=parts,
                     dt=1e-7, end_time=1e-7, hard_sphere=hs, cloud=brk,
                     decompose=decompose, write_format="binary")
    return parts, parents, L


def overlaps(c, x, L):
    """The pairs of particles that overlap (the brute-force oracle: a
    k-d tree over all pairs within the largest contact distance, the
    cyclic directions x and z wrapped) and the deepest overlap as a
    fraction of the contact distance."""
    box = np.array([L[0], 100 * L[1], L[2]])
    tree = cKDTree(np.mod(x, box), boxsize=box)
    pairs = tree.query_pairs(c["d"].max())
    deepest, n = 0.0, 0
    for i, j in pairs:
        dx = x[i] - x[j]
        dx -= box * np.round(dx / box)
        R = 0.5 * (c["d"][i] + c["d"][j])
        gap = np.linalg.norm(dx) / R
        if gap < 1:
            n += 1
            deepest = max(deepest, 1 - gap)
    return n, deepest


@pytest.mark.parametrize("mode", ["erosion", "binary"])
def test_fragments_never_overlap_a_neighbour(case_dir, foam_env, mode):
    """doc/breakup.md 3.2 (the spec's V4: no overlaps with seeded
    neighbours): after the step no two particles overlap (a brute-force
    search over all pairs, through the cyclic faces too; the previous
    placement left many); each parent either broke, its fragments placed
    by one of the tries (the first, the opposite one and further ones all
    used), or waited whole and unchanged, counted in nBreakupNoRoom;
    primaries, mass, momentum and angular momentum kept; 2 ranks give the
    same fragments, ids and tries; breakupReplay -check reproduces every
    logged break-up along its logged try."""
    serial, par = case_dir / "serial", case_dir / "parallel"
    _, parents, L = crowded_parents(serial, mode)
    crowded_parents(par, mode, decompose=(2, 1, 1))
    boxcase.run_case(serial)
    boxcase.run_case(par, parallel=2)

    c0, x0, m0 = state(serial, 0)
    assert overlaps(c0, x0, L)[0] == 0          # the seeded state
    t = last_time(serial)
    c1, x1, m1 = state(serial, t)
    n, deepest = overlaps(c1, x1, L)
    assert n == 0, f"{n} overlapping pairs, deepest {deepest:.3f}"

    # the positions unwrapped: each particle's image nearest to where it
    # started, a new fragment's nearest to where its parent started (a
    # fragment placed through a cyclic face moves by a period, and so
    # would its angular momentum about the origin)
    ev = breakuplog.read_breakup_events(serial)
    start = {(p, i): x for p, i, x in zip(c0["origProcId"], c0["origId"],
                                            x0)}
    for e in ev:
        start[(e["newProc"], e["newId"])] = start[(e["proc"], e["id"])]
    box = np.array(L)
    ref = np.array([start[k] for k in zip(c1["origProcId"], c1["origId"])])
    x1 = ref + (x1 - ref) - box * np.round((x1 - ref) / box)

    N0, M0, P0, L0 = totals(c0, x0, m0)
    N1, M1, P1, L1 = totals(c1, x1, m1)
    assert N1 == N0
    assert M1 == pytest.approx(M0, rel=1e-12)
    # to 1e-12 of the sum of the magnitudes: the spins before, the
    # fragments' spins and orbits about the origin after
    scale = np.sum((0.1 * m0 * c0["d"] ** 2)
                   * np.linalg.norm(c0["omega"], axis=1)) + np.sum(
        (0.1 * m1 * c1["d"] ** 2) * np.linalg.norm(c1["omega"], axis=1)
        + m1 * np.linalg.norm(np.cross(x1, c1["U"]), axis=1))
    assert np.linalg.norm(L1 - L0) < 1e-12 * scale

    # every parent broke or waited whole, and the counts say which
    stats = read_stats(serial)
    broke = len(m1) - len(m0)
    waited = int(stats["nBreakupNoRoom"][-1])
    assert stats["nBreakupRotation"][-1] == broke
    assert broke + waited == len(parents)
    s0, _ = by_id(c0, x0)
    s1, _ = by_id(c1, x1)
    seeded = s1["origProcId"] >= 0              # fragments: -2
    assert np.array_equal(s1["origId"][seeded], s0["origId"])
    same = (s1["nPrimary"][seeded] == s0["nPrimary"]) & np.all(
        s1["omega"][seeded] == s0["omega"], axis=1)
    assert int(np.sum(same & (s0["nPrimary"] > 1))) == waited
    assert waited > 0 and broke > 0

    assert len(ev) == broke
    tries = np.bincount(ev["attempt"], minlength=3)
    assert tries[0] > 0 and tries[1] > 0 and tries[2:].sum() > 0, tries
    assert ev["attempt"].max() < 6

    cs, xs = by_id(c1, x1)
    cp, xp = by_id(*state(par, t)[:2])
    for k in ("origProcId", "origId", "nPrimary"):
        assert np.array_equal(cs[k], cp[k]), k
    for k in ("d", "U", "omega"):
        assert np.allclose(cs[k], cp[k], rtol=1e-12, atol=0), k
    dx = xs - xp
    assert np.max(np.abs(dx - box * np.round(dx / box))) < 1e-12 * L[0]
    assert int(read_stats(par)["nBreakupNoRoom"][-1]) == waited
    ep = breakuplog.read_breakup_events(par)
    order = np.lexsort((ev["id"], ev["proc"]))
    order_p = np.lexsort((ep["id"], ep["proc"]))
    assert np.array_equal(ev["attempt"][order], ep["attempt"][order_p])
    for c in (serial, par):
        res = breakuplog.replay_breakups(c, check=True)
        assert res["configurations"][0]["reproduced"] == broke
