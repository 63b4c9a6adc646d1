"""The verticalChannel tests' smoke runs and helpers: the tutorial's own
./Allrun, preset smoke (doc/cases.md A.11), configurations C1 and C2,
in a copy (tests/runs/test_verticalChannel), serially and on 2 MPI
ranks; the tutorial's scripts as modules; the runs' stage folders. The
session fixture smoke_runs (conftest.py) runs them once for every test
module of this folder."""

import os
import shutil
import subprocess

import numpy as np

from aggloTools.runner import project_dir, tutorial_module

ROOT = project_dir()
RUNS = ROOT / "tests" / "runs"
TUTORIAL = ROOT / "tutorials" / "verticalChannel"
STEPS_AGG = 30          # smoke: 0.6 T* at dt* = 0.02
N_RELEASED, N_PAIRS = 2000, 50
N_TOTAL = N_RELEASED + 2 * N_PAIRS


def run_smoke(tmp, np_):
    case = tmp / f"verticalChannel_np{np_}"
    if case.exists():
        shutil.rmtree(case)
    case.mkdir(parents=True)
    for name in ["0.orig", "constant", "system", "presets",
                 "breakupModels", "channel", "Allrun", "Allclean"]:
        src = TUTORIAL / name
        if src.is_dir():
            shutil.copytree(src, case / name,
                            ignore=shutil.ignore_patterns("__pycache__"))
        else:
            shutil.copy2(src, case / name)
    res = subprocess.run(
        ["./Allrun", "-preset", "smoke", "-configs", "C1 C2", "-np",
         str(np_), "-every", "600"], cwd=case, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, text=True, timeout=900,
        env=dict(os.environ, PWD=str(case)))
    (case / "log.Allrun").write_text(res.stdout)
    if res.returncode != 0:
        raise AssertionError(res.stdout[-4000:])
    return case


def script(name):
    """A script of the tutorial as a module (the siblings it imports
    found in the tutorial's folder)."""
    return tutorial_module("verticalChannel", name)


def agg_runs(case):
    base = case / "runs" / "smoke"
    return {("C1", "EAM"): base / "C1/agglomeration",
            ("C1", "MAM"): base / "C1/agglomeration",
            ("C2", "EAM"): base / "C2/agglomeration-EAM",
            ("C2", "MAM"): base / "C2/agglomeration-MAM"}


def last_profiles(adir, cloud):
    files = sorted((adir / "postProcessing" / f"{cloud}HardSphere").glob(
        "*/profiles.dat"), key=lambda f: float(f.parent.name))
    text = files[-1].read_text()
    return text, np.loadtxt(files[-1])


def write_dispersion(p, case, with_stats=True, cloud="particles",
                     counts=1):
    """A release uniform for its first 10 steps (alpha 1 everywhere), then
    20 steps with the slabs next to the walls at 3 and the rest at 1,
    written as the averages over 10 and 30 steps at T* 0.5 and 1.5 after
    the release; stats.dat: 4 collisions and 1 wall impact by the first
    write, 24 and 11 by the second (counters from 0 at the release),
    times counts; of the cloud named."""
    settings = script("channel.case.settings")
    nb = 16
    later = np.ones(nb)
    later[[0, -1]] = 3.0
    t0 = settings.end_time(p, "unladen")
    writes = ((10, np.ones(nb), t0 + 0.5 * p["tScale"], 4, 1),
              (30, (10 * np.ones(nb) + 20 * later) / 30,
               t0 + 1.5 * p["tScale"], 24, 11))
    base = case / "postProcessing" / f"{cloud}HardSphere"
    rows = [f"{t0:.17g} 0 0"]
    for n, alpha, t, ncol, nwall in writes:
        d = base / f"{t:.12g}"
        d.mkdir(parents=True)
        prof = "\n".join(f"{(i + 0.5) / nb:.6g} {float(a):.17g}"
                          for i, a in enumerate(alpha))
        (d / "profiles.dat").write_text(
            f"# Profiles of cloud {cloud} along (0 1 0), {n} steps "
            f"sampled\n# x alpha\n{prof}\n")
        rows.append(f"{t:.17g} {counts * ncol} {counts * nwall}")
    if with_stats:
        d = base / f"{t0:.12g}"
        d.mkdir(parents=True, exist_ok=True)
        (d / "stats.dat").write_text(
            f"# Hard-sphere statistics of cloud {cloud}\n# Time nCol nWall"
            "\n" + "\n".join(rows) + "\n")
    return t0
