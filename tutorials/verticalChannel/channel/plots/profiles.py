"""verticalChannel: the report's pictures (channel.post writes them):
time histories with the paper's rates, agglomerate sizes, wall-normal
profiles, particle velocities and the pyvista picture of the particles."""

import numpy as np

from aggloTools import cloud, times, uncertainty
from aggloTools.stats import last_output, read_table

from channel.case import settings

TABLE_D6 = settings.TABLE_D6


def run_label(p, k, r):
    """'C2 EAM'; with the particle number where the run released another
    than the preset's (its perConfiguration entry): its counts per volume
    and volume fraction are of that number."""
    n = r["nParticles"]
    return f"{k[0]} {k[1]}" + (f" (N = {n:g})" if n != p["nParticles"]
                               else "")


def read_profiles(p, adir, cloud):
    """profiles.dat of the last write with per-volume values and the
    volume fraction based on the geometric slab volumes. Files written
    before the statistics split cell volumes over the slabs (no 'slab
    volumes' header line) used the cells whose centre lies in a slab: the
    counts are recovered from that volume (VSMALL for slabs without a
    cell centre) and divided by the slab volume; the volume fraction of
    such empty slabs is unknown (NaN)."""
    f = last_output(adir, cloud, "profiles.dat")
    if f is None:
        return None
    t = read_table(f)
    if "slab volumes" in f.read_text()[:400]:
        return t
    Lx, Ly, Lz = p["L"]
    pts = cloud.read_lagrangian(adir / "constant/polyMesh/points")
    yf = np.unique(np.round(pts[:, 1], 12))
    yc, dy = 0.5 * (yf[1:] + yf[:-1]), np.diff(yf)
    nb = len(t["x"])
    w = (yf[-1] - yf[0]) / nb
    b = np.minimum(np.floor((yc - yf[0]) / w).astype(int), nb - 1)
    Vc = np.bincount(b, weights=dy, minlength=nb) * Lx * Lz
    Vg = np.full(nb, w * Lx * Lz)
    Vused = np.where(Vc > 0, Vc, 1e-300)
    for c in ("nColPerVolume", "nColFirstPerVolume", "nAggPerVolume"):
        t[c] = t[c] * Vused / Vg
    t["alpha"] = np.where(Vc > 0, t["alpha"] * Vc / Vg, np.nan)
    return t


# ----------------------------------------------------------------- plots

def plots(out, p, res, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker  # noqa: F401

    keys = sorted(res)
    w0, w1 = p["window"]
    # time histories, with the paper's rates (Table D.6, scaled to this
    # run's particles by 1/s^2) over the window where it gives them
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for i, k in enumerate(keys):
        s = res[k]["_series"]
        lab = run_label(p, k, res[k])
        colour = f"C{i}"
        ax[0, 0].plot(s["T"], s["nCol"], label=lab, color=colour)
        ax[0, 1].plot(s["T"], s["nAgg"], label=lab, color=colour)
        with np.errstate(invalid="ignore", divide="ignore"):
            ax[1, 0].plot(s["T"], np.where(s["nCol"] > 0,
                                           s["nAgg"] / s["nCol"], np.nan),
                          label=lab, color=colour)
        ax[1, 1].plot(s["T"], s["Npp"], label=lab, color=colour)
        ref = TABLE_D6.get(k[0])
        if ref:
            for a, q, n in ((ax[0, 0], "fcol", s["nCol"]),
                            (ax[0, 1], "fagg", s["nAgg"])):
                n0 = float(np.interp(w0, s["T"], n))
                a.plot([w0, w1], [n0, n0 + ref[q][k[1]] / res[k]["scale"]
                                  * (w1 - w0)],
                       "--", color=colour, lw=0.9,
                       label=f"paper {lab} (rate / s^2)")
            ax[1, 0].axhline(ref["fagg"][k[1]] / ref["fcol"][k[1]],
                             ls="--", color=colour, lw=0.9,
                             label=f"paper {lab} alpha_f")
    for a, yl in zip(ax.flat, (r"collisions $N_{col}$ [-]",
                               r"agglomerations $N_{agg}$ [-]",
                               r"$\alpha = N_{agg}/N_{col}$ [-]",
                               r"primaries in agglomerates $N_{pp}$ [-]")):
        a.set_xlabel(r"$T^*_{agg} = t\,U_B/\delta$ since the start of"
                     " agglomeration [-]")
        a.set_ylabel(yl)
        a.axvspan(w0, w1, color="0.92", zorder=0)
        a.grid(alpha=0.3)
    # alpha on a log axis: the paper's 0.2-1.7 % and the start-up's tens
    # of per cent both show (zeros before the first agglomeration drop)
    ax[1, 0].set_yscale("log")
    alphas = [TABLE_D6[k[0]]["fagg"][k[1]] / TABLE_D6[k[0]]["fcol"][k[1]]
              for k in keys if k[0] in TABLE_D6]
    data = [v for k in keys for v in np.asarray(res[k]["_series"]["nAgg"]
            / np.maximum(res[k]["_series"]["nCol"], 1)) if v > 0]
    if alphas or data:
        # the paper's alpha inside the axis, however far the run is
        ax[1, 0].set_ylim(min(alphas + data) / 3, max(alphas + data) * 3)
    ax[0, 0].legend(fontsize=7)
    ax[1, 0].legend(fontsize=7)
    fig.suptitle(f"verticalChannel {p['name']}: time histories"
                 " (grey: Eq. 87 window; dashed: the paper)")
    fig.tight_layout()
    fig.savefig(out / "history.png", dpi=110)
    plt.close(fig)

    # agglomerate sizes at the end
    fig, ax = plt.subplots(figsize=(7, 4.5))
    width = 0.8 / max(1, len(keys))
    kmax, nmax = 2, 1.0
    for i, k in enumerate(keys):
        f = last_output(*runs[k], "agglomerateSizes.dat")
        if f is None:
            continue
        t = read_table(f)
        if len(t["k"]):
            # each run's bar inside its size's integer bin
            xb = t["k"] - 0.4 + (i + 0.5) * width
            ax.bar(xb, t["count"], width=width, label=f"{k[0]} {k[1]}",
                   color=f"C{i}")
            # the counts written on the bars: the log axis hides 24 vs 20
            for xx, n in zip(xb, t["count"]):
                ax.text(xx, n * 1.08, f"{n:.0f}", ha="center",
                        va="bottom", fontsize=7)
            kmax = max(kmax, int(np.max(t["k"])))
            nmax = max(nmax, float(np.max(t["count"])))
    ax.set_xticks(range(2, kmax + 1))
    ax.set_xlim(1.5, kmax + 0.5)
    ax.set_xlabel("primaries per agglomerate [-]")
    ax.set_ylabel("agglomerates $N_a$ [-]")
    ax.set_yscale("log")
    ax.set_ylim(0.5, 3 * nmax)     # room above the tallest bar
    ax.legend(fontsize=8)
    ends = sorted({f"{res[k]['T_end']:.0f}" for k in keys})
    ax.set_title("agglomerates per size at the end of the agglomeration"
                 f" stage (T*agg = {', '.join(ends)})")
    fig.tight_layout()
    fig.savefig(out / "agglomerateSizes.png", dpi=110)
    plt.close(fig)

    profile_plots(out, p, res, runs, plt)


#: Events a bin of the collision profiles should hold on average (the
#: bins are merged from the wall outwards until they do)
EVENTS_PER_BIN = 10


def fold(v):
    """Mean of the two halves of a profile across the channel, from the
    wall (bin 0) to the centre: the channel is symmetric in y."""
    v = np.asarray(v, float)
    h = len(v) // 2
    return 0.5 * (v[:h] + v[::-1][:h])


def merge(v, g):
    """Sums of g adjacent bins (the last may hold fewer)."""
    return np.add.reduceat(np.asarray(v, float), np.arange(0, len(v), g))


def profile_plots(out, p, res, runs, plt):
    """profiles.png and particleVelocity.png: the wall-normal profiles
    over the agglomeration stage (Eqs. 86, 88), folded about the centre
    plane and plotted against the distance from the nearer wall; the
    collision and agglomeration counts in bins merged until they hold
    about EVENTS_PER_BIN collisions on average, with Poisson (counts) and
    binomial (their ratio) standard errors."""
    d = p["delta"]
    Lx, Ly, Lz = p["L"]
    keys = sorted(res)
    fig, ax = plt.subplots(2, 3, figsize=(15, 8))
    fig2, ax2 = plt.subplots(1, 2, figsize=(12, 4.5))
    merged = {}
    for i, k in enumerate(keys):
        t = read_profiles(p, *runs[k])
        if t is None:
            continue
        colour, lab = f"C{i}", run_label(p, k, res[k])
        nb = len(t["x"])
        V = Lx * Lz * Ly / nb
        ncol = fold(t["nColPerVolume"]) * 2 * V     # both halves' counts
        nagg = fold(t["nAggPerVolume"]) * 2 * V
        yw = 1 - fold(np.abs(t["x"] / d - 1))       # wall distance / delta
        h = len(yw)
        g = int(np.ceil(h / np.clip(ncol.sum() / EVENTS_PER_BIN, 1, h)))
        merged[k] = g
        edges = np.arange(0, h + g, g).clip(max=h) / h
        yc = 0.5 * (edges[1:] + edges[:-1])
        C, A = merge(ncol, g), merge(nagg, g)
        Vb = 2 * V * merge(np.ones(h), g)
        kw = dict(color=colour, label=lab, capsize=2, marker="o", ms=3)
        ax[0, 0].errorbar(yc, C / Vb, yerr=np.sqrt(C) / Vb, **kw)
        ax[0, 1].errorbar(yc, A / Vb, yerr=np.sqrt(A) / Vb, **kw)
        with np.errstate(invalid="ignore", divide="ignore"):
            a = np.where(C > 0, A / C, np.nan)
        sa = np.array([uncertainty.binomial_sigma(x, c) if c > 0 else np.nan
                       for x, c in zip(A, C)])
        ax[0, 2].errorbar(yc, a, yerr=np.where(C > 0, sa, np.nan), **kw)
        dp = float(settings.read_settings(runs[k][0])["dParticle"])
        ax[1, 0].plot(yw, fold(t["alpha"]), color=colour, label=lab)
        ax[1, 1].plot(yw, fold(t["meanD"]) / dp - 1, color=colour,
                      label=lab)
        ax[1, 2].plot(yw, fold(t["Ux"]) / p["Ubar"], color=colour,
                      label=lab)
        ls = "-" if k[1] == "EAM" else ":"
        ax2[0].plot(yw, np.sqrt(np.maximum(fold(t["uu"]), 0)) / p["Ubar"],
                    ls, color=colour, label=f"{lab} u'")
        ax2[0].plot(yw, np.sqrt(np.maximum(fold(t["vv"]), 0)) / p["Ubar"],
                    ls, color=colour, alpha=0.5, label=f"{lab} v'")
        # <u'v'> is odd about the centre plane: folded with its sign
        uv = np.asarray(t["uv"], float)
        ax2[1].plot(yw, 0.5 * (uv[:h] - uv[::-1][:h]) / p["Ubar"]**2, ls,
                    color=colour, label=lab)
    for a, yl in zip(ax.flat, (
            r"collisions per volume [m$^{-3}$]",
            r"agglomerations per volume [m$^{-3}$]",
            r"agglomerations / collisions [-]",
            "particle volume fraction [-]",
            r"mean diameter / $d_p$ $-$ 1 [-]",
            r"particle $\langle u\rangle/U_B$ [-]")):
        a.set_ylabel(yl)
        a.set_xlabel(r"distance from the nearer wall $y_w/\delta$ [-]")
        a.set_xlim(0, 1)
        a.grid(alpha=0.3)
    ax[1, 1].ticklabel_format(axis="y", style="sci", scilimits=(-2, 2),
                              useOffset=False)
    ax[0, 0].legend(fontsize=8)
    g = ", ".join(f"{k[0]} {k[1]} {v}" for k, v in merged.items())
    fig.suptitle(f"verticalChannel {p['name']}: wall-normal profiles over"
                 " the agglomeration stage (Eqs. 86, 88), both halves"
                 " folded\ntop: bins merged to about"
                 f" {EVENTS_PER_BIN} collisions each (slabs per bin: {g});"
                 " error bars one standard error (Poisson, binomial)")
    fig.tight_layout()
    fig.savefig(out / "profiles.png", dpi=110)
    plt.close(fig)
    ax2[0].set_ylabel(r"particle rms velocity $/U_B$ [-]")
    ax2[1].set_ylabel(r"particle $\langle u'v'\rangle/U_B^2$ [-]"
                      " (lower-wall sign)")
    for a in ax2:
        a.set_xlabel(r"distance from the nearer wall $y_w/\delta$ [-]")
        a.set_xlim(0, 1)
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig2.suptitle(f"verticalChannel {p['name']}: particle velocity"
                  " statistics (solid EAM, dotted MAM; the two clouds of"
                  " a one-way configuration share the flow and start from"
                  " the same particles,\nso their lines coincide until"
                  " agglomerates differ)", fontsize=10)
    fig2.tight_layout()
    fig2.savefig(out / "particleVelocity.png", dpi=110)
    plt.close(fig2)


def picture(out, p, runs):
    """pyvista picture of the first finished run's last time, from its
    legacy positions or, where the preset writes none, from the
    barycentric coordinates and the mesh; a run without particles to draw
    is named, never skipped silently. Returns the picture's path (None:
    none drawn, and said why)."""
    from aggloTools import render
    for (c, m), (adir, cname) in sorted(runs.items()):
        t = times.time_dirs(adir)[-1]
        cdir = t / "lagrangian" / cname
        if not any((cdir / f).exists() for f in ("positions",
                                                 "coordinates")):
            print(f"channelPost: no particle picture of {c} {m}: {cdir} "
                  "holds neither positions nor coordinates")
            continue
        x = cloud.cloud_positions(adir, t.name, cname)
        n = cloud.read_lagrangian(cdir / "nPrimary")
        if not len(x):
            print(f"channelPost: no particle picture of {c} {m}: no "
                  f"particles at {t}")
            continue
        Lx, Ly, Lz = p["L"]
        png = out / f"particles{c}{m}.png"
        render.particles_picture(
            png, x, n, (0, Lx, 0, Ly, 0, Lz),
            title=f"verticalChannel {p['name']} {c} {m}: T*agg ="
                  f" {res_time(p, t):.3g}, {len(x)} particles,"
                  f" {int((n > 1).sum())} agglomerates",
            axes=("x (flow, gravity) [m]", "y (wall-normal) [m]",
                  "z (spanwise) [m]"),
            walls=((1, 0.0), (1, Ly)),
            arrow=((0.1 * Lx, 0.5 * Ly, 1.15 * Lz), (0.25 * Lx, 0, 0),
                   "flow and g"))
        return png
    print("channelPost: no particle picture: no finished run has particles"
          " to draw")
    return None


def res_time(p, t):
    return (float(t.name) - settings.end_time(p, "dispersion")) / p["tScale"]


