"""The stressThreshold break-up model in the cloud (doc/breakup.md): the
critical spin of verification case V1 for both structure models and
N = 2, 3, 4, 10, 1000, the fragments' placement, spins and conservation,
their global ids and the restart record, and a break-up at a processor
boundary on 2 ranks against the serial run. The expectations are the
spec's hand formulas (doc/breakup.md 1.4, 2, 3.2, 3.3), computed here
independently of the C++ kernels."""

import math
import re

import numpy as np
import pytest

from aggloTools import boxcase, breakuplog
from aggloTools.cloud import cloud_positions, read_cloud, read_record
from aggloTools.stats import read_stats
from aggloTools.times import last_time

H, DELTA0, RHO_P, DP = 6.3e-20, 2e-10, 2200.0, 12e-6   # boxcase.KERNEL
GAP = 1e-3                                             # delta_gap/d_p
CSM_F = {2: 0.26683, 3: 0.31574, 4: 0.42099, 9: 0.47106, 10: 0.41216}
F_LARGE = 0.52

BREAKUP = ("breakupModel stressThreshold;\n    stressThresholdCoeffs {"
           " strength { rumpfPrefactor 1; coordination exactSmallRumpf; }"
           " stresses { mechanisms (rotation);"
           " rotationFactor 0.0625; }"
           f" fragmentation {{ mode erosion; direction extensional;"
           f" gap {GAP}; spin conserveL; }} }}")


def kernel(hamaker=None, structure="CSM"):
    """The box cases' kernel (boxcase.KERNEL) with EAM, smooth walls and,
    where given, another Hamaker constant or structure model."""
    k = boxcase.KERNEL.replace("structureModel CSM;",
                               f"structureModel {structure};")
    if hamaker is not None:
        k = k.replace("H 6.3e-20", f"H {hamaker!r}")
    return k + ("    agglomerationModel EAM;\n"
                f"    walls {{ \".*\" {boxcase.WALL} }}\n")


def packing(n):
    return CSM_F.get(n, F_LARGE)


def size_density(n, structure):
    """Effective diameter and density (doc/breakup.md 1)."""
    if n == 1:
        return DP, RHO_P
    if structure == "VSM":
        return DP * n ** (1 / 3), RHO_P
    f = packing(n)
    return DP * (n / f) ** (1 / 3), f * RHO_P


def tensile_strength(n, structure):
    """Rumpf with c_R = 1 and k = pi/eps, the weakest plane for N <= 4
    (doc/breakup.md 2); the bond force of two equal primaries
    A d_p/(24 delta0^2); VSM takes the CSM porosity for the strength."""
    F = H * DP / (24 * DELTA0 ** 2)
    if n <= 4:
        da = size_density(n, structure)[0]
        return (n - 1) * F / (math.pi * da ** 2 / 4)
    eps = 1 - packing(n)
    return (1 - eps) * (math.pi / eps) * F / (math.pi * DP ** 2)


def omega_crit(n, structure):
    """sigma_r = rho_a omega^2 d_a^2/16 = sigma_T (doc/breakup.md 1.4)."""
    da, rho = size_density(n, structure)
    return 4 / da * math.sqrt(tensile_strength(n, structure) / rho)


def state(case, t):
    c = read_cloud(case, t)
    x = cloud_positions(case, t)
    m = c["rho"] * math.pi * c["d"] ** 3 / 6
    return c, x, m


def totals(c, x, m):
    """Primaries, mass, momentum and angular momentum about the origin."""
    L = (0.1 * m * c["d"] ** 2)[:, None] * c["omega"] \
        + m[:, None] * np.cross(x, c["U"])
    return (int(c["nPrimary"].sum()), m.sum(),
            (m[:, None] * c["U"]).sum(0), L.sum(0))


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
                     hard_sphere=hs, breakup=BREAKUP)
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


# ------------------------------------------------- parallel and restart

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
                     write_interval=write, hard_sphere=hs, breakup=BREAKUP,
                     decompose=decompose, write_format="binary")
    return parts


def by_id(c, x):
    """Rows sorted by the global id (origProcId, origId)."""
    order = np.lexsort((c["origId"], c["origProcId"]))
    return {k: v[order] for k, v in c.items()}, x[order]


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
    """An N = 1000 agglomerate spun at 1.5 omega_crit erodes once per
    step: three steps in one run equal one step, a restart and two steps
    (the fragment ids go on from the record's nFragmentIds), and a record
    that counts fewer ids than the particles hold is refused."""
    da, rho = size_density(1000, "CSM")
    part = [dict(x=(1e-3, 0.5e-3, 0.5e-3), U=(0, 0, 0), d=da, rho=rho,
                 nPrimary=1000, omega=(0, 0, 1.5 * omega_crit(1000, "CSM")))]
    hs = kernel()
    runs = {}
    for name in ("whole", "restart", "corrupt"):
        case = case_dir / name
        boxcase.box_case(case, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                         particles=part, dt=1e-7, end_time=3e-7,
                         write_interval=1, hard_sphere=hs, breakup=BREAKUP,
                         write_format="binary")
        runs[name] = case
    boxcase.run_case(runs["whole"])
    for name in ("restart", "corrupt"):
        ctl = runs[name] / "system/controlDict"
        ctl.write_text(ctl.read_text().replace("endTime 3e-07",
                                               "endTime 1e-07"))
        boxcase.run_case(runs[name])
        ctl.write_text(ctl.read_text().replace("endTime 1e-07",
                                               "endTime 3e-07"))
    assert read_record(runs["restart"], "1e-07",
                       "kinematicCloud")["nFragmentIds"] == 1

    from aggloTools.runner import foam_bin, run
    run([foam_bin("aggloPimpleFoam")], runs["restart"], "log.restart")
    t = last_time(runs["whole"])
    assert t == last_time(runs["restart"])
    a = read_cloud(runs["whole"], t)
    b = read_cloud(runs["restart"], t)
    assert np.array_equal(np.sort(a["origId"][a["origProcId"] == -2]),
                          np.arange(3))
    for k in a:
        assert np.array_equal(a[k], b[k]), k
    assert read_record(runs["restart"], t, "kinematicCloud")[
        "nFragmentIds"] == 3

    rec = (runs["corrupt"] / "1e-07/uniform/lagrangian/kinematicCloud"
           / "hardSphereCloudState")
    rec.write_text(rec.read_text().replace("nFragmentIds    1;",
                                           "nFragmentIds    0;"))
    assert "nFragmentIds    0;" in rec.read_text()
    res = run([foam_bin("aggloPimpleFoam")], runs["corrupt"], "log.corrupt",
              check=False)
    log = (runs["corrupt"] / "log.corrupt").read_text()
    assert res.returncode != 0
    assert "holds the fragment id 0" in log, log[-1500:]


# ------------------------------------------------------------ V2 shear

NU_F, RHO_F = 1.5e-5, 1.2
GAMMA_CRIT = 1e4          # the bonds are weakened to give it
L_C, N_C = (0.01, 0.01, 0.005), (5, 10, 2)


@pytest.mark.parametrize("n", [2, 10])
@pytest.mark.parametrize("factor", [0.99, 1.01])
def test_critical_shear_rate_laminar(case_dir, foam_env, n, factor):
    """V2: an agglomerate in laminar simple shear (frozen Couette flow,
    no slip) breaks by the turbulent stress C_v mu (eps/nu)^(1/2) =
    C_v mu gamma (eps = nu gamma^2 in the viscous subrange, d_a < eta)
    above gamma_crit = sigma_T/(C_v mu) and not below; the fragments lie
    along the extensional direction, at 45 degrees in the x-y plane."""
    # sigma_T is proportional to the Hamaker constant
    h_weak = H * GAMMA_CRIT * NU_F * RHO_F / tensile_strength(n, "CSM")
    gamma = factor * GAMMA_CRIT
    da, rho = size_density(n, "CSM")
    assert da < math.sqrt(NU_F / gamma)            # viscous subrange
    y0 = 0.0052
    x0 = (0.005, y0, 0.0025)
    u0 = gamma * (y0 - L_C[1] / 2)
    part = [dict(x=x0, U=(u0, 0, 0), d=da, rho=rho, nPrimary=n,
                 omega=(0, 0, -gamma / 2))]
    hs = kernel(h_weak)
    brk = BREAKUP.replace("mechanisms (rotation); rotationFactor 0.0625;",
                          "mechanisms (turbulence); Cv 1; Ci 1;")
    assert "turbulence" in brk
    uw = gamma * L_C[1] / 2
    boxcase.box_case(case_dir, L=L_C, n=N_C,
                     kinds=("cyclic", "wall", "cyclic"), particles=part,
                     dt=1e-7, end_time=1e-7, nu=NU_F, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     hard_sphere=hs, breakup=brk)
    boxcase.write_internal_U(case_dir, L_C, N_C,
                             lambda x, y, z: (gamma * (y - L_C[1] / 2), 0,
                                              0))
    boxcase.run_case(case_dir)
    t = last_time(case_dir)
    c, x, _ = state(case_dir, t)
    if factor < 1:
        assert len(c["d"]) == 1 and c["nPrimary"][0] == n
        return
    assert sorted(c["nPrimary"]) == [1, n - 1]
    r = x[c["origProcId"] == -2][0] - x[c["origProcId"] == 0][0]
    assert abs(r[2]) < 1e-9 * np.linalg.norm(r)
    assert r[0] * r[1] > 0
    assert abs(abs(r[0]) - abs(r[1])) < 1e-6 * np.linalg.norm(r)


# ------------------------------------------- V6 guard, V7 time step

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
                     write_interval=5, hard_sphere=hs, breakup=BREAKUP)
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
                     hard_sphere=hs, breakup=BREAKUP, rotation=True)
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


# ---------------------------------------- V4: 10^4 parents, 2 ranks

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
    brk = BREAKUP.replace("mode erosion;", f"mode {mode};").replace(
        "spin conserveL; }", "spin conserveL; } eventLog true;")
    boxcase.box_case(case, L=(2.2e-3, 2.2e-3, 2.1e-3), n=(11, 11, 10),
                     particles=parts, dt=1e-7, end_time=1e-7,
                     hard_sphere=hs, breakup=brk, decompose=decompose,
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


# ------------------------------------------------ stochastic rate (1.6)

@pytest.mark.parametrize("scale", ["kolmogorov", "eddy"])
def test_stochastic_rate_breaks_the_expected_share(case_dir, foam_env,
                                                   scale):
    """doc/breakup.md 1.6: 2016 doublets in laminar shear at twice their
    critical shear rate (turbulent stress); with the stochastic rate the
    share that breaks in the first step is 1 - exp(-dt/t_e), t_e = (nu/
    eps)^(1/2) = 1/gamma (kolmogorov) or d_a^(2/3) eps^(-1/3) (eddy),
    within 4 binomial standard deviations; the others are deferred. The
    deterministic rate breaks them all (test_critical_shear_rate)."""
    n = 2
    gamma = 2 * GAMMA_CRIT
    h_weak = H * GAMMA_CRIT * NU_F * RHO_F / tensile_strength(n, "CSM")
    da, rho = size_density(n, "CSM")
    eps = NU_F * gamma ** 2
    t_e = math.sqrt(NU_F / eps) if scale == "kolmogorov" else \
        (da ** 2 / eps) ** (1 / 3)
    dt = 0.5 * math.sqrt(NU_F / eps)        # the same step for both
    share = 1 - math.exp(-dt / t_e)
    assert 0.35 < share < 0.55
    parts = []
    for i in range(16):
        for j in range(14):
            for k in range(9):
                y = 0.11e-3 + 60e-6 * j + 0.5 * (L_C[1] - 1e-3)
                parts.append(dict(
                    x=(0.3e-3 + 0.6e-3 * i, y, 0.25e-3 + 0.5e-3 * k),
                    U=(gamma * (y - L_C[1] / 2), 0, 0), d=da, rho=rho,
                    nPrimary=n, omega=(0, 0, -gamma / 2)))
    hs = kernel(h_weak)
    brk = BREAKUP.replace(
        "mechanisms (rotation); rotationFactor 0.0625;",
        "mechanisms (turbulence); Cv 1; Ci 1;").replace(
        "spin conserveL; }",
        f"spin conserveL; }} rate {{ model stochastic; timeScale {scale}; }}")
    assert "stochastic" in brk and "turbulence" in brk
    uw = gamma * L_C[1] / 2
    boxcase.box_case(case_dir, L=L_C, n=N_C,
                     kinds=("cyclic", "wall", "cyclic"), particles=parts,
                     dt=dt, end_time=dt, nu=NU_F, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     hard_sphere=hs, breakup=brk, write_format="binary")
    boxcase.write_internal_U(case_dir, L_C, N_C,
                             lambda x, y, z: (gamma * (y - L_C[1] / 2), 0,
                                              0))
    boxcase.run_case(case_dir)
    m = re.search(r"Break-up: (\d+) events \(turbulence (\d+), drag 0, "
                  r"rotation 0, wallImpact 0\), deferred by the rate (\d+)",
                  (case_dir / "log.aggloPimpleFoam").read_text())
    assert m, "no break-up line"
    broke, deferred = int(m.group(1)), int(m.group(3))
    N = len(parts)
    assert broke + deferred == N
    sd = math.sqrt(N * share * (1 - share))
    assert abs(broke - N * share) < 4 * sd, (broke, N * share, sd)


# ------------------------------------------------------------ V3 drag

def sn_drag_stress(u, da):
    """C_d |F_D|/(pi d_a^2) with C_d = 1 and the Schiller-Naumann drag
    3 pi mu d_a u (1 + 0.15 Re^0.687) (doc/breakup.md 1.3)."""
    mu = NU_F * RHO_F
    re = RHO_F * u * da / mu
    return 3 * mu * u * (1 + 0.15 * re ** 0.687) / da


@pytest.mark.parametrize("ratio", [0.99, 1.01])
def test_critical_drag_slip(case_dir, foam_env, ratio):
    """V3: an agglomerate released into still air with the slip U0 at
    which the code's drag law (Schiller-Naumann) gives the drag stress
    ratio x sigma_T breaks by drag at 1.01 and not at 0.99 (one step of
    1e-5 of its response time, so the slip is U0 to 1e-5). The bonds are
    weakened so that sigma_T is the drag stress at 1 m/s."""
    n = 10
    da, rho = size_density(n, "CSM")
    sigma_t = sn_drag_stress(1.0, da)
    h_weak = H * sigma_t / tensile_strength(n, "CSM")
    lo, hi = 0.1, 10.0                      # the slip of ratio x sigma_T
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if sn_drag_stress(mid, da) < ratio * sigma_t \
            else (lo, mid)
    u0 = 0.5 * (lo + hi)
    mu = NU_F * RHO_F
    tau = rho * da ** 2 / (18 * mu)
    part = [dict(x=(1e-3, 0.5e-3, 0.5e-3), U=(u0, 0, 0), d=da, rho=rho,
                 nPrimary=n)]
    hs = kernel(h_weak)
    brk = BREAKUP.replace("mechanisms (rotation); rotationFactor 0.0625;",
                          "mechanisms (drag); Cd 1;")
    assert "(drag)" in brk
    dt = 1e-5 * tau
    boxcase.box_case(case_dir, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                     particles=part, dt=dt, end_time=dt, nu=NU_F,
                     rho_f=RHO_F, forces="{ SchillerNaumannDrag; }",
                     hard_sphere=hs, breakup=brk)
    boxcase.run_case(case_dir)
    log = (case_dir / "log.aggloPimpleFoam").read_text()
    m = re.search(r"Break-up: (\d+) events \(turbulence 0, drag (\d+), "
                  r"rotation 0, wallImpact 0\)", log)
    assert m, log[-2000:]
    assert int(m.group(2)) == (1 if ratio > 1 else 0)
    c = read_cloud(case_dir, last_time(case_dir))
    assert sorted(c["nPrimary"]) == ([1, n - 1] if ratio > 1 else [n])


# ------------------------------------------------- wall impact (1.5)

EN_PAIR, P_MAX = 0.97, 1.612985e9                      # boxcase.KERNEL


def wall_impact_speed(n):
    """doc/breakup.md 1.5 [rec]: C_w M v^2/2 = n_b dE_vdW(v), with the
    EAM's bond energy of two primaries (AB16 Eq. 37) dE = c v; n_b = N - 1
    for N <= 4, else k/2 with Rumpf's k = pi/eps, eps = 1 - f(N)."""
    c = H / (12 * DELTA0 ** 2) * DP ** 4 * math.sqrt(
        RHO_P ** 2 * (1 - EN_PAIR ** 2)
        / (6 * P_MAX * 2 * DP * 2 * RHO_P * DP ** 3))
    nb = n - 1 if n <= 4 else 0.5 * math.pi / (1 - packing(n))
    M = n * RHO_P * math.pi / 6 * DP ** 3
    return 2 * nb * c / M


@pytest.mark.parametrize("n", [2, 10])
@pytest.mark.parametrize("factor", [0.99, 1.01])
def test_wall_impact_breaks_above_the_critical_speed(case_dir, foam_env, n,
                                                     factor):
    """The wallImpact option: an agglomerate thrown at a wall (no fluid
    force, no spin) at 0.99 or 1.01 of its critical normal speed breaks
    at 1.01 only, by wall impact, into a primary and the rest, keeping
    its primaries and mass; the statistics and the log count it."""
    da, rho = size_density(n, "CSM")
    v = factor * wall_impact_speed(n)
    dt = 1e-3
    L = (1e-3, 1e-3, 1e-3)
    part = [dict(x=(0.5e-3, da / 2 + 0.5 * v * dt, 0.5e-3), U=(0, -v, 0),
                 d=da, rho=rho, nPrimary=n)]
    brk = BREAKUP.replace("mechanisms (rotation); rotationFactor 0.0625;",
                          "mechanisms (wallImpact); Cw 1;")
    assert "wallImpact" in brk
    boxcase.box_case(case_dir, L=L, n=(4, 4, 4), particles=part, dt=dt,
                     end_time=dt, hard_sphere=kernel(), breakup=brk)
    boxcase.run_case(case_dir)
    t = last_time(case_dir)
    c, x, m = state(case_dir, t)
    stats = read_stats(case_dir)
    log = (case_dir / "log.aggloPimpleFoam").read_text()
    assert stats["nWall"][-1] == 1
    if factor < 1:
        assert list(c["nPrimary"]) == [n]
        assert stats["nBreakupWallImpact"][-1] == 0
        return
    assert sorted(c["nPrimary"]) == [1, n - 1]
    assert stats["nBreakupWallImpact"][-1] == 1
    assert re.search(r"Break-up: 1 events \(rotation 0, wallImpact 1\)",
                     log.replace("turbulence 0, drag 0, ", "")), log[-1500:]
    M0 = rho * math.pi / 6 * da ** 3
    assert m.sum() == pytest.approx(M0, rel=1e-12)
    assert np.all(x[:, 1] > 0)                      # both off the wall
