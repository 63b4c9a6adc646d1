"""The regime study's variants one shortcut apart (channel.regime.pairs):
the ratio of a variant's scaled frequencies to its base's, its standard
error by propagation, the verdict on the shortcut, the pairs of the
checks (particle number, phase lengths) and their derivation from the
presets."""

import math

import pytest

from channelTestRuns import script


@pytest.fixture(scope="module")
def pairs():
    return script("channel.regime.pairs")


def model(fcol, scol, fagg, sagg):
    return {"f_col_scaled": fcol, "sigma_col_scaled": scol,
            "f_agg_scaled": fagg, "sigma_agg_scaled": sagg,
            "alpha_f": fagg / fcol if fcol else None}


def result(m, near_wall=None):
    return {"models": {"EAM": m},
            "concentration": ({"nearWallOverCentre": near_wall}
                              if near_wall else None)}


def study(**results):
    return {"variants": [{"name": n, "result": r}
                         for n, r in results.items()]}


def test_ratio_and_its_sigma(pairs):
    """f_col x s^2 8,000 +- 400 (5 %) over 10,000 +- 1,200 (12 %): ratio
    0.8 +- 0.8 x 13 %, z = -0.2 / 0.104 = -1.92: consistent; alpha_f's
    relative sigma from f_agg's and f_col's of each run."""
    base = result(model(10000.0, 1200.0, 500.0, 100.0))
    var = result(model(8000.0, 400.0, 200.0, 20.0))
    rows = pairs.compare(study(regime32=base, regime32n3=var), ("EAM",),
                         "particleNumber")
    r = rows[0]["EAM"]
    col = r["f_col_scaled"]
    assert col["ratio"] == pytest.approx(0.8, rel=1e-12)
    assert col["sigma"] == pytest.approx(0.8 * 0.13, rel=1e-12)
    assert col["z"] == pytest.approx(-0.2 / 0.104, rel=1e-12)
    assert col["consistent"]
    agg = r["f_agg_scaled"]
    assert agg["ratio"] == pytest.approx(0.4, rel=1e-12)
    assert agg["z"] == pytest.approx(-0.6 / (0.4 * math.hypot(0.1, 0.2)),
                                     rel=1e-12)
    assert not agg["consistent"]
    alpha = r["alpha_f"]
    rel_v, rel_b = math.hypot(0.1, 0.05), math.hypot(0.2, 0.12)
    assert alpha["ratio"] == pytest.approx(0.5, rel=1e-12)
    assert alpha["sigma"] == pytest.approx(0.5 * math.hypot(rel_v, rel_b),
                                           rel=1e-12)
    text = "\n".join(pairs.lines(rows, ("EAM",), "particleNumber"))
    assert "regime32n3 over regime32 EAM: f_col x s^2 0.80 +- 0.10 " \
        "(z -1.9: consistent)" in text
    assert "f_agg x s^2 0.40 +- 0.09 (z -6.7: depends on N)" in text


def test_pairs_not_yet_comparable_and_no_events(pairs):
    """A pair with a run missing is n/r naming it; a quantity with no
    agglomeration in the window is n/r, not a ratio of 0."""
    base = result(model(10000.0, 1000.0, 500.0, 100.0))
    var = result(model(9000.0, 500.0, 0.0, 0.0))
    rows = pairs.compare(
        study(regime32=base, regime32n3=var, regime48=None), ("EAM",),
        "particleNumber")
    assert rows[0]["EAM"]["f_agg_scaled"] is None
    assert rows[0]["EAM"]["alpha_f"] is None
    assert rows[1] == {"variant": "regime48n3", "base": "regime48",
                       "missing": ["regime48n3", "regime48"]}
    text = "\n".join(pairs.lines(rows, ("EAM",), "particleNumber"))
    assert "regime48n3 over regime48: n/r (regime48n3, regime48 not " \
        "finished)" in text
    assert "f_agg x s^2 n/r (no events or no sigma)" in text


def test_a_dropped_variant_is_named_so(pairs):
    """A pair whose variant the study dropped is n/r saying so, a missing
    base beside it still 'not finished'."""
    rows = pairs.compare(
        {"variants": [{"name": "regime48n3", "result": None,
                       "dropped": "why"},
                      {"name": "regime48", "result": None}]},
        ("EAM",), "particleNumber")
    p = [r for r in rows if r["variant"] == "regime48n3"][0]
    assert p["dropped"] == ["regime48n3"]
    text = "\n".join(pairs.lines(rows, ("EAM",), "particleNumber"))
    assert "regime48n3 over regime48: n/r (regime48 not finished; " \
        "regime48n3 dropped)" in text


def test_phase_lengths(pairs):
    """The paper's phases over small's at one grid: regime64 over
    regime64short and regime32 over small. f_col x s^2 40,000 +- 2,000
    over 10,000 +- 1,000: ratio 4 +- 4 x hypot(0.05, 0.1) = 0.447, z =
    3 / 0.447 = 6.7: depends on the phases; the near-wall over centre
    concentrations of both runs (3.85 and 1.4) stand beside; a pair with
    its base missing (small) is n/r."""
    base = result(model(10000.0, 1000.0, 400.0, 80.0), near_wall=1.4)
    var = result(model(40000.0, 2000.0, 400.0, 40.0), near_wall=3.85)
    rows = pairs.compare(study(regime64short=base, regime64=var,
                               regime32=var), ("EAM",), "phaseLength")
    assert rows[0] == {"variant": "regime32", "base": "small",
                       "missing": ["small"]}
    col = rows[1]["EAM"]["f_col_scaled"]
    assert col["ratio"] == pytest.approx(4.0, rel=1e-12)
    assert col["sigma"] == pytest.approx(4 * math.hypot(0.05, 0.1),
                                         rel=1e-12)
    assert not col["consistent"]
    agg = rows[1]["EAM"]["f_agg_scaled"]
    assert agg["ratio"] == pytest.approx(1.0, rel=1e-12)
    assert agg["z"] == pytest.approx(0.0, abs=1e-12)
    assert rows[1]["nearWallOverCentre"] == [3.85, 1.4]
    text = "\n".join(pairs.lines(rows, ("EAM",), "phaseLength"))
    assert text.startswith("Phase lengths (the paper's 240/100/520/200 T*")
    assert "regime32 over small: n/r (small not finished)" in text
    assert "regime64 over regime64short EAM: f_col x s^2 4.00 +- 0.45 " \
        "(z +6.7: depends on the phases)" in text
    assert "regime64 over regime64short: c_w/c_0 at the start of " \
        "agglomeration 3.85 / 1.4" in text


def test_pairs_derived_from_the_presets(pairs):
    """The pairs come from the presets (the entries in which they differ),
    not from a list: the study's variants give exactly the pairs the study
    was designed with; a preset that changes a second entry besides the
    check's (the grid with the particle number: regime48n3 against
    regime32) or the grid in every direction (regime48 against regime32,
    the grid trend's) is no pair; the time step in seconds, the write
    interval and the solver tolerance do not count as shortcuts; a
    variant at a larger step belongs to the time-step check alone."""
    assert pairs.check_pairs("particleNumber") == [
        ("regime32n3", "regime32"), ("regime48n3", "regime48")]
    assert pairs.check_pairs("phaseLength") == [
        ("regime32", "small"), ("regime64", "regime64short")]
    assert pairs.check_pairs("wallNormal") == [("printed", "regime64")]
    # regime64dt2 is regime64 at twice the step: the time-step check's
    # pair, and no base of the wall-normal check although printed
    # differs from it in the wall-normal entries alone
    assert pairs.check_pairs("timeStep") == [("regime64dt2", "regime64")]
    channel = script("channel.case.settings")
    # the study's variants are C1's: a preset's entries for other
    # configurations (regime64dt2's perConfiguration for C4) are none
    p, q = channel.preset("printed", "C1"), channel.preset("regime64dt2",
                                                           "C1")
    assert pairs.shortcut(p, q) == pairs.CHECKS["wallNormal"]["entries"]
    assert "perConfiguration" in pairs.shortcut(
        channel.preset("printed"), channel.preset("regime64dt2"))
    names = ["regime32", "regime48", "regime48n3"]
    assert pairs.check_pairs("particleNumber", names) == [
        ("regime48n3", "regime48")]
    assert pairs.check_pairs("wallNormal", names) == []
    channel = script("channel.case.settings")
    a, b = channel.preset("regime32"), channel.preset("small")
    assert {"UTolerance", "writeStar"} <= {
        k for k in a if a[k] != b.get(k)}
    assert pairs.shortcut(a, b) == pairs.CHECKS["phaseLength"]["entries"]


@pytest.mark.parametrize("agg, verdict", [
    (1.0, "the matrix may run at regime64dt2's step"),
    (1.5, "the matrix stays at regime64's step"),
    (None, "the matrix's step: n/r")])
def test_time_step_adoption(pairs, agg, verdict):
    """The time-step pair's last line: adopted only where all six ratios
    (both models' f_col x s^2, f_agg x s^2, alpha_f) lie within 2 sigma
    of 1; one quantity 1.5 times its base's at 10 % errors (z about 3.5)
    keeps the matrix at regime64's step; a quantity without events
    leaves it open."""
    def model(fagg):
        return {"f_col_scaled": 5e4, "sigma_col_scaled": 5e3,
                "f_agg_scaled": fagg, "sigma_agg_scaled": 0.1 * fagg
                if fagg else None, "alpha_f": fagg / 5e4 if fagg else 0}
    base = {"models": {m: model(500.0) for m in ("EAM", "MAM")},
            "concentration": None}
    var = {"models": {"EAM": model(None if agg is None else 500.0 * agg),
                      "MAM": model(500.0)}, "concentration": None}
    res = {"variants": [{"name": "regime64", "result": base},
                        {"name": "regime64dt2", "result": var}]}
    rows = pairs.compare(res, ("EAM", "MAM"), "timeStep")
    text = pairs.lines(rows, ("EAM", "MAM"), "timeStep")
    assert text[-1].startswith("  regime64dt2 over regime64: " + verdict)
