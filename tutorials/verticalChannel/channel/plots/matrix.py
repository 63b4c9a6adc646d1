"""verticalChannel: the figure of the matrix (matrix.png of the report):
each configuration's f_col x s^2, f_agg x s^2 and alpha_f = f_agg/f_col
with its sigma, both models, beside Table D.6's values, on shared
logarithmic axes, so that a reader of the paper sees at once where each
configuration and each model stands (R80 and R60 have no published
values: the simulation only)."""

import math

from channel.case import settings

#: The order of the paper's configurations on the axis
ORDER = ("C1", "C2", "C3", "C4", "R80", "R60")
MODELS = settings.MODELS
#: The panels: the quantity's key, its axis label
PANELS = (("col", r"$f_{col}\,s^2$ [1/T*]"),
          ("agg", r"$f_{agg}\,s^2$ [1/T*]"),
          ("alpha", r"$\alpha_f = f_{agg}/f_{col}$ [-]"))


def order(res):
    """The configurations on the axis: ORDER, then any other run (the
    sub-model variants of the presets file) by name."""
    return ORDER + tuple(sorted({c for c, _ in res} - set(ORDER)))


def points(res):
    """The values drawn: per panel and model, (configuration, value,
    sigma, paper) of every run in res[(config, model)] (sigma of alpha_f
    propagated; the paper's None where Table D.6 has none)."""
    out = {q: {m: [] for m in MODELS} for q, _ in PANELS}
    for c in order(res):
        ref = settings.TABLE_D6.get(c)
        for m in MODELS:
            r = res.get((c, m))
            if not r:
                continue
            for q in ("col", "agg"):
                out[q][m].append((c, r[f"f_{q}_scaled"],
                                  r[f"sigma_{q}"] * r["scale"],
                                  ref[f"f{q}"][m] if ref else None))
            a = r["alpha_f"]
            sa = (a * math.hypot(r["sigma_col"] / r["f_col"],
                                 r["sigma_agg"] / r["f_agg"])
                  if a and r["f_agg"] > 0 else None)
            out["alpha"][m].append((c, a, sa, ref["fagg"][m] / ref["fcol"][m]
                                    if ref else None))
    return out


def matrix_figure(out, p, res):
    """matrix.png in out; returns what it drew (points)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pts = points(res)
    configs = [c for c in order(res)
               if any((c, m) in res for m in MODELS)]
    x = {c: i for i, c in enumerate(configs)}
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    for ax, (q, label) in zip(axes, PANELS):
        for j, m in enumerate(MODELS):
            dx = -0.12 if j == 0 else 0.12
            rows = [r for r in pts[q][m] if r[1]]
            if rows:
                ax.errorbar([x[c] + dx for c, *_ in rows],
                            [v for _, v, _, _ in rows],
                            yerr=[s or 0 for _, _, s, _ in rows], fmt="o",
                            color=f"C{j}", capsize=3, label=f"{m} (sim, σ)")
            paper = [r for r in pts[q][m] if r[3]]
            if paper:
                ax.plot([x[c] + dx for c, *_ in paper],
                        [r[3] for r in paper], "s", mfc="none",
                        color=f"C{j}", ms=8, label=f"{m} (paper)")
        ax.set_yscale("log")
        ax.set_xticks(range(len(configs)))
        # one unit per configuration, however few ran
        ax.set_xlim(-0.5, len(configs) - 0.5)
        ax.set_xticklabels(configs)
        ax.set_xlabel("configuration")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"verticalChannel {p['name']}: the matrix against Table "
                 "D.6 (Eq. 87 window; frequencies scaled by s^2 to the "
                 "paper's number; a run without events is not drawn)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "matrix.png", dpi=110)
    plt.close(fig)
    return pts
