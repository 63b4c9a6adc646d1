"""verticalChannel: the paper's comparisons judged (README.md,
"Regression"). At the preset for comparisons with the paper (PAPER_REGIME)
the absolute rows are judged against a factor 2 of Table D.6 and each
ratio of doc/cases.md A.9 is judged where its sigma is below a third of
the effect the paper reports (|paper - 1|), n/r with the reason where it
is not. At every preset, the paper's qualitative conclusions (Sec. 5,
Table 4) are statement rows, each judged with its sigma: PASS where the
stated direction holds beyond 3 sigma, FAIL where the opposite does, n/r
where the difference is within 3 sigma.

    rows += statements(res, R)      # res[(config, model)]: the runs
"""

import math

from aggloTools import regression as reg
from aggloTools.uncertainty import ratio

#: The preset for comparisons with the paper (README.md, "Presets")
PAPER_REGIME = "regime64"
#: Absolute rows at PAPER_REGIME: within this factor of the paper
FACTOR = 2.0
#: ... judged only where sigma is at most this share of the value
MAX_REL_SIGMA = 0.5
#: Ratio rows at PAPER_REGIME: judged where sigma < effect / EFFECT_SIGMAS
EFFECT_SIGMAS = 3.0
#: A direction holds where it is beyond this many sigma
DIRECTION_SIGMAS = 3.0

#: The paper's conclusions: the words, and the parts that must all hold
#: (numerator, denominator, quantity col/agg/alpha, sign of ratio - 1);
#: a part with model None compares the models' ratios (MAM over EAM)
STATEMENTS = (
    ("the three sub-models lower alpha markedly (AB16 Sec. 5.1)",
     (("C2", "C1", "alpha", -1),)),
    ("rough walls reduce f_col and slightly raise f_agg (Sec. 5.3)",
     (("C3", "C2", "col", -1), ("C3", "C2", "agg", 1))),
    ("4 um particles: a higher alpha, a lower f_agg (Sec. 5.4)",
     (("C4", "C2", "alpha", 1), ("C4", "C2", "agg", -1))),
    ("a lower e_n,p gives more collisions and agglomerations (Sec. 5.2)",
     (("R80", "C1", "col", 1), ("R80", "C1", "agg", 1),
      ("R60", "C1", "col", 1), ("R60", "C1", "agg", 1))),
)
#: ... and the one across the models: MAM gains more agglomerations than
#: EAM from a lower e_n,p (Table 4)
MODEL_GAIN = ("MAM gains more agglomerations than EAM from a lower e_n,p"
              " (Table 4)", ("R80", "R60"))


def frequency_ratio(ra, rb, q):
    """The ratio of the frequencies f_q (col, agg) of two runs scaled to
    the paper's particles (each run's s^2: a configuration may release its
    own number) and its sigma; (None, None) without events. Runs of one
    particle number: the ratio of their frequencies as they are."""
    r, s = ratio(ra[f"f_{q}"], ra[f"sigma_{q}"], rb[f"f_{q}"],
                 rb[f"sigma_{q}"])
    if r is None:
        return r, s
    k = ra["scale"] / rb["scale"]
    return r * k, s * k


def quantity_ratio(ra, rb, q):
    """The ratio of q (col, agg: the frequencies scaled to the paper's
    particles; alpha: alpha_f) of two runs and its sigma (relative errors
    in quadrature); (None, None) without events."""
    if q != "alpha":
        return frequency_ratio(ra, rb, q)
    qs = ("col", "agg")
    if any(ra[f"f_{x}"] <= 0 or rb[f"f_{x}"] <= 0 for x in qs):
        return None, None
    r = ra["alpha_f"] / rb["alpha_f"]
    rel = math.sqrt(sum((ra[f"sigma_{x}"] / ra[f"f_{x}"])**2
                        + (rb[f"sigma_{x}"] / rb[f"f_{x}"])**2 for x in qs))
    return r, r * rel


def direction_status(r, s, sign):
    """PASS / FAIL / n/r of 'r - 1 has the sign `sign`' and the note."""
    if r is None:
        return reg.NR, "no events in the window"
    if abs(r - 1) <= DIRECTION_SIGMAS * s:
        return reg.NR, f"difference within {DIRECTION_SIGMAS:g} sigma"
    ok = (r - 1) * sign > 0
    return reg.status(ok), "must be " + ("> 1" if sign > 0 else "< 1")


def factor_row(R, name, sim, sig, ref, note):
    """An absolute row at PAPER_REGIME: PASS within a factor FACTOR of the
    paper, FAIL beyond; n/r without events or where sigma exceeds
    MAX_REL_SIGMA of the value (too few events to judge a factor)."""
    if not sim or sim <= 0:
        return R(name, sim, sig, ref, None, reg.NR,
                 note or "no events in the window")
    if sig is not None and sig > MAX_REL_SIGMA * sim:
        return R(name, sim, sig, ref, FACTOR, reg.NR,
                 f"sigma {sig / sim:.0%} of the value: too few events to"
                 f" judge a factor {FACTOR:g}")
    factor = max(sim / ref, ref / sim)
    return R(name, sim, sig, ref, FACTOR, reg.status(factor <= FACTOR),
             f"within a factor {FACTOR:g} of the paper" + (
                 f"; {note}" if note else ""))


def ratio_row(R, name, sim, sig, ref, rel_tol):
    """A ratio row at PAPER_REGIME: judged where sigma is below the
    paper's effect |ref - 1| over EFFECT_SIGMAS (PASS where |sim - ref|
    <= max(3 sigma, rel_tol ref)), n/r with the reason where it is not."""
    if sim is None:
        return R(name, None, None, ref, None, reg.NR,
                 "no events in the window")
    effect = abs(ref - 1)
    if not sig < effect / EFFECT_SIGMAS:
        return R(name, sim, sig, ref, None, reg.NR,
                 f"sigma {sig:.3g} not below a third of the paper's effect"
                 f" {effect:.3g}")
    tol = max(3 * sig, rel_tol * ref)
    return R(name, sim, sig, ref, tol, reg.status(abs(sim - ref) <= tol),
             "")


def statements(res, R, models=("EAM", "MAM")):
    """The statement rows of the runs res[(config, model)], one per part
    and model (and the models' gain); a part whose runs are missing is
    left out."""
    rows = []
    for words, parts in STATEMENTS:
        for a, b, q, sign in parts:
            for m in models:
                ra, rb = res.get((a, m)), res.get((b, m))
                if not (ra and rb):
                    continue
                r, s = quantity_ratio(ra, rb, q)
                status, note = direction_status(r, s, sign)
                name = "alpha_f" if q == "alpha" else f"f_{q}"
                rows.append(R(f"statement {m} {name} {a}/{b}", r, s, None,
                              None if s is None else DIRECTION_SIGMAS * s,
                              status, f"{words}: {note}"))
    words, configs = MODEL_GAIN
    for c in configs:
        runs = [res.get((c, m)) for m in models] + \
            [res.get(("C1", m)) for m in models]
        if not all(runs):
            continue
        (re_, rm, be, bm) = runs
        ge, se = quantity_ratio(re_, be, "agg")
        gm, sm = quantity_ratio(rm, bm, "agg")
        if ge is None or gm is None:
            r = s = None
        else:
            r = gm / ge
            s = r * math.hypot(se / ge, sm / gm)
        status, note = direction_status(r, s, 1)
        rows.append(R(f"statement f_agg {c}/C1, MAM over EAM", r, s, None,
                      None if s is None else DIRECTION_SIGMAS * s, status,
                      f"{words}: {note}"))
    return rows
