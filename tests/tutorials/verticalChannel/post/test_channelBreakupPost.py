"""The break-up report's arithmetic (channel.post.breakup), on records
and size histories made here: the kinetic energy of a split against what
conservation of mass says it must be, and the steadiness rule against
size histories that are steady or drift by a known amount."""

import math

import numpy as np
import pytest

from aggloTools import breakuplog
from channelTestRuns import script

breakup = script("channel.post.breakup")


def records(n, rng):
    """n splits of a spinning, moving parent into two fragments of the
    parent's density whose masses add up to the parent's, both moving
    with the parent's velocity and not spinning."""
    ev = np.zeros(n, dtype=breakuplog.DTYPE)
    dp = rng.uniform(20e-6, 60e-6, n)
    share = rng.uniform(0.1, 0.9, n)          # fragment a's mass share
    rho = rng.uniform(1000, 3000, n)
    U = rng.normal(0, 5, (n, 3))
    omega = rng.normal(0, 2e4, (n, 3))
    ev["d_p"], ev["rho_p"], ev["U_p"], ev["omega_p"] = dp, rho, U, omega
    ev["d_a"], ev["d_b"] = dp * np.cbrt(share), dp * np.cbrt(1 - share)
    ev["rho_a"], ev["rho_b"], ev["U_a"], ev["U_b"] = rho, rho, U, U
    return ev, dp, rho, omega


def test_a_split_that_stops_the_spin_loses_the_rotational_energy():
    """Mass kept, the velocity kept, the spin gone: the translational
    energies cancel and the change is minus the parent's rotational
    energy (I = m d^2/10 = (pi/60) rho d^5), -1 of it."""
    ev, dp, rho, omega = records(200, np.random.default_rng(3))
    dke, rot = breakup.energy(ev)
    hand = 0.5 * (math.pi / 60) * rho * dp**5 * (omega**2).sum(1)
    assert rot == pytest.approx(hand, rel=1e-12)
    assert dke / rot == pytest.approx(np.full(200, -1.0), abs=1e-9)


def test_fragments_spinning_as_the_parent_keep_part_of_it():
    """The same splits with both fragments spinning at the parent's rate:
    the fragments keep (d_a^5 + d_b^5)/d_p^5 of the rotational energy."""
    ev, dp, rho, omega = records(200, np.random.default_rng(4))
    ev["omega_a"], ev["omega_b"] = omega, omega
    dke, rot = breakup.energy(ev)
    kept = (ev["d_a"]**5 + ev["d_b"]**5) / dp**5
    assert dke / rot == pytest.approx(kept - 1, abs=1e-9)


T = np.linspace(0, 200, 201)      # the statistics of every T*


def test_steady_sizes():
    na, npp = np.full(201, 400.0), np.full(201, 920.0)
    s = breakup.steadiness(T, na, npp, 100, 200, spread=0.5)
    assert s["steps"] == 51 and (s["from"], s["to"]) == (150, 200)
    assert s["steady"] and s["N_a"]["change"] == pytest.approx(0, abs=1e-9)
    assert s["N_a"]["sigma"] == pytest.approx(20.0)
    assert s["meanSize"]["sigma"] == pytest.approx(0.5 / 20.0)


@pytest.mark.parametrize("growth, steady", [(30.0, True), (50.0, False)])
def test_a_drift_beyond_twice_the_poisson_error_is_not_steady(growth,
                                                               steady):
    """N_a grows linearly by `growth` over the window's second half
    (150-200), the mean size stays 2: sqrt(N_a) at its end is about
    20.7, so steady within 2 sigma up to about 41."""
    na = 400 + growth * (T - 150) / 50
    s = breakup.steadiness(T, na, 2 * na, 100, 200, spread=0.5)
    assert s["N_a"]["change"] == pytest.approx(growth, rel=1e-9)
    assert s["meanSize"]["change"] == pytest.approx(0, abs=1e-12)
    assert s["N_a"]["steady"] is steady and s["steady"] is steady


def test_mean_size_drift_and_too_few_steps():
    """The mean size grows by 0.05 over the second half: against
    2 x 0.5/sqrt(400) = 0.05 steady at the bound's edge, not with a
    spread of 0.4; fewer than three steps with agglomerates: n/r."""
    na = np.full(201, 400.0)
    npp = na * (2 + T / 1000)
    s = breakup.steadiness(T, na, npp, 100, 200, spread=0.4)
    assert s["meanSize"]["change"] == pytest.approx(0.05, rel=1e-9)
    assert not s["meanSize"]["steady"] and not s["steady"]
    assert breakup.steadiness(T, na, npp, 100, 200, spread=0.6)["steady"]
    na[:199] = 0
    assert breakup.steadiness(T, na, npp, 100, 200) is None


def test_sizes_all_alike_are_steady_within_one_primary():
    """One doublet throughout: no spread, the mean size's error one
    primary over N_a (1/1): round-off in the fit is steady, a doublet
    that becomes a triplet half-way is within twice that (the line's
    change about 1.5), one that becomes a quintuplet is not."""
    na = np.ones(201)
    s = breakup.steadiness(T, na, 2 * na * (1 + 1e-16 * T), 100, 200,
                           spread=0.0)
    assert s["meanSize"]["sigma"] == 1.0 and s["steady"]
    s = breakup.steadiness(T, na, np.where(T < 175, 2.0, 3.0), 100, 200,
                           spread=0.0)
    assert s["meanSize"]["change"] > 0.5 and s["meanSize"]["steady"]
    s = breakup.steadiness(T, na, np.where(T < 175, 2.0, 5.0), 100, 200,
                           spread=0.0)
    assert not s["meanSize"]["steady"]
