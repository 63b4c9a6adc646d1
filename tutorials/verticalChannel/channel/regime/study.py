"""verticalChannel: the regime study of the main case (README.md, "The
regime study"). Why is `small` another flow of collisions than the
paper's? Each variant is `small`'s configuration C1 (EAM and MAM as two
clouds of one LES) with one shortcut changed: the phase lengths, the grid
or the particle number. Each is a preset of the presets file, run by
./Allrun -preset NAME (resumable; the long ones from a clone outside the
work tree, --runs). Nothing is tuned: every variant run is reported.

    channel.regime list                   the variants and what each changes
    channel.regime run [-np N] [-j J] [--runs DIR] [VARIANT ...]
                                            ./Allrun each (default: all),
                                            J at a time (default 1; with
                                            J > 1 each one's output goes
                                            to runs/<variant>.log)
    channel.regime post [--runs DIR] [--out DIR | --reference]
                          [--earlier JSON]
                                            regime.json, regime.txt,
                                            regime.png in DIR/report-regime
                                            (--reference: the committed
                                            results/regime)

--runs: the folder holding runs/<preset> (default: this tutorial's runs/);
post takes every variant with a finished agglomeration stage there;
of the others it reports how far they are and what their release and
dispersion stages show so far (an interim, not the window). --earlier
JSON keeps the finished results of that earlier regime.json for the
variants whose C1 runs are not under --runs (marked so; the folder may
hold other configurations' runs). A --runs
folder that holds no variant's runs is refused before anything is
written; the three files are written together (each to a temporary
file first), so a failed post leaves the earlier ones as they were."""

import argparse
import json
import os
import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from channel import TUTORIAL
from channel.regime import pairs
from channel.regime import trend
from channel.regime import verdict
from channel.regime.analysis import (MODELS, PAPER, analyse_variant, progress,
                                   runs_base)
from channel.regime.plots import plots
from channel.regime.report import table
from channel.regime.variants import DROPPED, VARIANTS


def post_folder(runs=None, out=None, reference=False):
    """Where post writes: out, else the committed results/regime with
    reference, else <runs>/report-regime."""
    if out:
        return Path(out)
    if reference:
        return TUTORIAL / "results" / "regime"
    return Path(runs or TUTORIAL / "runs") / "report-regime"


def earlier_variants(path):
    """The variants of an earlier regime.json (a missing or unreadable
    file stops naming it)."""
    try:
        return json.loads(Path(path).read_text()).get("variants", [])
    except (OSError, ValueError) as e:
        raise SystemExit(f"channel.regime post: --earlier {path}: {e}")


def earlier_results(variants):
    """The finished variants' results of earlier_variants: name ->
    result."""
    return {v["name"]: v["result"] for v in variants if v.get("result")}


def earlier_progress(variants):
    """The unfinished variants' progress of earlier_variants: name ->
    progress (how far their runs had come then)."""
    return {v["name"]: v["progress"] for v in variants
            if not v.get("result") and v.get("progress")}


def run_post(runs=None, out=None, names=None, reference=False,
             earlier=None):
    """The study's report of the variants under runs; with earlier (an
    earlier regime.json), a variant with no C1 runs there keeps its
    finished result from it (said so: its runs are gone, its numbers
    were measured), so that a variant run later is compared with those
    run before. Its folder may hold other configurations (the Table D.6
    matrix runs C2 and on at regime64 and regime48, with their unladen
    LES): the study is C1's."""
    before = earlier_variants(earlier) if earlier else []
    kept, begun = earlier_results(before), earlier_progress(before)
    runs_dir = Path(runs or TUTORIAL / "runs")
    if not runs_dir.is_dir():
        raise SystemExit(f"channel.regime post: no folder {runs_dir}")
    if not any(runs_base(runs, n).is_dir() for n in names or dict(VARIANTS)):
        raise SystemExit(f"channel.regime post: no variant has run under "
                         f"{runs_dir} (runs/<variant> of: "
                         f"{' '.join(names or dict(VARIANTS))}); nothing "
                         "written")
    final = post_folder(runs, out, reference)
    final.mkdir(parents=True, exist_ok=True)
    out = Path(tempfile.mkdtemp(prefix=".post-", dir=final))
    res = {"variants": []}
    what = dict(VARIANTS)
    for name in names or list(what):
        v = {"name": name, "changes": what.get(name, "-"),
             "runs": str(runs_base(runs, name)),
             "result": analyse_variant(name, runs)}
        if v["result"] is None and name in kept \
                and not (runs_base(runs, name) / "C1").is_dir():
            v["result"] = kept[name]
            v["from"] = str(earlier)
        if v["result"] is None:
            v["progress"] = progress(name, runs)
            if name in DROPPED:
                v["dropped"] = DROPPED[name]
                # a dropped variant's runs do not come back: how far they
                # had come, as the earlier report had it
                if v["progress"] is None and name in begun:
                    v["progress"], v["from"] = begun[name], str(earlier)
        res["variants"].append(v)
    res["gridTrend"] = trend.grid_trend(res, MODELS, PAPER)
    res["gridTrendFinestPair"] = trend.finest_pair(res, MODELS, PAPER)
    for check in pairs.CHECKS:
        res[check] = pairs.compare(res, MODELS, check)
    res["verdict"] = verdict.verdict(res, MODELS)
    try:
        (out / "regime.json").write_text(json.dumps(res, indent=1) + "\n")
        (out / "regime.txt").write_text(table(res))
        plots(res, out)
        for f in ("regime.json", "regime.txt", "regime.png"):
            if (out / f).is_file():
                os.replace(out / f, final / f)
            else:
                # no picture without a finished or growing variant: none
                # of an earlier post stays beside this report
                (final / f).unlink(missing_ok=True)
    finally:
        shutil.rmtree(out, ignore_errors=True)
    print(table(res))
    print(f"Written: {final}")
    return res


def run_variants(names, nprocs, jobs):
    """./Allrun -preset NAME -np nprocs of each variant, `jobs` at a time
    (on a machine of jobs x nprocs cores: two serial runs side by side
    make more steps per hour than one on two ranks, whose ranks wait on
    each other whenever another process takes a core). With jobs > 1
    each one's output goes to runs/<variant>.log. The exit status: the
    first failed variant's, in the order given."""
    def one(n):
        cmd = ["./Allrun", "-preset", n, "-np", str(nprocs)]
        if jobs == 1:
            return subprocess.call(cmd, cwd=TUTORIAL)
        log = TUTORIAL / "runs" / f"{n}.log"
        log.parent.mkdir(parents=True, exist_ok=True)
        with open(log, "a") as f:
            print(f"{n}: running, output in {log}", flush=True)
            rc = subprocess.call(cmd, cwd=TUTORIAL, stdout=f,
                                 stderr=subprocess.STDOUT)
        print(f"{n}: {'finished' if rc == 0 else f'failed ({rc})'}",
              flush=True)
        return rc

    with ThreadPoolExecutor(max_workers=jobs) as ex:
        rcs = list(ex.map(one, names))
    return next((rc for rc in rcs if rc), 0)


def main(argv):
    ap = argparse.ArgumentParser(prog="channel.regime",
                                 description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("list")
    r = sub.add_parser("run")
    r.add_argument("-np", type=int, default=1)
    r.add_argument("-j", type=int, default=1)
    r.add_argument("--runs")
    r.add_argument("variants", nargs="*")
    q = sub.add_parser("post")
    q.add_argument("--runs")
    where = q.add_mutually_exclusive_group()
    where.add_argument("--out")
    where.add_argument("--reference", action="store_true")
    q.add_argument("--earlier", help="an earlier regime.json whose "
                   "finished variants are kept where their runs are not "
                   "under --runs (e.g. results/regime/regime.json)")
    q.add_argument("variants", nargs="*")
    a = ap.parse_args(argv[1:])
    if getattr(a, "j", 1) < 1 or getattr(a, "np", 1) < 1:
        ap.error("run: -np and -j need a positive number")
    known = [n for n, _ in VARIANTS]
    for v in getattr(a, "variants", []):
        if v not in known:
            ap.error(f"unknown variant '{v}'; valid: {' '.join(known)}")
    if a.cmd == "list":
        for n, what in VARIANTS:
            print(f"{n:14s} {what}"
                  + (f" (dropped: {DROPPED[n]})" if n in DROPPED else ""))
    elif a.cmd == "run":
        if a.runs and Path(a.runs).resolve() != (TUTORIAL / "runs").resolve():
            ap.error("run: the runs go to this tutorial's runs/; run the "
                     "study from a clone outside the work tree instead")
        return run_variants(a.variants or [n for n in known
                                           if n not in DROPPED],
                            a.np, a.j)
    else:
        run_post(a.runs, a.out, a.variants or None, a.reference,
                 a.earlier)
    return 0

