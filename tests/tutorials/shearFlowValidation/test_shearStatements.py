"""The statements of App. B (shear.post.statements), each a row that can fail:
on a constructed pair of runs that the paper's words describe (EAM and
MAM slightly below alpha_th, the EAM lower, alpha falling with time, the
theory following both at first and dropping faster later, ...) every row
passes; one edit per statement, the physics the words deny, makes its row
and no other fail. The series are built here, step by step, as
shear.post.postprocess.Run.series writes them."""

import math

import numpy as np
import pytest

from aggloTools import regression as reg
from aggloTools.runner import tutorial_module

st = tutorial_module("shearFlowValidation", "shear.post.statements")
theory = tutorial_module("shearFlowValidation", "shear.theory")

A_TH, GAMMA, NP0, STEPS = 0.034, 71.0, 100000, 1000


def d10_for(alpha):
    """The diameter whose alpha_th (B.5) is alpha (bisection)."""
    lo, hi = 1e-6, 1e-3
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if theory.alpha_th(mid, GAMMA) > alpha:
            lo = mid
        else:
            hi = mid
    return mid


def run(a_early, a_late, n_col=1e6, a_theory=0.031, d10=None):
    """A run's series: n_col collisions at a constant rate, alpha a_early
    over the first half and a_late over the second, the B.8 curve losing
    a_theory per collision, D10 (default: alpha_th(D10) = a_late)."""
    tg = np.linspace(1.4, 1400, STEPS)
    dcol = np.full(STEPS, n_col / STEPS)
    a = np.where(np.arange(STEPS) < STEPS // 2, a_early, a_late)
    ncol = np.cumsum(dcol)
    nagg = np.round(np.cumsum(a * dcol))
    return {"np0": NP0, "tg": tg, "Np": NP0 - nagg, "nCol": ncol,
            "nAgg": nagg, "nColFirst": 0.05 * ncol,
            "D10": np.full(STEPS, d10 or d10_for(a_late)),
            "theory": NP0 - a_theory * ncol}


def paper_like():
    return {"EAM": run(0.030, 0.020, 1.05e6),
            "MAM": run(0.032, 0.026)}


def status(rows):
    return {r["statement"]: r["status"] for r in rows}


def test_every_statement_holds_on_the_paper_like_pair():
    s = status(st.statements(paper_like(), A_TH, gamma_dot=GAMMA))
    assert set(s) == set(st.IDS)
    assert all(v == reg.PASS for v in s.values()), s


def _edit(name):
    r = paper_like()
    if name == "S1":        # the EAM far below alpha_th
        r["EAM"] = run(0.015, 0.010, 1.05e6)
    elif name == "S1d":     # the MAM above alpha_th
        r["MAM"] = run(0.040, 0.036)
    elif name == "S1b":     # the MAM farther from alpha_th than the EAM
        r["MAM"] = run(0.020, 0.016)
    elif name == "S1c":     # the EAM's rate the higher
        r["EAM"] = run(0.034, 0.029, 1.05e6)
    elif name == "S2":      # twice the agglomerations
        r["EAM"] = run(0.060, 0.040, 1.05e6)
    elif name == "S3":      # fewer EAM collisions
        r["EAM"] = run(0.030, 0.020, 0.9e6)
    elif name == "S4":      # the theory twice as fast from the start
        r["EAM"]["theory"] = NP0 - 0.062 * r["EAM"]["nCol"]
    elif name == "S4b":     # the theory above both at the end
        for m in r:
            r[m]["theory"] = NP0 - 0.018 * r[m]["nCol"]
    elif name == "S5":      # alpha rising
        r["MAM"] = run(0.026, 0.032, d10=d10_for(0.032))
    elif name == "S6":      # the mean diameter's alpha_th far off
        r["MAM"]["D10"] = np.full(STEPS, d10_for(0.013))
    elif name == "S7":      # the MAM farther from B.8
        r["MAM"]["theory"] = NP0 - 0.040 * r["MAM"]["nCol"]
        r["EAM"]["theory"] = NP0 - 0.027 * r["EAM"]["nCol"]
    elif name == "S8":      # the curves the same at the end (both lose
        r["MAM"] = run(0.0305, 0.022)   # 26,250 particles)
    return r


@pytest.mark.parametrize("name", st.IDS)
def test_each_statement_can_fail(name):
    """The edit of a statement makes its row FAIL (others its physics
    also moves may fail with it: twice the agglomerations are no longer
    'slightly' below alpha_th either)."""
    s = status(st.statements(_edit(name), A_TH, gamma_dot=GAMMA))
    assert s[name] == reg.FAIL, s


def test_unresolved_set_up_is_nr_not_judged():
    rows = st.statements(paper_like(), A_TH, "a short preset",
                         gamma_dot=GAMMA)
    assert {r["status"] for r in rows} == {reg.NR}
    assert all(r["reason"] == "a short preset" for r in rows)


def test_first_stage_ends_where_the_curves_part():
    """The EAM and MAM curves part where |N_EAM - N_MAM| first exceeds
    3 sqrt of their summed losses. Per step (1,050 and 1,000 collisions)
    they lose 31.5 and 32 particles over the first half, 0.5 apart,
    which never parts them there (0.5 k > 3 sqrt(63.5 k) needs k > 2,286);
    in the second half (21 and 26) they are 250 + 5 j apart after j more
    steps, with 31,750 + 47 j lost: apart from j = 62, sample 561."""
    r = paper_like()
    k = st.first_stage_end(r["EAM"], r["MAM"])
    assert 559 <= k <= 563, k
