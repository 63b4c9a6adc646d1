"""The hard-sphere agglomerating cloud (HardSphereCloud) in aggloPimpleFoam
on small scripted cases (cloudBoxCases): frozen fluid at rest, no particle
forces, so the particles move in straight lines between events. A pair
against the kernel utility hardSphereCollide, also across a cyclic plane
and a processor boundary; a wall impact against the smooth-wall formulas
of doc/models.md 7.1 written out here. The gases (kinetic theory), the
reproducibility (restart, repetition, decomposition, cell order), the
settings and the pair search are in the test_hardSphereGas,
test_cloudReproducibility, test_cloudSettings and test_cloudPairSearch
modules beside this one."""

import json
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.boxcase import box_case, run_case
from aggloTools.cloud import cloud_dir, read_positions
from aggloTools.foamfile import dict_text
from aggloTools.runner import foam_bin
from aggloTools.stats import stats_rows as stats
from aggloTools.times import last_time
from cloudBoxCases import C, D, L, cloud_state, pair_particles


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
    f.write_text(dict_text({**boxcase.kernel(model), "walls": None}) + body)
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
             end_time=1e-3, particles=parts, hard_sphere=boxcase.kernel(model),
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
