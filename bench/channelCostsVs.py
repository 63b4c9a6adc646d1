#!/usr/bin/env python3
"""The verticalChannel costs of this build side by side with a baseline
build on the same machine in one call: bench/channelCosts.py of the
baseline (its own script, cases and binaries, in its own environment),
then of this build, alternating per preset, and the ratios this/baseline.

    source etc/bashrc
    .venv/bin/python bench/channelCostsVs.py BASELINE [--presets "small"]
        [--np "2"] [--steps N] [--repeat R] [--out FILE]

BASELINE: the project folder of the baseline build (a clone at the
baseline commit, set up and built: bin/aggloSetup; ./Allwmake), e.g.
$HOME/aggloRuns/base-8967eb5. --repeat runs each build R times (default
1), alternating, and keeps each build's fastest step times (the machine's
other load only ever slows a run). Writes --out (default
bench/results/channelCosts-vs-<baseline commit>.json) and prints a table
of the ratios: s per step of each stage, the cloud's us per
particle-step, and the peak memory per particle; and, per build, the
projected wall time of a C1 of the preset at its phase lengths on those
ranks (unladen steps at the unladen step's cost, release and dispersion
at the one-cloud step's, agglomeration at the two-cloud step's; the
steps measured right after the release, so a developed near-wall
concentration may cost more).

    .venv/bin/python bench/channelCostsVs.py --report FILE
        prints the table of a stored FILE again, with the projections
"""

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

from aggloTools.runner import project_dir, tutorial_module

ROOT = project_dir()
RESULTS = Path("bench/runs/channelCosts/results.json")
STAGES = ("unladen", "laden1", "laden2")
CLOUD = ("tracking_us", "stage_us", "rest_us")
#: Which step of the cost runs each phase of a configuration runs
PHASES = (("unladen", "unladen"), ("release", "laden1"),
          ("dispersion", "laden1"), ("agglomeration", "laden2"))


def commit(root):
    """The build's commit, with -dirty where its tree has changes."""
    return subprocess.run(["git", "-C", str(root), "describe", "--always",
                           "--dirty", "--abbrev=7"], capture_output=True,
                          text=True, check=True).stdout.strip()


def clean_env(root):
    """The environment without this project's paths, for the other
    build's etc/bashrc to set up its own."""
    env = dict(os.environ)
    for k in ("AGGLO_PROJECT_DIR", "FOAM_USER_APPBIN", "FOAM_USER_LIBBIN",
              "FOAM_SITE_APPBIN", "FOAM_SITE_LIBBIN"):
        env.pop(k, None)
    for k in ("PATH", "LD_LIBRARY_PATH"):
        env[k] = ":".join(p for p in env.get(k, "").split(":")
                          if p and not p.startswith(str(ROOT)))
    return env


def costs(root, preset, a):
    """bench/channelCosts.py of the build in root, for one preset."""
    cmd = (f"source {root}/etc/bashrc >/dev/null && exec "
           f"{root}/.venv/bin/python {root}/bench/channelCosts.py"
           f" --presets {preset} --np '{a.np}' --decompose-timeout 1"
           + (f" --steps {a.steps}" if a.steps else ""))
    print(f"{commit(root)}: {preset}", flush=True)
    res = subprocess.run(["bash", "-c", cmd], cwd=root, env=clean_env(root),
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    if res.returncode:
        sys.exit(f"channelCostsVs: {root}: channelCosts.py failed:\n"
                 f"{res.stdout[-3000:]}")
    return json.loads((root / RESULTS).read_text())[preset]


def fastest(runs):
    """Per rank count and stage, the run with the fastest step."""
    best = json.loads(json.dumps(runs[0]))
    for r in runs[1:]:
        for key in (k for k in r if k.startswith("np")):
            for s in STAGES:
                if r[key][s]["step_s"] < best[key][s]["step_s"]:
                    best[key][s] = r[key][s]
    return best


def ratios(base, this):
    out = {}
    for key in sorted(k for k in this if k.startswith("np")):
        row = {}
        for s in STAGES:
            row[f"{s}_step"] = this[key][s]["step_s"] / base[key][s]["step_s"]
        l1b, l1t = base[key]["laden1"], this[key]["laden1"]
        for c in CLOUD:
            if l1b.get(c):
                row[c] = l1t.get(c, 0) / l1b[c]
        n = this["particles"]
        if n:
            per = [(r[key]["laden2"]["peak_B"] - r[key]["unladen"]["peak_B"])
                   / (2 * n) for r in (base, this)]
            row["B_per_particle"] = per
        out[key] = row
    return out


def projection_h(preset, costs_np):
    """Hours of a C1 of the preset at its phase lengths from one build's
    step costs on one rank count: {phase: h, "total": h}."""
    p = tutorial_module("verticalChannel",
                        "channel.case.settings").preset(preset)
    out = {ph: p[ph] / p["dtStar"] * costs_np[stage]["step_s"] / 3600
           for ph, stage in PHASES}
    out["total"] = sum(out.values())
    return out


def table(res):
    lines = ["| preset | ranks | unladen | laden 1 cloud | laden 2 clouds |"
             " tracking | stage | rest | B/particle (baseline -> this) |",
             "|" + "---|" * 9]
    for p, r in res["presets"].items():
        for key, q in r["ratios"].items():
            b = q.get("B_per_particle")
            lines.append(
                f"| {p} | {key[2:]} | {q['unladen_step']:.3f} |"
                f" {q['laden1_step']:.3f} | {q['laden2_step']:.3f} | "
                + " | ".join(f"{q[c]:.3f}" if c in q else "-"
                             for c in CLOUD)
                + (f" | {b[0]:.0f} -> {b[1]:.0f} |" if b else " | - |"))
    lines += ["", "| preset | ranks | C1 at the phase lengths, h: baseline"
              " -> this (unladen + release + dispersion + agglomeration)"
              " |", "|---|---|---|"]
    for p, r in res["presets"].items():
        for key in r["ratios"]:
            h = [projection_h(p, r[b][key]) for b in ("baseline", "this")]
            lines.append(f"| {p} | {key[2:]} | {h[0]['total']:.1f} -> "
                         f"{h[1]['total']:.1f} (" + " + ".join(
                             f"{h[1][ph]:.1f}" for ph, _ in PHASES)
                         + ") |")
    return "\n".join(lines)


def main():
    if sys.argv[1:2] == ["--report"] and len(sys.argv) == 3:
        res = json.loads(Path(sys.argv[2]).read_text())
        print(f"this build ({res['this'][:7]}) / baseline "
              f"({res['baseline']}), fastest of each:\n" + table(res))
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("baseline", type=Path)
    ap.add_argument("--presets", default="small")
    ap.add_argument("--np", default="2")
    ap.add_argument("--steps", type=int, default=None)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--out", type=Path, default=None)
    a = ap.parse_args()
    base_root = a.baseline.resolve()
    if not (base_root / "bench/channelCosts.py").is_file():
        sys.exit(f"channelCostsVs: {base_root} is not a project folder")
    res = {"what": f"bench/channelCostsVs.py {' '.join(sys.argv[1:])}",
           "baseline": commit(base_root), "this": commit(ROOT),
           "presets": {}}
    for p in a.presets.split():
        runs = {"baseline": [], "this": []}
        for _ in range(a.repeat):
            runs["baseline"].append(costs(base_root, p, a))
            runs["this"].append(costs(ROOT, p, a))
        b, t = fastest(runs["baseline"]), fastest(runs["this"])
        res["presets"][p] = {"baseline": b, "this": t,
                             "ratios": ratios(b, t)}
    out = a.out or \
        ROOT / f"bench/results/channelCosts-vs-{res['baseline']}.json"
    out.write_text(json.dumps(res, indent=1) + "\n")
    print(f"\nthis build ({res['this']}) / baseline ({res['baseline']}),"
          " fastest of each:\n" + table(res) + f"\n\n({out})")


if __name__ == "__main__":
    main()
