"""shearFlowValidation: the paper's four statements about its shear-flow
validation (AB16 App. B, Figs. B.13, B.14), judged on an EAM and a MAM run
of the same set-up (doc/models.md 2.6):

    S1  alpha = N_agg/N_col close to alpha_th for both models
    S1b the MAM closer than the EAM (n/r within the counts' noise)
    S2  both models give almost the same number of agglomerations
    S3  the EAM has more collisions than the MAM
    S4  N_p/N_p0 follows the B.8 curve at first (the theory drops faster
        later: reported)

Each is PASS, FAIL or n/r (with the reason) against the tolerance stated
in its row; the tolerances are the paper's words made numbers, not fits.
"""

import math

import numpy as np

from aggloTools import regression as reg

#: S1: "close" as the factor-of-two band of the regression's alpha rows
S1_BAND = (0.5, 2.0)
#: S2: "almost the same", or the Poisson noise of equal counts if larger
S2_TOL = 0.15
#: S4: "follows", or the Poisson noise of the theory's loss if larger
S4_TOL = 0.10

IDS = ("S1", "S1b", "S2", "S3", "S4")


def _row(sid, check, value, tolerance, ok, nr=None):
    r = reg.row(ok, nr, statement=sid, check=check, value=value,
                tolerance=tolerance)
    return r


def first_half_loss(run, alpha_th):
    """The particles lost by half the run's duration, simulated and by
    the B.8 recursion (consistent form) driven by the run's own kernel."""
    h = int(np.searchsorted(run.tg, 0.5 * run.tg[-1]))
    h = min(h, len(run.tg) - 1)
    sim = run.np0 - run.np_after[h]
    th = run.np0 * (1 - run.decay(alpha_th, "consistent")[h])
    return float(sim), float(th), float(run.tg[h])


#: The duration the paper's statements describe (t gammaDot, App. B)
PAPER_END = 1400.0


def statements(runs, alpha_th, unresolved=None):
    """The rows of S1-S4 (and S4b, reported) for runs {"EAM": Run,
    "MAM": Run} (shearPost.Run); unresolved: the reason why this set-up
    cannot judge them (every row n/r with it)."""
    e, m = runs["EAM"], runs["MAM"]
    rows = []

    ae, am = e.alpha()[-1], m.alpha()[-1]
    re_, rm = ae / alpha_th, am / alpha_th
    lo, hi = S1_BAND
    rows.append(_row(
        "S1", "alpha/alpha_th (all contacts) of EAM and MAM in the band",
        f"{re_:.3g}, {rm:.3g}", f"{lo}-{hi}",
        bool(lo <= re_ <= hi and lo <= rm <= hi)))
    # MAM closer: the difference of the distances against the Poisson
    # noise of the two alphas (alpha/sqrt(N_agg) each)
    diff = abs(ae - alpha_th) - abs(am - alpha_th)
    sig = math.hypot(ae / math.sqrt(max(e.final("nAgg"), 1.0)),
                     am / math.sqrt(max(m.final("nAgg"), 1.0)))
    rows.append(_row(
        "S1b", "MAM closer to alpha_th: |alpha_EAM - alpha_th| - "
        "|alpha_MAM - alpha_th| >= 0 (in alpha_th)", diff / alpha_th,
        f">=0 (3 sigma = {3 * sig / alpha_th:.2g})", diff >= 0,
        f"the difference is within 3 sigma ({3 * sig / alpha_th:.2g} "
        "alpha_th) of the counts' noise" if abs(diff) < 3 * sig
        else None))

    ne, nm = e.final("nAgg"), m.final("nAgg")
    if ne + nm == 0:
        rows.append(_row("S2", "N_agg(EAM)/N_agg(MAM)", math.nan, "-",
                         None, "no agglomeration in either run"))
    else:
        # sigma of the ratio of two Poisson counts if both had the mean
        # of the two (the statement's hypothesis): 2/sqrt(N_EAM + N_MAM)
        ratio = ne / max(nm, 1.0)
        sig = 2 / math.sqrt(ne + nm)
        tol = max(S2_TOL, 3 * sig)
        rows.append(_row("S2", "N_agg(EAM)/N_agg(MAM) = 1 within the "
                         "larger of 15 % and 3 sigma (Poisson)", ratio,
                         f"{tol:.2g}", abs(ratio - 1) <= tol,
                         f"3 sigma = {3 * sig:.2f}: the band holds 0"
                         if tol >= 1 else None))

    ce, cm = e.final("nCol"), m.final("nCol")
    rows.append(_row("S3", "N_col(EAM)/N_col(MAM) > 1", ce / max(cm, 1.0),
                     ">1", ce > cm))

    oks, vals, tols = [], [], []
    for r in (e, m):
        sim, th, tg = first_half_loss(r, alpha_th)
        tol = max(S4_TOL * th, 3 * math.sqrt(max(th, 1.0)))
        oks.append(abs(sim - th) <= tol)
        vals.append(f"{sim:.0f}/{th:.0f}")
        tols.append(f"{tol:.0f}")
    rows.append(_row(
        "S4", f"N_p0 - N_p at half the run, simulated/B.8 (own K, "
        f"consistent), EAM, MAM; within the larger of 10 % and 3 sqrt",
        ", ".join(vals), ", ".join(tols), all(oks)))
    faster = [bool(r.decay(alpha_th, "consistent")[-1]
                   < r.np_after[-1] / r.np0) for r in (e, m)]
    rows.append(_row("S4b", "theory below the simulation at the end "
                     "(EAM, MAM)", ", ".join(map(str, faster)), "-",
                     None))
    if unresolved:
        for r in rows:
            if r["status"] != reg.INFO:
                r.update(status=reg.NR, reason=unresolved)
    return rows


def verdicts(rows):
    """{"S1": "PASS", ...} of the judged statements."""
    return {r["statement"]: r["status"] for r in rows
            if r["statement"] in IDS}
