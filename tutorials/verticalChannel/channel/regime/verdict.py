"""verticalChannel regime study: its verdict. Which finished variant is in
the paper's regime, which of those is the cheapest preset, and, where
none is, which comes closest and what the grid trend says at 128^3.

In the regime: for both models, f_col x s^2 and alpha_f within a factor
FACTOR of Table 3's C1 values (README.md, 'The regime study'). The factor
of a value v to the paper's p is max(v/p, p/v); a variant's worst factor
is the largest of its four (infinite where a model has no agglomeration
in the window). The cost of a variant's C1 on 2 cores: the CPU hours of
its C1 stages (unladen, release, dispersion, agglomeration; all ranks)
over 2, i.e. the serial run's work split over two ranks at a parallel
efficiency of 1 (the channel's, measured at 128^3 on 2 ranks: 1.07;
README.md); affordable: at most BUDGET_H hours. The preset: the cheapest
affordable variant in the regime. Where there is none: the finished
variant of the smallest worst factor, and, per model and quantity, where
the trend's 68 % band at 128^3 (channelRegimeTrend) lies against the
factor: 'within' (all of it), 'overlaps' or 'outside', and what the
regime needs by the trend (channelRegimeNeeds): the grid where each
value, and all four, lie within the factor, and the cost of a C1 there
(also where variants are in the regime but none is affordable: where
the trend enters the regime is the cheapest grid it points to);
with three grids, the same read off the finest two grids' law too
(trend.finest_pair). The printed resolution (PRINTED, the
wall-normal grid the paper prints over PRINTED_BASE) is judged against
factors 2 and 1.5, and its worst factor against its base's says which
grid the Table D.6 matrix belongs on."""

import math

from channel.regime import needs

#: Largest factor to the paper of each of the four values
FACTOR = 2.0
#: Largest cost of the preset's C1 on 2 cores [h]
BUDGET_H = 3.0
#: The printed resolution and its base (the wall-normal grid alone),
#: judged against these factors too
PRINTED, PRINTED_BASE = "printed", "regime64"
PRINTED_FACTORS = (2.0, 1.5)
#: The four values judged, per model: key of the result, its name
QUANTITIES = (("colFactorToPaper", "f_col x s^2"),
              ("alphaFactorToPaper", "alpha_f"))


def worst(x):
    """max(x, 1/x) of a factor to the paper (inf for None or 0)."""
    if not x:
        return math.inf
    return max(x, 1.0 / x)


def judge_variant(v, models):
    """One finished variant: its four factors, the worst of them and
    where, whether it is in the regime, its C1 hours on 2 cores and
    whether they are affordable."""
    r = v["result"]
    factors = {m: {name: r["models"][m][key] for key, name in QUANTITIES}
               for m in models}
    w, at = max(((worst(x), f"{m} {name}")
                 for m in models for name, x in factors[m].items()),
                key=lambda t: t[0])
    hours = r["times"]["cpu_s"] / 3600 / 2
    return {"name": v["name"], "factors": factors, "worst": w,
            "worstAt": at, "inRegime": w <= FACTOR,
            "c1Hours2Cores": hours, "affordable": hours <= BUDGET_H}


def band_class(fit):
    """Where a trend's band at 128^3 lies against [1/FACTOR, FACTOR]
    times the paper's value (None without a trend)."""
    if not fit:
        return None
    lo, hi = fit["low"] / fit["paper"], fit["high"] / fit["paper"]
    if lo >= 1 / FACTOR and hi <= FACTOR:
        return "within"
    if hi < 1 / FACTOR or lo > FACTOR:
        return "outside"
    return "overlaps"


def verdict(res, models):
    """The study's verdict from run_post's results (with its gridTrend)."""
    judged = [judge_variant(v, models) for v in res["variants"]
              if v["result"]]
    ok = [j for j in judged if j["inRegime"] and j["affordable"]]
    preset = min(ok, key=lambda j: j["c1Hours2Cores"]) if ok else None
    closest = min(judged, key=lambda j: j["worst"]) if judged else None
    at128 = {m: {q: band_class(res.get("gridTrend", {}).get(m, {}).get(q))
                 for q in ("f_col_scaled", "alpha_f")} for m in models}
    return {"factor": FACTOR, "budget_h": BUDGET_H, "variants": judged,
            "printed": printed(judged),
            "preset": preset["name"] if preset else None,
            "closest": (closest["name"] if closest and not preset
                        else None),
            "trendAt128": at128,
            "needs": needs.needs(res.get("gridTrend"), judged, models,
                                 FACTOR),
            "needsFinestPair": (
                needs.needs(res["gridTrendFinestPair"], judged, models,
                            FACTOR)
                if res.get("gridTrendFinestPair") else None)}


def printed(judged):
    """The printed resolution's verdict: whether its four values lie
    within each factor of PRINTED_FACTORS of Table 3's C1, its worst
    factor against its base's, and the grid that this points the Table
    D.6 matrix to (None before the variant has finished)."""
    by = {j["name"]: j for j in judged}
    j, base = by.get(PRINTED), by.get(PRINTED_BASE)
    if not j:
        return None
    out = {"worst": j["worst"], "worstAt": j["worstAt"],
           "within": {f"{f:g}": j["worst"] <= f for f in PRINTED_FACTORS},
           "baseWorst": base["worst"] if base else None}
    if base is None:
        out["matrixGrid"] = None
    elif j["worst"] < base["worst"] and j["worst"] <= FACTOR:
        out["matrixGrid"] = PRINTED
    else:
        out["matrixGrid"] = PRINTED_BASE
    return out


def printed_lines(pv):
    """The printed resolution's lines of the verdict."""
    if pv is None:
        return [f"  the printed resolution ({PRINTED}): not finished, n/r"]
    within = "; ".join(f"within a factor {f}: "
                       + ("yes" if ok else "no")
                       for f, ok in pv["within"].items())
    out = [f"  the printed resolution ({PRINTED}): worst factor "
           f"{pv['worst']:.3g} ({pv['worstAt']}); {within}"]
    if pv["matrixGrid"] is None:
        out.append(f"  its base {PRINTED_BASE} not finished: the matrix's "
                   "grid n/r")
    elif pv["matrixGrid"] == PRINTED:
        out.append(f"  closer to the paper than {PRINTED_BASE} (worst "
                   f"factor {pv['baseWorst']:.3g}) and within the factor"
                   f" {FACTOR:g}: the Table D.6 matrix belongs on the "
                   "printed grid")
    else:
        out.append(f"  not closer to the paper than {PRINTED_BASE} (worst"
                   f" factor {pv['baseWorst']:.3g}) within the factor "
                   f"{FACTOR:g}: the matrix stays at {PRINTED_BASE}")
    return out


def headline(vd):
    """The verdict in one line (regime.png's headline)."""
    if not vd or not vd["variants"]:
        return "no variant has finished"
    if vd["preset"]:
        return (f"the preset in the paper's regime (within a factor"
                f" {vd['factor']:g} of Table 3's C1, C1 within"
                f" {vd['budget_h']:g} h on 2 cores): {vd['preset']}")
    by = {j["name"]: j for j in vd["variants"]}
    c = by.get(vd["closest"])
    close = (f"; closest: {c['name']} (worst factor {c['worst']:.3g},"
             f" {c['worstAt']}; C1 {c['c1Hours2Cores']:.1f} h on 2 cores)"
             if c else "")
    return (f"no variant within a factor {vd['factor']:g} of Table 3's C1"
            f" and within {vd['budget_h']:g} h on 2 cores" + close)


def lines(vd, models):
    """The verdict's lines of regime.txt."""
    out = [f"Verdict (in the regime: both models' f_col x s^2 and alpha_f"
           f" within a factor {vd['factor']:g} of Table 3's C1; "
           f"affordable: C1 on 2 cores, its CPU hours / 2, at most "
           f"{vd['budget_h']:g} h):"]
    for j in vd["variants"]:
        w = ("inf" if math.isinf(j["worst"]) else f"{j['worst']:.3g}")
        out.append(
            f"  {j['name']:14s} worst factor {w} ({j['worstAt']}), C1 on "
            f"2 cores {j['c1Hours2Cores']:.2f} h: "
            + ("in the regime" if j["inRegime"] else "not in the regime")
            + ("" if j["affordable"] else ", not affordable"))
    if not vd["variants"]:
        out.append("  no variant has finished")
    elif vd["preset"]:
        out.append(f"  the preset in the regime: {vd['preset']}")
    else:
        if any(j["inRegime"] for j in vd["variants"]):
            out.append("  in the regime, none affordable: " + ", ".join(
                j["name"] for j in vd["variants"] if j["inRegime"]))
        else:
            out.append(f"  no finished variant is in the regime; closest:"
                       f" {vd['closest']}")
        out.append("  the grid trend's 68 % band at 128^3 against the "
                   "factor: " + "; ".join(
                       f"{m} {needs.NAMES[q]} {c or 'n/r'}"
                       for m in models
                       for q, c in vd["trendAt128"][m].items()))
        out += needs.lines(vd["needs"], models)
        if vd.get("needsFinestPair"):
            out += needs.lines(vd["needsFinestPair"], models,
                               "the finest two grids' law")
    return out + printed_lines(vd.get("printed"))
