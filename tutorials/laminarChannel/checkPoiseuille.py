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

import json
import re
import sys
from pathlib import Path

case = Path(__file__).resolve().parent


def read_entry(path, key):
    text = Path(path).read_text()
    m = re.search(r"^\s*" + re.escape(key) + r"\s+([^;]+);", text, re.M)
    if not m:
        sys.exit(f"{key} not found in {path}")
    return m.group(1).strip()


nu = float(read_entry(case / "constant/transportProperties", "nu"))
ubar = float(read_entry(case / "constant/fvOptions", "Ubar").strip("()").split()[0])
blocks = (case / "system/blockMeshDict").read_text()
ny = int(re.search(r"\(\s*\d+\s+(\d+)\s+\d+\s*\)\s*simpleGrading", blocks).group(1))
height = 2.0
h = height / 2
dy = height / ny

times = sorted((p for p in case.iterdir() if re.fullmatch(r"[0-9.e+-]+", p.name)
                and p.name != "0"), key=lambda p: float(p.name))
last = times[-1]
G = float(read_entry(last / "uniform/momentumSourceProperties", "gradient"))

G_analytic = 3 * nu * ubar / h**2
G_fv = 3 * nu * ubar / (h**2 + dy**2 / 2)

n_injected = len(re.findall(r"^\s*\(\s*[-+0-9.eE]+\s+[-+0-9.eE]+\s+[-+0-9.eE]+\s*\)", (case / "constant/kinematicCloudPositions").read_text(), re.M))
positions = (last / "lagrangian/kinematicCloud/positions").read_text()
m = re.search(r"^(\d+)\s*$", positions.split("// * *")[-1], re.M)
n_final = int(m.group(1)) if m else 0

rows = [
    ("gradient vs discrete FV Poiseuille", abs(G / G_fv - 1), 1e-6),
    ("gradient vs analytic Poiseuille", abs(G / G_analytic - 1), 1e-2),
    ("particles kept (injected - final)", abs(n_injected - n_final), 0),
]
summary = {
    "time": float(last.name), "gradient": G, "gradientAnalytic": G_analytic,
    "gradientFV": G_fv, "particlesInjected": n_injected,
    "particlesFinal": n_final,
    "checks": [{"name": n, "value": v, "tolerance": t, "pass": v <= t}
               for n, v, t in rows],
}
(case / "results").mkdir(exist_ok=True)
(case / "results/summary.json").write_text(json.dumps(summary, indent=2) + "\n")

print(f"laminarChannel at t = {last.name}: G = {G:.10g} "
      f"(discrete FV {G_fv:.10g}, analytic {G_analytic:.10g})")
ok = True
for n, v, t in rows:
    status = "PASS" if v <= t else "FAIL"
    ok &= v <= t
    print(f"  {status}  {n}: {v:.3g} (tolerance {t:g})")
print(f"results in {case / 'results/summary.json'}")
sys.exit(0 if ok else 1)
