"""shearFlowValidation: the plots of a preset's report (paper Appendix B;
doc/cases.md B.4-B.6): agglomeration and decay against theory, and the
particle picture; called by shear.post.postprocess.post."""

import numpy as np

from aggloTools import cloud, render, times
from shear.theory import alpha_th


def plots(runs, out, a_th, K_ST, n0, gamma):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    phys = [r for r in ("EAM", "MAM") if r in runs]
    col = {"EAM": "C0", "MAM": "C3", "bounce": "C2", "detect": "k"}

    if phys:
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for name in phys:
            r = runs[name]
            ax.plot(r.tg, r.alpha(), color=col[name], label=f"{name}")
            ax.plot(r.tg, r.alpha(first=True), color=col[name], ls=":",
                    label=f"{name}, first contacts")
            ax.plot(r.tg, alpha_th(r.st["D10"], gamma), color=col[name],
                    ls="--", lw=0.8, label=rf"$\alpha_{{th}}(\bar d)$, {name}")
        ax.axhline(a_th, color="k", lw=0.8,
                   label=rf"$\alpha_{{th}}(d_p)$ = {100 * a_th:.2f} %")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_ylabel(r"$\alpha = N_{agg}/N_{col}$")
        ax.set_ylim(0, 0.1)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "alpha.png", dpi=120)
        plt.close(fig)

        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for name in phys:
            r = runs[name]
            ax.plot(r.tg, r.st["nCol"], color=col[name],
                    label=rf"$N_{{col}}$ {name}")
            ax.plot(r.tg, r.st["nColFirst"], color=col[name], ls=":",
                    label=rf"$N_{{col,first}}$ {name}")
            ax.plot(r.tg, 20 * r.st["nAgg"], color=col[name], ls="--",
                    label=rf"$20 N_{{agg}}$ {name}")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_ylabel("cumulative count")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "counts.png", dpi=120)
        plt.close(fig)

        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for name in phys:
            r = runs[name]
            ax.plot(r.tg, r.np_after / r.np0, color=col[name], lw=2,
                    label=f"{name}")
            ax.plot(r.tg, r.decay(a_th, "consistent"), color=col[name],
                    ls="--", label=f"theory, K from {name}, consistent")
            ax.plot(r.tg, r.decay(a_th, "printed"), color=col[name],
                    ls=":", label=f"theory, K from {name}, printed B.8")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_ylabel(r"$N_p(t)/N_p(0)$")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "decay.png", dpi=120)
        plt.close(fig)

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, r in runs.items():
        if name == "detect":
            t0 = float(r.s["countFrom"])
            k0 = int(np.argmin(np.abs(r.t - t0)))
            y = r.st["nColFirst"] - r.st["nColFirst"][k0]
            rate = 0.5 * K_ST * (r.np0 / r.V)**2 * r.V
            ax.plot(r.tg[k0:], y[k0:], color="k",
                    label="detection only (ghost), first contacts")
            ax.plot(r.tg[k0:], rate * (r.t[k0:] - r.t[k0]), "k--",
                    label=r"$\frac{1}{2} K_{ST} n_0^2 V (t - t_0)$")
        else:
            ax.plot(r.tg, r.st["nColFirst"], color=col[name],
                    label=f"{name}, first contacts")
    ax.set_xlabel(r"$t\dot\gamma$")
    ax.set_ylabel(r"$N_{col,first}$")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "firstContacts.png", dpi=120)
    plt.close(fig)


def picture(runs, out):
    """pyvista picture of the final particle field of each agglomerating
    run, coloured by primaries per agglomerate."""
    for name in ("EAM", "MAM"):
        if name not in runs:
            continue
        r = runs[name]
        tdirs = [p for p in times.time_dirs(r.case)
                 if (p / "lagrangian" / "kinematicCloud" / "positions")
                 .exists() and float(p.name) > 0]
        if not tdirs:
            continue
        lag = tdirs[-1] / "lagrangian" / "kinematicCloud"
        x = cloud.read_positions(lag / "positions")
        npr = cloud.read_lagrangian(lag / "nPrimary")
        delta, Lx, Lz = (float(r.s[k]) for k in ("delta", "Lx", "Lz"))
        n_ag = int(np.sum(npr > 1))
        render.particles_picture(
            out / f"particles{name}.png", x, npr,
            (0, Lx, -delta, delta, 0, Lz),
            title=f"{name}, t*gammaDot = {float(tdirs[-1].name) * r.gamma:.0f}"
                  f": {len(x)} particles, {n_ag} agglomerates (coloured)")
