#!/usr/bin/env python3
"""Benchmark of the hard-sphere cloud: cost of the collision stage against
the cost of tracking, measured in the same run, and memory per particle.

Set-up at the number density of the paper's 12 um channel case
(N_p = 6e6 in 2*pi x 2 x pi delta^3 with delta = 0.02 m gives
n = 1.9e10 m^-3 and 2.9 particles per cell on the 128^3 grid): a periodic
box holding N quartz particles of 12 um with random positions and Gaussian
velocities (sigma 0.5 m/s), fluid at rest (frozen), drag and gravity,
dt = 1.1e-5 s (the paper's channel step), 2.9 particles per cell.

For N = 1e4, 1e5, 3e5 it runs 21 steps with each pair search: the
baseline interactionLists (OpenFOAM's InteractionLists: mesh cells as
bins) and particleGrid (the default: swept boxes in a hashed grid), and
reports, per particle and step (first step excluded: it builds the
interaction lists; its time is reported apart):
  tracking [us], collision stage [us], their ratio (target <= 15 %),
  and the peak memory per particle against the same mesh without
  particles (target <= 400 B); then the ratio of the collision stages
  interactionLists / particleGrid measured in this run. The ratio of the
  per-particle costs at 3e5 and 1e4 checks O(N) (target: flat within
  30 %).

Usage (after ./Allwmake; about 6 minutes on one core):
    source etc/bashrc && .venv/bin/python bench/hardSphereCloud.py [N ...]
"""

import math
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

import hscase  # noqa: E402

N_DENSITY = 6e6 / (2 * math.pi * 2 * math.pi * 0.02**3)
PER_CELL = 6e6 / 128**3
D, DT, STEPS = 12e-6, 1.1e-5, 21


SEARCHES = ("interactionLists", "particleGrid")


def make_case(case, N, particles=True, search="particleGrid"):
    shutil.rmtree(case, ignore_errors=True)
    Lb = (N / N_DENSITY) ** (1 / 3)
    nc = max(2, round((N / PER_CELL) ** (1 / 3)))
    rng = np.random.default_rng(1)
    parts = []
    if particles:
        X = rng.uniform(0, Lb, (N, 3))
        U = rng.normal(0, 0.5, (N, 3))
        parts = [dict(x=tuple(x), U=tuple(u), id=i)
                 for i, (x, u) in enumerate(zip(X, U))]
    hscase.box_case(case, L=(Lb,) * 3, n=(nc,) * 3, kinds=("cyclic",) * 3,
                    particles=parts, dt=DT, end_time=STEPS * DT,
                    agglomeration="EAM",
                    forces="{ sphereDrag; gravity; }",
                    gravity=(0, -9.81, 0), rotation=True,
                    hard_sphere=hscase.KERNEL
                    + f"    pairSearch {search};\n"
                    + "    agglomerationModel EAM;\n    walls {}\n")
    return nc**3


def run(case):
    subprocess.run(["blockMesh"], cwd=case, check=True,
                   stdout=subprocess.DEVNULL)
    t0 = time.time()
    with open(Path(case) / "log.aggloPimpleFoam", "w") as log:
        p = subprocess.Popen(["aggloPimpleFoam"], cwd=case, stdout=log,
                             stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
    assert status == 0, f"aggloPimpleFoam failed in {case}"
    return usage.ru_maxrss * 1024, time.time() - t0


def times(case):
    text = (Path(case) / "log.aggloPimpleFoam").read_text()
    rows = re.findall(r"tracking ([0-9.eE+-]+) s, collision stage "
                      r"([0-9.eE+-]+) s", text)
    rows = np.array(rows, dtype=float)
    first = rows[0].sum()  # the first step builds the interaction lists
    rows = rows[1:]
    return rows[:, 0].sum(), rows[:, 1].sum(), len(rows), first



def main():
    Ns = [int(float(a)) for a in sys.argv[1:]] or [10000, 100000, 300000]
    work = ROOT / "bench" / "runs"
    results = {search: [] for search in SEARCHES}
    for N in Ns:
        empty = work / f"N{N}_empty"
        make_case(empty, N, particles=False)
        rss0, _ = run(empty)
        for search in SEARCHES:
            case = work / f"N{N}_{search}"
            cells = make_case(case, N, search=search)
            rss, wall = run(case)
            track, coll, steps, first = times(case)
            res = dict(N=N, cells=cells, steps=steps,
                       track_us=1e6 * track / (N * steps),
                       coll_us=1e6 * coll / (N * steps),
                       bytes=(rss - rss0) / N, wall=wall, first=first)
            res["ratio"] = res["coll_us"] / res["track_us"]
            results[search].append(res)
            print(f"N={N:>7} cells={cells:>7} {search:>16}: tracking "
                  f"{res['track_us']:.3f} us, collision stage "
                  f"{res['coll_us']:.3f} us per particle-step, "
                  f"collision/tracking {100*res['ratio']:.1f} %, first "
                  f"step {first:.2f} s, memory {res['bytes']:.0f} "
                  f"B/particle, run {wall:.1f} s", flush=True)
        a, b = results[SEARCHES[0]][-1], results[SEARCHES[1]][-1]
        print(f"N={N:>7}: collision stage {SEARCHES[0]} / {SEARCHES[1]} = "
              f"{a['coll_us']/b['coll_us']:.2f}, first step "
              f"{a['first']/b['first']:.2f}, run {a['wall']/b['wall']:.2f}",
              flush=True)
    for search in SEARCHES:
        r = results[search]
        if len(r) > 1:
            a, b = r[0], r[-1]
            print(f"O(N) check ({search}): per-particle cost at "
                  f"N={b['N']} / N={a['N']}: tracking "
                  f"{b['track_us']/a['track_us']:.2f}, collision stage "
                  f"{b['coll_us']/a['coll_us']:.2f} (target within 1.3)")


if __name__ == "__main__":
    main()
