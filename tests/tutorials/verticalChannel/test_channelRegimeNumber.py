"""The regime study's particle-number check (channelRegimeNumber.py): the
ratio of a 3e5 variant's scaled frequencies to its 1e5 base's, its
standard error by propagation, and the s^2 scaling's verdict."""

import math

import pytest

from channelTestRuns import script


@pytest.fixture(scope="module")
def num():
    return script("channelRegimeNumber")


def model(fcol, scol, fagg, sagg):
    return {"f_col_scaled": fcol, "sigma_col_scaled": scol,
            "f_agg_scaled": fagg, "sigma_agg_scaled": sagg,
            "alpha_f": fagg / fcol if fcol else None}


def study(**results):
    return {"variants": [{"name": n, "result": r}
                         for n, r in results.items()]}


def test_ratio_and_its_sigma(num):
    """f_col x s^2 8,000 +- 400 (5 %) over 10,000 +- 1,200 (12 %): ratio
    0.8 +- 0.8 x 13 %, z = -0.2 / 0.104 = -1.92: consistent; alpha_f's
    relative sigma from f_agg's and f_col's of each run."""
    base = {"models": {"EAM": model(10000.0, 1200.0, 500.0, 100.0)}}
    var = {"models": {"EAM": model(8000.0, 400.0, 200.0, 20.0)}}
    rows = num.particle_number(study(regime32=base, regime32n3=var),
                               ("EAM",))
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
    text = "\n".join(num.lines(rows, ("EAM",)))
    assert "regime32n3 over regime32 EAM: f_col x s^2 0.80 +- 0.10 " \
        "(z -1.9: consistent)" in text
    assert "f_agg x s^2 0.40 +- 0.09 (z -6.7: depends on N)" in text


def test_pairs_not_yet_comparable_and_no_events(num):
    """A pair with a run missing is n/r naming it; a quantity with no
    agglomeration in the window is n/r, not a ratio of 0."""
    base = {"models": {"EAM": model(10000.0, 1000.0, 500.0, 100.0)}}
    var = {"models": {"EAM": model(9000.0, 500.0, 0.0, 0.0)}}
    rows = num.particle_number(
        study(regime32=base, regime32n3=var, regime48=None), ("EAM",))
    assert rows[0]["EAM"]["f_agg_scaled"] is None
    assert rows[0]["EAM"]["alpha_f"] is None
    assert rows[1] == {"variant": "regime48n3", "base": "regime48",
                       "missing": ["regime48n3", "regime48"]}
    text = "\n".join(num.lines(rows, ("EAM",)))
    assert "regime48n3 over regime48: n/r (regime48n3, regime48 not " \
        "finished)" in text
    assert "f_agg x s^2 n/r (no events or no sigma)" in text
