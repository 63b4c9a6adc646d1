"""Hard-sphere gases in a periodic box (cloudBoxCases) against kinetic
theory: the collision rate of an elastic gas (Enskog's factor of
Carnahan-Starling) and Haff's cooling law of an inelastic one, to 5 %."""

import math
from pathlib import Path

import numpy as np
import pytest

from aggloTools.boxcase import box_case, run_case
from aggloTools.stats import stats_rows as stats
from aggloTools.times import last_time
from cloudBoxCases import cloud_state, gas_kernel, gas_particles


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
