"""shearFlowValidation: the statements of the paper's Appendix B about its
shear-flow validation (AB16 App. B, Figs. B.13, B.14), each judged as the
paper words it on an EAM and a MAM run of the same set-up (doc/models.md
2.6):

    S1  "the theory ... slightly higher": alpha/alpha_th of both models in
        the declared band of "slightly" below 1
    S1d the direction of S1: both models below alpha_th
    S1b the MAM closer to alpha_th than the EAM
    S1c "the lower agglomeration rate predicted by EAM": alpha_EAM <
        alpha_MAM
    S2  both models give almost the same number of agglomerations
    S3  the EAM has more collisions than the MAM
    S4  "during the first stage both agglomeration models predict almost
        the same results and agree very well with the theory": N_p/N_p0
        of both against B.8 over the first stage, the time before the EAM
        and MAM curves part by more than their noise
    S4b "... the theoretical curve drops faster": afterwards, the theory
        below both simulations at the end
    S5  "the assumption of a constant agglomeration rate ... is not
        realistic": alpha over the second half of the run below alpha
        over the first half, both models
    S6  "setting d_p in the theoretical model equal to the mean diameter
        ... an excellent agreement with the momentum-based model": alpha_th
        at the final mean diameter D10 against the MAM's alpha over the
        last quarter of the run
    S7  "the MAM results are in better agreement with the theoretical
        model than the energy-based model" (Fig. B.14): the largest
        deviation of N_p/N_p0 from B.8, MAM below EAM
    S8  "[the curves] differ during the remaining time": N_p/N_p0 of EAM
        and MAM apart at the end

Each is PASS, FAIL or n/r (with the reason) against the tolerance stated
in its row; a direction is judged against 3 sigma of the counts' noise
(n/r within it); the bands are the paper's words made numbers, declared
below, not fits. The statements read the time series of a run (series():
shear.post.postprocess.Run.series, or series.json beside a summary.json).
"""

import json
import math

import numpy as np

from aggloTools import regression as reg
from shear.theory import alpha_th as alpha_theory

#: S1: "slightly" below alpha_th: the band of alpha/alpha_th
S1_BAND = (0.7, 1.0)
#: S2: "almost the same", or the Poisson noise of equal counts if larger
S2_TOL = 0.15
#: S4: "agree very well", or the Poisson noise of the theory's loss if
#: larger, at the end of the first stage
S4_TOL = 0.10
#: S6: "excellent agreement", or 3 sigma of the MAM's alpha if larger
S6_TOL = 0.10
#: The duration the paper's statements describe (t gammaDot, App. B)
PAPER_END = 1400.0

IDS = ("S1", "S1d", "S1b", "S1c", "S2", "S3", "S4", "S4b", "S5", "S6",
       "S7", "S8")


def _row(sid, check, value, tolerance, ok, nr=None):
    return reg.row(ok, nr, statement=sid, check=check, value=value,
                   tolerance=tolerance)


def _direction(sid, check, diff, sigma, value, tolerance=None):
    """A direction: PASS if diff > 3 sigma, FAIL if diff < -3 sigma, else
    n/r (within the noise)."""
    tol = tolerance or f">0 (3 sigma = {3 * sigma:.2g})"
    nr = (f"the difference is within 3 sigma ({3 * sigma:.2g}) of the "
          "counts' noise" if abs(diff) <= 3 * sigma else None)
    return _row(sid, check, value, tol, diff > 0, nr)


def _at(s, key, k):
    return float(np.asarray(s[key])[k])


def alpha_between(s, k0, k1):
    """alpha = dN_agg/dN_col between the samples k0 and k1, and its
    Poisson sigma (alpha/sqrt(dN_agg))."""
    dc = _at(s, "nCol", k1) - (_at(s, "nCol", k0) if k0 >= 0 else 0.0)
    da = _at(s, "nAgg", k1) - (_at(s, "nAgg", k0) if k0 >= 0 else 0.0)
    if dc <= 0:
        return math.nan, math.inf
    a = da / dc
    return a, (a / math.sqrt(da) if da > 0 else math.inf)


def first_stage_end(e, m):
    """The sample index where the EAM and MAM curves N_p(t) part: the
    first where |N_EAM - N_MAM| exceeds 3 sqrt of their summed losses
    (their Poisson noise); the last sample if they never part."""
    ne, nm = np.asarray(e["Np"], float), np.asarray(m["Np"], float)
    loss = (e["np0"] - ne) + (m["np0"] - nm)
    apart = np.abs(ne - nm) > 3 * np.sqrt(np.maximum(loss, 1.0))
    k = int(np.argmax(apart)) if apart.any() else len(ne) - 1
    return k


#: The reason of the rows that need a run's time series where a summary
#: holds only its final values (written before the series were kept)
NO_SERIES = ("the summary holds only the run's final values (written "
             "before the time series were kept): run the post-processing "
             "on the runs again")


def series_text(series):
    """The series of the runs {"EAM": s, "MAM": s} as the text of
    series.json: one line per run and quantity (the statements read them
    back with read_series)."""
    lines = []
    for run, s in series.items():
        items = [f'  "{k}": {json.dumps(np.asarray(v).tolist())}'
                 if hasattr(v, "__len__") else f'  "{k}": {json.dumps(v)}'
                 for k, v in s.items()]
        lines.append(f' "{run}": {{\n' + ",\n".join(items) + "\n }")
    return "{\n" + ",\n".join(lines) + "\n}\n"


def read_series(path):
    """The series of series.json ({} if there is none)."""
    if not path.is_file():
        return {}
    return {run: {k: (np.asarray(v) if isinstance(v, list) else v)
                  for k, v in s.items()}
            for run, s in json.loads(path.read_text()).items()}


def from_summary(info, np0):
    """The series of a run as far as a summary.json's run entry gives
    them (np0: the summary's N0): its final values only, a series of one
    sample marked partial (the statements that need the time series are
    then n/r)."""
    return {"partial": True, "np0": np0, "tg": np.array([info["tGamma_end"]]),
            "Np": np.array([info["Np_final_over_Np0"] * np0]),
            "nCol": np.array([info["N_col"]]),
            "nAgg": np.array([info["N_agg"]]),
            "D10": np.array([info["D10_final"]]),
            "theory": np.array([info["Np_theory_consistent_final"] * np0])}


def statements(series, alpha_th, unresolved=None, gamma_dot=None):
    """The rows of the statements for series {"EAM": s, "MAM": s} (dicts
    of shear.post.postprocess.Run.series, read_series or from_summary);
    unresolved: the reason why this set-up cannot judge them (every row
    n/r)."""
    e, m = series["EAM"], series["MAM"]
    rows = []
    last = len(e["tg"]) - 1
    ae, se = alpha_between(e, -1, last)
    am, sm = alpha_between(m, -1, last)
    re_, rm = ae / alpha_th, am / alpha_th
    sre, srm = se / alpha_th, sm / alpha_th

    lo, hi = S1_BAND
    rows.append(_row(
        "S1", "alpha/alpha_th (all contacts) of EAM and MAM in the band of"
        " 'slightly' below (widened by 3 sigma)", f"{re_:.3g}, {rm:.3g}",
        f"{lo}-{hi}", bool(lo - 3 * sre <= re_ <= hi + 3 * sre
                           and lo - 3 * srm <= rm <= hi + 3 * srm)))
    # S1d: both below: the one nearer to 1 decides
    worst = min((1 - re_) / sre if sre > 0 else math.inf,
                (1 - rm) / srm if srm > 0 else math.inf)
    rows.append(_row(
        "S1d", "both below alpha_th: (1 - alpha/alpha_th)/sigma of the "
        "nearer model > 3", f"{worst:.3g}", ">3", worst > 3,
        "within 3 sigma of alpha_th" if abs(worst) <= 3 else None))
    diff = abs(ae - alpha_th) - abs(am - alpha_th)
    rows.append(_direction(
        "S1b", "MAM closer to alpha_th: |alpha_EAM - alpha_th| - "
        "|alpha_MAM - alpha_th| (in alpha_th)", diff / alpha_th,
        math.hypot(se, sm) / alpha_th, diff / alpha_th))
    rows.append(_direction(
        "S1c", "EAM's rate lower: (alpha_MAM - alpha_EAM)/alpha_th",
        (am - ae) / alpha_th, math.hypot(se, sm) / alpha_th,
        (am - ae) / alpha_th))

    ne, nm = _at(e, "nAgg", last), _at(m, "nAgg", last)
    if ne + nm == 0:
        rows.append(_row("S2", "N_agg(EAM)/N_agg(MAM)", math.nan, "-",
                         None, "no agglomeration in either run"))
    else:
        ratio = ne / max(nm, 1.0)
        sig = 2 / math.sqrt(ne + nm)
        tol = max(S2_TOL, 3 * sig)
        rows.append(_row("S2", "N_agg(EAM)/N_agg(MAM) = 1 within the "
                         "larger of 15 % and 3 sigma (Poisson)", ratio,
                         f"{tol:.2g}", abs(ratio - 1) <= tol,
                         f"3 sigma = {3 * sig:.2f}: the band holds 0"
                         if tol >= 1 else None))
    ce, cm = _at(e, "nCol", last), _at(m, "nCol", last)
    rows.append(_row("S3", "N_col(EAM)/N_col(MAM) > 1", ce / max(cm, 1.0),
                     ">1", ce > cm))

    # S4: the first stage, judged at its end
    k = first_stage_end(e, m)
    oks, vals, tols = [], [], []
    for s in (e, m):
        sim = s["np0"] - _at(s, "Np", k)
        th = s["np0"] - _at(s, "theory", k)
        tol = max(S4_TOL * th, 3 * math.sqrt(max(th, 1.0)))
        oks.append(abs(sim - th) <= tol)
        vals.append(f"{sim:.0f}/{th:.0f}")
        tols.append(f"{tol:.0f}")
    rows.append(_row(
        "S4", f"first stage (until the EAM and MAM curves part by 3 sigma:"
        f" t*gammaDot {_at(e, 'tg', k):.4g}): N_p0 - N_p simulated/B.8 "
        "(own K, consistent), EAM, MAM, within the larger of 10 % and "
        "3 sqrt", ", ".join(vals), ", ".join(tols), all(oks)))
    # S4b: afterwards the theory drops faster: below both at the end
    gaps, sigs = [], []
    for s in (e, m):
        gaps.append(_at(s, "Np", last) - _at(s, "theory", last))
        sigs.append(math.sqrt(max(s["np0"] - _at(s, "theory", last), 1.0)))
    g = min(x / sg for x, sg in zip(gaps, sigs))
    rows.append(_row(
        "S4b", "theory below both simulations at the end: (N_sim - "
        "N_B.8)/sqrt(loss) of the nearer model > 3", f"{g:.3g}", ">3",
        g > 3, "within 3 sigma" if abs(g) <= 3 else None))

    # S5: alpha falls with time
    h = last // 2
    zs = []
    for s in (e, m):
        a1, s1 = alpha_between(s, -1, h)
        a2, s2 = alpha_between(s, h, last)
        zs.append((a1 - a2) / math.hypot(s1, s2)
                  if math.isfinite(s1) and math.isfinite(s2) else math.nan)
    z = min(zs)
    rows.append(_row(
        "S5", "alpha of the second half below that of the first: "
        "(alpha_1 - alpha_2)/sigma of the nearer model > 3",
        f"{zs[0]:.3g}, {zs[1]:.3g}", ">3", z > 3,
        "within 3 sigma" if not abs(z) > 3 else None))

    # S6: B.5 at the final mean diameter against the MAM's late alpha
    if gamma_dot is not None and "D10" in m:
        a_d10 = float(alpha_theory(_at(m, "D10", last), gamma_dot))
        a_late, s_late = alpha_between(m, (3 * last) // 4, last)
        tol = max(S6_TOL * a_d10, 3 * s_late)
        rows.append(_row(
            "S6", "alpha_th(D10 at the end) against the MAM's alpha over "
            "the last quarter, within the larger of 10 % and 3 sigma",
            f"{a_late:.4g}/{a_d10:.4g}", f"{tol:.2g}",
            abs(a_late - a_d10) <= tol))

    # S7: MAM closer to B.8 than EAM (largest deviation over the run)
    devs, noise = [], []
    for s in (e, m):
        np_ = np.asarray(s["Np"], float)
        th = np.asarray(s["theory"], float)
        dev = np.abs(np_ - th) / s["np0"]
        j = int(np.argmax(dev))
        devs.append(float(dev[j]))
        noise.append(math.sqrt(max(s["np0"] - th[j], 1.0)) / s["np0"])
    rows.append(_direction(
        "S7", "MAM closer to B.8: max|N_p - N_B.8|/N_p0 of EAM minus "
        "MAM's", devs[0] - devs[1], math.hypot(*noise),
        devs[0] - devs[1]))

    # S8: the curves differ at the end
    d_end = abs(_at(e, "Np", last) - _at(m, "Np", last))
    sig = math.sqrt(max((e["np0"] - _at(e, "Np", last))
                        + (m["np0"] - _at(m, "Np", last)), 1.0))
    rows.append(_row(
        "S8", "EAM and MAM apart at the end: |N_EAM - N_MAM|/sigma > 3",
        d_end / sig, ">3", d_end > 3 * sig))

    if e.get("partial") or m.get("partial"):
        for r in rows:
            if r["statement"] in ("S4", "S5", "S6", "S7"):
                r.update(status=reg.NR, reason=NO_SERIES)
    if unresolved:
        for r in rows:
            if r["status"] != reg.INFO:
                r.update(status=reg.NR, reason=unresolved)
    return rows


def verdicts(rows):
    """{"S1": "PASS", ...} of the judged statements."""
    return {r["statement"]: r["status"] for r in rows
            if r["statement"] in IDS}
