"""verticalChannel regime study: the variants one shortcut apart,
compared. Four checks (CHECKS), each over the pairs (variant, base) whose
presets differ in that shortcut alone (check_pairs: derived from the
presets, not listed):

* the particle number: each 3 x 10^5 variant (s = 20) over its 10^5 base
  (s = 60), the same grid and phases. The frequencies are compared
  scaled to the paper's number (f x s^2, Eq. 87 over the window): where
  the collisions of a particle depend only on the others' concentration,
  f_col grows as N^2 and f_col x s^2 is the same at both numbers (ratio
  1), and so is alpha_f;
* the phase lengths: each variant at the paper's phases (240/100/520/200
  T*, window 100-200) over its base at `small`'s (60/10/30/60, window
  30-60), the same grid and particles. Ratio 1: `small`'s shorter
  release, dispersion and window give the paper's phases' result;
* the wall-normal resolution: `printed` (the paper's printed grid, 128
  cells across with the first cell centre at y+ 0.63, Delta t* 0.005)
  over `regime64` (64 cells, first cell centre at y+ 1), the same x and
  z cells, phases and particles.
* the time step: `regime64dt2` (Delta t* 0.02) over `regime64` (0.01),
  everything else the same: the matrix's shortcut (the fluid is most of
  a 64^3 step), adopted only where every quantity is consistent.

Per model and quantity (f_col x s^2, f_agg x s^2, alpha_f): the ratio
variant / base, its standard error from both runs' sigmas (relative
errors in quadrature; alpha_f's from f_agg's and f_col's), and z =
(ratio - 1) / sigma. |z| <= Z_CONSISTENT: consistent (the shortcut does
not change it); beyond it the quantity depends on the shortcut. Per
pair, the near-wall over centre concentration at the start of
agglomeration of both runs (no sigma: the two values)."""

from channel.regime import trend
from aggloTools import uncertainty
from channel.regime.variants import larger_step, presets, shortcut

#: The checks: the preset entries each changes alone (its pairs are the
#: variants whose presets differ in those alone and are `alike` otherwise,
#: the variant the one with the larger `order` value), the heading of
#: their lines in regime.txt and the words for a ratio beyond
#: Z_CONSISTENT
CHECKS = {
    "particleNumber": {
        "entries": {"nParticles", "couplingScale"},
        "order": lambda p: p["nParticles"],
        "head": "Particle number (3e5 over 1e5 particles, the same grid "
                "and phases; the s^2 scaling holds where the ratio is 1 "
                "within {z:g} sigma):",
        "differs": "depends on N"},
    "phaseLength": {
        "entries": {"unladen", "release", "dispersion", "agglomeration",
                    "window"},
        "order": lambda p: p["agglomeration"],
        "head": "Phase lengths (the paper's 240/100/520/200 T* over "
                "small's 60/10/30/60, the same grid and particles; the "
                "phases do not matter where the ratio is 1 within {z:g} "
                "sigma):",
        "differs": "depends on the phases"},
    "wallNormal": {
        "entries": {"n", "yGrading", "dtStar"},
        "order": lambda p: p["n"][1],
        # the cells across only (a grid refined in every direction is
        # the grid trend's, channelRegimeTrend)
        "alike": lambda a, b: (a["n"][0], a["n"][2]) == (b["n"][0],
                                                         b["n"][2]),
        "head": "Wall-normal resolution (the printed 128 cells, first "
                "cell centre at y+ 0.63, over regime64's 64, the same x "
                "and z cells, phases and particles; the wall-normal grid "
                "does not matter where the ratio is 1 within {z:g} "
                "sigma):",
        "differs": "depends on the wall-normal grid"},
    "timeStep": {
        "entries": {"dtStar"},
        "order": lambda p: p["dtStar"],
        "head": "Time step (regime64dt2's dt* 0.02 over regime64's 0.01, "
                "the same grid, phases and particles; the matrix may run "
                "at the larger step where every quantity's ratio is 1 "
                "within {z:g} sigma):",
        "differs": "depends on the step"},
}
#: The quantities compared, each with its sigma (key or function)
NAMES = {"f_col_scaled": "f_col x s^2", "f_agg_scaled": "f_agg x s^2",
         "alpha_f": "alpha_f"}
#: Largest |z| consistent with no effect of the shortcut (two standard
#: errors)
Z_CONSISTENT = 2.0


def sigma_of(m, q):
    """The standard error of quantity q of one model's result m."""
    if q == "alpha_f":
        return trend.alpha_sigma(m)
    return m["sigma_col_scaled" if q == "f_col_scaled"
             else "sigma_agg_scaled"]


def ratio(mv, mb, q):
    """{"ratio", "sigma", "z", "consistent"} of quantity q, variant mv
    over base mb; None where either value is 0 or has no sigma."""
    v, b = mv[q], mb[q]
    sv, sb = sigma_of(mv, q), sigma_of(mb, q)
    if not v or not b or not sv or not sb:
        return None
    r = v / b
    s = r * uncertainty.relative_error((v, sv), (b, sb))
    z = (r - 1.0) / s
    return {"ratio": r, "sigma": s, "z": z,
            "consistent": abs(z) <= Z_CONSISTENT}


def _near_wall(result):
    return (result.get("concentration") or {}).get("nearWallOverCentre")


def check_pairs(check, names=None):
    """The pairs (variant, base) of the check among the presets names
    (default: the study's variants; in their order): those whose presets
    differ in the check's entries alone (variants.shortcut)."""
    c = CHECKS[check]
    p = presets(names)
    names = list(p)
    alike = c.get("alike", lambda a, b: True)
    # a variant at a larger step belongs to the time-step check alone
    other = {n for n in names if check != "timeStep"
             and larger_step(n, presets())}
    return [(v, b) for v in names for b in names
            if v != b and shortcut(p[v], p[b]) == c["entries"]
            and not {v, b} & other
            and alike(p[v], p[b]) and c["order"](p[v]) > c["order"](p[b])]


def compare(res, models, check):
    """Per pair of the check whose variant and base both finished in res
    (run_post's): {"variant", "base", "nearWallOverCentre": [variant's,
    base's], model: {q: ratio(...)}}; the pairs not yet comparable as
    {"variant", "base", "missing": [names]}."""
    done = {v["name"]: v["result"] for v in res["variants"]
            if v["result"]}
    dropped = [v["name"] for v in res["variants"] if v.get("dropped")]
    out = []
    for var, base in check_pairs(check):
        missing = [n for n in (var, base) if n not in done]
        if missing:
            out.append({"variant": var, "base": base, "missing": missing})
            gone = [n for n in missing if n in dropped]
            if gone:
                out[-1]["dropped"] = gone
            continue
        row = {"variant": var, "base": base, "nearWallOverCentre":
               [_near_wall(done[var]), _near_wall(done[base])]}
        for m in models:
            mv, mb = done[var]["models"][m], done[base]["models"][m]
            row[m] = {q: ratio(mv, mb, q) for q in NAMES}
        out.append(row)
    return out


def _g(x):
    return "-" if x is None else f"{x:.3g}"


def lines(pairs, models, check):
    """The lines of regime.txt of one check."""
    c = CHECKS[check]
    out = [c["head"].format(z=Z_CONSISTENT)]
    for p in pairs:
        head = f"  {p['variant']} over {p['base']}"
        if "missing" in p:
            gone = p.get("dropped", [])
            left = [n for n in p["missing"] if n not in gone]
            why = ([f"{', '.join(left)} not finished"] if left else []) \
                + [f"{n} dropped" for n in gone]
            out.append(f"{head}: n/r ({'; '.join(why)})")
            continue
        for m in models:
            parts = []
            for q, name in NAMES.items():
                r = p[m][q]
                parts.append(
                    f"{name} n/r (no events or no sigma)" if not r else
                    f"{name} {r['ratio']:.2f} +- {r['sigma']:.2f} (z "
                    f"{r['z']:+.1f}: "
                    + ("consistent" if r["consistent"]
                       else c["differs"]) + ")")
            out.append(f"{head} {m}: " + "; ".join(parts))
        cv, cb = p["nearWallOverCentre"]
        out.append(f"{head}: c_w/c_0 at the start of agglomeration "
                   f"{_g(cv)} / {_g(cb)}")
        if check == "timeStep":
            out.append(f"{head}: " + adoption(p, models))
    return out


def adoption(p, models):
    """Whether the Table D.6 matrix may run at the variant's step: every
    quantity of both models resolved and consistent with the base."""
    r = [p[m][q] for m in models for q in NAMES]
    if any(x is None for x in r):
        return "the matrix's step: n/r (a quantity without events)"
    if all(x["consistent"] for x in r):
        return (f"the matrix may run at {p['variant']}'s step (every "
                f"quantity within {Z_CONSISTENT:g} sigma)")
    return (f"the matrix stays at {p['base']}'s step (not every quantity "
            f"within {Z_CONSISTENT:g} sigma)")
