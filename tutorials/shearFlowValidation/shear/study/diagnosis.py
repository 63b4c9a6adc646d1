"""shearFlowValidation: where EAM and MAM part (doc/models.md 2.6). The
collision-event log of a run is replayed through the EAM (v_E = |u_n| and
|u_r|) and the MAM on the same frozen contacts (hardSphereReplay
-eventsOut); per contact category (first, repeat, overlap at the start of
the step) the fraction that agglomerates under each kernel, against the
normal and tangential relative speeds, and which term of the EAM's
condition (AB16 Eq. 21: dE_vdW >= E_kin,r+ + E_rot+ - E_rot,ag) or of the
MAM's (Eq. 75 (i): f*_nc >= e_n |u_n|) decides.

    diagnose(case, out, tag)   diagnosis<tag>.json and diagnosis<tag>.png
"""

import json
from pathlib import Path

import numpy as np

from aggloTools import eventlog

KERNELS = {
    "EAMnormal": {"agglomerationModel": "EAM",
                  "EAMCoeffs": {"impactVelocity": "normal"}},
    "EAMfull": {"agglomerationModel": "EAM",
                "EAMCoeffs": {"impactVelocity": "full"}},
    "MAM": {"agglomerationModel": "MAM",
            "MAMCoeffs": {"impactVelocity": "normal"}},
}


def _frac(a):
    return float(np.mean(a)) if len(a) else None


def category_table(ev):
    """Per category: counts, the agglomerating fraction per kernel, the
    median speeds and spins, and the decisive terms of Eq. 21."""
    out = {}
    for k, cat in enumerate(eventlog.CATEGORIES):
        sel = ev["category"] == k
        n = int(sel.sum())
        row = {"events": n}
        for name in KERNELS:
            row[f"alpha_{name}"] = _frac(ev[f"{name}.agglomerates"][sel])
        if n:
            row["median_abs_un"] = float(np.median(np.abs(ev["un"][sel])))
            row["median_utCentres"] = float(np.median(ev["utCentres"][sel]))
            row["median_slip"] = float(np.median(ev["slip"][sel]))
            row["median_omega"] = float(np.median(
                0.5 * (ev["omega1"][sel] + ev["omega2"][sel])))
            for name in ("EAMnormal", "EAMfull"):
                dE = ev[f"{name}.dEvdW"][sel]
                kin = ev[f"{name}.EkinPlus"][sel]
                rot = ev[f"{name}.ErotPlus"][sel] - ev[f"{name}.ErotAg"][sel]
                ok = np.isfinite(dE) & np.isfinite(kin) & np.isfinite(rot)
                # Eq. 21 with and without its spin term
                trans = dE[ok] >= kin[ok]
                full = dE[ok] >= kin[ok] + rot[ok]
                row[f"{name}_translationOnly"] = _frac(trans)
                row[f"{name}_withSpin"] = _frac(full)
                row[f"{name}_spinTermPositive"] = _frac(rot[ok] > 0)
                row[f"{name}_median_dEvdW_over_Ekin"] = (
                    float(np.median(dE[ok] / np.maximum(kin[ok], 1e-300)))
                    if ok.any() else None)
            fnc = ev["MAM.fncStar"][sel]
            un = np.abs(ev["un"][sel])
            okm = np.isfinite(fnc)
            row["MAM_median_fncStar_over_un"] = (
                float(np.median(fnc[okm] / un[okm])) if okm.any() else None)
        out[cat] = row
    return out


def binned(ev, key, edges):
    """Agglomerating fraction per kernel and category in bins of key."""
    x = np.abs(ev[key])
    out = {}
    for k, cat in enumerate(eventlog.CATEGORIES):
        sel = ev["category"] == k
        b = np.digitize(x[sel], edges)
        out[cat] = {name: [_frac(ev[f"{name}.agglomerates"][sel][b == i])
                           for i in range(1, len(edges))]
                    for name in KERNELS}
        out[cat]["events"] = [int(np.sum(b == i))
                              for i in range(1, len(edges))]
    return out


def diagnose(case, out, tag):
    """Replay the run's log through the three kernels; write the
    category table and the binned fractions (json) and their plot."""
    res, ev = eventlog.replay_events(case, KERNELS)
    table = category_table(ev)
    edges = {"un": np.logspace(-6, -2, 17),
             "utCentres": np.logspace(-6, -2, 17)}
    result = {"case": f"{Path(case).parent.name}/{Path(case).name}",
              "kernels": KERNELS, "categories": table,
              "edges": {k: v.tolist() for k, v in edges.items()},
              "binned": {k: binned(ev, k, e) for k, e in edges.items()}}
    (Path(out) / f"diagnosis{tag}.json").write_text(
        json.dumps(result, indent=1) + "\n")
    plot(result, Path(out) / f"diagnosis{tag}.png")
    return result


def plot(res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(2, 3, figsize=(12, 7), sharey=True)
    style = {"EAMnormal": ("C0", "o"), "EAMfull": ("C2", "^"),
             "MAM": ("C3", "s")}
    for r, key in enumerate(("un", "utCentres")):
        e = np.array(res["edges"][key])
        xc = np.sqrt(e[1:] * e[:-1])
        for c, cat in enumerate(eventlog.CATEGORIES):
            ax = axs[r, c]
            b = res["binned"][key][cat]
            for name, (col, m) in style.items():
                y = np.array([np.nan if v is None else v for v in b[name]])
                ax.semilogx(xc, y, marker=m, color=col, label=name)
            ax.set_title(f"{cat} ({sum(b['events'])} contacts)", fontsize=9)
            ax.set_xlabel({"un": r"$|u_n|$ [m/s]",
                           "utCentres": r"$|u_t|$ of the centres [m/s]"}[key])
            ax.grid(alpha=0.3)
        axs[r, 0].set_ylabel("fraction agglomerating")
    axs[0, 0].legend(fontsize=8)
    fig.suptitle(f"Replay of {res['case']}: the same contacts through "
                 "three kernels", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
