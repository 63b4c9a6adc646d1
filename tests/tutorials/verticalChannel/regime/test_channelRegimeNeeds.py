"""What the paper's regime needs by the regime study's grid trend
(channel.regime.needs): where each fitted power law lies within the
verdict's factor, the 68 % range of its entry against a brute-force scan
of the fit's band, the grid range of all four and the cost law through
the grid variants' hours."""

import math

import numpy as np
import pytest

from channelTestRuns import script


@pytest.fixture(scope="module")
def nd():
    return script("channel.regime.needs")


def fitted(nd, n, v, rel, paper):
    """The trend module's fit of v(n) with relative sigma rel, and the
    paper's value."""
    trend = script("channel.regime.trend")
    f = trend.power_law(n, v, rel * np.asarray(v, float))
    f["paper"] = paper
    return f


def test_window_of_an_exact_law(nd):
    """v = 2 n^2 against p = 80,000 and a factor 2: within from
    2 n^2 = 40,000 (n = 141.4) to 2 n^2 = 160,000 (n = 282.8); a falling
    law v = 1e4 n^-1.5 against p = 10 enters at 20 (n = 500^(2/3)) and
    leaves at 5."""
    f = fitted(nd, [32, 48, 64], [2 * n**2 for n in (32, 48, 64)], 0.1,
               80000.0)
    w = nd.window(f, 2.0)
    assert w["enter"] == pytest.approx(math.sqrt(20000), rel=1e-9)
    assert w["leave"] == pytest.approx(math.sqrt(80000), rel=1e-9)
    assert w["edge"] == pytest.approx(40000.0)
    g = fitted(nd, [32, 64], [1e4 * n**-1.5 for n in (32, 64)], 0.1, 10.0)
    w = nd.window(g, 2.0)
    assert w["edge"] == pytest.approx(20.0)
    assert w["enter"] == pytest.approx(500**(2 / 3), rel=1e-9)
    assert w["leave"] == pytest.approx(2000**(2 / 3), rel=1e-9)


def test_entry_range_against_a_scan_of_the_band(nd):
    """The roots bound exactly the n at which the fit's 68 % band (a + b x
    +- se(x), se^2 = g C g) holds the edge: a fine scan in ln n agrees to
    its step."""
    n = [32.0, 48.0, 64.0]
    f = fitted(nd, n, [900.0, 2100.0, 3600.0], 0.15, 81400.0)
    lo, hi = nd.band_holds(f, 81400.0 / 2)
    x = np.linspace(math.log(32), math.log(1e5), 400001)
    c = np.asarray(f["cov"])
    se = np.sqrt(c[0, 0] + 2 * c[0, 1] * x + c[1, 1] * x * x)
    held = np.abs(f["a"] + f["b"] * x - math.log(40700.0)) <= se
    step = x[1] - x[0]
    assert math.log(lo) == pytest.approx(x[held][0], abs=step)
    assert math.log(hi) == pytest.approx(x[held][-1], abs=step)
    assert lo < nd.window(f, 2.0)["enter"] < hi


def test_no_entry_range_for_a_slope_within_its_sigma(nd):
    """Two points whose slope is below one standard error: the band holds
    the edge over an unbounded range, n/r."""
    f = fitted(nd, [32, 64], [1000.0, 1100.0], 0.3, 81400.0)
    assert f["b"] ** 2 < f["cov"][1][1]
    assert nd.band_holds(f, 40700.0) is None
    text = "\n".join(nd.lines(nd.needs(
        {"EAM": {"f_col_scaled": f, "alpha_f": None}}, [], ("EAM",), 2.0),
        ("EAM",)))
    assert "the slope is within one standard error of 0" in text
    assert "EAM alpha_f: n/r (no trend)" in text
    assert "all four within: n/r (a trend is missing)" in text


def test_all_four_and_the_cost(nd):
    """Both models' f_col rising, alpha_f falling: all within from the
    largest entry to the smallest exit; hours = c n^k through the grid
    variants (small is not one), at that entry and at 128^3."""
    ns = [32, 64]
    col = fitted(nd, ns, [2 * n**2 for n in ns], 0.1, 80000.0)
    col2 = fitted(nd, ns, [n**2 for n in ns], 0.1, 80000.0)
    alpha = fitted(nd, ns, [10.0 * n**-1.0 for n in ns], 0.1, 0.05)
    t = {"EAM": {"f_col_scaled": col, "alpha_f": alpha},
         "MAM": {"f_col_scaled": col2, "alpha_f": alpha}}
    judged = [{"name": "small", "c1Hours2Cores": 99.0},
              {"name": "regime32", "c1Hours2Cores": 1.0},
              {"name": "regime64", "c1Hours2Cores": 8.0}]
    r = nd.needs(t, judged, ("EAM", "MAM"), 2.0)
    # alpha_f enters at 10/n = 0.1 (n = 100) and leaves at 0.025 (400);
    # MAM f_col enters at n^2 = 40,000 (200); EAM f_col leaves at 282.8
    assert r["all"]["from"] == pytest.approx(200.0, rel=1e-9)
    assert r["all"]["to"] == pytest.approx(math.sqrt(80000), rel=1e-9)
    assert r["cost"]["k"] == pytest.approx(3.0, rel=1e-9)
    assert r["hoursAtPaperGrid"] == pytest.approx(64.0, rel=1e-9)
    assert r["hoursAtAll"] == pytest.approx(1.0 * (200 / 32)**3, rel=1e-9)
    text = "\n".join(nd.lines(r, ("EAM", "MAM")))
    assert "all four within for n 200-283" in text
    assert "~ n^3.00 through regime32, regime64: 64 h at 128^3, 244 h " \
        "at 200^3" in text


def test_ranges_that_do_not_overlap(nd):
    """f_col reaches the factor only beyond where alpha_f has left it: no
    grid holds all four; one grid variant's hours give no cost law."""
    ns = [32, 64]
    col = fitted(nd, ns, [2 * n**2 for n in ns], 0.1, 80000.0)
    alpha = fitted(nd, ns, [10.0 * n**-1.0 for n in ns], 0.1, 0.2)
    t = {"EAM": {"f_col_scaled": col, "alpha_f": alpha}}
    r = nd.needs(t, [{"name": "regime32", "c1Hours2Cores": 1.0}],
                 ("EAM",), 2.0)
    assert r["all"] is None and r["cost"] is None
    assert r["hoursAtPaperGrid"] is None
    text = "\n".join(nd.lines(r, ("EAM",)))
    assert "all four within: at no n (their ranges do not overlap)" in text
    assert "the cost: n/r (fewer than two finished grid variants)" in text


def test_a_law_the_grids_reject_is_marked(nd):
    """Three grids off a power law beyond their sigmas (p < 5 %): the
    reading of that law says so; an exact law is not marked."""
    ns = [32, 48, 64]
    off = fitted(nd, ns, [2 * n**2 * (1.2 if n == 48 else 1.0)
                          for n in ns], 0.02, 80000.0)
    exact = fitted(nd, ns, [2 * n**2 for n in ns], 0.02, 80000.0)
    assert off["p"] < 0.05
    for fit, marked in ((off, True), (exact, False)):
        t = {"EAM": {"f_col_scaled": fit, "alpha_f": None}}
        r = nd.needs(t, [], ("EAM",), 2.0)
        assert r["windows"]["EAM"]["f_col_scaled"]["rejected"] is marked
        line = [ln for ln in nd.lines(r, ("EAM",)) if "f_col" in ln][0]
        assert ("the grids reject the law" in line) is marked
