"""Case test: the laminarChannel tutorial (aggloPimpleFoam, constant mass
flux, particles) run end to end; its regression rows compare the driving
gradient with the discrete and analytic Poiseuille solutions."""

import json
import shutil

from aggloTools.runner import project_dir, run

ROOT = project_dir()


def test_laminar_channel_allrun(case_dir, foam_env):
    src = ROOT / "tutorials" / "laminarChannel"
    dst = case_dir / "laminarChannel"
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns(
        "results", "log.*", "postProcessing", "[1-9]*", "0", "polyMesh"))
    res = run(["./Allrun"], dst, "log.Allrun", check=False)
    summary = json.loads((dst / "results" / "summary.json").read_text())
    assert res.returncode == 0, res.stdout
    nu, ubar, h, dy = 0.1, 1.0, 1.0, 0.1
    assert abs(summary["gradient"] / (3 * nu * ubar / (h**2 + dy**2 / 2))
               - 1) < 1e-6
    assert summary["particlesFinal"] == summary["particlesInjected"] == 4
    assert [r["status"] for r in summary["regression"]] == ["PASS"] * 3
