"""verticalChannel regime study: its figure, regime.png, from the
variants' results (channelRegimeAnalysis): the rates and alpha_f of the
finished variants, the concentration at the start of agglomeration, the
release and dispersion between writes, the contacts' distributions and
where along the wall distance they agglomerate, the ratios of the
variants one shortcut apart and the grid trend against the paper."""

import textwrap

import numpy as np

from channel.post.contacts import QUANTILES
from channel.regime import pairs, trend, verdict
from channel.post.concentration import START_SPAN
from channel.regime.analysis import (MODELS, PAPER, paper_alpha,
                                     variant_history)


def plots(res, out):
    """regime.png: f_col x s^2 and alpha_f of the finished variants, the
    concentration profile at the start of agglomeration; over the
    release and dispersion stages of every variant that has them (dashed:
    not finished) the near-wall peak, the collision rate and the wall
    impacts between writes; the distributions of |u_n| and of the wall
    distance at contact, the grid trend against the paper; the contacts'
    rate and their ratio of agglomerations per bin of wall distance, and
    the ratios of the variants one shortcut apart."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [v for v in res["variants"] if v["result"]]
    grown = [v for v in res["variants"] if variant_history(v)]
    if not done and not grown:
        return
    fig, axs = plt.subplots(4, 3, figsize=(15, 16.8))
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
        ax[1].axhline(paper_alpha(m), ls="--", color=f"C{k}", lw=0.8,
                      label=f"paper {m}")
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
    # the dispersion done, the agglomeration still running: dashed
    for v in res["variants"]:
        c = None if v["result"] else (v.get("progress") or {}).get(
            "concentration")
        if c:
            ax[2].plot(np.asarray(c["y"]) / 0.02, c["alpha"], "--",
                       label=f"{v['name']} (not finished)")
    ax[2].set_xlabel(r"wall-normal position $y/\delta$ [-]")
    ax[2].set_ylabel("particle volume fraction [-]")
    ax[2].set_title("at the start of agglomeration (the dispersion's "
                    f"last {START_SPAN:g} T*)", fontsize=9)
    if not done:
        for a_ in ax[:2]:
            _empty(a_, "no variant has finished yet")
    if not ax[2].lines:
        _empty(ax[2], "no variant has finished its dispersion yet")
    for k, (key, label) in enumerate((
            ("nearWallOverCentre", "near-wall / centre volume fraction [-]"),
            ("fColScaled", r"collisions per T* $\times s^2$ [1/T*]"),
            ("wallImpacts_per_particle_T",
             "wall impacts per particle and T* [-]"))):
        a_ = ax[3 + k]
        for j, v in enumerate(grown):
            h = [x for x in variant_history(v) if x.get(key) is not None]
            if h:
                a_.step([x["T1"] for x in h], [x[key] for x in h],
                        where="pre", color=f"C{j}", marker=".",
                        ls="-" if v["result"] else "--",
                        label=v["name"] + ("" if v["result"]
                                           else " (not finished)"))
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
    _wall_bin_panels(ax[9], ax[10], done)
    _pairs_panel(ax[11], res)
    for a_ in (*ax[2:9], ax[11]):   # 9, 10: the figure's legend below
        if a_.get_legend_handles_labels()[0] and a_.get_legend() is None:
            a_.legend(fontsize=7)
    head = textwrap.fill("Verdict: " + verdict.headline(res.get("verdict")),
                         110)
    fig.suptitle("The regime study: C1 of `small` with one shortcut"
                 " changed per variant, against the paper (Table 3)\n"
                 + head, fontsize=13, fontweight="bold")
    fig.tight_layout(rect=(0, 0.05, 1, 0.955))
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


def _empty(ax, text):
    """A panel with nothing to draw says why."""
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center",
            va="center", color="0.4")


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
        _empty(ax, "no variant has finished yet")


def _wall_bin_panels(ax_alpha, ax_rate, done):
    """Per finished variant and model, over the bins of wall distance
    (channel.post.contacts.by_wall_distance): the ratio of agglomerating
    to all contacts (bins without an agglomeration at the panel's foot,
    open) and the contacts per T* x s^2 of the window."""
    import matplotlib.transforms
    foot = matplotlib.transforms.blended_transform_factory(
        ax_alpha.transData, ax_alpha.transAxes)
    for i, v in enumerate(done):
        r = v["result"]
        for k, m in enumerate(MODELS):
            b = (r["models"][m]["contacts"] or {}).get("byWallDistance")
            if not b:
                continue
            e = np.asarray(b["edges"])
            yc = np.sqrt(np.maximum(e[:-1], 0.5 * e[1:]) * e[1:])
            n = np.asarray(b["n"], float)
            a = np.array([x if x is not None else np.nan
                          for x in b["alpha"]])
            mk = "o" if m == "EAM" else "s"
            lab = f"{v['name']} {m}"
            ax_alpha.plot(yc, np.where(a > 0, a, np.nan), mk + "-",
                          color=f"C{i}", lw=0.8, label=lab)
            # bins with contacts but no agglomeration: open markers at
            # the panel's foot (a ratio of 0 has no place on a log axis)
            ax_alpha.plot(yc[a == 0], np.full((a == 0).sum(), 0.03), mk,
                          mfc="white", color=f"C{i}", transform=foot,
                          clip_on=False)
            w0, w1 = r["window"]
            ax_rate.plot(yc, n / (w1 - w0) * r["scale_s2"], mk + "-",
                         color=f"C{i}", lw=0.8, label=lab)
    for k, m in enumerate(MODELS):
        ax_alpha.axhline(paper_alpha(m), ls="--",
                         color="0.4" if k else "0.2", lw=0.8,
                         label=f"paper alpha_f {m}")
    ticks = (0.02, 0.05, 0.1, 0.2, 0.5, 1.0)
    for a_ in (ax_alpha, ax_rate):
        a_.set_xscale("log")
        a_.set_yscale("log")
        a_.set_xticks(ticks)
        a_.set_xticklabels([f"{t:g}" for t in ticks])
        a_.set_xticks([], minor=True)
        a_.set_xlabel(r"wall distance at contact $y/\delta$ [-] (bins)")
    ax_alpha.set_ylim(top=1.5)
    ax_alpha.set_ylabel("agglomerating / all contacts [-]")
    ax_alpha.set_title("the window's contacts by wall distance (o EAM,"
                       " s MAM; open at the foot:\ncontacts, none"
                       " agglomerated; dashed: the paper's alpha_f)",
                       fontsize=9)
    ax_rate.set_ylabel(r"contacts per T* $\times s^2$ in the bin [1/T*]")
    ax_rate.set_title("the window's contacts by wall distance", fontsize=9)
    # one legend for both panels, under the figure, clear of the data
    h, lab = ax_rate.get_legend_handles_labels()
    ax_rate.figure.legend(h, lab, fontsize=8, ncol=7, loc="lower center",
                          title="the window's contacts by wall distance"
                          " (bottom left and middle panels)")


def _pairs_panel(ax, res):
    """The ratios of the variants one shortcut apart (channelRegimePairs:
    particle number, phase lengths) with their sigma; 1: no effect."""
    rows = [p for check in pairs.CHECKS for p in res.get(check) or []
            if "missing" not in p]
    names = ("f_col_scaled", "f_agg_scaled", "alpha_f")
    labels = (r"$f_{col}s^2$", r"$f_{agg}s^2$", r"$\alpha_f$")
    step = 0.8 / max(2 * len(rows), 1)
    for i, p in enumerate(rows):
        for k, m in enumerate(MODELS):
            dx = (2 * i + k - (2 * len(rows) - 1) / 2) * step
            for j, q in enumerate(names):
                r = p[m][q]
                if r:
                    ax.errorbar(j + dx, r["ratio"], r["sigma"],
                                fmt="o" if k == 0 else "s",
                                color=f"C{i}", capsize=3,
                                label=(f"{p['variant']} / {p['base']} {m}"
                                       if j == 0 else None))
    ax.axhline(1, color="k", lw=0.8)
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(labels)
    ax.set_xlim(-0.5, len(names) - 0.5)
    ax.set_ylabel("variant over its base [-]")
    ax.set_title("one shortcut apart (1: no effect): particle number "
                 "3e5 / 1e5,\nphase lengths the paper's / small's",
                 fontsize=9)
    if not rows:
        _empty(ax, "no pair one shortcut apart has finished yet")
