#!/usr/bin/env python3
"""Measured costs of the verticalChannel presets: short
runs of every stage of configuration C1 (or of --config, e.g. a group of
one-way configurations as clouds of one LES, C1+R80+R60: one cloud per
configuration in laden1, one per configuration and model in laden2, the
results under "<preset> <config>"), serially and on MPI ranks, with
the same inputs, sizes and code paths as ./Allrun of the tutorial.

    source etc/bashrc
    .venv/bin/python bench/channelCosts.py [--presets "smoke small"]
        [--np "1 2"] [--steps N] [--decompose-timeout 600]
        [--config C1+R80+R60]

For each preset under bench/runs/channelCosts/<preset>/: blockMesh and the
initial flow; then for each rank count n:
  unladen   `steps` LES steps from the initial flow (after decomposePar
            of the fluid on n > 1 ranks)
  laden1    the release of nParticles (into the processor folders on
            n > 1 ranks) and `steps` steps of the release stage: one
            cloud, collisions on
  laden2    `steps` steps of the agglomeration stage: clouds EAM and MAM
            (one LES, one-way coupled), each with the released particles
and, once per preset, reconstructPar -latestTime of the 2-rank laden2
case and decomposePar of the serial laden1 case with its particles (the
route ./Allrun no longer takes; stopped after --decompose-timeout s).

Each run writes once, at its last step. Reported (printed as a table and
written to results.json): s per step (the mean of the steps between the
first and the last; the first carries the start-up, the last the write),
the first step and the write, the cloud's own split (tracking, collision
stage, rest; master rank) in us per particle-step, peak resident memory
(all ranks) and per particle, disk per write, and the parallel efficiency
t(1)/(n t(n)). On the 2-core development machine: small takes about 1
min, medium about 6 min and paper about 50 min, 10 of them the stopped
decomposePar (tutorials/verticalChannel/README.md has the figures).

--perf profiles instead: the serial runs of each stage under `perf record`
(their timings then include perf's overhead), and writes where the time
goes, by library and by function, to bench/results/channelProfile.md.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

from aggloTools import times
from aggloTools.runner import (bench_module, package_command, project_dir,
                               tutorial_module)

ROOT = project_dir()
TUTORIAL = ROOT / "tutorials" / "verticalChannel"
channel = tutorial_module("verticalChannel", "channel.case.settings")
channelParticles = tutorial_module("verticalChannel", "channel.case.particles")
channelGroups = tutorial_module("verticalChannel", "channel.case.groups")
channelProfile = bench_module("channelProfile")

OUT = ROOT / "bench" / "runs" / "channelCosts"
STEPS = {"smoke": 60, "small": 40, "medium": 12, "paper": 6}
APP = "aggloPimpleFoam"


# ----------------------------------------------------------- processes

def rss_of(name):
    """Summed resident memory [B] of the processes called name."""
    total = 0
    for d in Path("/proc").iterdir():
        if not d.name.isdigit():
            continue
        try:
            if (d / "comm").read_text().strip() != name[:15]:
                continue
            m = re.search(r"VmRSS:\s+(\d+)", (d / "status").read_text())
            total += 1024 * int(m.group(1)) if m else 0
        except OSError:
            pass
    return total


def run(cmd, cwd, log, name=None, timeout=None):
    """Run cmd in cwd (output to cwd/log); returns (wall s, peak summed
    memory of the processes called name, finished)."""
    name = name or Path(cmd[0]).name
    peak, done = [0], threading.Event()

    def sample():
        while not done.is_set():
            peak[0] = max(peak[0], rss_of(name))
            time.sleep(0.2)

    th = threading.Thread(target=sample)
    th.start()
    t0 = time.time()
    finished = True
    with open(Path(cwd) / log, "w") as f:
        try:
            res = subprocess.run(cmd, cwd=cwd, stdout=f,
                                 stderr=subprocess.STDOUT, timeout=timeout,
                                 env=dict(os.environ, PWD=str(cwd)))
            if res.returncode != 0:
                raise SystemExit(f"{' '.join(cmd)} failed in {cwd}: see "
                                 f"{Path(cwd) / log}")
        except subprocess.TimeoutExpired:
            finished = False
    wall = time.time() - t0
    done.set()
    th.join()
    return wall, peak[0], finished


#: Record a profile of the serial solver runs (--perf)
PERF = {"on": False}
#: The configuration measured (--config): C1, or a group of one-way
#: configurations run as clouds of one LES (C1+R80+R60)
CONFIG = {"name": "C1"}
MODELS = ("EAM", "MAM")


def solver(case, n, log=f"log.{APP}"):
    cmd = [APP] if n == 1 else ["mpirun", "-np", str(n), APP, "-parallel"]
    if PERF["on"] and n == 1:
        cmd = ["perf", "record", "-F", "499", "-o", "perf.data", "--"] + cmd
    return run(cmd, case, log, APP)


# ---------------------------------------------------------------- cases

def settings(case, pname, stage, steps, n, models=()):
    """caseSettings of the stage, ending `steps` steps after the latest
    time and writing at its end."""
    text = channel.settings(pname, CONFIG["name"], stage, models, n)
    channelGroups.properties(case, CONFIG["name"], stage, MODELS)
    p = channel.preset(pname)
    t0 = float(times.time_dirs(case)[-1].name)
    text = re.sub(r"\nendTime\s+[^;]+;",
                  f"\nendTime         {t0 + steps * p['deltaT']:.10g};",
                  text)
    text = re.sub(r"\nwriteSteps\s+[^;]+;", f"\nwriteSteps      {steps};",
                  text)
    (case / "system" / "caseSettings").write_text(text)


def branch(src, dst, n):
    """dst: the mesh, system and latest time of src (and of its processor
    folders); returns the time name."""
    if dst.exists():
        shutil.rmtree(dst)
    t = times.time_dirs(src)[-1].name
    roots = [Path()] + [Path(p.name) for p in src.glob("processor*")]
    for r in roots:
        (dst / r).mkdir(parents=True)
        shutil.copytree(src / r / "constant", dst / r / "constant")
        if (src / r / t).is_dir():
            shutil.copytree(src / r / t, dst / r / t)
            shutil.rmtree(dst / r / t / "uniform/functionObjects",
                          ignore_errors=True)
    shutil.copytree(src / "system", dst / "system")
    if n > 1:
        t = times.time_dirs(dst / "processor0")[-1].name
    return t


def step_times(case):
    """Per-step wall times from the solver log (ExecutionTime differences)
    and the cloud's split per step (rows: tracking, stage, rest)."""
    text = (case / f"log.{APP}").read_text()
    ex = [float(x) for x in re.findall(r"ExecutionTime = ([0-9.eE+-]+) s",
                                       text)]
    start = re.search(r"Starting time loop", text)
    f = r"([0-9.eE+-]+)"
    split = [[float(v) for v in row] for row in re.findall(
        rf"tracking {f} s, collision stage {f} s, rest of the cloud step "
        rf"{f} s", text)]
    return ex, split, start is not None


def disk(path):
    return sum(f.stat().st_size for f in Path(path).rglob("*")
               if f.is_file())


def last_write_size(case):
    roots = [case] + sorted(case.glob("processor*"))
    t = times.time_dirs(roots[-1])[-1].name
    return sum(disk(r / t) for r in roots if (r / t).is_dir())


def stage(case, n, steps, N, clouds):
    wall, peak, _ = solver(case, n)
    ex, split, _ = step_times(case)
    prof = channelProfile.profile(case) if PERF["on"] and n == 1 else None
    dt = [b - a for a, b in zip([0.0] + ex[:-1], ex)]
    mid = dt[1:-1] or dt
    res = {"wall_s": wall, "first_step_s": dt[0],
           "step_s": sum(mid) / len(mid), "write_step_s": dt[-1],
           "peak_B": peak, "write_B": last_write_size(case),
           "steps": len(dt)}
    if prof:
        res["profile"] = prof
    if split and N:
        # per cloud and step on the master rank; us per particle-step of
        # the whole run: times n ranks over the particles of all ranks
        rows = split[clouds:-clouds] if len(split) > 2 * clouds else split
        for i, k in enumerate(("tracking", "stage", "rest")):
            res[f"{k}_us"] = (1e6 * sum(r[i] for r in rows) / len(rows)
                              * n / N)
    return res


# --------------------------------------------------------------- preset

def preset_costs(pname, nps, steps, dec_timeout):
    p = channel.preset(pname)
    N = int(p["nParticles"])
    base = OUT / (pname if CONFIG["name"] == "C1"
                  else f"{pname}-{CONFIG['name']}")
    shutil.rmtree(base, ignore_errors=True)
    mesh = base / "mesh"
    mesh.mkdir(parents=True)
    for d in ("system", "constant"):
        shutil.copytree(TUTORIAL / d, mesh / d)
    shutil.copytree(TUTORIAL / "0.orig", mesh / "0")
    settings(mesh, pname, "unladen", steps, 1)
    out = {"preset": pname, "cells": p["n"][0] * p["n"][1] * p["n"][2],
           "particles": N, "config": CONFIG["name"]}
    out["blockMesh_s"] = run(["blockMesh"], mesh, "log.blockMesh")[0]
    run(["postProcess", "-func", "writeCellCentres", "-time", "0"], mesh,
        "log.postProcess")
    out["init_s"] = run(package_command(TUTORIAL, "channel.case", "init",
                                        "."), mesh, "log.init", "python3")[0]
    py = package_command(TUTORIAL, "channel.case.particles")
    for n in nps:
        r = out[f"np{n}"] = {}
        un = base / f"unladen_np{n}"
        branch(mesh, un, 1)
        settings(un, pname, "unladen", steps, n)
        if n > 1:
            r["decomposePar_fluid_s"] = run(["decomposePar", "-force"], un,
                                            "log.decomposePar")[0]
        r["unladen"] = stage(un, n, steps, 0, 0)
        if n > 1:       # the release reads the fluid of the serial case
            r["reconstructPar_fluid_s"] = run(
                ["reconstructPar", "-latestTime"], un,
                "log.reconstructPar")[0]
        print(f"{pname} np{n} unladen: {r['unladen']['step_s']:.3g} s/step",
              flush=True)
        l1 = base / f"laden1_np{n}"
        t = branch(un, l1, n)
        settings(l1, pname, "release", steps, n)
        run(["postProcess", "-func", "writeCellCentres", "-time", t], l1,
            "log.postProcess")
        w, mem, _ = run(["/usr/bin/time", "-f", "maxrss %M"] + py
                        + ["release", "."], l1, "log.release", "python3")
        m = re.search(r"maxrss (\d+)", (l1 / "log.release").read_text())
        r["release_s"] = w
        r["release_peak_B"] = 1024 * int(m.group(1)) if m else mem
        r["release_B"] = sum(disk(d / t / "lagrangian") for d in
                             [l1] + sorted(l1.glob("processor*"))
                             if (d / t / "lagrangian").is_dir())
        k = len(channelGroups.members(CONFIG["name"]))
        r["laden1"] = stage(l1, n, steps, N, k)
        print(f"{pname} np{n} laden1: {r['laden1']['step_s']:.3g} s/step",
              flush=True)
        l2 = base / f"laden2_np{n}"
        t = branch(l1, l2, n)
        channelParticles.branch_clouds(
            l2, t, channelGroups.branches(CONFIG["name"], MODELS))
        settings(l2, pname, "agglomeration", steps, n, MODELS)
        r["laden2"] = stage(l2, n, steps, N, 2 * k)
        print(f"{pname} np{n} laden2: {r['laden2']['step_s']:.3g} s/step",
              flush=True)
    if 2 in nps:
        l2 = base / "laden2_np2"
        out["reconstructPar_2clouds_s"] = run(
            ["reconstructPar", "-latestTime"], l2, "log.reconstructPar")[0]
    if 1 in nps:
        l1 = base / "laden1_np1"
        dec = base / "decompose_particles"
        branch(l1, dec, 1)
        (dec / "system/caseSettings").write_text(
            (l1 / "system/caseSettings").read_text().replace(
                "nProcs          1;", "nProcs          2;"))
        w, _, ok = run(["decomposePar", "-force"], dec, "log.decomposePar",
                       timeout=dec_timeout)
        out["decomposePar_particles_s"] = w if ok else None
        out["decomposePar_particles_timeout_s"] = None if ok else w
        shutil.rmtree(dec)
    for n in nps:
        if n > 1 and 1 in nps:
            for s in ("unladen", "laden1", "laden2"):
                out[f"np{n}"][s]["efficiency"] = (
                    out["np1"][s]["step_s"]
                    / (n * out[f"np{n}"][s]["step_s"]))
    return out


def table(res):
    gb = 1e9
    lines = ["| preset | cells | particles | ranks | unladen s/step |"
             " laden 1 cloud s/step | laden 2 clouds s/step |"
             " us/particle-step (tracking + stage + rest, 1 cloud) |"
             " first laden step s | peak GB (2 clouds) | B/particle |"
             " write GB (2 clouds) | efficiency (unladen/1/2 clouds) |",
             "|" + "---|" * 13]
    for r in res:
        for key in sorted(k for k in r if k.startswith("np")):
            n = int(key[2:])
            s = r[key]
            l1, l2, un = s["laden1"], s["laden2"], s["unladen"]
            group = ("" if r.get("config", "C1") == "C1"
                     else f" {r['config']}")
            us = (f"{l1.get('tracking_us', 0):.2f} + "
                  f"{l1.get('stage_us', 0):.2f} + "
                  f"{l1.get('rest_us', 0):.2f}")
            per = ((l2["peak_B"] - un["peak_B"]) / (2 * r["particles"])
                   if r["particles"] else 0)
            eff = ("/".join(f"{s[k]['efficiency']:.2f}" for k in
                            ("unladen", "laden1", "laden2"))
                   if "efficiency" in un else "-")
            lines.append(
                f"| {r['preset']}{group} | {r['cells']:,} |"
                f" {r['particles']:,} |"
                f" {n} | {un['step_s']:.3g} | {l1['step_s']:.3g} |"
                f" {l2['step_s']:.3g} | {us} | {l1['first_step_s']:.3g} |"
                f" {l2['peak_B'] / gb:.2f} | {per:.0f} |"
                f" {l2['write_B'] / gb:.3g} | {eff} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--presets", default="smoke small medium paper")
    ap.add_argument("--np", default="1 2")
    ap.add_argument("--steps", type=int, default=None,
                    help="steps per run (default: smoke 60, small 40,"
                    " medium 12, paper 6: the CPU clock ticks 0.01 s)")
    ap.add_argument("--decompose-timeout", type=float, default=600)
    ap.add_argument("--config", default="C1",
                    help="the configuration (default C1), or one-way ones"
                    " as clouds of one LES (C1+R80+R60): laden1 then has"
                    " a cloud per configuration, laden2 one per"
                    " configuration and model")
    ap.add_argument("--perf", action="store_true",
                    help="profile the serial runs (perf record) into"
                    " bench/results/channelProfile.md")
    a = ap.parse_args()
    PERF["on"] = a.perf
    CONFIG["name"] = a.config
    nps = [int(x) for x in a.np.split()]
    OUT.mkdir(parents=True, exist_ok=True)
    jf = OUT / ("profile.json" if a.perf else "results.json")
    old = json.loads(jf.read_text()) if jf.exists() else {}
    for pname in a.presets.split():
        steps = a.steps or STEPS.get(pname, 6)
        key = pname if a.config == "C1" else f"{pname} {a.config}"
        old[key] = preset_costs(pname, nps, steps, a.decompose_timeout)
        jf.write_text(json.dumps(old, indent=1))
    print(table([old[k] for k in old]))
    print(f"\n(all figures: {jf})")
    if a.perf:
        md = ROOT / "bench/results/channelProfile.md"
        md.write_text(channelProfile.profile_table([old[k] for k in old])
                      + "\n")
        print(f"(profile: {md})")


if __name__ == "__main__":
    main()
