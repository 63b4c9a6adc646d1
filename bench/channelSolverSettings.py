#!/usr/bin/env python3
"""The channel's solver settings against what they change: each variant
of system/fvSolution or system/fvSchemes of tutorials/verticalChannel
(one setting changed from the tutorial's) runs the unladen LES of a
preset over a declared window from the same developed flow, and its cost
per step, its u_tau/U_B and its mean and rms profiles are set against
those of the tutorial's settings over the same window.

    source etc/bashrc
    .venv/bin/python bench/channelSolverSettings.py [--preset small]
        [--from CASE] [--spinup 20] [--batches 10] [--batch 10]
        [--variants "base null UTol1e-6 ..."] [-j 2]
        [--cost-from CASE --cost-steps 150] [--add | --rejudge]
        [--cost-only "coarsest100 ..." --cost-from CASE]
        [--results channelSolverSettings]

The developed flow: the latest time of --from (an unladen run of the
preset, e.g. tutorials/verticalChannel/runs/small/unladen), else the
preset's unladen stage run here from the initial flow; then --spinup T*
more with the tutorial's settings. From there each variant runs
--batches solver runs of --batch T* each, averaging U (fieldAverage,
restarted at each run): a batch gives u_tau/U_B (from the mean driving
gradient, doc/cases.md A.10) and the profiles folded about the centre
plane (U, u', v', w' over U_B, <u'v'> over U_B^2).

Judged per quantity (and per bin of a profile), paired by batch: the
bias d = mean over batches of (variant - base), its standard error from
the batches' differences, and sigma_run, the standard error of the base's
own window mean (what a regression over this window resolves). The
regression can see a variant where, in some bin of some quantity, |d|
exceeds sigma_run and d is significant (|d| > t_0.975 SE, Student's t
with batches - 1 degrees of freedom): a run that has parted from the base
differs from it by about sqrt(2) sigma_run by noise alone, so its
difference must also be more than its own noise. `null` (the tutorial's
settings from the start flow rounded to 12 digits) shows what a change
of round-off alone gives.

--cost-from CASE (a developed flow of another grid, e.g. the medium one)
times --cost-steps serial steps of each variant from its latest time (and
of base again with --add, so that the new ones have a baseline timed
beside them). --add runs the variants that the stored study lacks (or
holds with other settings) from its start flow and adds them;
--rejudge judges the stored batches again and rewrites the report;
--cost-only times the tutorial's settings and the COST_ONLY variants
(GAMG's other knobs) at --cost-from and adds them to the report.
--results NAME: the report's name under bench/results (a later study
against changed tutorial settings beside an earlier one).

Writes bench/results/channelSolverSettings.json and .txt. About 5 min of
one core per variant at small (100 T*), two at a time with -j 2.
"""

import argparse
import json
import math
import re
import shutil
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

from aggloTools import batches, fields, foamfile, stages, times
from aggloTools.runner import (bench_module, package_command, project_dir,
                               run, tutorial_module)

ROOT = project_dir()
TUTORIAL = ROOT / "tutorials" / "verticalChannel"
channel = tutorial_module("verticalChannel", "channel.case.settings")

channelCosts = bench_module("channelCosts")
variants = bench_module("channelSolverVariants")
VARIANTS, COST_ONLY = variants.VARIANTS, variants.COST_ONLY
settings_of, write_settings = variants.settings_of, variants.write_settings
OUT = ROOT / "bench" / "runs" / "channelSolverSettings"
RESULTS = {"path": ROOT / "bench" / "results" / "channelSolverSettings"}
APP = "aggloPimpleFoam"

AVERAGE = """
functions
{
    average
    {
        type            fieldAverage;
        libs            ("libfieldFunctionObjects.so");
        writeControl    writeTime;
        restartOnRestart true;
        fields          ( U { mean on; prime2Mean on; base time; } );
    }
}
"""


def set_stage(case, pname, steps):
    """caseSettings of the unladen stage: `steps` steps from the latest
    time of case, written at the last."""
    channelCosts.settings(case, pname, "unladen", steps, 1)


def steps_of(pname, tstar_span):
    return round(tstar_span / channel.preset(pname)["dtStar"])


def tstar(case, pname):
    return float(times.time_dirs(case)[-1].name) / \
        channel.preset(pname)["tScale"]


def branch(src, dst):
    """dst: mesh, system, constant files and the latest time of src."""
    return stages.branch_case(src, dst, extra_constant=src / "constant")


def solve(case, log):
    run([APP], case, log, timeout=36000)


def developed_flow(a):
    """The start flow of every variant: OUT/start."""
    start = OUT / "start"
    if a.source:
        branch(Path(a.source).resolve(), start)
    else:
        start.mkdir(parents=True, exist_ok=True)
        for d in ("system", "constant"):
            shutil.copytree(TUTORIAL / d, start / d, dirs_exist_ok=True)
        shutil.copytree(TUTORIAL / "0.orig", start / "0", dirs_exist_ok=True)
        set_stage(start, a.preset,
                  steps_of(a.preset, channel.preset(a.preset)["unladen"]))
        run(["blockMesh"], start, "log.blockMesh")
        run(["postProcess", "-func", "writeCellCentres", "-time", "0"],
            start, "log.postProcess")
        run(package_command(TUTORIAL, "channel.case", "init", "."), start,
            "log.init")
        solve(start, "log.develop")
    write_settings(start, "base")
    set_stage(start, a.preset, steps_of(a.preset, a.spinup))
    solve(start, "log.spinup")
    t = times.time_dirs(start)[-1].name
    run(["postProcess", "-func", "writeCellCentres", "-time", t], start,
        "log.cellCentres")
    return start


def round_flow(case):
    """The start U rounded to 12 significant digits (the null variant)."""
    f = case / times.time_dirs(case)[-1].name / "U"
    text = f.read_text()
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*", text)
    u = foamfile.ascii_list(text, m.end())
    body = "\n".join("(%.12g %.12g %.12g)" % tuple(v) for v in u)
    end = text.index(")\n)", m.end()) + 3
    f.write_text(text[:m.end()] + f"{len(u)}\n(\n{body}\n)" + text[end:])


# --------------------------------------------------------------- batches

def log_steps(text):
    """Per step: the wall time, the driving gradients, and the iterations
    of the p solves and of the U component solves."""
    steps = []
    for block in re.split(r"\nTime = ", text)[1:]:
        it_p = [int(x) for x in re.findall(
            r"Solving for p,.*No Iterations (\d+)", block)]
        it_u = [int(x) for x in re.findall(
            r"Solving for U[xyz],.*No Iterations (\d+)", block)]
        g = [float(x) for x in re.findall(r"pressure gradient = (\S+)",
                                          block)]
        ex = re.search(r"ExecutionTime = (\S+) s", block)
        if ex:
            steps.append((float(ex.group(1)), g, it_p, it_u))
    return steps


def batch_values(case, t, log, y, p):
    """One batch's quantities from its log and written averages."""
    steps = log_steps((case / log).read_text())
    g = np.array([s[1][-1] for s in steps])
    ub = p["Ubar"]
    um = fields.read_internal(case / t / "UMean")
    r = fields.read_internal(case / t / "UPrime2Mean")
    prof = {k: (v / (ub**2 if k == "uv" else ub)).tolist() for k, v in
            fields.channel_profiles(y, um, r).items()}
    return {"uTauByUb": math.sqrt(max(g.mean(), 0) * p["delta"]) / ub,
            **step_stats(steps), "profiles": prof}


def step_stats(steps):
    """Mean step time (the first and the last, with start-up and write,
    left out), the number of steps and the mean iterations (p, pFinal,
    U's components summed) of log_steps' steps."""
    dt = np.diff([0.0] + [s[0] for s in steps])
    return {"step_s": float(dt[1:-1].mean()), "steps": len(steps),
            "itP": float(np.mean([s[2][0] for s in steps])),
            "itPFinal": float(np.mean([s[2][-1] for s in steps])),
            "itU": float(np.mean([sum(s[3]) for s in steps]))}


def run_variant(name, start, a):
    p = channel.preset(a.preset)
    case = OUT / name
    branch(start, case)
    write_settings(case, name)
    (case / "system" / "controlDict").write_text(
        (case / "system" / "controlDict").read_text() + AVERAGE)
    if name == "null":
        round_flow(case)
    y = fields.read_internal(start / times.time_dirs(start)[-1].name
                             / "C")[:, 1]
    out = []
    for b in range(a.batches):
        set_stage(case, a.preset, steps_of(a.preset, a.batch))
        log = f"log.batch{b}"
        solve(case, log)
        out.append(batch_values(case, times.time_dirs(case)[-1].name, log,
                                y, p))
        print(f"  {name} batch {b + 1}/{a.batches}: u_tau/U_B "
              f"{out[-1]['uTauByUb']:.5f}, {out[-1]['step_s']:.4f} s/step",
              flush=True)
    return out


def cost(name, src, steps, pname):
    """Serial s/step of a variant from the developed flow src."""
    case = OUT / "cost" / name
    branch(src, case)
    write_settings(case, name)
    set_stage(case, pname, steps)
    solve(case, "log.cost")
    return step_stats(log_steps((case / "log.cost").read_text()))


# --------------------------------------------------------------- judging

def judge(base, var):
    """Per quantity (u_tau/U_B, each profile): batches.paired_bias of the
    variant's batches against the base's."""
    keys = ["uTauByUb"] + [f"profiles.{k}" for k in base[0]["profiles"]]

    def rows(runs, k):
        if k.startswith("profiles."):
            return np.array([b["profiles"][k[9:]] for b in runs], float)
        return np.array([[b[k]] for b in runs], float)

    return {k: batches.paired_bias(rows(base, k), rows(var, k))
            for k in keys}


def report(res):
    # The width of the variant column: the longest name
    wn = max([12] + [len(n) for n in res["variants"]]
             + [len(n) for n in res.get("cost", {})])
    lines = [f"channelSolverSettings: preset {res['preset']}, "
             f"{res['batches']} batches of {res['batch']} T* from T* "
             f"{res['startTstar']:.0f}; serial; bias: the mean over the "
             "batches of variant - base",
             "base: the tutorial's fvSolution when the study ran (p: "
             + ", ".join(f"{k} {v}" for k, v in res["settings"]["base"]
                         ["solvers"]["p"].items())
             + "; U tolerance " + str(res["settings"]["base"]["solvers"]
                                      ["(U|UFinal)"]["tolerance"]) + ")",
             f"{'variant':<{wn}}  s/step  ratio  it p/pFinal/U    "
             "u_tau/U_B  largest |bias|/sigma_run (quantity, bias/SE)  "
             "visible"]
    base_s = np.mean([x["step_s"] for x in res["variants"]["base"]
                      ["batches"]])
    for name, v in res["variants"].items():
        b = v["batches"]
        q, w = max(v["judged"].items(), key=lambda kv: (
            kv[1]["significant"], kv[1]["biasBySigmaRun"]))
        st = np.mean([x["step_s"] for x in b])
        t = (abs(w["bias"]) / w["biasSE"] if w["biasSE"] else
             0.0 if w["bias"] == 0 else math.inf)
        lines.append(
            f"{name:<{wn}}  {st:.4f}  {st / base_s:5.3f}  "
            f"{np.mean([x['itP'] for x in b]):3.1f}/"
            f"{np.mean([x['itPFinal'] for x in b]):4.1f}/"
            f"{np.mean([x['itU'] for x in b]):4.1f}   "
            f"{np.mean([x['uTauByUb'] for x in b]):.5f}    "
            f"{w['biasBySigmaRun']:5.2f} ({q}, {t:.1f})"
            f"{'yes' if v['visible'] else 'no':>{max(3, 27 - len(q))}}")
    cost = res.get("cost", {})
    for name, c in cost.items():
        lines.append(f"cost {res['costCase']}: {name:<{wn}} {c['step_s']:.4f}"
                     f" s/step ({c['step_s'] / cost['base']['step_s']:.3f}"
                     f" of base), it p/pFinal/U {c['itP']:.1f}/"
                     f"{c['itPFinal']:.1f}/{c['itU']:.1f}")
    co = res.get("costOnly", {})
    for name, c in co.items():
        if name not in ("settings", "steps"):
            tol = co["settings"]["base"]["solvers"]["p"]["tolerance"]
            lines.append(
                f"cost only, {res['costCase']}, against the tutorial's "
                f"(p tolerance {tol}): {name:<14} "
                f"{c['step_s'] / co['base']['step_s']:.3f}, it p/pFinal "
                f"{c['itP']:.1f}/{c['itPFinal']:.1f}")
    return "\n".join(lines) + "\n"


def write(res):
    out = RESULTS["path"]
    out.parent.mkdir(parents=True, exist_ok=True)
    out.with_suffix(".json").write_text(json.dumps(res, indent=1))
    text = report(res)
    out.with_suffix(".txt").write_text(text)
    print(text, end="")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--preset", default="small")
    ap.add_argument("--from", dest="source")
    ap.add_argument("--spinup", type=float, default=20)
    ap.add_argument("--batches", type=int, default=10)
    ap.add_argument("--batch", type=float, default=10)
    ap.add_argument("--variants", default=" ".join(VARIANTS))
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("--cost-from")
    ap.add_argument("--cost-preset", default="medium")
    ap.add_argument("--cost-steps", type=int, default=150)
    ap.add_argument("--add", action="store_true")
    ap.add_argument("--rejudge", action="store_true")
    ap.add_argument("--cost-only")
    ap.add_argument("--results", default="channelSolverSettings")
    a = ap.parse_args(argv)
    RESULTS["path"] = RESULTS["path"].with_name(a.results)
    names = a.variants.split()
    unknown = [n for n in names if n not in VARIANTS]
    if unknown or "base" not in names or not 3 <= a.batches <= 31:
        sys.exit(f"channelSolverSettings: variants {unknown} unknown or base"
                 f" missing (valid: {' '.join(VARIANTS)}), or --batches "
                 f"{a.batches} outside 3-31")
    if a.cost_only is not None:
        valid = VARIANTS | COST_ONLY
        bad = [n for n in a.cost_only.split() if n not in valid]
        if bad or not a.cost_from:
            sys.exit(f"channelSolverSettings --cost-only: {bad} unknown "
                     f"(valid: {' '.join(valid)}) or no --cost-from")
        res = json.loads(RESULTS["path"].with_suffix(".json").read_text())
        res["costOnly"] = {"settings": {}, "steps": a.cost_steps}
        for n in ["base"] + a.cost_only.split():
            res["costOnly"][n] = cost(n, Path(a.cost_from).resolve(),
                                      a.cost_steps, a.cost_preset)
            res["costOnly"]["settings"][n] = settings_of(n)
        return write(res)
    if a.rejudge:
        res = json.loads(RESULTS["path"].with_suffix(".json").read_text())
        for v in res["variants"].values():
            v["judged"] = judge(res["variants"]["base"]["batches"],
                                v["batches"])
            v["visible"] = any(j["visible"] for j in v["judged"].values())
        return write(res)
    OUT.mkdir(parents=True, exist_ok=True)
    old = {}
    if a.add:
        old = json.loads(RESULTS["path"].with_suffix(".json").read_text())
        same = {k: old[k] == getattr(a, k)
                for k in ("preset", "batches", "batch")}
        if not all(same.values()) or not (OUT / "start").is_dir():
            sys.exit(f"channelSolverSettings --add: the stored study differs"
                     f" ({same}) or {OUT / 'start'} is gone")
        start = OUT / "start"
    else:
        start = developed_flow(a)
    res = {"preset": a.preset, "batches": a.batches, "batch": a.batch,
           "startTstar": tstar(start, a.preset), "settings": {},
           "variants": {}}
    runs = {n: v["batches"] for n, v in old.get("variants", {}).items()
            if old["settings"][n] == settings_of(n)}
    todo = [n for n in names if n not in runs]
    with ThreadPoolExecutor(max_workers=a.j) as ex:
        runs.update(zip(todo, ex.map(lambda n: run_variant(n, start, a),
                                     todo)))
    for n in runs:
        j = judge(runs["base"], runs[n])
        res["settings"][n] = settings_of(n)
        res["variants"][n] = {"batches": runs[n], "judged": j,
                              "visible": any(v["visible"]
                                             for v in j.values())}
    if a.cost_from:
        res["costCase"] = a.cost_preset
        res["cost"] = {n: c for n, c in old.get("cost", {}).items()
                       if n in runs and n not in todo}
        res["cost"].update({n: cost(n, Path(a.cost_from).resolve(),
                                    a.cost_steps, a.cost_preset)
                            for n in todo + ["base"] if n != "null"})
    write(res)


if __name__ == "__main__":
    main()
