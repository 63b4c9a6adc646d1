#!/usr/bin/env python3
"""Benchmark of the hard-sphere cloud: the whole cloud step per particle,
against OpenFOAM's own basicKinematicCloud run in the same script.

Box cases at the number density of the paper's 12 um channel case
(N_p = 6e6 in 2*pi x 2 x pi delta^3 with delta = 0.02 m: n = 1.9e10 m^-3,
2.9 particles per cell on the 128^3 grid) and at 10 times that density:
a periodic box of N quartz particles of 12 um, random positions, Gaussian
velocities (sigma 0.5 m/s), fluid at rest (frozen), sphereDrag and
gravity, no rotation, dt = 1.1e-5 s (the paper's channel step), 2.9
particles per cell at both densities (the mesh follows the particles).
N = 1e4, 1e5, 1e6; 21 steps each (300 at 1e4, 30 at 1e5). For each case it runs:

  ours    aggloPimpleFoam, collisionModel hardSphere (EAM, particleGrid);
          its log splits every cloud step into tracking, collision stage
          and the rest of the cloud step (vorticity, injection, sources,
          function objects, cloud info), so nothing hides outside the
          timers
  stock   aggloStockCloudBench (bench/stockCloud): basicKinematicCloud,
          same particles, forces and fluid, no collisions: its whole
          cloud step (evolve) is the baseline of our tracking
  IL      ours with pairSearch interactionLists (mesh cells as bins), at
          the paper's density for N <= 1e5 (the previous default)
  empty   both solvers on the same mesh without particles: memory baseline

and prints per particle-step [us] (first step apart: it is the set-up),
memory per particle (resident memory while stepping, minus the empty
case's), and the ratios of the pair search's targets: collision stage
<= 0.10 us and <= 10 % of tracking for N >= 1e5 at the paper's density;
per-particle cost flat within 30 % from 1e4 to 1e6; our tracking <= 1.10 x
stock; memory <= 300 B per particle at 1e6; first step <= 2 x an ordinary
step. Then the shear ghost case (shearFlowValidation `ci` geometry,
11,719 particles, ghost collisions, 400 steps) at dt*gammaDot = 0.005 and
0.05: the collision stage per particle-step at 0.05 over that at 0.005
(target <= 1.3; the tracking grows with the cell faces crossed).

Usage (after ./Allwmake; about 9 minutes on one core of the development
machine, peak memory about 2 GB):
    source etc/bashrc && .venv/bin/python bench/hardSphereCloud.py [N ...]

The cost of the collision-event log (doc/eventLog.md): the collision
stage of the same case with eventLog off and on, alternating, two runs
each (about 2 minutes at 1e5):
    .venv/bin/python bench/hardSphereCloud.py eventLog [N]
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

import numpy as np

from aggloTools.runner import package_command, project_dir
from hardSphereCloudCases import as_variant, make_case

ROOT = project_dir()

WORK = ROOT / "bench" / "runs"
# Memory per particle is reported from this N on: below it the particles'
# share of the resident memory is within the noise of sampling it
MEMORY_N = 1000000
SHEAR = ROOT / "tutorials" / "shearFlowValidation"


def vm_rss(pid):
    try:
        m = re.search(r"VmRSS:\s+(\d+)",
                      Path(f"/proc/{pid}/status").read_text())
    except OSError:
        return None
    return 1024 * int(m.group(1)) if m else None


def run(case, app="aggloPimpleFoam"):
    """blockMesh and the application; returns the largest resident
    memory seen while stepping (sampled after the first step; the peak of
    the whole run, reading included, if the steps were too quick to be
    sampled) and the wall time."""
    subprocess.run(["blockMesh"], cwd=case, check=True,
                   stdout=subprocess.DEVNULL)
    logp = Path(case) / f"log.{app}"
    peak = [0]

    done = threading.Event()

    def sample(pid):
        while not done.is_set():
            try:
                steps = logp.read_text().count("wall-clock time")
            except OSError:
                steps = 0
            rss = vm_rss(pid)
            if steps >= 1 and rss:
                peak[0] = max(peak[0], rss)
            time.sleep(0.05)

    t0 = time.time()
    with open(logp, "w") as log:
        p = subprocess.Popen([app], cwd=case, stdout=log,
                             stderr=subprocess.STDOUT)
        th = threading.Thread(target=sample, args=(p.pid,))
        th.start()
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = status
        done.set()
        th.join()
    assert status == 0, f"{app} failed in {case}"
    return peak[0] or usage.ru_maxrss * 1024, time.time() - t0


def ours_times(case):
    """Per step: tracking, collision stage, rest of the cloud step [s]."""
    text = (Path(case) / "log.aggloPimpleFoam").read_text()
    f = r"([0-9.eE+-]+)"
    rows = re.findall(rf"tracking {f} s, collision stage {f} s, rest of "
                      rf"the cloud step {f} s", text)
    return np.array(rows, dtype=float)


def stock_times(case):
    text = (Path(case) / "log.aggloStockCloudBench").read_text()
    rows = re.findall(r"Stock cloud wall-clock time: step ([0-9.eE+-]+)",
                      text)
    return np.array(rows, dtype=float)


def box(N, density, il):
    """All runs of one box case; a dict of per-particle-step figures."""
    tag = f"N{N}_x{density}"
    ours = WORK / f"{tag}_ours"
    cells = make_case(ours, N, density)
    empty = WORK / f"{tag}_empty"
    make_case(empty, N, density, particles=False)
    stock, stock0 = WORK / f"{tag}_stock", WORK / f"{tag}_stock0"
    as_variant(ours, stock, stock=True)
    as_variant(empty, stock0, stock=True)
    sorted_ = WORK / f"{tag}_sorted"
    make_case(sorted_, N, density, cell_order=True)
    stock_sorted = WORK / f"{tag}_stock_sorted"
    as_variant(sorted_, stock_sorted, stock=True)
    unsorted = WORK / f"{tag}_unsorted"
    as_variant(ours, unsorted, unsorted=True)

    res = dict(N=N, density=density, cells=cells)
    rss0, _ = run(empty)
    rss, res["wall"] = run(ours)
    t = ours_times(ours)
    n = N * (len(t) - 1)
    res["track"], res["stage"], res["rest"] = 1e6 * t[1:].sum(0) / n
    res["step"] = res["track"] + res["stage"] + res["rest"]
    res["first"] = t[0].sum() / (t[1:].sum(1).mean())
    res["bytes"] = (rss - rss0) / N

    srss0, _ = run(stock0, "aggloStockCloudBench")
    srss, _ = run(stock, "aggloStockCloudBench")
    s = stock_times(stock)
    res["stock"] = 1e6 * s[1:].sum() / (N * (len(s) - 1))
    res["stock_bytes"] = (srss - srss0) / N
    run(stock_sorted, "aggloStockCloudBench")
    s = stock_times(stock_sorted)
    res["stock_sorted"] = 1e6 * s[1:].sum() / (N * (len(s) - 1))

    # Ours with the cell order off: the gain of ordering on our cloud
    run(unsorted)
    tu = ours_times(unsorted)
    res["unsorted_track"], res["unsorted_stage"], _ = \
        1e6 * tu[1:].sum(0) / n

    if il:
        ilc = WORK / f"{tag}_IL"
        as_variant(ours, ilc, search="interactionLists")
        run(ilc)
        ti = ours_times(ilc)
        res["il_stage"] = 1e6 * ti[1:, 1].sum() / n
        res["il_first"] = ti[0].sum() / (ti[1:].sum(1).mean())
    for c in (ours, empty, stock, stock0, sorted_, stock_sorted, unsorted):
        shutil.rmtree(c, ignore_errors=True)
    return res


def ghost(dt_gamma, steps=400):
    """The shear ghost case at one step: per particle-step [us]."""
    case = WORK / f"ghost_{dt_gamma}"
    shutil.rmtree(case, ignore_errors=True)
    case.mkdir(parents=True)
    for d in ("0.orig", "constant", "system"):
        shutil.copytree(SHEAR / d, case / d)
    shutil.copytree(SHEAR / "0.orig", case / "0")
    text = subprocess.run(package_command(SHEAR, "shear.case", "settings",
                                          "ci", "detect"), check=True,
                          text=True, capture_output=True).stdout
    gamma = float(re.search(r"gammaDot\s+([0-9.eE+-]+);", text).group(1))
    dt = dt_gamma / gamma
    for key, val in (("deltaT", dt), ("endTime", steps * dt),
                     ("writeInterval", 10 * steps * dt)):
        text = re.sub(rf"\n{key}\s+[^;]+;", f"\n{key} {val!r};", text)
    (case / "system" / "caseSettings").write_text(text)
    subprocess.run(["blockMesh"], cwd=case, check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run(package_command(SHEAR, "shear.case", "init", "."),
                   cwd=case, check=True, stdout=subprocess.DEVNULL)
    with open(case / "log.aggloPimpleFoam", "w") as log:
        subprocess.run(["aggloPimpleFoam"], cwd=case, stdout=log,
                       stderr=subprocess.STDOUT, check=True)
    t = ours_times(case)
    N = int(re.search(r"nParticles\s+(\d+);", text).group(1))
    out = 1e6 * t[1:].sum(0) / (N * (len(t) - 1))
    shutil.rmtree(case, ignore_errors=True)
    return dict(zip(("track", "stage", "rest"), out), step=out.sum())


def event_log(N, repeats=2):
    """The collision stage with the event log off and on (same case,
    alternating runs): per particle-step [us] and the log's bytes per
    event."""
    tag = f"N{N}_log"
    off, on = WORK / f"{tag}_off", WORK / f"{tag}_on"
    make_case(off, N, 1)
    as_variant(off, on, log=True)
    stage = {"off": [], "on": []}
    for _ in range(repeats):
        for name, c in (("off", off), ("on", on)):
            shutil.rmtree(c / "postProcessing", ignore_errors=True)
            run(c)
            t = ours_times(c)
            stage[name].append(1e6 * t[1:, 1].sum() / (N * (len(t) - 1)))
    logs = list((on / "postProcessing").glob("*CollisionEvents/*.bin"))
    size = sum(f.stat().st_size - 128 for f in logs)
    events = size // 220
    for c in (off, on):
        shutil.rmtree(c, ignore_errors=True)
    return dict(off=min(stage["off"]), on=min(stage["on"]), runs=stage,
                events=events, bytes=size / max(events, 1))


def verdict(ok):
    return "met" if ok else "MISSED"


def main():
    if sys.argv[1:2] == ["eventLog"]:
        N = int(float(sys.argv[2])) if len(sys.argv) > 2 else 100000
        r = event_log(N)
        print(f"collision event log, N = {N:g} at the paper's density: "
              f"collision stage {r['off']:.3f} us per particle-step off, "
              f"{r['on']:.3f} on (on/off {r['on']/r['off']:.2f}; best of "
              f"{len(r['runs']['off'])} alternating runs: off "
              + ", ".join(f"{v:.3f}" for v in r["runs"]["off"]) + "; on "
              + ", ".join(f"{v:.3f}" for v in r["runs"]["on"]) + "); "
              f"{r['events']} events logged, {r['bytes']:.0f} B each")
        return
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("N", nargs="*", type=float,
                    default=[1e4, 1e5, 1e6], help="cloud sizes")
    ap.add_argument("--densities", default="1 10",
                    help="multiples of the paper's number density")
    ap.add_argument("--paper", action="store_true",
                    help="add N = 6e6 at the paper's density (the "
                    "channel's cloud; about 10 GB and 15 minutes)")
    ap.add_argument("--json", metavar="FILE",
                    help="write the figures of every case to FILE")
    ap.add_argument("--no-ghost", action="store_true",
                    help="skip the shear ghost case")
    args = ap.parse_args()
    Ns = sorted({int(n) for n in args.N})
    densities = [int(float(d)) for d in args.densities.split()]
    results = []
    print(f"{'n/n_paper':>9} {'N':>8} {'cells':>7} | per particle-step "
          f"[us]: {'track':>6} {'stage':>6} {'rest':>6} {'step':>6} | "
          f"{'stock':>6} {'sorted':>6} | unsorted {'track':>6} "
          f"{'stage':>6} | {'1st/step':>8} | B/particle ours stock",
          flush=True)
    for density in densities:
        sizes = Ns + ([6000000] if args.paper and density == 1 else [])
        for N in sizes:
            r = box(N, density, il=density == 1 and N <= 100000)
            results.append(r)
            print(f"{density:>9} {N:>8} {r['cells']:>7} | {'':>22}"
                  f"{r['track']:6.3f} {r['stage']:6.3f} {r['rest']:6.3f} "
                  f"{r['step']:6.3f} | {r['stock']:6.3f} "
                  f"{r['stock_sorted']:6.3f} | {'':>8} "
                  f"{r['unsorted_track']:6.3f} {r['unsorted_stage']:6.3f} "
                  f"| {r['first']:8.2f} | "
                  + (f"{r['bytes']:15.0f} {r['stock_bytes']:5.0f}"
                     if N >= MEMORY_N else f"{'n/r':>15} {'n/r':>5}"),
                  flush=True)
            if "il_stage" in r:
                print(f"{'':>9} {'':>8} {'':>7}   interactionLists: stage "
                      f"{r['il_stage']:.3f} us ({r['il_stage']/r['stage']:.2f}"
                      f" x particleGrid), first step {r['il_first']:.2f} x "
                      "an ordinary step", flush=True)

    print("\nTargets (ratios within this run; stock: OpenFOAM's "
          "basicKinematicCloud, unsorted as users have it):")
    for density in densities:
        rs = {r["N"]: r for r in results if r["density"] == density}
        tag = f"{density} x paper density"
        lo, hi = min(rs), max(rs)
        if hi >= 1000000 and lo <= 10000:
            q = rs[hi]["track"] / rs[lo]["track"]
            print(f"  {tag}: tracking at N={hi:.0e} / at N={lo:.0e} = "
                  f"{q:.2f} <= 1.6: {verdict(q <= 1.6)} (stock "
                  f"{rs[hi]['stock']/rs[lo]['stock']:.2f}, stock sorted "
                  f"{rs[hi]['stock_sorted']/rs[lo]['stock_sorted']:.2f})")
        for N, r in sorted(rs.items()):
            if N >= 1000000:
                q = r["track"] / r["stock"]
                print(f"  {tag}, N={N:.0e}: tracking / stock {q:.2f} <= "
                      f"0.5: {verdict(q <= 0.5)}")
                print(f"  {tag}, N={N:.0e}: memory {r['bytes']:.0f} "
                      f"B/particle <= 350: {verdict(r['bytes'] <= 350)} "
                      f"(stock {r['stock_bytes']:.0f})")
            if N >= 100000:
                bound = 0.25 if N >= 1000000 else 0.35
                q = r["stage"] / r["stock"]
                print(f"  {tag}, N={N:.0e}: collision stage / stock "
                      f"{q:.2f} <= {bound}: {verdict(q <= bound)}")

    if args.json:
        cases = [dict(density=r["density"], N=r["N"],
                      tracking_us=r["track"], stage_us=r["stage"],
                      rest_us=r["rest"], stock_us=r["stock"],
                      stock_sorted_us=r["stock_sorted"],
                      unsorted_tracking_us=r["unsorted_track"],
                      unsorted_stage_us=r["unsorted_stage"],
                      memory_B=(r["bytes"] if r["N"] >= MEMORY_N
                                else None),
                      stock_memory_B=(r["stock_bytes"]
                                      if r["N"] >= MEMORY_N else None),
                      first_step_ratio=r["first"])
                 for r in results]
        Path(args.json).write_text(json.dumps({"cases": cases}, indent=1)
                                   + "\n")
        print(f"\nFigures: {args.json}")

    if args.no_ghost:
        return
    g1, g2 = ghost(0.005), ghost(0.05)
    print("\nShear ghost case (ci geometry, 11,719 particles), per "
          "particle-step [us]:")
    for name, g in (("0.005", g1), ("0.05", g2)):
        print(f"  dt*gammaDot = {name:>5}: tracking {g['track']:.3f}, "
              f"collision stage {g['stage']:.3f}, rest {g['rest']:.3f}, "
              f"cloud step {g['step']:.3f}")
    q = g2["stage"] / g1["stage"]
    print(f"  collision stage at 0.05 / at 0.005 = {q:.2f} <= 1.3: "
          f"{verdict(q <= 1.3)} (whole cloud step "
          f"{g2['step']/g1['step']:.2f}, tracking "
          f"{g2['track']/g1['track']:.2f}: ten times the displacement "
          "crosses more cell faces)")


if __name__ == "__main__":
    main()
