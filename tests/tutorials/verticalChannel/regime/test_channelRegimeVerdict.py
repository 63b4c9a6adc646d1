"""The regime study's verdict (channel.regime.verdict): which finished
variant is in the paper's regime (both models' f_col x s^2 and alpha_f
within a factor 2 of Table 3's C1), the cheapest affordable one (C1 on 2
cores, CPU hours / 2, at most 3 h), else the closest and where the grid
trend's band at 128^3 lies, on hand-made results."""

import math

import pytest

from channelTestRuns import script


@pytest.fixture(scope="module")
def vd():
    return script("channel.regime.verdict")


def variant(name, col, alpha, cpu_h, mam=None):
    """A finished variant: EAM's factors to the paper col and alpha, MAM's
    the same unless given, cpu_h CPU hours of its C1."""
    mc, ma = mam or (col, alpha)
    return {"name": name, "result": {
        "models": {"EAM": {"colFactorToPaper": col,
                           "alphaFactorToPaper": alpha},
                   "MAM": {"colFactorToPaper": mc,
                           "alphaFactorToPaper": ma}},
        "times": {"cpu_s": cpu_h * 3600}}}


def test_factor_and_cost_of_a_variant(vd):
    """Worst of max(x, 1/x) over the four factors, where it is; hours on 2
    cores = CPU hours / 2."""
    j = vd.judge_variant(variant("a", 0.4, 1.5, 5.0, mam=(0.9, 1.9)),
                         ("EAM", "MAM"))
    assert j["worst"] == pytest.approx(2.5)
    assert j["worstAt"] == "EAM f_col x s^2"
    assert not j["inRegime"]
    assert j["c1Hours2Cores"] == pytest.approx(2.5) and j["affordable"]
    j = vd.judge_variant(variant("b", 0.5, 2.0, 6.2), ("EAM", "MAM"))
    assert j["worst"] == pytest.approx(2.0) and j["inRegime"]
    assert j["c1Hours2Cores"] == pytest.approx(3.1)
    assert not j["affordable"]
    j = vd.judge_variant(variant("c", 1.0, None, 1.0), ("EAM", "MAM"))
    assert math.isinf(j["worst"]) and j["worstAt"] == "EAM alpha_f"


def test_the_cheapest_affordable_variant_in_the_regime(vd):
    res = {"variants": [
        variant("small", 0.1, 30.0, 0.3),
        variant("regime48", 0.7, 1.6, 5.0),     # 2.5 h
        variant("regime64", 1.1, 1.2, 5.8),     # 2.9 h
        variant("regime96", 1.0, 1.0, 40.0),    # in, not affordable
        {"name": "regime32n3", "result": None}]}
    v = vd.verdict(res, ("EAM", "MAM"))
    assert v["preset"] == "regime48" and v["closest"] is None
    assert [j["name"] for j in v["variants"]] == \
        ["small", "regime48", "regime64", "regime96"]
    text = "\n".join(vd.lines(v, ("EAM", "MAM")))
    assert "the preset in the regime: regime48" in text
    assert "regime96       worst factor 1 (EAM f_col x s^2), C1 on 2 " \
        "cores 20.00 h: in the regime, not affordable" in text


def test_none_in_the_regime_the_closest_and_the_trend(vd):
    """No variant within the factor: the smallest worst factor is the
    closest, and the trend's bands at 128^3 are classed against [0.5, 2]
    times the paper's value."""
    def fit(lo, hi):
        """A law v = c n through (lo hi)^1/2 at 128 with that band."""
        v = (lo * hi)**0.5
        return {"low": lo, "high": hi, "paper": 10.0, "value": v,
                "a": math.log(v / 128), "b": 1.0,
                "cov": [[0.01, 0.0], [0.0, 0.01]], "p": None}
    res = {"variants": [variant("regime32", 0.08, 30.0, 3.0),
                        variant("regime64", 0.3, 4.0, 8.0, mam=(0.35, 6))],
           "gridTrend": {
               "EAM": {"f_col_scaled": fit(6.0, 15.0),
                       "alpha_f": fit(15.0, 40.0)},
               "MAM": {"f_col_scaled": fit(21.0, 30.0), "alpha_f": None}}}
    v = vd.verdict(res, ("EAM", "MAM"))
    assert v["preset"] is None and v["closest"] == "regime64"
    assert v["trendAt128"] == {
        "EAM": {"f_col_scaled": "within", "alpha_f": "overlaps"},
        "MAM": {"f_col_scaled": "outside", "alpha_f": None}}
    text = "\n".join(vd.lines(v, ("EAM", "MAM")))
    assert "no finished variant is in the regime; closest: regime64" \
        in text
    assert "worst factor 6 (MAM alpha_f)" in text
    assert ("EAM f_col x s^2 within; EAM alpha_f overlaps; MAM f_col x "
            "s^2 outside; MAM alpha_f n/r") in text
    # What the regime needs follows (channel.regime.needs): EAM f_col x s^2
    # (v = n sqrt(90) / 128) lies within [5, 20] for n 67.5-270
    assert "what the regime needs, from the grid trend" in text
    assert "EAM f_col x s^2: within for n 67.5-270" in text
    # no finest pair (fewer than three grids): no second reading
    assert v["needsFinestPair"] is None
    assert "finest two grids" not in text
    # with one, its needs follow: EAM f_col x s^2 = n sqrt(90) / 64
    # (twice the above) lies within [5, 20] for n 33.7-135
    res["gridTrendFinestPair"] = {"EAM": {
        "f_col_scaled": dict(fit(6.0, 15.0),
                             a=math.log(math.sqrt(90) / 64))}}
    text = "\n".join(vd.lines(vd.verdict(res, ("EAM", "MAM")),
                               ("EAM", "MAM")))
    assert "what the regime needs, from the finest two grids' law" in text
    assert "EAM f_col x s^2: within for n 33.7-135" in text


def test_in_the_regime_but_none_affordable(vd):
    """In the regime at 15 h on 2 cores: no preset, and what the regime
    needs by the trend (where it enters: the cheapest grid it points to)
    follows as where none is in the regime. EAM f_col x s^2 = n 10 / 64
    (at 64: 10, the paper's value 10) lies within [5, 20] for n 32-128."""
    law = {"low": 18.0, "high": 22.0, "paper": 10.0, "value": 20.0,
           "a": math.log(10.0 / 64), "b": 1.0,
           "cov": [[0.01, 0.0], [0.0, 0.01]], "p": None}
    v = vd.verdict({"variants": [variant("regime64", 1.2, 0.8, 30.0)],
                    "gridTrend": {"EAM": {"f_col_scaled": law,
                                          "alpha_f": None}}}, ("EAM",))
    assert v["preset"] is None
    text = "\n".join(vd.lines(v, ("EAM",)))
    assert "in the regime, none affordable: regime64" in text
    assert "no finished variant is in the regime" not in text
    assert "the grid trend's 68 % band at 128^3 against the factor: EAM " \
        "f_col x s^2 overlaps; EAM alpha_f n/r" in text
    assert "EAM f_col x s^2: within for n 32-128" in text
    assert vd.lines(vd.verdict({"variants": []}, ("EAM",)),
                    ("EAM",))[1] == "  no variant has finished"


def test_printed_resolution_verdict(vd):
    """The printed resolution against factors 2 and 1.5, and the grid the
    matrix belongs on: the printed grid where it is closer to the paper
    than regime64 and within 2, else regime64; n/r before it finished
    or without its base."""
    models = ("EAM", "MAM")
    base = variant("regime64", 0.61, 2.11, 13.8, mam=(0.62, 1.50))
    closer = variant("printed", 0.9, 1.3, 70.0, mam=(0.8, 1.4))
    v = vd.verdict({"variants": [base, closer]}, models)
    p = v["printed"]
    assert p["worst"] == pytest.approx(1.4)
    assert p["within"] == {"2": True, "1.5": True}
    assert p["matrixGrid"] == "printed"
    text = "\n".join(vd.lines(v, models))
    assert "within a factor 2: yes; within a factor 1.5: yes" in text
    assert "the Table D.6 matrix belongs on the printed grid" in text
    farther = variant("printed", 0.3, 1.2, 70.0)
    v = vd.verdict({"variants": [base, farther]}, models)
    assert v["printed"]["within"] == {"2": False, "1.5": False}
    assert v["printed"]["matrixGrid"] == "regime64"
    assert "the matrix stays at regime64" in "\n".join(vd.lines(v, models))
    v = vd.verdict({"variants": [base]}, models)
    assert v["printed"] is None
    assert "the printed resolution (printed): not finished, n/r" in \
        "\n".join(vd.lines(v, models))
    v = vd.verdict({"variants": [closer]}, models)
    assert v["printed"]["matrixGrid"] is None
