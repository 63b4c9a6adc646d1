"""The stressThreshold model's other loads against the spec's critical
values (doc/breakup.md): the laminar shear of V2, the Stokes slip of V3
(Schiller-Naumann drag), the wall impact (1.5) at 0.99 and 1.01 of each,
and the stochastic rate (1.6) breaking the expected share of parents."""

import math
import re

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.cloud import read_cloud
from aggloTools.stats import read_stats
from aggloTools.times import last_time
from breakupCases import (DELTA0, DP, GAMMA_CRIT, H, L_C, N_C, NU_F, RHO_F,
                          RHO_P, breakup, kernel, packing, size_density,
                          state, tensile_strength)


@pytest.mark.parametrize("reading", ["total", "resolvedShear", "subgrid"])
@pytest.mark.parametrize("n", [2, 10])
@pytest.mark.parametrize("factor", [0.99, 1.01])
def test_critical_shear_rate_laminar(case_dir, foam_env, n, factor,
                                     reading):
    """V2: an agglomerate in laminar simple shear (frozen Couette flow,
    no slip) breaks by the turbulent stress C_v mu (eps/nu)^(1/2) =
    C_v mu gamma (eps = nu gamma^2 in the viscous subrange, d_a < eta)
    above gamma_crit = sigma_T/(C_v mu) and not below, by the readings
    total and resolvedShear of the dissipation rate (doc/breakup.md 1.1);
    by subgrid (no sub-grid part in laminar flow) not at all. The
    fragments lie along the extensional direction, at 45 degrees in the
    x-y plane."""
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
    brk = breakup({"mechanisms": ("turbulence",), "dissipation": reading,
                   "Cv": 1, "Ci": 1})
    uw = gamma * L_C[1] / 2
    boxcase.box_case(case_dir, L=L_C, n=N_C,
                     kinds=("cyclic", "wall", "cyclic"), particles=part,
                     dt=1e-7, end_time=1e-7, nu=NU_F, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     hard_sphere=hs, cloud=brk)
    boxcase.write_internal_U(case_dir, L_C, N_C,
                             lambda x, y, z: (gamma * (y - L_C[1] / 2), 0,
                                              0))
    boxcase.run_case(case_dir)
    t = last_time(case_dir)
    c, x, _ = state(case_dir, t)
    if factor < 1 or reading == "subgrid":
        assert len(c["d"]) == 1 and c["nPrimary"][0] == n
        return
    assert sorted(c["nPrimary"]) == [1, n - 1]
    r = x[c["origProcId"] == -2][0] - x[c["origProcId"] == 0][0]
    assert abs(r[2]) < 1e-9 * np.linalg.norm(r)
    assert r[0] * r[1] > 0
    assert abs(abs(r[0]) - abs(r[1])) < 1e-6 * np.linalg.norm(r)


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
    brk = breakup({"mechanisms": ("turbulence",), "dissipation": "total",
                   "Cv": 1, "Ci": 1},
                  rate={"model": "stochastic", "timeScale": scale})
    uw = gamma * L_C[1] / 2
    boxcase.box_case(case_dir, L=L_C, n=N_C,
                     kinds=("cyclic", "wall", "cyclic"), particles=parts,
                     dt=dt, end_time=dt, nu=NU_F, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     hard_sphere=hs, cloud=brk, write_format="binary")
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
    brk = breakup({"mechanisms": ("drag",), "Cd": 1}, drag=True)
    dt = 1e-5 * tau
    boxcase.box_case(case_dir, L=(2e-3, 1e-3, 1e-3), n=(8, 4, 4),
                     particles=part, dt=dt, end_time=dt, nu=NU_F,
                     rho_f=RHO_F, hard_sphere=hs, cloud=brk)
    boxcase.run_case(case_dir)
    log = (case_dir / "log.aggloPimpleFoam").read_text()
    m = re.search(r"Break-up: (\d+) events \(turbulence 0, drag (\d+), "
                  r"rotation 0, wallImpact 0\)", log)
    assert m, log[-2000:]
    assert int(m.group(2)) == (1 if ratio > 1 else 0)
    c = read_cloud(case_dir, last_time(case_dir))
    assert sorted(c["nPrimary"]) == ([1, n - 1] if ratio > 1 else [n])


EN_PAIR, P_MAX = 0.97, 1.612985e9           # boxcase.kernel(): en, pMax


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
    brk = breakup({"mechanisms": ("wallImpact",), "Cw": 1})
    boxcase.box_case(case_dir, L=L, n=(4, 4, 4), particles=part, dt=dt,
                     end_time=dt, hard_sphere=kernel(), cloud=brk)
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
