"""verticalChannel: the pictures of the break-up report (channel.post.breakup
writes them): breakupHistory.png (the break-ups per mechanism, the
agglomerates N_a and the agglomerations, and each step's largest
load/strength ratio over T*agg, with the window) and
breakupSizes.png (the agglomerates per size at four times of the stage)."""

import numpy as np


def plots(out, p, res):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    w0, w1 = p["window"]
    keys = sorted(res)
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    for i, k in enumerate(keys):
        r = res[k]["_series"]
        T = r["T"]
        label = f"{k[0]} {k[1]}"
        for j, mech in enumerate(res[k]["mechanisms"]):
            if mech == "NoRoom":
                continue
            ax[0].plot(T, r["nBreakup" + mech], color=f"C{i}",
                       ls=("-", "--", ":", "-.")[j % 4],
                       label=f"{label}: {mech}")
        ax[1].plot(T, r["nAgglomerates"], color=f"C{i}",
                   label=f"{label}: agglomerates $N_a$")
        ax[1].plot(T, r["nAgg"], color=f"C{i}", ls="--",
                   label=f"{label}: agglomerations $N_{{agg}}$")
        tr, ratio = r["ratio"]
        if len(ratio):
            ax[2].semilogy(tr, ratio, ".", ms=2, color=f"C{i}",
                           label=label)
    for a in ax:
        a.axvspan(w0, w1, color="0.9", zorder=0)
        a.set_xlabel("$T^*_{agg}$ [-]")
        if a.get_legend_handles_labels()[0]:
            a.legend(fontsize=7)
    ax[0].set_ylabel("break-ups since the stage's start [-]")
    ax[1].set_ylabel("count [-]")
    ax[2].axhline(1.0, color="k", lw=0.8)
    ax[2].set_ylabel("largest load/strength of the step [-] (1 breaks)")
    fig.suptitle(f"verticalChannel {p['name']}: break-up over the "
                 "agglomeration stage (grey: Eq. 87 window)")
    fig.tight_layout()
    fig.savefig(out / "breakupHistory.png", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    kmax = 2
    for i, k in enumerate(keys):
        sizes = res[k]["sizes"]
        if not sizes:
            continue
        # four writes spread over the stage, the last one included
        pick = sorted({int(round(x)) for x in
                       np.linspace(0, len(sizes) - 1, 4)})
        for j, n in enumerate(pick):
            s = sizes[n]
            kk = np.array([int(a) for a in s["counts"]])
            cc = np.array([s["counts"][a] for a in s["counts"]], float)
            if not len(kk):
                continue
            kmax = max(kmax, int(kk.max()))
            ax.plot(kk, cc, marker="o", color=f"C{i}",
                    alpha=0.4 + 0.6 * (j + 1) / len(pick),
                    label=f"{k[0]} {k[1]}, $T^*_{{agg}}$ = {s['T']:.0f}")
    ax.set_xlim(1.5, kmax + 0.5)
    ax.set_xlabel("primaries per agglomerate [-]")
    ax.set_ylabel("agglomerates $N_a$ [-]")
    ax.set_yscale("log")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
    ax.set_title(f"verticalChannel {p['name']}: agglomerates per size")
    fig.tight_layout()
    fig.savefig(out / "breakupSizes.png", dpi=110)
    plt.close(fig)
