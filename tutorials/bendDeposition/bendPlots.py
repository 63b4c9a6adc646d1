"""The pictures of bendDeposition: the efficiency against the Stokes
number (with its binomial sigma), and where the particles of one Stokes
number deposited on the bent pipe (the wall faces coloured by the mass
deposited on them, seen from the bend's axis)."""

import re

import numpy as np

from aggloTools.fields import read_patch
from aggloTools.mesh import Mesh
from aggloTools.times import last_time

from bendMeasured import BAND


def _patch_faces(case, patch):
    text = (case / "constant/polyMesh/boundary").read_text()
    m = re.search(r"\b" + patch + r"\s*\{[^}]*?nFaces\s+(\d+);[^}]*?"
                  r"startFace\s+(\d+);", text)
    return int(m.group(2)), int(m.group(1))


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def efficiency_plot(rows, g, out, measured=None):
    """efficiency.png: eta against St with the binomial sigma, and
    `measured(St)` (Pui et al.'s laminar expression, bendMeasured) with
    its band where given."""
    plt = _pyplot()
    st = np.array([r["St"] for r in rows])
    eta = np.array([r["eta"] for r in rows])
    sig = np.array([r["sigma"] for r in rows])
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    if measured is not None:
        s = np.geomspace(st.min(), st.max(), 200)
        m = np.array([measured(x) for x in s])
        ax.fill_between(s, np.clip(m - BAND, 0, 1),
                        np.clip(m + BAND, 0, 1), color="0.85",
                        label=f"band of the rows (+-{BAND:g})")
        ax.plot(s, m, "k--", label="Pui et al. (1987), laminar expression")
    ax.errorbar(st, eta, yerr=sig, fmt="o-", capsize=3,
                label="this model (binomial sigma)")
    ax.set_xscale("log")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel("St = rho_p d_p² U / (9 mu D)")
    ax.set_ylabel("deposition efficiency of the bend")
    ax.set_title(f"90° bend, Re = 1000, R/a = {g.R / g.a:g}: "
                 "laminar inflow, sticking walls", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(out / "efficiency.png", dpi=120)
    plt.close(fig)


def deposits_plot(case, what, out):
    """deposits.png: where the particles of one run (`what`: 'St = 0.3')
    deposited: every wall face coloured by its deposited mass, projected
    on the bend's plane (x, z)."""
    plt = _pyplot()
    mesh = Mesh(case)
    Cf, _ = mesh.face_centres_and_areas()
    t = last_time(case)
    fig, ax = plt.subplots(figsize=(6.5, 5.5))
    xs, zs, ms = [], [], []
    for patch in ("inletPipe", "bend", "outletPipe"):
        start, n = _patch_faces(case, patch)
        m = read_patch(case / t / "kinematicCloud:depositedMass", patch, n)
        c = Cf[start:start + n]
        top = c[:, 1] >= 0              # the half facing the viewer
        ax.scatter(c[top, 0] * 1e3, c[top, 2] * 1e3, s=4, c="0.85")
        hit = m > 0
        xs += list(c[hit, 0] * 1e3)
        zs += list(c[hit, 2] * 1e3)
        ms += list(m[hit])
    sc = ax.scatter(xs, zs, s=12, c=np.array(ms) * 1e12, cmap="viridis")
    fig.colorbar(sc, ax=ax, label="deposited mass per face [pg]")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm] (inflow along +z, outflow along +x)")
    ax.set_title(f"Where particles of {what} deposit (faces of both "
                 "halves;\ngrey: the wall's faces on the near half)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "deposits.png", dpi=120)
    plt.close(fig)
