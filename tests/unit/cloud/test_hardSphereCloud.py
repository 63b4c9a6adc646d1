"""The hard-sphere agglomerating cloud (HardSphereCloud) in aggloPimpleFoam
on small scripted cases: frozen fluid at rest, no particle forces, so the
particles move in straight lines between events.

Independent expectations: the kernel utility hardSphereCollide for pair
collisions; the smooth-wall formulas of doc/models.md 7.1 written out here;
kinetic theory (collision rate of a hard-sphere gas, Haff's cooling law);
exact equality for restart, repetition and decomposition."""

import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from aggloTools import placement
from aggloTools.boxcase import KERNEL, box_case, run_case
from aggloTools.cloud import cloud_dir, read_cloud, read_lagrangian, \
    read_positions
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows as stats
from aggloTools.times import last_time

STATE = ("U", "omega", "d", "rho", "nPrimary", "origId", "origProcId",
         "lastPartnerId", "lastContactTime")


def cloud_state(case, time):
    """The particle state of a written cloud (numpy arrays)."""
    return read_cloud(case, time, names=STATE)

D = 12e-6
L = 1e-4
C = 0.5 * L


def pair_particles(v, theta_deg, gap=1e-6, centre=(C, C, C), spin=None):
    """Two 12 um primaries approaching along x with relative speed v; the
    impact parameter gives the angle theta between -u_r and the contact
    normal."""
    b = D * math.sin(math.radians(theta_deg))
    X = D * math.cos(math.radians(theta_deg)) + gap
    cx, cy, cz = centre
    p1 = dict(x=(cx - 0.5 * X, cy - 0.5 * b, cz), U=(0.5 * v, 0, 0), id=0)
    p2 = dict(x=(cx + 0.5 * X, cy + 0.5 * b, cz), U=(-0.5 * v, 0, 0), id=1)
    if spin:
        p1["omega"], p2["omega"] = spin
    return [p1, p2]


def contact_positions(p1, p2, R=D):
    """Positions at first contact for constant velocities
    (doc/models.md 6.3)."""
    x1, x2 = np.array(p1["x"]), np.array(p2["x"])
    u1, u2 = np.array(p1["U"]), np.array(p2["U"])
    xr, vr = x2 - x1, u2 - u1
    a, b, c = vr @ vr, xr @ vr, xr @ xr - R * R
    t = (-b - math.sqrt(b * b - a * c)) / a
    return x1 + u1 * t, x2 + u2 * t, t


def kernel(tmp, model, p1, p2):
    """hardSphereCollide on the contact state of the pair."""
    x1, x2, _ = contact_positions(p1, p2)
    fmt = lambda t: "(" + " ".join(repr(float(c)) for c in t) + ")"
    body = "".join(
        f"particle{k} {{ position {fmt(x)}; U {fmt(p['U'])}; "
        f"omega {fmt(p.get('omega', (0, 0, 0)))}; d {D}; rho 2200; "
        f"nPrimary 1; }}\n"
        for k, (x, p) in ((1, (x1, p1)), (2, (x2, p2))))
    f = Path(tmp) / "collideDict"
    f.write_text(KERNEL + f"agglomerationModel {model};\n" + body)
    res = subprocess.run([foam_bin("hardSphereCollide"), str(f)],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    return json.loads(res.stdout)


PAIRS = {
    # name: (model, v [m/s], theta [deg], spins)
    "headOn": ("EAM", 3e-3, 0, None),
    "oblique": ("EAM", 20e-3, 35, None),
    "spin": ("MAM", 10e-3, 20, ((0, 0, 800.0), (300.0, 0, -500.0))),
    "agglomerating": ("EAM", 3e-3, 60, None),
}


def run_pair(case_dir, name, kinds=("wall", "wall", "wall"), shift=0.0,
             parallel=0, decompose=(1, 1, 1)):
    model, v, theta, spin = PAIRS[name]
    parts = pair_particles(v, theta, spin=spin, centre=(C + shift, C, C))
    if shift:  # wrap into the periodic box
        for p in parts:
            p["x"] = ((p["x"][0]) % L, p["x"][1], p["x"][2])
    box_case(case_dir, L=(L, L, L), n=(4, 4, 4), kinds=kinds, dt=1e-4,
             end_time=1e-3, particles=parts, agglomeration=model,
             decompose=decompose)
    run_case(case_dir, parallel=parallel)
    return parts, cloud_state(case_dir, last_time(case_dir))


def check_against_kernel(case_dir, name, parts, state):
    model = PAIRS[name][0]
    ref = kernel(case_dir, model, *pair_particles(*PAIRS[name][1:3],
                                                  spin=PAIRS[name][3]))
    if ref["agglomerate"]:
        ag = ref["agglomerateState"]
        assert len(state["U"]) == 1 and list(state["nPrimary"]) == [2]
        assert state["d"][0] == pytest.approx(ag["d"], rel=1e-12)
        assert state["rho"][0] == pytest.approx(ag["rho"], rel=1e-12)
        np.testing.assert_allclose(state["U"][0], ag["U"], rtol=0,
                                   atol=1e-9 * PAIRS[name][1])
        np.testing.assert_allclose(state["omega"][0], ag["omega"], rtol=0,
                                   atol=1e-9 * max(1, abs(ag["omega"][2])))
        return
    assert len(state["U"]) == 2
    order = np.argsort(state["origId"])
    v = PAIRS[name][1]
    for k, idx in enumerate(order):
        post = ref["particles"][k]
        np.testing.assert_allclose(state["U"][idx], post["U"], rtol=0,
                                   atol=1e-9 * v)
        np.testing.assert_allclose(state["omega"][idx], post["omega"],
                                   rtol=0, atol=1e-9 * v / D)


@pytest.mark.parametrize("name", list(PAIRS))
def test_pair_matches_kernel(case_dir, foam_env, name):
    parts, state = run_pair(case_dir, name)
    check_against_kernel(case_dir, name, parts, state)
    s = stats(case_dir)[-1]
    assert s["nCol"] == 1 and s["nColFirst"] == 1
    assert s["nAgg"] == (1 if name == "agglomerating" else 0)
    assert s["nPrimaries"] == 2
    assert s["mass"] == pytest.approx(2 * 2200 * math.pi * D**3 / 6,
                                      rel=1e-12)


@pytest.mark.parametrize("name", ["oblique", "agglomerating"])
def test_pair_across_cyclic(case_dir, foam_env, name):
    """The same pair split by the periodic x plane."""
    parts, state = run_pair(case_dir, name,
                            kinds=("cyclic", "wall", "wall"), shift=C)
    assert any(p["x"][0] < 0.1 * L for p in parts)
    assert any(p["x"][0] > 0.9 * L for p in parts)
    check_against_kernel(case_dir, name, parts, state)
    assert stats(case_dir)[-1]["nCol"] == 1


@pytest.mark.parametrize("name", ["oblique", "agglomerating"])
def test_pair_across_processors(case_dir, foam_env, name):
    """The same pair split by the processor boundary of a 2-rank run."""
    parts, state = run_pair(case_dir, name, parallel=2,
                            decompose=(2, 1, 1))
    check_against_kernel(case_dir, name, parts, state)
    s = stats(case_dir)[-1]
    assert s["nCol"] == 1 and s["nPrimaries"] == 2


def smooth_wall(U, omega, d, n, en, et, muSt, muKin):
    """doc/models.md 7.1, written out independently of the C++ code."""
    U, omega, n = map(np.asarray, (U, omega, n))
    un = U @ n
    uc = U - un * n - 0.5 * d * np.cross(omega, n)
    s = np.linalg.norm(uc)
    Jn = -(1 + en) * un
    if s <= 3.5 * muSt * (1 + en) * abs(un) / (1 + et):
        J = Jn * n - 2 / 7 * (1 + et) * uc
    else:
        J = Jn * n - muKin * Jn * uc / s
    return U + J, omega - 5 / d * np.cross(n, J)


@pytest.mark.parametrize("Ut,spin", [(2e-3, 0.0), (30e-3, 2000.0)])
def test_wall_impact_at_one_radius(case_dir, foam_env, Ut, spin):
    """A particle hitting the yMin wall: impulse from the smooth-wall
    formulas, contact when the centre is one radius from the wall, then
    straight on from the contact point (wallPositionCorrection reflect)."""
    U0 = np.array([Ut, -10e-3, 0.0])
    om0 = np.array([0.0, 0.0, spin])
    x0 = np.array([C, 0.5 * D + 3.3e-6, C])
    dt, T = 1e-4, 1e-3
    box_case(case_dir, L=(L, L, L), particles=[dict(x=x0, U=U0,
             omega=om0)], dt=dt, end_time=T)
    run_case(case_dir)
    state = cloud_state(case_dir, last_time(case_dir))
    Uref, omref = smooth_wall(U0, om0, D, np.array([0, 1.0, 0]), 0.8, 0.4,
                              0.3, 0.15)
    np.testing.assert_allclose(state["U"][0], Uref, rtol=0, atol=1e-12)
    np.testing.assert_allclose(state["omega"][0], omref, rtol=0,
                               atol=1e-9 * max(1, np.abs(omref).max()))
    # contact at h = r: t_c = 3.3e-6/10e-3
    tc = 3.3e-6 / 10e-3
    xc = x0 + U0 * tc
    xend = xc + Uref * (T - tc)
    x = read_positions(cloud_dir(case_dir, last_time(case_dir))
                       / "positions")
    np.testing.assert_allclose(x[0], xend, rtol=0, atol=1e-12)
    s = stats(case_dir)[-1]
    assert s["nWall"] == 1 and s["nWallCentre"] == 0


# ------------------------------------------------------------------ gases

def gas_particles(N, Lbox, phi, sigma, seed):
    """N equal spheres of volume fraction phi, uniform and non-overlapping
    (gap 5 % of d) in the periodic box, with Gaussian velocities of
    standard deviation sigma and zero mean."""
    rng = np.random.default_rng(seed)
    d = Lbox * (6 * phi / (math.pi * N)) ** (1 / 3)
    xs = placement.place(N, 1.05 * d, (0, 0, 0), (Lbox,) * 3, (Lbox,) * 3,
                         rng)
    U = rng.normal(0, sigma, (N, 3))
    U -= U.mean(axis=0)
    parts = [dict(x=tuple(x), U=tuple(u), d=d, rho=2200, id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    return parts, d, U


def gas_kernel(en):
    return ("    material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.6e9;"
            " delta0 2e-10; rho0 2200; }\n"
            f"    particleCollision {{ en {en}; et 1; muSt 0; muKin 0; }}\n"
            "    agglomerationModel none;\n    walls {}\n")


def enskog(phi):
    return (1 - 0.5 * phi) / (1 - phi) ** 3


N_GAS, L_GAS, PHI, SIGMA = 1000, 1e-3, 0.01, 1e-3


def test_elastic_gas_collision_rate(case_dir, foam_env):
    """Elastic frictionless spheres in a periodic box: collisions per unit
    volume and time = 2 sqrt(pi) n^2 d^2 sigma g(phi) (Enskog factor of
    Carnahan-Starling)."""
    parts, d, U = gas_particles(N_GAS, L_GAS, PHI, SIGMA, seed=3)
    dt, T = 1e-3, 2.0
    box_case(case_dir, L=(L_GAS,) * 3, n=(5, 5, 5),
             kinds=("cyclic",) * 3, particles=parts, dt=dt, end_time=T,
             hard_sphere=gas_kernel(1))
    run_case(case_dir)
    rows = stats(case_dir)
    sigma = math.sqrt((U ** 2).sum() / (3 * N_GAS))
    n = N_GAS / L_GAS**3
    rate = 2 * math.sqrt(math.pi) * n**2 * d**2 * sigma * enskog(PHI)
    expected = rate * L_GAS**3 * T
    measured = rows[-1]["nCol"]
    assert measured == pytest.approx(expected, rel=0.05)
    # energy is conserved by elastic collisions
    Uend = np.array(cloud_state(case_dir, last_time(case_dir))["U"])
    assert (Uend**2).sum() == pytest.approx((U**2).sum(), rel=1e-9)


def test_inelastic_gas_haff_cooling(case_dir, foam_env):
    """Inelastic frictionless gas: T^(-1/2) grows linearly in time with
    slope 1/(tau_H sqrt(T0)), 1/tau_H = f0 (1 - e^2)/6 (Haff's law), where
    f0 = 4 sqrt(pi) n d^2 sigma0 g(phi) is the initial collision frequency
    per particle."""
    en = 0.8
    parts, d, U = gas_particles(N_GAS, L_GAS, PHI, SIGMA, seed=5)
    dt, T = 1e-3, 3.0
    box_case(case_dir, L=(L_GAS,) * 3, n=(5, 5, 5),
             kinds=("cyclic",) * 3, particles=parts, dt=dt, end_time=T,
             write_interval=300, hard_sphere=gas_kernel(en))
    run_case(case_dir)
    times, Ts = [0.0], [(U**2).sum() / (3 * N_GAS)]
    for t in sorted((p for p in Path(case_dir).iterdir()
                     if p.name not in ("0",) and p.name[0].isdigit()),
                    key=lambda p: float(p.name)):
        Ut = np.array(cloud_state(case_dir, t.name)["U"])
        times.append(float(t.name))
        Ts.append((Ut**2).sum() / (3 * N_GAS))
    times, Ts = np.array(times), np.array(Ts)
    slope = np.polyfit(times, Ts ** -0.5, 1)[0]
    tauH_sim = Ts[0] ** -0.5 / slope
    n = N_GAS / L_GAS**3
    f0 = 4 * math.sqrt(math.pi) * n * d**2 * math.sqrt(Ts[0]) * enskog(PHI)
    tauH = 6 / (f0 * (1 - en**2))
    assert Ts[-1] / Ts[0] < 0.35  # it really cooled (about one tau_H)
    assert tauH_sim == pytest.approx(tauH, rel=0.05)


# ------------------------------------------- restart, determinism, MPI

def agglomerating_gas(case_dir, end_time, write_interval, decompose=(1,1,1)):
    """300 quartz primaries at about 2 mm/s in a box periodic in x and z,
    walls in y: collisions, agglomerates (under EAM and MAM: seed 13) and
    wall impacts within 40 steps."""
    rng = np.random.default_rng(13)
    Lb, N = 2e-4, 300
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0), (Lb, Lb - 0.6 * D, Lb),
                         (Lb, None, Lb), rng)
    U = rng.normal(0, 1.5e-3, (N, 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    box_case(case_dir, L=(Lb, Lb, Lb), n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=end_time, write_interval=write_interval,
             agglomeration="EAM", decompose=decompose)


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


# ------------------------------------------------------------ cell order

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
                 agglomeration="EAM")
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


# ------------------------------------------------------------ bad input

BAD = {
    "unknownModel": ("agglomerationModel EAM;", "agglomerationModel EAMX;",
                     "EAMX"),
    "missingCoefficient": ("en 0.97; ", "", "en"),
    "restitution": ("en 0.97;", "en 1.2;", "en"),
    "unknownWallModel": ("wallModel smooth;", "wallModel rough;", "rough"),
    "ghostAgglomerating": ("agglomerationModel EAM;",
                           "agglomerationModel EAM; collisionResponse ghost;",
                           "ghost"),
    "unknownResponse": ("agglomerationModel EAM;",
                        "agglomerationModel EAM; collisionResponse gost;",
                        "gost"),
    "negativeRelease": ("agglomerationModel EAM;",
                        "agglomerationModel EAM; encounterRelease -1;",
                        "encounterRelease"),
    "negativeCellOrderInterval": ("solution\n{\n",
                                  "solution\n{\n    cellOrderInterval -1;\n",
                                  "cellOrderInterval"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_is_fatal(case_dir, foam_env, name):
    old, new, word = BAD[name]
    box_case(case_dir, L=(L, L, L), particles=pair_particles(3e-3, 0),
             agglomeration="EAM", dt=1e-4, end_time=2e-4)
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    assert old in text
    f.write_text(text.replace(old, new, 1))
    res = run_case(case_dir, check=False)
    assert res.returncode != 0
    assert "FOAM FATAL" in res.stdout
    assert word in res.stdout.split("FOAM FATAL", 1)[1]


# ------------------------------------------- ghost contacts and counting

def set_hs(case_dir, entries):
    """Add entries to the hardSphereCoeffs dictionary of a box case."""
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    old = "agglomerationModel none;"
    assert old in text
    f.write_text(text.replace(old, old + " " + entries, 1))


@pytest.mark.parametrize("release", ["0.1", "none"])
def test_ghost_pair_passes_through(case_dir, foam_env, release):
    """collisionResponse ghost: an oblique pair (30 deg) passes through;
    counted once as a first contact, then as overlapStart at every step
    start that finds it overlapping and approaching; velocities unchanged.
    The last partner is forgotten beyond 1.1 (r1 + r2) (release 0.1) or
    kept (none)."""
    v, dt, gap = 3e-3, 1e-4, 1e-6
    parts = pair_particles(v, 30, gap=gap)
    box_case(case_dir, L=(L, L, L), particles=parts, dt=dt, end_time=2e-2)
    set_hs(case_dir, f"collisionResponse ghost; encounterRelease {release};")
    run_case(case_dir)
    rows = stats(case_dir)
    last = rows[-1]
    # contact at gap/v, closest approach at X/v (X: initial x distance)
    X = D * math.cos(math.radians(30)) + gap
    n_overlap = math.floor(X / v / dt) - math.floor(gap / v / dt)
    assert (last["nCol"], last["nColFirst"], last["nColRepeat"],
            last["nAgg"]) == (1 + n_overlap, 1, 0, 0)
    assert last["nColOverlapStart"] == n_overlap
    st = cloud_state(case_dir, last_time(case_dir))
    for k, p in enumerate(parts):
        assert st["U"][k] == pytest.approx(p["U"], abs=1e-15)
    expect = [-1, -1] if release == "0.1" else [1, 0]
    assert [int(i) for i in st["lastPartnerId"]] == expect


@pytest.mark.parametrize("release", ["0.1", "none"])
def test_encounter_release_makes_a_new_first_contact(case_dir, foam_env,
                                                      release):
    """A head-on pair rebounds, both hit the walls and meet again. After
    separating beyond 1.1 (r1 + r2) the second meeting is a first contact
    (doc/cases.md B.4); without release it is a repeat of the last partner
    (doc/models.md 6.7, unlimited memory)."""
    parts = pair_particles(3e-3, 0)
    box_case(case_dir, L=(L, L, L), particles=parts, dt=1e-4, end_time=0.1)
    set_hs(case_dir, f"encounterRelease {release};")
    run_case(case_dir)
    rows = stats(case_dir)
    last = rows[-1]
    assert last["nCol"] >= 2 and last["nWall"] >= 2
    if release == "0.1":
        assert (last["nColFirst"], last["nColRepeat"]) == (last["nCol"], 0)
    else:
        assert (last["nColFirst"], last["nColRepeat"]) == \
            (1, last["nCol"] - 1)


# ------------------------------------------------------------ cloud list

def test_two_clouds_share_one_flow(case_dir, foam_env):
    """constant/cloudProperties clouds (EAMCloud MAMCloud): two one-way
    clouds with different agglomeration models in one run give, each, the
    statistics of the same cloud run alone (bit-identical rows)."""
    single = {}
    for model in ("EAM", "MAM"):
        d = case_dir / model
        agglomerating_gas(d, 4e-3, 40)
        f = d / "constant" / "kinematicCloudProperties"
        f.write_text(f.read_text().replace("agglomerationModel EAM;",
                                           f"agglomerationModel {model};"))
        run_case(d)
        single[model] = stats(d)
        assert single[model][-1]["nAgg"] > 0

    both = case_dir / "both"
    agglomerating_gas(both, 4e-3, 40)
    props = (both / "constant" / "kinematicCloudProperties").read_text()
    for model in ("EAM", "MAM"):
        name = f"{model}Cloud"
        (both / "constant" / f"{name}Properties").write_text(
            props.replace("agglomerationModel EAM;",
                          f"agglomerationModel {model};")
            .replace("kinematicCloudProperties", f"{name}Properties"))
        for sub in ("0/lagrangian", "0/uniform/lagrangian"):
            shutil.copytree(both / sub / "kinematicCloud", both / sub / name)
    (both / "constant" / "kinematicCloudProperties").unlink()
    shutil.rmtree(both / "0" / "lagrangian" / "kinematicCloud")
    (both / "constant" / "cloudProperties").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object cloudProperties; }\nclouds (EAMCloud MAMCloud);\n")
    res = run_case(both)
    assert "Constructing cloud EAMCloud" in res.stdout
    assert "Constructing cloud MAMCloud" in res.stdout
    for model in ("EAM", "MAM"):
        rows = stats(both, cloud=f"{model}Cloud")
        assert rows == single[model]
    assert single["EAM"][-1]["nCol"] != single["MAM"][-1]["nCol"] or \
        single["EAM"][-1]["nAgg"] != single["MAM"][-1]["nAgg"]


# ------------------------------------------ pair search vs brute force

def use_search(case_dir, entries):
    """Extra pair-search entries in the hardSphereCoeffs of a box case."""
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    old = "agglomerationModel "
    assert old in text
    f.write_text(text.replace(old, entries + " " + old, 1))


def use_brute_force(case_dir):
    use_search(case_dir, "pairSearch bruteForce;")


def oracle_cloud(case_dir, kind, decompose=(1, 1, 1)):
    """Random clouds for the search oracle: 'gas' (periodic in x, y, z,
    fast: about one cell per step), 'fast' (the gas with one particle in
    ten ten times faster: its box spans many bins of the others' size),
    'stream' (four gases side by side in a box 4 x 1 x 1, streaming at
    +3 m/s along x, one particle in ten at +2 m/s: per step they move
    more than a quarter of the short y and z periods, which only the
    per-axis reach check admits), 'wall' (periodic in x and z, packed
    against the lower wall, EAM),
    'poly' (diameters 12-60 um, agglomerates of up to 125 primaries,
    periodic in x and z, EAM)."""
    rng = np.random.default_rng(
        {"gas": 21, "fast": 25, "wall": 22, "poly": 23, "stream": 26}[kind])
    Lb = 2e-4
    if kind == "stream":
        parts = []
        for m in range(4):
            gas, d, U = gas_particles(400, Lb, 0.02, 0.05, seed=30 + m)
            for p in gas:
                x, u = p["x"], p["U"]
                p["x"] = (x[0] + m * Lb, x[1], x[2])
                p["id"] = len(parts)
                p["U"] = (u[0] + (2 if p["id"] % 10 == 0 else 3),
                          u[1], u[2])
                parts.append(p)
        box_case(case_dir, L=(4 * Lb, Lb, Lb), n=(20, 5, 5),
                 kinds=("cyclic",) * 3, particles=parts, dt=2e-5,
                 end_time=1.2e-3, write_interval=1,
                 hard_sphere=gas_kernel(0.9), decompose=decompose)
        return
    if kind in ("gas", "fast"):
        parts, d, U = gas_particles(400, Lb, 0.02, 0.05, seed=24)
        if kind == "fast":
            for p in parts[::10]:
                p["U"] = tuple(10 * u for u in p["U"])
        box_case(case_dir, L=(Lb,) * 3, n=(5, 5, 5), kinds=("cyclic",) * 3,
                 particles=parts, dt=2e-4 if kind == "gas" else 2e-5,
                 end_time=6e-3 if kind == "gas" else 2.4e-3, write_interval=1,
                 hard_sphere=gas_kernel(0.9), decompose=decompose)
        return
    xs, ds = [], []
    while len(xs) < 250:
        d = D if kind == "wall" else D * rng.integers(1, 6)
        lo = (0.6 * d, 0.6 * d, 0.6 * d)
        hi = (Lb - 0.6 * d, (0.25 if kind == "wall" else 1) * Lb - 0.6 * d,
              Lb - 0.6 * d)
        x = rng.uniform(lo, hi)
        if all(np.linalg.norm(x - y) > 0.55 * (d + e) * 1.02
               for y, e in zip(xs, ds)):
            xs.append(x)
            ds.append(d)
    U = rng.normal(0, 1.5e-3, (len(xs), 3))
    parts = [dict(x=tuple(x), U=tuple(u), d=d, id=i,
                  nPrimary=round((d / D) ** 3))
             for i, (x, u, d) in enumerate(zip(xs, U, ds))]
    box_case(case_dir, L=(Lb,) * 3, n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=4e-3, write_interval=1, agglomeration="EAM",
             decompose=decompose)


def search_checks(case_dir):
    """The candidate counts of the pairSearchCheck lines of a run's log."""
    text = (case_dir / "log.aggloPimpleFoam").read_text()
    return [int(m) for m in re.findall(
        r"pairSearchCheck: (\d+) candidate pairs, identical", text)]


# The fast and stream boxes take 1-3 minutes each on 2 cores: -m slow
SLOW = pytest.mark.slow


@pytest.mark.parametrize("kind,ranks", [
    ("gas", 0), pytest.param("fast", 0, marks=SLOW), ("wall", 0),
    ("poly", 0), pytest.param("stream", 0, marks=SLOW), ("gas", 2),
    pytest.param("fast", 2, marks=SLOW), ("wall", 2),
    pytest.param("stream", 2, marks=SLOW)])
def test_pair_search_matches_brute_force(case_dir, foam_env, kind, ranks):
    """The particleGrid pair search finds exactly the candidate pairs of
    the O(N^2) search over all particles and all periodic images (the
    same swept-box predicate): pairSearchCheck compares the two sets,
    pair by pair with the partner's image position, every step on every
    rank and stops the run if they differ. Then the runs with either
    search give identical counters every step (any missed or extra
    candidate changes the events) and the same particles after the first
    step with a collision, serially and on 2 ranks; and so does the
    InteractionLists search (serial gas and wall, 2-rank wall), the
    baseline of bench/. The particle states agree to round-off only (a
    referred partner's end position is the barycentric position of a
    transformed copy in InteractionLists), and round-off grows
    chaotically with every later collision."""
    searches = ["particleGrid", "bruteForce"]
    if (kind, ranks) in (("gas", 0), ("wall", 0), ("wall", 2)):
        searches.append("interactionLists")
    out = {}
    for search in searches:
        c = case_dir / search
        oracle_cloud(c, kind, decompose=(2, 1, 1))
        use_search(c, f"pairSearch {search};"
                   + (" pairSearchCheck true;"
                      if search == "particleGrid" else ""))
        run_case(c, parallel=ranks)
        if ranks:
            run([foam_bin("reconstructPar")], c, "log.reconstructPar.all")
        rows = stats(c)
        # the first step with a collision
        first = next(r["Time"] for r in rows if r["nCol"] > 0)
        t = min((p.name for p in c.iterdir()
                 if re.fullmatch(r"[0-9.e-]+", p.name)),
                key=lambda name: abs(float(name) - first))
        out[search] = (rows, cloud_state(c, t))
    checks = search_checks(case_dir / "particleGrid")
    # one check per step, and candidates to check
    assert len(checks) == len(out["particleGrid"][0])
    assert sum(checks) >= 100
    rows, state = out["bruteForce"]
    assert rows[-1]["nCol"] >= 20
    if kind not in ("gas", "fast", "stream"):
        assert rows[-1]["nAgg"] > 0 and rows[-1]["nWall"] > 0
    for search in searches[:1] + searches[2:]:
        assert out[search][0] == rows, search
        other = out[search][1]
        assert other.keys() == state.keys()
        for name in ("nPrimary", "origId", "origProcId", "lastPartnerId"):
            assert np.array_equal(other[name], state[name]), (search, name)
        for name in ("U", "omega", "d", "rho", "lastContactTime"):
            np.testing.assert_allclose(other[name], state[name], rtol=1e-9,
                                       atol=1e-9, err_msg=(search, name))
