"""The stressThreshold break-up model in the cloud (doc/breakup.md): the
critical spin of verification case V1 for both structure models and
N = 2, 3, 4, 10, 1000, the fragments' placement, spins and conservation,
their global ids and the restart record, and a break-up at a processor
boundary on 2 ranks against the serial run. The expectations are the
spec's hand formulas (doc/breakup.md 1.4, 2, 3.2, 3.3, in breakupCases),
computed independently of the C++ kernels. The other loads are in
test_breakupCriteria, the fragments' fate and V4 in
test_breakupFragments."""

import re

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.cloud import read_cloud, read_record
from aggloTools.stats import read_stats
from aggloTools.times import last_time
from aggloTools.foamfile import edit
from breakupCases import (BREAKUP, DP, GAP, RHO_P, by_id, kernel,
                          omega_crit, size_density, state, totals)


NS = (2, 3, 4, 10, 1000)


def spinning_case(case, structure, factors=(0.99, 1.01)):
    """One agglomerate per N and factor, spinning at factor*omega_crit
    about z in fluid at rest; no forces, no fluid torque: one step."""
    parts = []
    for i, n in enumerate(NS):
        for j, fac in enumerate(factors):
            da, rho = size_density(n, structure)
            parts.append(dict(x=(0.2e-3 + 0.4e-3 * i, 0.3e-3 + 0.4e-3 * j,
                                 0.5e-3), U=(0, 0, 0), d=da, rho=rho,
                              nPrimary=n,
                              omega=(0, 0, fac * omega_crit(n, structure))))
    hs = kernel(structure=structure)
    boxcase.box_case(case, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                     particles=parts, dt=1e-7, end_time=1e-7,
                     hard_sphere=hs, cloud=BREAKUP)
    return parts


@pytest.mark.parametrize("structure", ["CSM", "VSM"])
def test_critical_spin_erodes_one_primary(case_dir, foam_env, structure):
    """V1: at 0.99 omega_crit nothing breaks, at 1.01 omega_crit one
    primary leaves (erosion), for N = 2, 3, 4, 10, 1000. The two fragments
    lie perpendicular to the spin, (d1 + d2)/2 + gap d_p apart about the
    parent's centre of mass, and spin at omega' = I_a omega/J (angular
    momentum kept); primaries, mass, momentum and angular momentum are
    kept; the fragments' ids are (-2, 0..4) in the parents' id order and
    the restart record counts 5."""
    parts = spinning_case(case_dir, structure)
    boxcase.run_case(case_dir)
    t = last_time(case_dir)
    c0, x0, m0 = state(case_dir, 0)
    c1, x1, m1 = state(case_dir, t)

    # Which broke: the 1.01 ones (odd ids), each into N - 1 and 1
    parents = c1["origProcId"] >= 0
    frag = ~parents
    order = np.argsort(c1["origId"][parents])
    n_after = c1["nPrimary"][parents][order]
    n_before = np.array([p["nPrimary"] for p in parts])
    broke = np.arange(len(parts)) % 2 == 1
    assert np.array_equal(n_after, np.where(broke, n_before - 1, n_before))
    assert np.array_equal(np.sort(c1["origId"][frag]), np.arange(5))
    assert np.all(c1["origProcId"][frag] == -2)
    assert np.all(c1["nPrimary"][frag] == 1)

    # Fragment k belongs to the k-th breaking parent in id order
    for k, pid in enumerate(np.flatnonzero(broke)):
        n = parts[pid]["nPrimary"]
        X = np.array(parts[pid]["x"])
        w = parts[pid]["omega"][2]
        ia = np.flatnonzero(frag & (c1["origId"] == k))[0]
        ib = np.flatnonzero(parents & (c1["origId"] == pid))[0]
        da, rho_a = size_density(n, structure)
        d2, rho2 = size_density(n - 1, structure)
        assert c1["d"][ia] == pytest.approx(DP, rel=1e-12)
        assert c1["d"][ib] == pytest.approx(d2, rel=1e-12)
        assert c1["rho"][ib] == pytest.approx(rho2, rel=1e-12)

        # Placement (doc/breakup.md 3.2): perpendicular to the spin, the
        # gap apart, the centre of mass kept
        r = x1[ia] - x1[ib]
        assert abs(r[2]) < 1e-12
        assert np.linalg.norm(r) == pytest.approx(
            (DP + d2) / 2 + GAP * DP, rel=1e-9)
        ma, mb = m1[ia], m1[ib]
        com = (ma * x1[ia] + mb * x1[ib]) / (ma + mb)
        assert np.linalg.norm(com - X) < 1e-9 * da

        # Spin (doc/breakup.md 3.3): omega' = I_a omega/J about z
        M = ma + mb
        Ia = 0.1 * M * da ** 2
        J = sum(0.1 * m * d ** 2 + m * np.linalg.norm(xi - X) ** 2
                for m, d, xi in ((ma, DP, x1[ia]), (mb, d2, x1[ib])))
        for i in (ia, ib):
            assert c1["omega"][i][2] == pytest.approx(Ia * w / J, rel=1e-9)

    N0, M0, P0, L0 = totals(c0, x0, m0)
    N1, M1, P1, L1 = totals(c1, x1, m1)
    assert N1 == N0
    assert M1 == pytest.approx(M0, rel=1e-12)
    scale = sum(m * np.linalg.norm(p["omega"]) * p["d"] for m, p in
                zip(m0, parts))
    assert np.linalg.norm(P1 - P0) < 1e-12 * scale
    assert np.linalg.norm(L1 - L0) < 1e-10 * np.linalg.norm(L0)

    rec = read_record(case_dir, t, "kinematicCloud")
    assert int(rec["nFragmentIds"]) == 5
    stats = read_stats(case_dir)
    assert [stats[f"nBreakup{m}"][-1] for m in
            ("Turbulence", "Drag", "Rotation")] == [0, 0, 5]
    log = (case_dir / "log.aggloPimpleFoam").read_text()
    assert re.search(r"Break-up: 5 events \(turbulence 0, drag 0, "
                     r"rotation 5, wallImpact 0\)", log), log[-2000:]


def test_hit_agglomerate_checked_in_the_same_step(case_dir, foam_env):
    """An overloaded agglomerate (N = 10 at 1.5 omega_crit) hit by a
    primary breaks in the step of the collision, checked in the state the
    collision left (doc/breakup.md 4.1): the primary comes along the spin
    axis, so the contact point does not move tangentially and the spin is
    unchanged. Before, an agglomerate that collided was skipped in that
    step (it broke a step late; one hit every step never broke)."""
    n, structure = 10, "CSM"
    da, rho = size_density(n, structure)
    X = np.array([1e-3, 0.5e-3, 0.5e-3])
    gap = 0.01 * DP
    parts = [dict(x=tuple(X), U=(0, 0, 0), d=da, rho=rho, nPrimary=n,
                  omega=(0, 0, 1.5 * omega_crit(n, structure))),
             dict(x=tuple(X + [0, 0, 0.5 * (da + DP) + gap]),
                  U=(0, 0, -2.0), d=DP, rho=RHO_P, nPrimary=1,
                  omega=(0, 0, 0))]
    boxcase.box_case(case_dir, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                     particles=parts, dt=1e-7, end_time=1e-7,
                     hard_sphere=kernel(structure=structure),
                     cloud=BREAKUP)
    boxcase.run_case(case_dir)
    stats = read_stats(case_dir)
    assert stats["nCol"][0] == 1              # the hit, in the first step
    assert stats["nAgg"][0] == 0              # a rebound at 2 m/s
    assert stats["nBreakupRotation"][0] == 1  # and the break-up with it
    c1, _, _ = state(case_dir, last_time(case_dir))
    assert sorted(c1["nPrimary"]) == [1, 1, n - 1]


def boundary_case(case, decompose=(1, 1, 1), steps=2, write=None):
    """Six N = 2 CSM agglomerates within 2 um of the plane x = 1 mm (the
    processor boundary of a (2 1 1) decomposition), spinning at 1.2
    omega_crit about z: each erodes in the first step, in a direction at
    random in the x-y plane, so that some fragments cross the plane."""
    n, (da, rho) = 2, size_density(2, "CSM")
    w = 1.2 * omega_crit(2, "CSM")
    parts = [dict(x=(1e-3 + (2e-6 if i % 2 else -2e-6),
                     0.12e-3 + 0.15e-3 * i, 0.5e-3), U=(0, 0, 0), d=da,
                  rho=rho, nPrimary=n, omega=(0, 0, w)) for i in range(6)]
    hs = kernel()
    boxcase.box_case(case, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                     particles=parts, dt=1e-7, end_time=steps * 1e-7,
                     write_interval=write, hard_sphere=hs, cloud=BREAKUP,
                     decompose=decompose, write_format="binary")
    return parts


def test_breakup_across_processors_equals_serial(case_dir, foam_env):
    """V4 on 2 ranks: parents at the processor boundary break as in the
    serial run, their fragments cross to the other rank and get the same
    global ids; the final states (reconstructed) equal the serial ones."""
    serial, par = case_dir / "serial", case_dir / "parallel"
    boundary_case(serial)
    boundary_case(par, decompose=(2, 1, 1))
    boxcase.run_case(serial)
    boxcase.run_case(par, parallel=2)

    t = last_time(serial)
    cs, xs = by_id(*state(serial, t)[:2])
    cp, xp = by_id(*state(par, t)[:2])
    assert np.sum(cs["origProcId"] == -2) == 6
    for k in ("origProcId", "origId", "nPrimary"):
        assert np.array_equal(cs[k], cp[k]), k
    for k in ("d", "rho", "U", "omega"):
        assert np.allclose(cs[k], cp[k], rtol=1e-12, atol=0), k
    assert np.max(np.abs(xs - xp)) < 1e-12 * 2e-3

    # Some fragment ended on the other rank than its parent (the parent
    # of fragment k is particle k: all six break, ids in parent order)
    rank = {}
    for r in (0, 1):
        c = read_cloud(par / f"processor{r}", t,
                       names=["origProcId", "origId"])
        for p, i in zip(c["origProcId"], c["origId"]):
            rank[(int(p), int(i))] = r
    crossed = [k for k in range(6) if rank[(-2, k)] != rank[(0, k)]]
    assert crossed, rank


def test_restart_continues_the_fragment_ids(case_dir, foam_env):
    """An N = 1000 agglomerate spun at 1.5 omega_crit erodes a primary in
    every step where the primary finds room (doc/breakup.md 3.2): three
    steps in one run equal one step, a restart and two steps (the
    fragment ids go on from the record's nFragmentIds: 0 to the number
    of break-ups less one), and a record that counts fewer ids than the
    particles hold is refused."""
    da, rho = size_density(1000, "CSM")
    part = [dict(x=(1e-3, 0.5e-3, 0.5e-3), U=(0, 0, 0), d=da, rho=rho,
                 nPrimary=1000, omega=(0, 0, 1.5 * omega_crit(1000, "CSM")))]
    hs = kernel()
    runs = {}
    for name in ("whole", "restart", "corrupt"):
        case = case_dir / name
        boxcase.box_case(case, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                         particles=part, dt=1e-7, end_time=3e-7,
                         write_interval=1, hard_sphere=hs, cloud=BREAKUP,
                         write_format="binary")
        runs[name] = case
    boxcase.run_case(runs["whole"])
    for name in ("restart", "corrupt"):
        ctl = runs[name] / "system/controlDict"
        edit(ctl, "endTime 3e-07",
             "endTime 1e-07")
        boxcase.run_case(runs[name])
        edit(ctl, "endTime 1e-07",
             "endTime 3e-07")
    assert read_record(runs["restart"], "1e-07",
                       "kinematicCloud")["nFragmentIds"] == 1

    from aggloTools.runner import foam_bin, run
    run([foam_bin("aggloPimpleFoam")], runs["restart"], "log.restart")
    t = last_time(runs["whole"])
    assert t == last_time(runs["restart"])
    a = read_cloud(runs["whole"], t)
    b = read_cloud(runs["restart"], t)
    n = int(read_stats(runs["whole"])["nBreakupRotation"][-1])
    assert n >= 2            # one break-up after the restart at least
    assert np.array_equal(np.sort(a["origId"][a["origProcId"] == -2]),
                          np.arange(n))
    for k in a:
        assert np.array_equal(a[k], b[k]), k
    assert read_record(runs["restart"], t, "kinematicCloud")[
        "nFragmentIds"] == n

    rec = (runs["corrupt"] / "1e-07/uniform/lagrangian/kinematicCloud"
           / "hardSphereCloudState")
    edit(rec, "nFragmentIds    1;",
         "nFragmentIds    0;")
    assert "nFragmentIds    0;" in rec.read_text()
    res = run([foam_bin("aggloPimpleFoam")], runs["corrupt"], "log.corrupt",
              check=False)
    log = (runs["corrupt"] / "log.corrupt").read_text()
    assert res.returncode != 0
    assert "holds the fragment id 0" in log, log[-1500:]
