"""verticalChannel regime study: the report of the variants' results
(channelRegimeAnalysis): regime.txt, one row per variant and model, and
regime.png."""

import numpy as np

import channelRegimeNumber as number
import channelRegimeTrend as trend
import channelRegimeVerdict as verdict
from channelRegimeAnalysis import MODELS, PAPER, QUANTILES


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
    lines += ["", "fcol*s2, fagg*s2: Eq. 87 over the window, scaled by "
              "(6e6/N)^2; +-: sigma (batch means or Poisson); x paper: "
              "sim/paper; alpha_end: N_agg/N_col at the window's end; "
              "first/rep: first and repeat contacts by then; |un| med: "
              "median normal approach speed at contact (mm/s), y/d med: "
              "median wall distance of the contacts (in delta), both over"
              " the window's contacts of the event log; wall/N/T*: wall "
              "impacts per particle and T*; c_w/c_0: particle volume "
              "fraction next to the walls over the centre's at the start "
              "of the agglomeration phase; wall h, cpu h: the C1 stages' "
              "wall-clock and CPU hours (all ranks; the solver's, every "
              "resumed segment counted)."]
    if "gridTrend" in res:
        lines += [""] + trend.lines(res["gridTrend"], MODELS)
    if res.get("gridTrendFinestPair"):
        lines += [""] + trend.lines(res["gridTrendFinestPair"], MODELS,
                                    finest=True)
    if "particleNumber" in res:
        lines += [""] + number.lines(res["particleNumber"], MODELS)
    if "verdict" in res:
        lines += [""] + verdict.lines(res["verdict"], MODELS)
    lines += _wall_bin_lines(res)
    lines += _history_lines(res)
    lines += _agglomeration_lines(res)
    return "\n".join(lines) + "\n"


def _history(v):
    """A variant's release and dispersion history (finished or not)."""
    if v["result"]:
        return v["result"].get("concentrationHistory") or []
    return (v.get("progress") or {}).get("history") or []


def _where(v):
    """How far a variant without results stands."""
    g = v.get("progress")
    if not g:
        return f"not run in {v['runs']}"
    parts = []
    for folder, x in g["stages"].items():
        at = x["lastWrite_Tstar"]
        parts.append(f"{folder} at T* {_g(at, '.0f')} of "
                     f"{x['end_Tstar']:.0f}"
                     + (f" ({', '.join(x['done'])} done)" if x["done"]
                        else ""))
    return ("not finished: " + "; ".join(parts)
            + (" (interim below)" if g["history"] else ""))


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
        h = _history(v)
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
    """The unfinished variants' agglomeration stages so far."""
    rows = [(v["name"], m, x) for v in res["variants"]
            if not v["result"] and v.get("progress")
            for m, x in (v["progress"].get("agglomeration") or {}).items()]
    if not rows:
        return []
    out = ["", "Agglomeration stages so far (unfinished variants, to their"
           " last complete write; Eq. 87 over the part of the window run"
           " by then, sigma as for a window: an interim, not the "
           "window's result):"]
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


def plots(res, out):
    """regime.png: f_col x s^2 and alpha_f of the finished variants, the
    concentration profile at the start of agglomeration; over the
    release and dispersion stages of every variant that has them (dashed:
    not finished) the near-wall peak, the collision rate and the wall
    impacts between writes; the distributions of |u_n| and of the wall
    distance at contact, and the grid trend against the paper."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [v for v in res["variants"] if v["result"]]
    grown = [v for v in res["variants"] if _history(v)]
    if not done and not grown:
        return
    fig, axs = plt.subplots(3, 3, figsize=(15, 12.6))
    ax = axs.ravel()
    xs = np.arange(len(done))
    for k, m in enumerate(MODELS):
        f = [v["result"]["models"][m]["f_col_scaled"] for v in done]
        s = [v["result"]["models"][m]["sigma_col_scaled"] for v in done]
        a = [v["result"]["models"][m]["alpha_f"] or np.nan for v in done]
        ax[0].errorbar(xs + 0.1 * k, f, s, fmt="o", label=m)
        ax[1].plot(xs + 0.1 * k, a, "o", label=m)
        ax[0].axhline(PAPER["f_col_scaled"][m], ls="--", color=f"C{k}",
                      lw=0.8, label=f"paper {m}")
        ax[1].axhline(PAPER["f_agg_scaled"][m] / PAPER["f_col_scaled"][m],
                      ls="--", color=f"C{k}", lw=0.8, label=f"paper {m}")
    for a_ in ax[:2]:
        a_.set_xlim(-0.5, max(len(done), 1) - 0.5)
        a_.set_xticks(xs)
        a_.set_xticklabels([v["name"] for v in done], rotation=30,
                           fontsize=8)
        a_.set_yscale("log")
        a_.legend(fontsize=7)
    ax[0].set_ylabel(r"$f_{col}\,s^2$ over the window [1/T*]")
    ax[1].set_ylabel(r"$\alpha_f = f_{agg}/f_{col}$ [-]")
    for v in done:
        c = v["result"]["concentration"]
        if c:
            ax[2].plot(np.asarray(c["y"]) / 0.02, c["alpha"], label=v["name"])
    ax[2].set_xlabel(r"wall-normal position $y/\delta$ [-]")
    ax[2].set_ylabel("particle volume fraction [-]")
    ax[2].set_title("at the start of agglomeration", fontsize=9)
    if not done:
        for a_ in ax[:3]:
            a_.text(0.5, 0.5, "no variant has finished yet",
                    transform=a_.transAxes, ha="center", va="center",
                    color="0.4")
    for k, (key, label) in enumerate((
            ("nearWallOverCentre", "near-wall / centre volume fraction [-]"),
            ("fColScaled", r"collisions per T* $\times s^2$ [1/T*]"),
            ("wallImpacts_per_particle_T",
             "wall impacts per particle and T* [-]"))):
        a_ = ax[3 + k]
        for j, v in enumerate(grown):
            h = [x for x in _history(v) if x.get(key) is not None]
            if h:
                a_.step([x["T1"] for x in h], [x[key] for x in h],
                        where="pre", color=f"C{j}", marker=".",
                        ls="-" if v["result"] else "--",
                        label=v["name"] + ("" if v["result"]
                                           else " (running)"))
        a_.set_xlabel(r"$T^*$ (release and dispersion) [-]")
        a_.set_ylabel(label)
        a_.set_title("between writes", fontsize=9)
    ax[3].axhline(1, color="0.6", lw=0.8)
    for k, m in enumerate(MODELS):
        ax[4].axhline(PAPER["f_col_scaled"][m], ls=":", color="0.4",
                      lw=0.8, label=None if k else
                      "paper C1, window (EAM, MAM)")
    ax[4].set_yscale("log")
    for a_, key, label in (
            (ax[6], "un_mm_s", r"normal approach speed $|u_n|$ [mm/s]"),
            (ax[7], "wallDistance_delta",
             r"wall distance at contact $y/\delta$ [-]")):
        _contact_panel(a_, done, key, label)
    _trend_panel(ax[8], res)
    for a_ in ax[2:]:
        if a_.get_legend_handles_labels()[0]:
            a_.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "regime.png", dpi=110)
    plt.close(fig)


def _contact_panel(ax, done, key, label):
    """The window's contacts of each finished variant and model: 10-90 %
    (thin) and 25-75 % (thick) of a distribution and its median, all
    contacts (filled) and the agglomerating ones (open)."""
    q = [QUANTILES.index(x) for x in (0.1, 0.25, 0.5, 0.75, 0.9)]
    for i, v in enumerate(done):
        for k, m in enumerate(MODELS):
            ct = v["result"]["models"][m]["contacts"] or {}
            for j, (suffix, what) in enumerate((("", "all"),
                                                ("_agg", "agglomerating"))):
                d = ct.get(key + suffix)
                if not d:
                    continue
                x = i + 0.15 * (2 * k + j) - 0.225
                ax.plot([x, x], [d[q[0]], d[q[4]]], color=f"C{k}", lw=0.8)
                ax.plot([x, x], [d[q[1]], d[q[3]]], color=f"C{k}", lw=3)
                ax.plot(x, d[q[2]], "o", color=f"C{k}",
                        mfc="white" if j else f"C{k}",
                        label=f"{m}, {what}" if i == 0 else None)
    ax.set_xticks(range(len(done)))
    ax.set_xticklabels([v["name"] for v in done], rotation=30, fontsize=8)
    ax.set_xlim(-0.5, max(len(done), 1) - 0.5)
    ax.set_yscale("log")
    ax.set_ylabel(label)
    ax.set_title("contacts in the window: 10/25/50/75/90 %", fontsize=9)


def _law(ax, f, n0, color, ls, lw):
    """A fitted power law over the paper's value from n0 to 128 cells."""
    n = np.geomspace(n0, trend.N_PAPER_GRID, 30)
    ax.plot(n, f["value"] / f["paper"] * (n / trend.N_PAPER_GRID)**f["b"],
            color=color, ls=ls, lw=lw)


def _trend_panel(ax, res):
    """f_col x s^2 and alpha_f over the paper's, per model, of the grid
    variants at the paper's phases, with the fitted power laws to 128^3
    and their 68 % bands there, dotted the finest two grids' laws (with
    three grids); shaded: within the verdict's factor."""
    done = {v["name"]: v["result"] for v in res["variants"] if v["result"]}
    fits = res.get("gridTrend") or {}
    pair = res.get("gridTrendFinestPair") or {}
    for k, m in enumerate(MODELS):
        for q, key, mk, name in (
                ("f_col_scaled", "colFactorToPaper", "o", r"$f_{col}s^2$"),
                ("alpha_f", "alphaFactorToPaper", "s", r"$\alpha_f$")):
            pts = [(n, done[v]["models"][m][key])
                   for v, n in trend.GRID_VARIANTS
                   if v in done and done[v]["models"][m][key]]
            if pts:
                ax.plot(*zip(*pts), mk, color=f"C{k}", label=f"{m} {name}")
            f = fits.get(m, {}).get(q)
            if f:
                _law(ax, f, 32, f"C{k}",
                     "-" if q == "f_col_scaled" else "--", 0.8)
                ax.errorbar(trend.N_PAPER_GRID * (1.02 + 0.02 * k),
                            f["factorToPaper"],
                            [[f["factorToPaper"] - f["low"] / f["paper"]],
                             [f["high"] / f["paper"] - f["factorToPaper"]]],
                            fmt=mk, mfc="white", color=f"C{k}", capsize=3)
            f = pair.get(m, {}).get(q)
            if f:
                _law(ax, f, 48, f"C{k}", ":", 1.2)
    ax.axhline(1, color="k", lw=0.8)
    ax.axhspan(1 / verdict.FACTOR, verdict.FACTOR, color="0.9", zorder=0,
               label=f"within a factor {verdict.FACTOR:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(28, 150)
    ax.set_xticks([32, 48, 64, 128])
    ax.set_xticklabels(["32", "48", "64", "128"])
    ax.set_xticks([], minor=True)
    ax.set_xlabel("cells per direction n [-] (the paper: 128)")
    ax.set_ylabel("sim / paper, C1 [-]")
    ax.set_title("grid trend (paper's phases), extrapolated", fontsize=9)
    if not done:
        ax.text(0.5, 0.5, "no variant has finished yet",
                transform=ax.transAxes, ha="center", va="center",
                color="0.4")
