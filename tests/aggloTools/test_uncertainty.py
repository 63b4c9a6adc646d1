"""aggloTools.uncertainty, the project's estimators, against independent
expectations: a windowed rate of a count with known increments, binomial
errors at hand values, the Wilson interval against scipy's own, the
propagated error of a ratio against a Monte Carlo sample, and the
power-law fit on exact data."""
import math

import numpy as np
import pytest
from scipy import stats

from aggloTools import uncertainty as unc


def test_window_rate_of_known_increments():
    """A count rising by 3 per unit in the first half of the window and
    by 1 in the second: the rate is 2, the ten sub-window rates are five
    3s and five 1s (batch sigma sd/sqrt(10)), Poisson sqrt(N)/T."""
    t = np.linspace(0, 20, 2001)
    n = np.where(t < 10, 3 * t, 30 + (t - 10))
    f, sb, sp, dn = unc.window_rate(t, n, 0, 20)
    assert f == pytest.approx(2.0) and dn == pytest.approx(40.0)
    rates = [3.0] * 5 + [1.0] * 5
    assert sb == pytest.approx(np.std(rates, ddof=1) / math.sqrt(10))
    assert sp == pytest.approx(math.sqrt(40) / 20)
    # no events: not exact, one event's Poisson error
    f, sb, sp, dn = unc.window_rate(t, np.zeros_like(t), 5, 15)
    assert (f, sb, dn) == (0.0, 0.0, 0.0) and sp == pytest.approx(0.1)


def test_binomial_sigma_hand_values():
    assert unc.binomial_sigma(50, 100) == pytest.approx(0.05)
    assert unc.binomial_sigma(0, 100) == pytest.approx(0.01)
    assert unc.binomial_sigma(100, 100) == pytest.approx(0.01)


@pytest.mark.parametrize("k, n", [(0, 10), (3, 10), (10, 10), (17, 250),
                                  (1, 1)])
def test_wilson_against_scipy(k, n):
    z = stats.norm.ppf(0.975)
    ci = stats.binomtest(k, n).proportion_ci(0.95, method="wilson")
    lo, hi = unc.wilson(k, n, z)
    assert lo == pytest.approx(ci.low, abs=1e-12)
    assert hi == pytest.approx(ci.high, abs=1e-12)
    assert unc.wilson(k, 0) == (None, None)


def test_ratio_error_against_monte_carlo():
    rng = np.random.default_rng(5)
    a, sa, b, sb = 6.0, 0.12, 3.0, 0.09
    r, s = unc.ratio(a, sa, b, sb)
    assert r == 2.0 and s == pytest.approx(2 * math.hypot(0.02, 0.03))
    x = rng.normal(a, sa, 400000) / rng.normal(b, sb, 400000)
    assert s == pytest.approx(np.std(x), rel=0.02)
    assert unc.ratio(0.0, 1.0, 3.0, 0.1) == (None, None)
    assert unc.relative_error((2.0, 0.2), (4.0, 0.4), (1.0, 0.1)) == \
        pytest.approx(math.sqrt(3) * 0.1)


def test_power_law_on_exact_data():
    n = np.array([32.0, 48.0, 64.0])
    v = 5.0 * n**1.5
    f = unc.power_law(n, v, 0.1 * v, at=128)
    assert f["b"] == pytest.approx(1.5) and f["dof"] == 1
    assert f["value"] == pytest.approx(5.0 * 128**1.5)
    assert f["chi2"] == pytest.approx(0.0, abs=1e-20) and f["p"] == \
        pytest.approx(1.0)
    assert unc.power_law([32, 64], [1.0, 0.0], [0.1, 0.1], 128) is None
    with pytest.raises(ValueError):
        unc.chi2_sf(1.0, 0)
