"""verticalChannel regime study: the trend with the grid. Where no
affordable variant reaches the paper's regime, the study extrapolates the
grid variants at the paper's phase lengths (32^3, 48^3, 64^3; one shortcut
changed: the grid) to the paper's 128^3.

Per model and quantity (f_col x s^2, alpha_f): a power law v = c n^b in
the cells per direction n, fitted by weighted least squares to ln v (the
weight of a point 1 / (sigma_v / v)^2, its relative standard error), its
covariance from those sigmas, scaled by chi^2 / dof where the points
scatter more than their sigmas (dof >= 1). The value at n = 128 with its
68 % band (one standard error of ln v there), and the factor to the
paper. With two points the fit passes through both and the band comes
from their sigmas alone; with one point, or a value of 0, there is no
trend (None). With three points the law is checked: the probability p of
a chi^2 at least as large on its degrees of freedom if the points lay on
a power law with their sigmas; below 5 % the law is rejected, and the
extrapolation says so."""

from aggloTools import uncertainty

from channel.regime.variants import larger_step, presets, shortcut

#: What a grid variant changes from the coarsest (regime32, the paper's
#: phases): the cells in every direction, their wall grading and the step
GRID_ENTRIES = {"n", "yGrading", "dtStar"}


def grid_variants(base="regime32"):
    """The grid variants at the paper's phases and their cells per
    direction: base and every variant of the study whose preset differs
    from base's in GRID_ENTRIES alone with the same cells in every
    direction (channelRegimeVariants), by cells; not the time-step
    check's variant (variants.larger_step)."""
    p = presets()
    out = [(name, s["n"][0]) for name, s in p.items()
           if len(set(s["n"])) == 1 and not larger_step(name, p)
           and (name == base or shortcut(s, p[base]) == GRID_ENTRIES)]
    return tuple(sorted(out, key=lambda v: v[1]))


#: The grid variants at the paper's phases and their cells per direction
GRID_VARIANTS = grid_variants()
#: The paper's grid (cells per direction)
N_PAPER_GRID = 128
#: Below this probability of its chi^2 the power law is rejected
P_REJECT = 0.05


def power_law(n, v, sigma, at=N_PAPER_GRID):
    """The weighted power-law fit of aggloTools.uncertainty, at the
    paper's grid by default."""
    return uncertainty.power_law(n, v, sigma, at)


def alpha_sigma(m):
    """The standard error of alpha_f = f_agg / f_col from theirs."""
    if not m["alpha_f"] or not m["f_agg_scaled"]:
        return None
    return m["alpha_f"] * uncertainty.relative_error(
        (m["f_agg_scaled"], m["sigma_agg_scaled"]),
        (m["f_col_scaled"], m["sigma_col_scaled"]))


def _finished_grids(res):
    done = {v["name"]: v["result"] for v in res["variants"]
            if v["result"]}
    return done, [(name, n) for name, n in GRID_VARIANTS if name in done]


def grid_trend(res, models, paper, names=None):
    """Per model, the power laws of f_col x s^2 and alpha_f over the
    finished grid variants of res (run_post's; of those in names only,
    if given), with the factor of the value at 128^3 to the paper's;
    {"variants": [...], model: {...}}."""
    done, pts = _finished_grids(res)
    if names is not None:
        pts = [x for x in pts if x[0] in names]
    out = {"variants": [name for name, _ in pts]}
    for m in models:
        rows = [done[name]["models"][m] for name, _ in pts]
        ns = [n for _, n in pts]
        col = power_law(ns, [r["f_col_scaled"] for r in rows],
                        [r["sigma_col_scaled"] for r in rows])
        alpha = power_law(ns, [r["alpha_f"] or 0.0 for r in rows],
                          [alpha_sigma(r) or 0.0 for r in rows])
        ref_alpha = paper["f_agg_scaled"][m] / paper["f_col_scaled"][m]
        for fit, ref in ((col, paper["f_col_scaled"][m]),
                         (alpha, ref_alpha)):
            if fit:
                fit["paper"] = ref
                fit["factorToPaper"] = fit["value"] / ref
        out[m] = {"f_col_scaled": col, "alpha_f": alpha}
    return out


def finest_pair(res, models, paper):
    """With three or more finished grid variants, grid_trend through the
    finest two alone: the local slope, the reading a law that bends with
    the grid favours over the fit through all of them; None with
    fewer."""
    _, pts = _finished_grids(res)
    if len(pts) < 3:
        return None
    return grid_trend(res, models, paper, [name for name, _ in pts[-2:]])


def check(fit):
    """The check of the law in words, for a fit with dof >= 1."""
    p = fit["p"]
    word = (f"the power law is rejected (p < {100 * P_REJECT:g} %): the"
            " extrapolation follows a law the points do not"
            if p < P_REJECT else "consistent with a power law")
    return (f" (chi2 {fit['chi2']:.1f} on {fit['dof']} dof, p = {p:.2g}:"
            f" {word})")


def lines(trend, models, finest=False):
    """The trend's lines of regime.txt (finest: finest_pair's)."""
    head = (f"Trend with the grid at the paper's phases "
            f"({', '.join(trend['variants']) or 'no grid variant'}"
            f" finished), extrapolated to {N_PAPER_GRID}^3 as v ~ n^b:"
            if not finest else
            f"The finest two grids alone ({', '.join(trend['variants'])}"
            f"; their local slope), extrapolated to {N_PAPER_GRID}^3:")
    out = [head]
    for m in models:
        for q in ("f_col_scaled", "alpha_f"):
            f = trend.get(m, {}).get(q)
            if not f:
                out.append(f"  {m} {q}: n/r (fewer than two finished grid"
                           " variants with a nonzero value)")
                continue
            out.append(
                f"  {m} {q}: b = {f['b']:.2f} +- {f['sigmaB']:.2f}; at "
                f"{N_PAPER_GRID}^3 {f['value']:.3g} (68 %: {f['low']:.3g}-"
                f"{f['high']:.3g}), paper {f['paper']:.3g}, x paper "
                f"{f['factorToPaper']:.2f}"
                + (check(f) if f["dof"]
                   else " (two points: no check of the law)"))
    return out
