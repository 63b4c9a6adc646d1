"""Fluid-particle sub-models through the solver: each test
compares the cloud with an independent number.

- Schiller-Naumann terminal velocity of a heavy particle (1 %);
- spin relaxation to half the fluid vorticity with rho_p d^2/(60 mu) (1 %),
  and frozenFlow leaves the fluid field bit-identical;
- Saffman-Mei and rotation lift in one short step against the formulas of
  doc/models.md 8.2-8.3 (2 %);
- Pozorski-Apte SGS velocity: stationary variance 2k/3 and Lagrangian time
  CT Delta/sigma (5 %);
- two-way coupling: fluid plus particle momentum conserved in a closed
  periodic box.
"""

import math

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.cloud import cloud_dir, read_lagrangian, read_positions
from aggloTools.fields import read_internal
from aggloTools.foamfile import merged
from aggloTools.times import last_time

NU, RHO_F = 1.5e-5, 1.2
MU = NU * RHO_F


def sn_factor(re):
    return 1 + 0.15 * re ** 0.687 if re <= 1000 else 0.44 * re / 24


def times(case):
    return sorted((p.name for p in case.iterdir()
                   if p.is_dir() and p.name.replace(".", "").replace(
                       "e-", "").isdigit() and p.name != "0"), key=float)


def lag(case, t, name):
    return read_lagrangian(cloud_dir(case, t) / name)


def last_positions(case):
    return read_positions(cloud_dir(case, last_time(case)) / "positions")


# ------------------------------------------------------------ terminal

def test_terminal_velocity_schiller_naumann(case_dir, foam_env):
    """50 um, rho_p 2500 in air: Re_t ~ 0.6, so Schiller-Naumann differs
    from Stokes by ~10 %; the cloud must reach the SN value within 1 %."""
    d, rho_p, g = 50e-6, 2500.0, 9.81
    tau = rho_p * d**2 / (18 * MU)
    dt = tau / 20
    boxcase.box_case(case_dir, L=(0.02, 0.1, 0.02), n=(2, 4, 2),
                     particles=[dict(x=(0.01, 0.09, 0.01), U=(0, 0, 0), d=d,
                                    rho=rho_p)],
                     dt=dt, end_time=200 * dt, write_interval=200,
                     cloud=forces({**boxcase.DRAG, "gravity": ""}),
                     gravity=(0, -g, 0), nu=NU, rho_f=RHO_F)
    boxcase.run_case(case_dir)
    U = lag(case_dir, times(case_dir)[-1], "U")[0]

    # Independent: solve 18 mu v f(Re(v))/(rho_p d^2) = g (1 - rho_f/rho_p)
    geff = g * (1 - RHO_F / rho_p)
    v = geff * tau
    for _ in range(200):
        v = geff * tau / sn_factor(v * d / NU)
    stokes = geff * tau
    assert abs(stokes / v - 1) > 0.05          # the test can tell them apart
    assert abs(-U[1] / v - 1) < 0.01, (U, v)
    assert abs(U[0]) < 1e-12 and abs(U[2]) < 1e-12


# ------------------------------------------------------- Couette helpers

L_C, N_C = (0.01, 0.01, 0.005), (5, 10, 2)


def forces(particle_forces, rotation="none"):
    """The cloud's particle forces and rotation model."""
    return {"subModels": {"particleForces": particle_forces,
                          "rotationModel": rotation}}


def couette_case(case, gamma, particles, dt, steps, write=1, **kw):
    uw = gamma * L_C[1] / 2
    boxcase.box_case(case, L=L_C, n=N_C, kinds=("cyclic", "wall", "cyclic"),
                     particles=particles, dt=dt, end_time=steps * dt,
                     write_interval=write, nu=NU, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0), "yMax": (uw, 0, 0)},
                     **kw)
    boxcase.write_internal_U(case, L_C, N_C,
                             lambda x, y, z: (gamma * (y - L_C[1] / 2), 0, 0))


# ---------------------------------------------------------------- spin

def test_spin_relaxes_to_half_vorticity(case_dir, foam_env):
    """Frozen Couette flow (vorticity -gamma e_z): omega_z -> -gamma/2 and
    omega_x -> 0, both with tau_w = rho_p d^2/(60 mu); the fluid field is
    unchanged by the run (frozenFlow)."""
    d, rho_p, gamma = 50e-6, 2500.0, 200.0
    tau = rho_p * d**2 / (60 * MU)
    dt = tau / 10
    couette_case(case_dir, gamma,
                 [dict(x=(0.005, 0.005, 0.0025), U=(0, 0, 0), d=d, rho=rho_p,
                       omega=(300.0, 0, 0))],
                 dt, 40, cloud=forces(boxcase.DRAG, "fluidTorque"))
    boxcase.run_case(case_dir)
    ts = times(case_dir)
    t = np.array([float(x) for x in ts])
    om = np.array([lag(case_dir, x, "omega")[0] for x in ts])

    wz = om[:, 2] + gamma / 2
    fit_z = -1 / np.polyfit(t, np.log(np.abs(wz)), 1)[0]
    fit_x = -1 / np.polyfit(t, np.log(om[:, 0]), 1)[0]
    assert abs(fit_z / tau - 1) < 0.01, (fit_z, tau)
    assert abs(fit_x / tau - 1) < 0.01, (fit_x, tau)
    # the whole history against w/2 + (omega0 - w/2) exp(-t/tau)
    exact = -gamma / 2 * (1 - np.exp(-t / tau))
    assert np.max(np.abs(om[:, 2] - exact)) < 0.01 * gamma / 2

    # frozenFlow: U and p at the end equal the initial fields bit for bit
    for f in ("U", "p"):
        va = read_internal(case_dir / "0" / f)
        vb = read_internal(case_dir / ts[-1] / f)
        assert va.shape == vb.shape and np.array_equal(va, vb)
    assert read_internal(case_dir / "0" / "U").shape == (100, 3)


# ---------------------------------------------------------------- lift

def lift_case(case, drag_lift, omega_p, gamma, us):
    """One particle at y' = 2 mm in Couette flow (or still fluid), slip us
    along x; one step of dt = tau_p/1000."""
    d, rho_p = 100e-6, 2500.0
    tau = rho_p * d**2 / (18 * MU)
    dt = tau / 1000
    y = 0.007
    uf = gamma * (y - L_C[1] / 2)
    couette_case(case, gamma,
                 [dict(x=(0.005, y, 0.0025), U=(uf - us, 0, 0), d=d,
                       rho=rho_p, omega=omega_p)],
                 dt, 1, cloud=forces(drag_lift))
    boxcase.run_case(case)
    U1 = lag(case, times(case)[-1], "U")[0]
    # Euler-implicit step: dv_y = (F_y/m) dt/(1 + b dt), b = f_D/tau_p
    m = rho_p * math.pi * d**3 / 6
    b = sn_factor(abs(us) * d / NU) / tau
    Fy = m * U1[1] * (1 + b * dt) / dt
    return Fy, d


def test_saffman_mei_lift(case_dir, foam_env):
    gamma, us = 1000.0, 0.5
    Fy, d = lift_case(case_dir, {**boxcase.DRAG,
                                 "SaffmanMeiLiftForce": {"U": "U"}},
                      (0, 0, 0), gamma, us)
    # doc/models.md 8.2: F = 1.615 d^2 (rho mu)^1/2 |w|^-1/2 f_Mei (u_s x w)
    rep = us * d / NU
    res = gamma * d**2 / NU
    beta = 0.5 * res / rep
    f = (1 - 0.3314 * beta**0.5) * math.exp(-rep / 10) + 0.3314 * beta**0.5
    # u_s = (us, 0, 0), w = (0, 0, -gamma): u_s x w = (0, us gamma, 0)
    F = 1.615 * d**2 * math.sqrt(RHO_F * MU) / math.sqrt(gamma) * f \
        * us * gamma
    assert 0.6 < f < 0.9                       # Mei's correction matters
    assert Fy > 0 and abs(Fy / F - 1) < 0.02, (Fy, F)


def test_rotation_lift(case_dir, foam_env):
    """Still fluid, particle moving at 0.5 m/s and spinning at 500 1/s:
    Omega = -omega_p, Re_p = 3.3, Re_R = 0.33 (Oesterle & Bui Dinh)."""
    us, wp = 0.5, 500.0
    Fy, d = lift_case(case_dir, {**boxcase.DRAG, "rotationLift":
                                 {"model": "OesterleBuiDinh"}},
                      (0, 0, wp), 0.0, us)
    # u_p = (-us, 0, 0): u_s = (us, 0, 0), Omega = (0, 0, -wp),
    # Omega x u_s = (0, -us wp, 0) (Magnus: omega_p x (u_p - u_f))
    rep = us * d / NU
    rer = wp * d**2 / NU
    crl_us = 0.45 * us + (wp * d - 0.45 * us) * math.exp(
        -0.05684 * rer**0.4 * rep**0.3)
    F = -math.pi / 8 * RHO_F * d**2 * crl_us * us * wp / wp
    rk = -math.pi / 8 * RHO_F * d**3 * us * wp
    assert abs(F / rk - 1) > 0.03               # differs from the RK limit
    assert Fy < 0 and abs(Fy / F - 1) < 0.02, (Fy, F)


# ----------------------------------------------------------------- SGS

SMAG = {"simulationType": "LES",
        "LES": {"LESModel": "Smagorinsky", "turbulence": "on",
                "printCoeffs": "on", "delta": "cubeRootVol",
                "cubeRootVolCoeffs": {"deltaCoeff": 1},
                "SmagorinskyCoeffs": {"Ck": 0.094, "Ce": 1.048}}}


def tracers(seed, beta_c, reflection):
    """Drag, Pozorski-Apte's dispersion (Smagorinsky's nu_t, the given
    seed, beta_C and wall reflection) and, instead of collisions (tracers
    move further per step than the pair search sees), the stock rebound
    at walls."""
    return {"subModels": {
        "particleForces": boxcase.DRAG,
        "dispersionModel": "PozorskiApte",
        "PozorskiApteCoeffs": {"kSgsSource": "nut", "Ck": 0.094, "CT": 1,
                               "betaC": beta_c, "seed": seed,
                               "wallReflection": reflection},
        "patchInteractionModel": "standardWallInteraction",
        "standardWallInteractionCoeffs": {"type": "rebound"}}}


def add_nut(case):
    boxcase.foamfile(case / "0/nut", "volScalarField", "0", "nut",
                     "dimensions [0 2 -1 0 0 0 0];\ninternalField uniform 0;\n"
                     "boundaryField\n{\n    \"(x|z).*\" { type cyclic; }\n"
                     "    \"y.*\" { type zeroGradient; }\n}\n")


def test_sgs_variance_and_time_scale(case_dir, foam_env):
    """Tracers in frozen uniform shear with Smagorinsky nu_t (uniform):
    u_sgs per component has variance 2 k_sgs/3, k_sgs = (nu_t/(Ck Delta))^2,
    and autocorrelation exp(-t/tau_L), tau_L = CT Delta/sigma (betaC 0;
    wallReflection off, since a reflection at a wall flips w)."""
    gamma = 100.0
    delta = (L_C[0] / N_C[0] * L_C[1] / N_C[1] * L_C[2] / N_C[2]) ** (1 / 3)
    # k of Smagorinsky (incompressible): 2 Ck Delta^2 (D:D)/Ce, D:D = g^2/2
    k_smag = 2 * 0.094 * delta**2 * gamma**2 / 2 / 1.048
    nut = 0.094 * delta * math.sqrt(k_smag)
    sigma = math.sqrt(2 / 3 * (nut / (0.094 * delta)) ** 2)
    tau_l = delta / sigma
    dt = tau_l / 10
    rng = np.random.default_rng(5)
    N = 3000
    X = rng.uniform((0, 0.001, 0), (L_C[0], 0.009, L_C[2]), (N, 3))
    parts = [dict(x=tuple(x), U=(gamma * (x[1] - L_C[1] / 2), 0, 0),
                  d=1e-6, rho=1000.0, id=i) for i, x in enumerate(X)]
    # tracers: no collisions (their displacement per step exceeds half the
    # period, beyond what the pair search can see); stock rebound at walls
    couette_case(case_dir, gamma, parts, dt, 60, write=1,
                 hard_sphere="none", turbulence=SMAG,
                 cloud=tracers(3, 0, False))
    add_nut(case_dir)
    boxcase.run_case(case_dir)
    ts = times(case_dir)
    # nu_t as computed by the solver (uniform) against the hand value
    nut_run = read_internal(case_dir / ts[-1] / "nut")[0]
    assert abs(nut_run / nut - 1) < 1e-6

    ids = [np.array(lag(case_dir, t, "origId"), int) for t in ts]
    W = []
    for t, i in zip(ts, ids):
        u = np.array(lag(case_dir, t, "UTurb"))
        w = np.empty_like(u)
        w[i] = u
        W.append(w)
    W = np.array(W) / sigma                    # (time, particle, component)
    var = np.mean(W[10:] ** 2)
    assert abs(var - 1) < 0.05, var

    # autocorrelation for lags 1..15 steps, all time origins
    lags = np.arange(1, 16)
    rho = np.array([np.mean(W[:-l] * W[l:]) / np.mean(W[:-l] ** 2)
                    for l in lags])
    tau_fit = -1 / np.polyfit(lags * dt, np.log(rho), 1)[0]
    assert abs(tau_fit / tau_l - 1) < 0.05, (tau_fit, tau_l)


# ------------------------------------------------------ two-way coupling

def test_two_way_coupling_conserves_momentum(case_dir, foam_env):
    """Closed periodic box, fluid at rest, 200 moving particles (drag,
    rotation, collisions), explicit PSI-cell source: the total momentum
    rho_f sum V U + sum m u_p keeps its initial value to round-off."""
    L, n = (4e-3, 4e-3, 4e-3), (4, 4, 4)
    d, rho_p = 60e-6, 2500.0
    rng = np.random.default_rng(2)
    N = 200
    X = rng.uniform(0.2e-3, 3.8e-3, (N, 3))
    # at most about 0.4 mm per step: the collision search distance stays
    # below half the 4 mm period
    Up = rng.normal(0, 0.05, (N, 3)) + (0.1, 0, 0)
    parts = [dict(x=tuple(x), U=tuple(u), d=d, rho=rho_p, id=i)
             for i, (x, u) in enumerate(zip(X, Up))]
    tau = rho_p * d**2 / (18 * MU)
    dt = tau / 20
    boxcase.box_case(case_dir, L=L, n=n, kinds=("cyclic",) * 3,
                     particles=parts, dt=dt, end_time=40 * dt,
                     write_interval=40,
                     frozen=False, tol=1e-13, nu=NU, rho_f=RHO_F,
                     hard_sphere=boxcase.kernel(walls={}),
                     cloud=merged(
                         forces(boxcase.DRAG, "fluidTorque"),
                         {"solution": {"coupled": True, "sourceTerms": {
                             "schemes": {"U": "explicit 1"}}}}))
    boxcase.run_case(case_dir)
    t = times(case_dir)[-1]
    m = rho_p * math.pi * d**3 / 6
    P0 = m * Up.sum(axis=0)
    up = np.array(lag(case_dir, t, "U"))
    uf = read_internal(case_dir / t / "U")
    assert len(uf) == 64
    V = np.prod(L) / 64
    Pf = RHO_F * V * uf.sum(axis=0)
    Pp = m * up.sum(axis=0)
    assert np.linalg.norm(Pf) > 0.1 * np.linalg.norm(P0)   # coupling acts
    err = np.linalg.norm(Pf + Pp - P0) / (m * np.abs(Up).sum())
    assert err < 1e-10, (err, Pf, Pp, P0)


@pytest.mark.parametrize("flow", ["couette", "poiseuille"])
def test_sgs_tracers_well_mixed(case_dir, foam_env, flow):
    """Well-mixed diagnostic (doc/models.md 9): tracers, initially uniform in a
    frozen laminar channel flow with Smagorinsky nu_t, after 10 Lagrangian
    times at the wall.

    couette: uniform shear, uniform sigma: the concentration stays uniform
    within 10 % per bin (measured: at most 6.7 %, a slight excess on the
    centre line: a 5 % tolerance would not be met). With
    wallReflection off the wall bins gain 25 %.
    poiseuille: sigma ~ |y'| vanishes on the centre line; the model has no
    drift term ~ grad(sigma^2), so tracers collect where sigma is small.
    This known defect of the model is kept (as in the paper) and measured:
    the centre bins gain more than 20 %."""
    L, n = (0.01, 0.02, 0.005), (4, 20, 2)
    h, uc = L[1] / 2, 1.0
    if flow == "couette":
        uc = 2.0        # the same wall shear as the Poiseuille flow
        prof = lambda y: uc * (y - h) / h
        wall_u = {"yMin": (-uc, 0, 0), "yMax": (uc, 0, 0)}
    else:
        prof = lambda y: uc * (1 - ((y - h) / h) ** 2)
        wall_u = None
    rng = np.random.default_rng(11)
    N = 40000
    X = rng.uniform((0, 0, 0), L, (N, 3))
    parts = [dict(x=tuple(x), U=(prof(x[1]), 0, 0), d=1e-6, rho=1000.0, id=i)
             for i, x in enumerate(X)]
    dt, steps = 2e-3, 100
    boxcase.box_case(case_dir, L=L, n=n, kinds=("cyclic", "wall", "cyclic"),
                     particles=parts, dt=dt, end_time=steps * dt,
                     write_interval=steps, nu=NU, rho_f=RHO_F,
                     wall_velocity=wall_u,
                     turbulence=SMAG, hard_sphere="none",
                     cloud=tracers(4, 1, True))
    boxcase.write_internal_U(case_dir, L, n,
                             lambda x, y, z: (prof(y), 0, 0))
    add_nut(case_dir)
    boxcase.run_case(case_dir)
    t = times(case_dir)[-1]
    # sigma near the wall, from the written nu_t: >= 8 tau_L have passed
    nut = read_internal(case_dir / t / "nut")
    delta = (np.prod(L) / np.prod(n)) ** (1 / 3)
    sigma_w = math.sqrt(2 / 3) * nut.max() / (0.094 * delta)
    assert steps * dt > 8 * delta / sigma_w

    x = last_positions(case_dir)
    assert len(x) == N
    counts, _ = np.histogram(x[:, 1], bins=10, range=(0, L[1]))
    c = counts / (N / 10)
    if flow == "couette":
        assert np.abs(c - 1).max() < 0.10, counts
    else:
        assert c[4] > 1.2 and c[5] > 1.2, counts
