"""The regime study's grid trend (channel.regime.trend): the weighted
power-law fit and its extrapolation to 128^3 against closed forms of
least squares in ln v."""

import math

import numpy as np
import pytest

from channelTestRuns import script


@pytest.fixture(scope="module")
def trend():
    return script("channel.regime.trend")


def test_exact_power_law_three_points(trend):
    """v = 5 n^1.5 with 10 % sigma: the slope and the value at 128 exact;
    var b = 1 / (w Sxx), var ln v(128) = 1 / (w N) + (x128 - xbar)^2 var b
    with w = 1 / 0.1^2 (chi^2 = 0: no scaling)."""
    n = np.array([32.0, 48.0, 64.0])
    v = 5 * n**1.5
    f = trend.power_law(n, v, 0.1 * v)
    x = np.log(n)
    w, sxx = 100.0, np.sum((x - x.mean())**2)
    var_b = 1 / (w * sxx)
    var_ln = 1 / (w * 3) + (math.log(128) - x.mean())**2 * var_b
    assert f["b"] == pytest.approx(1.5, rel=1e-12)
    assert f["value"] == pytest.approx(5 * 128**1.5, rel=1e-12)
    assert f["sigmaB"] == pytest.approx(math.sqrt(var_b), rel=1e-9)
    assert math.log(f["high"] / f["value"]) == \
        pytest.approx(math.sqrt(var_ln), rel=1e-9)
    assert f["dof"] == 1 and f["chi2"] == pytest.approx(0, abs=1e-20)


def test_two_points_pass_through_both(trend):
    """Two points: the line through them; var b = (s1^2 + s2^2) / (x2 -
    x1)^2 in the relative sigmas s."""
    f = trend.power_law([32, 64], [100.0, 400.0], [10.0, 80.0])
    assert f["b"] == pytest.approx(2.0, rel=1e-12)
    assert f["value"] == pytest.approx(1600.0, rel=1e-12)
    assert f["sigmaB"] == pytest.approx(
        math.sqrt(0.1**2 + 0.2**2) / math.log(2), rel=1e-9)
    assert f["dof"] == 0


def test_scatter_beyond_the_sigmas_widens_the_band(trend):
    """Three points off a line with 1 % sigmas: the covariance scaled by
    chi^2 / dof, so var b = sum r^2 / Sxx (equal weights), r the residuals
    of ordinary least squares in ln v."""
    n = np.array([32.0, 48.0, 64.0])
    v = np.array([1000.0, 1800.0, 2500.0])
    f = trend.power_law(n, v, 0.01 * v)
    x, y = np.log(n), np.log(v)
    b, a = np.polyfit(x, y, 1)
    r = y - a - b * x
    assert f["b"] == pytest.approx(b, rel=1e-9)
    assert f["chi2"] == pytest.approx(np.sum(r**2) / 0.01**2, rel=1e-9)
    assert f["sigmaB"] == pytest.approx(
        math.sqrt(np.sum(r**2) / np.sum((x - x.mean())**2)), rel=1e-9)


def test_no_trend_from_one_usable_point(trend):
    assert trend.power_law([32, 64], [100.0, 0.0], [10.0, 1.0]) is None
    assert trend.power_law([32], [100.0], [10.0]) is None


def test_grid_trend_of_the_study(trend):
    """From run_post's variants: only the grid variants at the paper's
    phases count (regime64short and small do not), alpha_f's sigma from
    f_agg's and f_col's, and the factor to the paper's value."""
    def result(fcol, fagg):
        m = {"f_col_scaled": fcol, "sigma_col_scaled": 0.1 * fcol,
             "f_agg_scaled": fagg, "sigma_agg_scaled": 0.2 * fagg,
             "alpha_f": fagg / fcol}
        return {"models": {"EAM": m}}
    res = {"variants": [
        {"name": "small", "result": result(1.0, 1.0)},
        {"name": "regime32", "result": result(8000.0, 2000.0)},
        {"name": "regime48", "result": None},
        {"name": "regime64short", "result": result(5.0, 1.0)},
        {"name": "regime64", "result": result(32000.0, 2000.0)}]}
    paper = {"f_col_scaled": {"EAM": 81400.0},
             "f_agg_scaled": {"EAM": 667.0}}
    t = trend.grid_trend(res, ("EAM",), paper)
    assert t["variants"] == ["regime32", "regime64"]
    col, alpha = t["EAM"]["f_col_scaled"], t["EAM"]["alpha_f"]
    assert col["b"] == pytest.approx(2.0, rel=1e-12)
    assert col["value"] == pytest.approx(128000.0, rel=1e-12)
    assert col["factorToPaper"] == pytest.approx(128000 / 81400, rel=1e-12)
    assert alpha["b"] == pytest.approx(-2.0, rel=1e-12)
    s = math.hypot(0.1, 0.2)          # relative sigma of each alpha_f
    assert alpha["sigmaB"] == pytest.approx(
        math.sqrt(2) * s / math.log(2), rel=1e-9)
    assert alpha["paper"] == pytest.approx(667 / 81400, rel=1e-12)
    text = "\n".join(trend.lines(t, ("EAM",)))
    assert "regime32, regime64 finished" in text and "x paper 1.57" in text


def test_three_points_off_the_law_are_rejected(trend):
    """Three grids whose middle point lies 5 sigma off the line through
    the outer two: chi^2 on 1 dof far beyond 3.84, p < 5 %, the lines
    say the law is rejected; on the line: consistent, p = 1."""
    n = [32.0, 48.0, 64.0]
    on = [100.0 * (x / 32) ** 2 for x in n]
    off = list(on)
    off[1] *= math.exp(5 * 0.02 * math.sqrt(1.5))
    text = {}
    for name, v in (("on", on), ("off", off)):
        f = trend.power_law(n, v, [0.02 * x for x in v])
        f["paper"], f["factorToPaper"] = 1e5, f["value"] / 1e5
        text[name] = "\n".join(trend.lines(
            {"variants": ["regime32", "regime48", "regime64"],
             "EAM": {"f_col_scaled": f, "alpha_f": None}}, ("EAM",)))
        if name == "off":
            assert f["chi2"] > 3.841 and f["p"] < 0.05
        else:
            assert f["p"] == pytest.approx(1.0, abs=1e-9)
    assert "the power law is rejected" in text["off"]
    assert "consistent with a power law" in text["on"]
    assert "rejected" not in text["on"]


def test_finest_pair_is_the_law_through_the_two_finest_grids(trend):
    """Three finished grids on a bent law (32^3: 100, 48^3: 200, 64^3:
    400): the finest pair's slope is ln 2 / ln(4/3) and its value at 128
    400 x 2^b; with two grids there is no finest pair; the lines name
    the pair and their local slope."""
    def result(fcol):
        m = {"f_col_scaled": fcol, "sigma_col_scaled": 0.05 * fcol,
             "f_agg_scaled": 0.0, "sigma_agg_scaled": 0.0,
             "alpha_f": None}
        return {"models": {"EAM": m}}
    paper = {"f_col_scaled": {"EAM": 1000.0},
             "f_agg_scaled": {"EAM": 10.0}}
    res = {"variants": [
        {"name": "regime32", "result": result(100.0)},
        {"name": "regime48", "result": result(200.0)},
        {"name": "regime64", "result": result(400.0)}]}
    f = trend.finest_pair(res, ("EAM",), paper)
    b = math.log(2) / math.log(64 / 48)
    assert f["variants"] == ["regime48", "regime64"]
    assert f["EAM"]["f_col_scaled"]["b"] == pytest.approx(b, rel=1e-12)
    assert f["EAM"]["f_col_scaled"]["value"] == pytest.approx(
        400 * 2**b, rel=1e-12)
    assert f["EAM"]["f_col_scaled"]["dof"] == 0
    assert f["EAM"]["alpha_f"] is None
    text = "\n".join(trend.lines(f, ("EAM",), finest=True))
    assert text.startswith("The finest two grids alone (regime48, "
                           "regime64; their local slope)")
    assert trend.finest_pair({"variants": res["variants"][1:]},
                             ("EAM",), paper) is None


def test_grid_variants_derived_from_the_presets():
    """The trend's variants come from the presets: those that change only
    the cells (the same in every direction), their grading and the step
    from regime32: 32, 48, 64; not regime64short (other phases), not
    printed (the cells across only), not the 3e5-particle variants."""
    trend = script("channel.regime.trend")
    assert trend.GRID_VARIANTS == (("regime32", 32), ("regime48", 48),
                                   ("regime64", 64))
    assert trend.grid_variants("regime32n3") == (("regime32n3", 32),
                                                 ("regime48n3", 48))
