"""verticalChannel regime study: what the paper's regime needs, read off
the grid trend (channelRegimeTrend) where no finished variant is in it.

Per model and quantity, the cells per direction n over which the fitted
power law v(n) = exp(a) n^b lies within a factor F of the paper's value p
(F: the verdict's): p/F <= v(n) <= F p, from where the law reaches the
edge it approaches ('enters') to where it passes the other ('leaves').
The entry's 68 % range: the n over which the fit's 68 % band (one
standard error of ln v, from the fit's covariance C of (a, b)) holds
that edge T, between the roots in x = ln n of

    (a + b x - ln T)^2 = C_aa + 2 C_ab x + C_bb x^2;

n/r where the slope is within one standard error of 0 (b^2 <= C_bb: the
band then holds the edge over an unbounded range of n). All four within
the factor: from the largest entry to the smallest exit. The cost there:
a C1 on 2 cores (the verdict's: the CPU hours of its stages over 2) as a
power law of n through the finished grid variants (least squares in
ln; none with fewer than two). A power law's extrapolation is a reading
of the trend, not a run: the README says so where it quotes these; a
reading of a law that the three grids reject (channelRegimeTrend's
check) says so in its line."""

import math

import numpy as np

from channel.regime import trend

#: Names of the quantities in the report
NAMES = {"f_col_scaled": "f_col x s^2", "alpha_f": "alpha_f"}


def band_holds(fit, target):
    """(n_low, n_high): the cells per direction over which the fit's 68 %
    band holds the value target; None where b^2 <= C_bb."""
    a, b = fit["a"], fit["b"]
    c = np.asarray(fit["cov"], float)
    d = a - math.log(target)
    qa = b * b - c[1, 1]
    if qa <= 0:
        return None
    qb = 2 * (d * b - c[0, 1])
    qc = d * d - c[0, 0]
    # At the central crossing x0 = -d/b the quadratic is -se^2(x0) < 0,
    # so with qa > 0 it has two real roots
    r = math.sqrt(qb * qb - 4 * qa * qc)
    x1, x2 = sorted(((-qb - r) / (2 * qa), (-qb + r) / (2 * qa)))
    return math.exp(x1), math.exp(x2)


def window(fit, factor):
    """Where the law lies within the factor of the paper's value:
    {"enter", "leave", "edge", "enterRange", "rejected"} (n; None for a
    law that is flat, b = 0), the edge the law approaches, its 68 % range
    and whether the points reject the law."""
    if not fit or fit["b"] == 0:
        return None
    a, b, p = fit["a"], fit["b"], fit["paper"]
    up = b > 0
    edge = p / factor if up else p * factor
    other = p * factor if up else p / factor
    return {"enter": math.exp((math.log(edge) - a) / b),
            "leave": math.exp((math.log(other) - a) / b),
            "edge": edge, "enterRange": band_holds(fit, edge),
            "rejected": fit["p"] is not None and fit["p"] < trend.P_REJECT}


def cost_law(judged):
    """The C1 hours on 2 cores of the finished grid variants as c n^k:
    {"k", "c", "variants"}, or None with fewer than two."""
    hours = {j["name"]: j["c1Hours2Cores"] for j in judged}
    pts = [(n, hours[v]) for v, n in trend.GRID_VARIANTS if v in hours]
    if len(pts) < 2:
        return None
    n, h = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    k, lnc = np.polyfit(n, h, 1)
    return {"k": float(k), "c": math.exp(lnc),
            "variants": [v for v, _ in trend.GRID_VARIANTS if v in hours]}


def needs(grid_trend, judged, models, factor):
    """Per model and quantity its window; the grid range where all four
    lie within the factor ({"from", "to"}, None where they do not
    overlap or a law is missing); the cost law and the hours of a C1 at
    the start of that range and at the paper's grid."""
    out = {m: {q: window((grid_trend or {}).get(m, {}).get(q), factor)
               for q in NAMES} for m in models}
    ws = [out[m][q] for m in models for q in NAMES]
    both = None
    if ws and all(ws):
        lo = max(w["enter"] for w in ws)
        hi = min(w["leave"] for w in ws)
        both = {"from": lo, "to": hi} if lo <= hi else None
    cost = cost_law(judged)
    at = (lambda n: cost["c"] * n**cost["k"] if cost and n else None)
    return {"windows": out, "all": both, "cost": cost,
            "hoursAtAll": at(both["from"] if both else None),
            "hoursAtPaperGrid": at(trend.N_PAPER_GRID)}


def _n(x):
    return "inf" if x is None or math.isinf(x) else f"{x:.3g}"


def lines(nd, models, source="the grid trend"):
    """The lines of regime.txt, under the verdict."""
    out = [f"  what the regime needs, from {source} (n: cells per "
           "direction of a power law's extrapolation, not a run):"]
    for m in models:
        for q, name in NAMES.items():
            w = nd["windows"][m][q]
            if not w:
                out.append(f"    {m} {name}: n/r (no trend)")
                continue
            r = w["enterRange"]
            out.append(
                f"    {m} {name}: within for n {_n(w['enter'])}-"
                f"{_n(w['leave'])} (reaches {w['edge']:.3g} at n "
                f"{_n(w['enter'])}, 68 %: "
                + (f"{_n(r[0])}-{_n(r[1])})" if r else
                   "n/r, the slope is within one standard error of 0)")
                + ("; the grids reject the law" if w["rejected"] else ""))
    c = nd["cost"]
    cost = (f"a C1 on 2 cores ~ n^{c['k']:.2f} through "
            f"{', '.join(c['variants'])}" if c else
            "the cost: n/r (fewer than two finished grid variants)")
    if nd["all"]:
        out.append(f"    all four within for n {_n(nd['all']['from'])}-"
                   f"{_n(nd['all']['to'])}")
    elif all(nd["windows"][m][q] for m in models for q in NAMES):
        out.append("    all four within: at no n (their ranges do not "
                   "overlap)")
    else:
        out.append("    all four within: n/r (a trend is missing)")
    if c:
        out.append(
            f"    {cost}: {nd['hoursAtPaperGrid']:.3g} h at "
            f"{trend.N_PAPER_GRID}^3"
            + (f", {nd['hoursAtAll']:.3g} h at "
               f"{_n(nd['all']['from'])}^3" if nd["all"] else ""))
    else:
        out.append(f"    {cost}")
    return out
