"""verticalChannel regime study: the report of the variants' results
(channelRegimeAnalysis) in words, regime.txt: one row per variant and
model, the trend, the variants one shortcut apart (particle number,
phase lengths), the verdict and the interims
(the figure: channelRegimePlots)."""

from channel.regime import pairs
from channel.regime import trend
from channel.regime import verdict
from channel.post.concentration import START_SPAN
from channel.regime.analysis import MODELS, PAPER, variant_history


def _g(v, fmt=".3g"):
    return "-" if v is None else format(v, fmt)


def table(res):
    """regime.txt: one row per variant and model."""
    lines = [
        "verticalChannel regime study, C1 (EAM and MAM clouds of one LES):"
        " one shortcut of `small` changed per variant (README.md, 'The"
        " regime study').",
        f"paper (Table 3/D.6): f_col x s^2 {PAPER['f_col_scaled']['EAM']:.3g}"
        f" / {PAPER['f_col_scaled']['MAM']:.3g}, alpha_f "
        f"{PAPER['f_agg_scaled']['EAM'] / PAPER['f_col_scaled']['EAM']:.3g}"
        f" / {PAPER['f_agg_scaled']['MAM'] / PAPER['f_col_scaled']['MAM']:.3g}"
        f" (EAM / MAM), u_tau/U_B {PAPER['u_tau_over_U_B']}", "",
        f"{'variant':14s} {'model':5s} {'fcol*s2':>9s} {'+-':>7s} "
        f"{'x paper':>7s} {'fagg*s2':>8s} {'alpha_f':>8s} {'x paper':>7s} "
        f"{'alpha_end':>9s} {'first/rep':>10s} {'|un| med':>8s} "
        f"{'y/d med':>7s} {'wall/N/T*':>9s} {'c_w/c_0':>7s} "
        f"{'u_tau/U_B':>9s} {'wall h':>6s} {'cpu h':>6s}"]
    for v in res["variants"]:
        r = v["result"]
        if r is None:
            lines.append(f"{v['name']:14s} " + _where(v))
            continue
        c = r["concentration"] or {}
        for m in MODELS:
            x = r["models"][m]
            ct = x["contacts"] or {}
            med = (lambda q: q[2] if q else None)
            lines.append(
                f"{v['name']:14s} {m:5s} {x['f_col_scaled']:9.4g} "
                f"{x['sigma_col_scaled']:7.3g} "
                f"{_g(x['colFactorToPaper']):>7s} "
                f"{x['f_agg_scaled']:8.4g} {_g(x['alpha_f']):>8s} "
                f"{_g(x['alphaFactorToPaper']):>7s} "
                f"{_g(x['alpha_end_of_phase']):>9s} "
                f"{int(x['nColFirst_end']):>5d}/{int(x['nColRepeat_end']):<4d}"
                f" {_g(med(ct.get('un_mm_s'))):>8s} "
                f"{_g(med(ct.get('wallDistance_delta'))):>7s} "
                f"{_g(x['wallImpacts_per_particle_T']):>9s} "
                f"{_g(c.get('nearWallOverCentre')):>7s} "
                f"{_g(r['u_tau_over_U_B']['agglomeration'], '.4f'):>9s} "
                f"{r['times']['wallTotal_s'] / 3600:6.2f} "
                f"{r['times']['cpu_s'] / 3600:6.2f}")
    kept = [v for v in res["variants"] if v.get("from")]
    if kept:
        lines += ["", "Kept from " + kept[0]["from"] + " (their runs are "
                  "not under --runs; the numbers as measured then): "
                  + ", ".join(v["name"] for v in kept) + "."]
    lines += ["", "fcol*s2, fagg*s2: Eq. 87 over the window, scaled by "
              "(6e6/N)^2; +-: sigma (batch means or Poisson); x paper: "
              "sim/paper; alpha_end: N_agg/N_col at the window's end; "
              "first/rep: first and repeat contacts by then; |un| med: "
              "median normal approach speed at contact (mm/s), y/d med: "
              "median wall distance of the contacts (in delta), both over"
              " the window's contacts of the event log; wall/N/T*: wall "
              "impacts per particle and T*; c_w/c_0: particle volume "
              "fraction next to the walls over the centre's at the start "
              "of the agglomeration phase (over the dispersion's last "
              f"{START_SPAN:g} T*, from the release where shorter); wall "
              "h, cpu h: the C1 stages' "
              "wall-clock and CPU hours (all ranks; the solver's, every "
              "resumed segment counted)."]
    if "gridTrend" in res:
        lines += [""] + trend.lines(res["gridTrend"], MODELS)
    if res.get("gridTrendFinestPair"):
        lines += [""] + trend.lines(res["gridTrendFinestPair"], MODELS,
                                    finest=True)
    for check in pairs.CHECKS:
        if check in res:
            lines += [""] + pairs.lines(res[check], MODELS, check)
    if "verdict" in res:
        lines += [""] + verdict.lines(res["verdict"], MODELS)
    lines += _wall_bin_lines(res)
    lines += _history_lines(res)
    lines += _agglomeration_lines(res)
    return "\n".join(lines) + "\n"


def _where(v):
    """How far a variant without results stands (and why it stops there,
    if the study dropped it)."""
    g = v.get("progress")
    if not g:
        state = f"not run in {v['runs']}"
    else:
        parts = []
        for folder, x in g["stages"].items():
            at = x["lastWrite_Tstar"]
            parts.append(f"{folder} at T* {_g(at, '.0f')} of "
                         f"{x['end_Tstar']:.0f}"
                         + (f" ({', '.join(x['done'])} done)" if x["done"]
                            else ""))
        state = ("not finished: " + "; ".join(parts)
                 + (" (interim below)" if g["history"] else ""))
    return f"dropped, {state}; {v['dropped']}" if v.get("dropped") \
        else state


def _history_lines(res, gap=40.0):
    """The release and dispersion stages between writes, per variant:
    intervals at least `gap` T* apart (all of them in regime.json)."""
    out = ["", "Release and dispersion between writes (T* from the start;"
           f" intervals at least {gap:g} T* apart, all in regime.json): "
           "c_w/c_0 of the steps between the two writes; collisions (they"
           " rebound there: not the window's f_col) per T* x s^2 and wall "
           "impacts per particle and T* over the interval.",
           f"{'variant':14s} {'T* from':>8s} {'to':>6s} {'c_w/c_0':>8s} "
           f"{'col*s2':>8s} {'wall/N/T*':>9s}"]
    for v in res["variants"]:
        last = None
        h = variant_history(v)
        for k, x in enumerate(h):
            if last is not None and x["T1"] - last < gap \
                    and k < len(h) - 1:
                continue
            last = x["T1"]
            out.append(
                f"{v['name']:14s} {x['T0']:8.4g} {x['T1']:6.4g} "
                f"{_g(x['nearWallOverCentre']):>8s} "
                f"{_g(x.get('fColScaled'), '.4g'):>8s} "
                f"{_g(x.get('wallImpacts_per_particle_T')):>9s}")
    return out


def _wall_bin_lines(res):
    """The finished variants' contacts of the window per bin of wall
    distance: contacts / agglomerating (alpha of the bin), median |u_n|."""
    rows = [(v["name"], m, (v["result"]["models"][m]["contacts"] or {})
             .get("byWallDistance")) for v in res["variants"]
            if v["result"] for m in MODELS]
    rows = [r for r in rows if r[2]]
    if not rows:
        return []
    e = rows[0][2]["edges"]
    out = ["", "Contacts of the window by wall distance y/delta (bins "
           + ", ".join(f"{a:g}-{b:g}" for a, b in zip(e[:-1], e[1:]))
           + "): contacts/agglomerating (their ratio) median |u_n| "
           "mm/s"]
    for name, m, b in rows:
        out.append(f"{name:14s} {m:5s} " + "; ".join(
            f"{n}/{na} ({_g(a, '.2g')}) {_g(u, '.2g')}" if n else "0"
            for n, na, a, u in zip(b["n"], b["nAgg"], b["alpha"],
                                   b["unMedian_mm_s"])))
    return out


def _agglomeration_lines(res):
    """The unfinished variants' agglomeration stages so far, after the
    concentration at their start where the dispersion is done."""
    going = [v for v in res["variants"]
             if not v["result"] and v.get("progress")]
    starts = [(v["name"], v["progress"]["concentration"]) for v in going
              if v["progress"].get("concentration")]
    rows = [(v["name"], m, x) for v in going
            for m, x in (v["progress"].get("agglomeration") or {}).items()]
    if not rows and not starts:
        return []
    out = ["", "Agglomeration stages so far (unfinished variants, to their"
           " last complete write; Eq. 87 over the part of the window run"
           " by then, sigma as for a window: an interim, not the "
           "window's result):"]
    for name, c in starts:
        out.append(f"{name:14s} c_w/c_0 at the start of agglomeration "
                   f"(the dispersion done): {_g(c['nearWallOverCentre'])}")
    for name, m, x in rows:
        line = (f"{name:14s} {m:5s} T*agg {x['TstarAgg']:.0f}: N_col "
                f"{x['nCol']:.0f}, N_agg {x['nAgg']:.0f}, alpha "
                f"{_g(x['alpha'])}")
        if "window" in x:
            line += (
                f"; window {x['window'][0]:g}-{x['window'][1]:.0f}: "
                f"f_col x s^2 {x['f_col_scaled']:.4g} +- "
                f"{x['sigma_col_scaled']:.3g} (x paper "
                f"{_g(x['colFactorToPaper'])}), f_agg x s^2 "
                f"{x['f_agg_scaled']:.4g}, alpha_f {_g(x['alpha_f'])} "
                f"(x paper {_g(x['alphaFactorToPaper'])})")
        out.append(line)
    return out
