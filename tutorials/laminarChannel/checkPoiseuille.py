#!/usr/bin/env python3
"""Regression check of the laminarChannel tutorial.

Plane Poiseuille flow of half-height h at bulk velocity U_B:
  analytic driving gradient      G = 3 nu U_B / h^2
  cell-centred finite volumes    G = 3 nu U_B / (h^2 + dy^2/2)
(uniform cells of height dy, linear wall gradient: the discrete profile is
the exact parabola shifted by G dy^2/(8 nu), so U_B gains G dy^2/(6 nu)).
The gradient the meanVelocityForce reports must match the discrete value
to 1e-6 and the analytic one to the discretisation error (1 %).
All injected particles must still be in the domain at the end."""

import argparse
import json
import re
import sys
from pathlib import Path

from aggloTools import cloud, regression as reg, times as ftimes
from aggloTools.foamfile import read_dict

argparse.ArgumentParser(
    prog="checkPoiseuille.py", description=__doc__.split("\n\n")[0],
    epilog="Run by ./Allrun after the solver, in the tutorial's folder; "
    "no options.").parse_args()
case = Path(__file__).resolve().parent

nu = float(read_dict(case / "constant/transportProperties")["nu"])
ubar = float(str(read_dict(case / "constant/fvOptions")["momentumSource"][
    "Ubar"][0]).strip("("))
blocks = (case / "system/blockMeshDict").read_text()
ny = int(re.search(r"\(\s*\d+\s+(\d+)\s+\d+\s*\)\s*simpleGrading",
                   blocks).group(1))
height = 2.0
h = height / 2
dy = height / ny

last = ftimes.time_dirs(case)[-1]
G = float(read_dict(last / "uniform/momentumSourceProperties")["gradient"])

G_analytic = 3 * nu * ubar / h**2
G_fv = 3 * nu * ubar / (h**2 + dy**2 / 2)

# the injected positions: an ASCII list of (x y z), read as a list file
n_injected = len(cloud.read_lagrangian(
    case / "constant/kinematicCloudPositions"))
n_final = len(cloud.cloud_positions(case, last.name))

rows = [reg.row(v <= t, check=n, value=v, tolerance=t) for n, v, t in (
    ("gradient vs discrete FV Poiseuille", abs(G / G_fv - 1), 1e-6),
    ("gradient vs analytic Poiseuille", abs(G / G_analytic - 1), 1e-2),
    ("particles kept (injected - final)", abs(n_injected - n_final), 0))]
summary = {
    "time": float(last.name), "gradient": G, "gradientAnalytic": G_analytic,
    "gradientFV": G_fv, "particlesInjected": n_injected,
    "particlesFinal": n_final, "regression": rows,
}
(case / "results").mkdir(exist_ok=True)
(case / "results/summary.json").write_text(json.dumps(summary, indent=2)
                                           + "\n")

print(f"laminarChannel at t = {last.name}: G = {G:.10g} "
      f"(discrete FV {G_fv:.10g}, analytic {G_analytic:.10g})")
cols = [reg.Column("status", "status", 6, gap=""),
        reg.Column("check", "check", 36, gap="  "),
        reg.Column("value", "value", 10, ">", lambda v: f"{v:.3g}"),
        reg.Column("tolerance", "tolerance", 10, ">", lambda v: f"{v:g}")]
print("\n".join(reg.table(rows, cols)))
print(f"results in {case / 'results/summary.json'}")
sys.exit(1 if reg.counts(rows)[reg.FAIL] else 0)
