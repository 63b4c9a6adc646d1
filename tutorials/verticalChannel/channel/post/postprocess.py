"""verticalChannel post-processing: frequencies by Eq. 87 of each run,
then the Table D.6 regression (channel.post.regression), the report's text
(channel.post.report), plots and the particle picture (channel.plots.profiles).

    channel.post PRESET [--reference]
        the report runs/PRESET/report: summary.json, regression.txt,
        plots, comparison.txt (against the committed reference
        results/PRESET); --reference writes the reference itself
        (exit 1 on a FAIL)

Every run's statistics come from postProcessing/<model>HardSphere of its
agglomeration stage (counters zeroed at the start of the stage)."""

import argparse
import json
import math
import re
import sys
from pathlib import Path

import numpy as np

from channel import TUTORIAL
from channel.case import groups, settings
from channel.post import contacts
from aggloTools.stats import read_stats
from aggloTools.uncertainty import window_rate
from channel.plots.matrix import matrix_figure
# picture: postprocess.picture for the callers of the report
from channel.plots.profiles import picture, plots  # noqa: F401
from channel.post.gridCheck import GRID_CHECK, grid_rows
from channel.post import nearWall
from channel.post.regression import R, regression
from channel.post.report import compare, write_regression
from channel.post.studyRuns import record_rows, study_runs


# ------------------------------------------------------------------ runs

def run_dirs(pname, base=None):
    """(config, model) -> (case directory, cloud name) of the finished
    agglomeration stages of a preset (under runs/PRESET, or base)."""
    base = Path(base) if base else TUTORIAL / "runs" / pname
    out = {}
    if not base.exists():
        return out
    for cdir in sorted(p for p in base.iterdir() if p.is_dir()):
        for adir in sorted(cdir.glob("agglomeration*")):
            if not (adir / "done.agglomeration").exists():
                continue
            s = settings.read_settings(adir)
            clouds = [str(c).strip("()") for c in
                      (s["clouds"] if isinstance(s["clouds"], list)
                       else [s["clouds"]])]
            for m in clouds:
                if m:
                    # a group's clouds are its configurations' (groups)
                    k = groups.cloud_key(cdir.name, m)
                    if k in out:
                        sys.exit(f"channel.post: {k[0]} {k[1]} ran twice,"
                                 f" in {out[k][0]} and in {adir}: remove "
                                 "one of them")
                    out[k] = (adir, m)
    return out


def analyse_run(p, adir, cloud):
    st = read_stats(adir, cloud)
    t0 = settings.end_time(p, "dispersion")
    T = (st["Time"] - t0) / p["tScale"]
    T = np.concatenate(([0.0], T))
    w0, w1 = p["window"]
    # the case relative to the tutorial, or absolute when the runs are
    # kept elsewhere (a clone outside the work tree)
    try:
        case = str(adir.relative_to(TUTORIAL))
    except ValueError:
        case = str(adir)
    r = {"case": case, "cloud": cloud}
    for key, col in (("col", "nCol"), ("agg", "nAgg"),
                     ("colFirst", "nColFirst"), ("wall", "nWall")):
        n = np.concatenate(([0.0], st[col]))
        f, sb, sp, dn = window_rate(T, n, w0, w1)
        r[f"f_{key}"] = f
        r[f"sigma_{key}"] = max(sb, sp)
        r[f"sigmaBatch_{key}"] = sb
        r[f"sigmaPoisson_{key}"] = sp
        r[f"events_{key}"] = dn
        r[f"N_{key}_end"] = float(n[-1])
        # the whole stage too (doc/cases.md A.8: reported in addition)
        r[f"f_{key}_wholeStage"] = float(n[-1] / T[-1])
    r["alpha_f"] = r["f_agg"] / r["f_col"] if r["f_col"] > 0 else None
    r["alpha_end"] = (r["N_agg_end"] / r["N_col_end"]
                      if r["N_col_end"] > 0 else None)
    # the particles this run released (a preset's perConfiguration entry
    # may give a configuration its own number)
    r["nParticles"] = int(settings.read_settings(adir)["nParticles"])
    s2 = (settings.N_PAPER / r["nParticles"])**2
    r["scale"] = s2
    r["f_col_scaled"] = r["f_col"] * s2
    r["f_agg_scaled"] = r["f_agg"] * s2
    r["Np_end"] = float(st["nParticles"][-1])
    r["Npp_end"] = float(st["nPrimariesInAgglomerates"][-1])
    r["nAgglomerates_end"] = float(st["nAgglomerates"][-1])
    r["maxPrimaries"] = float(st["maxPrimaries"].max())
    r["D10_end"] = float(st["D10"][-1])
    r["T_end"] = float(T[-1])
    # conservation and consistency (hard checks)
    m = st["mass"]
    r["massRelErr"] = float(np.max(np.abs(m / m[0] - 1)))
    r["primariesConstant"] = bool(np.all(st["nPrimaries"]
                                         == st["nPrimaries"][0]))
    cnt = [c for c in st if c.startswith("n") and c not in (
        "nParticles", "nPrimaries", "nAgglomerates",
        "nPrimariesInAgglomerates")]
    r["countersNonDecreasing"] = bool(all(np.all(np.diff(st[c]) >= 0)
                                          for c in cnt))
    # each agglomeration makes one particle of two, each break-up two of
    # one (the counters nBreakup<Mechanism>; NoRoom counts waits)
    splits = sum((st[c] for c in st if c.startswith("nBreakup")
                  and c != "nBreakupNoRoom"), np.zeros_like(st["nAgg"]))
    r["NpBalance"] = bool(np.all(st["nParticles"] == st["nPrimaries"][0]
                                 - st["nAgg"] + splits))
    r["_breakupCounted"] = any(c.startswith("nBreakup") for c in st)
    r["_series"] = {"T": T[1:], "nCol": st["nCol"], "nAgg": st["nAgg"],
                    "Npp": st["nPrimariesInAgglomerates"],
                    "Np": st["nParticles"], "D10": st["D10"]}
    return r


def step_values(log, pattern, times=False):
    """The values of a pattern in a solver log, every match of every time
    step in order; a run resumed with -append repeats the steps after its
    last write, and those repeated steps replace the killed run's (later
    wins). times: (time, value) pairs instead."""
    steps = []          # (time, [values])
    for line in log.splitlines():
        if line.startswith("Time = "):
            t = float(line.split()[2])
            while steps and steps[-1][0] >= t:
                steps.pop()
            steps.append((t, []))
        elif steps:
            m = re.search(pattern, line)
            if m:
                steps[-1][1].append(float(m.group(1)))
    return [(t, v) if times else v for t, vals in steps for v in vals]


def u_tau(p, case):
    """u_tau from the mean driving gradient over the second half of the
    stage in case (fluid check of doc/cases.md A.10): u_tau^2 = delta <G>;
    (None, None) where the case has no solver log."""
    f = case / "log.aggloPimpleFoam"
    if not f.is_file():
        return None, None
    log = f.read_text(errors="replace")
    g = np.array(step_values(log, r"pressure gradient = ([-0-9.eE+]+)"))
    if not len(g):
        return None, None
    g = g[len(g) // 2:]
    G = float(g.mean())
    return math.sqrt(max(G, 0) * p["delta"]), G


# ------------------------------------------------------------------ post

def grid_results(pname):
    """The runs of the preset pname analysed as post's (with C1 from the
    regime study where it has no C1 run): {(config, model): record}."""
    p = settings.preset(pname)
    runs = run_dirs(pname)
    res = {k: analyse_run(p, adir, cloud)
           for k, (adir, cloud) in runs.items()}
    res.update(study_runs(p, res))
    return res


def post(pname, reference=False):
    p = settings.preset(pname)
    runs = run_dirs(pname)
    out = settings.report_dir(pname, reference)
    # C1 from the regime study's record where the preset has no C1 run
    study = study_runs(p, runs)
    if not runs and not study:
        print(f"channel.post: no finished runs under runs/{pname}: "
              "nothing written")
        return 1
    out.mkdir(parents=True, exist_ok=True)
    fluid = {}
    # the unladen LES is this preset's, or its stagesFrom preset's
    ut, G = u_tau(p, (TUTORIAL / "runs" / (p["stagesFrom"] or pname)
                      / "unladen"))
    if ut:
        fluid["unladen"] = {"uTauByUb": ut / p["Ubar"], "gradient": G}
    res = {}
    for k, (adir, cloud) in runs.items():
        res[k] = analyse_run(p, adir, cloud)
        res[k]["nProcs"] = int(settings.read_settings(adir)["nProcs"])
        cd = contacts.contact_distributions(adir, cloud, p, *p["window"])
        share, sigma = contacts.near_wall_share(cd)
        res[k]["nearWallShare"], res[k]["nearWallSigma"] = share, sigma
        ut_k, G_k = u_tau(p, adir)
        if ut_k:
            res[k]["uTau"] = ut_k
            # a group's runs share one fluid: named once, by its folder
            fluid[f"{adir.parent.name} {adir.name}"] = {
                "uTauByUb": ut_k / p["Ubar"], "gradient": G_k}
    for k, r in study.items():
        res[k] = r
        if r.get("uTau") and k[1] == p["models"][0]:
            fluid[f"{k[0]} agglomeration (the regime study's)"] = {
                "uTauByUb": r["uTau"] / p["Ubar"], "gradient": None}
    rows = regression(p, res)
    # the statements on where the particles are when agglomeration starts
    rows += nearWall.concentration_rows(R, p)
    # C1's own run against the study's record of it, where both exist
    rows += record_rows(R, p, res)
    if pname in GRID_CHECK:
        # the judged ratios at the coarser grid too (gridCheck)
        rows += grid_rows(R, res, grid_results(GRID_CHECK[pname]))
    nf = write_regression(out / "regression.txt", p, rows, fluid, res)
    summary = {
        "preset": pname,
        "nParticles": p["nParticles"],
        "window": p["window"],
        "scale_s2": (settings.N_PAPER / p["nParticles"])**2,
        "fluid": fluid,
        "runs": {f"{c} {m}": {k: v for k, v in r.items()
                              if not k.startswith("_")}
                 for (c, m), r in sorted(res.items())},
        "regression": rows,
    }
    (out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
    # time histories and profiles: of the runs' own files (none where
    # every configuration's numbers are the study's)
    own = {k: r for k, r in res.items() if "_series" in r}
    if own:
        plots(out, p, own, runs)
    matrix_figure(out, p, res)
    picture(out, p, runs)
    print((out / "regression.txt").read_text())
    if not reference:
        text = compare(rows, settings.report_dir(pname, True)
                       / "summary.json", summary["runs"])
        (out / "comparison.txt").write_text(text + "\n")
        print(text.splitlines()[-1])
    return 1 if nf else 0


def command(argv, prog, doc, run, preset_help, reference_help,
            runs_help=None, options=None):
    """The command line of a report of a preset (channel.post and its
    siblings): PRESET [RUNS] [--reference], and the options a report adds
    (options(parser)), the preset checked before run(args) makes the
    report (an unknown preset: its message, exit 1)."""
    ap = argparse.ArgumentParser(
        prog=prog, description=doc.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("preset", help=preset_help)
    if runs_help:
        ap.add_argument("runs", nargs="?", help=runs_help)
    ap.add_argument("--reference", action="store_true", help=reference_help)
    if options:
        options(ap)
    a = ap.parse_args(argv)
    try:
        settings.preset(a.preset)
    except SystemExit as e:
        sys.stderr.write(f"{e}\n")
        return 1
    return run(a)


def main(argv):
    return command(argv, "channel.post", __doc__,
                   lambda a: post(a.preset, a.reference),
                   "the preset whose runs/PRESET is post-processed",
                   "write the committed reference results/PRESET instead "
                   "of runs/PRESET/report")