"""verticalChannel regime study: does the flow of collisions scale with
the particle number as the s^2 scaling assumes? Each particle-number
variant (3 x 10^5 particles, s = 20) against its base at 10^5 (s = 60),
the same grid and phases.

The frequencies are compared scaled to the paper's number (f x s^2,
Eq. 87 over the window): where the collisions of a particle depend only
on the others' concentration, f_col grows as N^2 and f_col x s^2 is the
same at both numbers (ratio 1), and so is alpha_f. Per model and
quantity (f_col x s^2, f_agg x s^2, alpha_f): the ratio variant / base,
its standard error from both runs' sigmas (relative errors in
quadrature; alpha_f's from f_agg's and f_col's), and z = (ratio - 1) /
sigma. |z| <= Z_CONSISTENT: consistent with the s^2 scaling; beyond it
the quantity depends on the particle number, and the study's values
scaled by s^2 carry that dependence to the paper's 6 x 10^6."""

import math

import channelRegimeTrend as trend

#: The particle-number variants and their bases (one shortcut apart)
PAIRS = (("regime32n3", "regime32"), ("regime48n3", "regime48"))
#: The quantities compared, each with its sigma (key or function)
NAMES = {"f_col_scaled": "f_col x s^2", "f_agg_scaled": "f_agg x s^2",
         "alpha_f": "alpha_f"}
#: Largest |z| consistent with the s^2 scaling (two standard errors)
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
    s = r * math.hypot(sv / v, sb / b)
    z = (r - 1.0) / s
    return {"ratio": r, "sigma": s, "z": z,
            "consistent": abs(z) <= Z_CONSISTENT}


def particle_number(res, models):
    """Per pair of res (run_post's) whose variant and base both finished:
    {"variant", "base", model: {q: ratio(...)}}; the pairs not yet
    comparable as {"variant", "base", "missing": [names]}."""
    done = {v["name"]: v["result"] for v in res["variants"]
            if v["result"]}
    out = []
    for var, base in PAIRS:
        missing = [n for n in (var, base) if n not in done]
        if missing:
            out.append({"variant": var, "base": base, "missing": missing})
            continue
        row = {"variant": var, "base": base}
        for m in models:
            mv, mb = done[var]["models"][m], done[base]["models"][m]
            row[m] = {q: ratio(mv, mb, q) for q in NAMES}
        out.append(row)
    return out


def lines(pairs, models):
    """The lines of regime.txt."""
    out = ["Particle number (3e5 over 1e5 particles, the same grid and "
           "phases; the s^2 scaling holds where the ratio is 1 within "
           f"{Z_CONSISTENT:g} sigma):"]
    for p in pairs:
        head = f"  {p['variant']} over {p['base']}"
        if "missing" in p:
            out.append(f"{head}: n/r ({', '.join(p['missing'])} not "
                       "finished)")
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
                       else "depends on N") + ")")
            out.append(f"{head} {m}: " + "; ".join(parts))
    return out
