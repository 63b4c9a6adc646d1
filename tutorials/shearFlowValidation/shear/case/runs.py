"""shearFlowValidation: the paper's laminar shear-flow validation (Appendix B)
against van de Ven & Mason theory and the Saffman-Turner collision kernel.

    ./Allrun [-preset paper|medium|small|ci] [-runs "detect EAM MAM"]
             [-j N] [-post] [-every S] [-study] [-reference]

Every run is a copy of this case under runs/<preset>/<run> (caseSettings
written from the preset, blockMesh, shear.case init, aggloPimpleFoam):
  detect  ghost contacts, no agglomeration: first contacts vs K_ST (B.6)
  EAM     energy-based agglomeration model
  MAM     momentum-based agglomeration model
  bounce  (optional) physical rebounds without agglomeration
Up to N runs at a time (-j, default: the number of cores, at most 3),
each printing a progress line with its ETA every S seconds (-every,
default 60).
An interrupted run continues from its last written time when Allrun is
called again; finished runs are kept (remove runs/<preset> to redo).
Then shear.case post writes the report into runs/<preset>/report/
(-reference: into results/<preset>/, the committed reference): summary.json,
regression.txt (printed at the end), alpha.png, counts.png, decay.png,
firstContacts.png, particlesEAM.png, particlesMAM.png; shear.post.replay
replays the runs' collision-event logs: replay.json, replay.txt,
alphaReplay<run>.png; shear.post.contacts replays the first contacts
spinless and splits them by partner: firstContactsSpinless.json, .txt.
-study runs the sensitivity study of the file study instead (each variant
an EAM and a MAM run under runs/<preset>/study/, resumable) and writes
runs/<preset>/study/report (-reference: results/study for small,
results/study-<preset> otherwise): study.json, study.txt, plots
(shear.study, doc/models.md 2.6).
Serial run times on one core of the 2-core development machine: README.md.
Ctrl-C stops every run it started (exit status 130); they continue from
their last complete write on the next call.
"""

import contextlib
import io
import os
import shutil
import sys
import time
import traceback

from aggloTools import runtimes, stages, times
from aggloTools.runner import foam_bin, package_command

from shear import TUTORIAL
from shear.case import settings
from shear.study import study



def options(argv):
    p = stages.Parser("shearFlowValidation", __doc__)
    p.add_argument("-preset", default="small")
    p.add_argument("-runs", default="detect EAM MAM")
    p.add_argument("-j", type=stages.positive("-j"),
                   default=min(os.cpu_count() or 1, 3))
    p.add_argument("-post", action="store_true")
    p.add_argument("-every", type=stages.positive("-every"), default=60)
    p.add_argument("-study", action="store_true")
    p.add_argument("-reference", action="store_true")
    return p.parse_args(argv)


def settings_text(a, run):
    """The caseSettings of a run (a study run: 'variant/run')."""
    if a.study:
        variant, name = run.split("/")
        return settings.settings_text(
            study.run_settings(a.preset, variant, name))
    return settings.settings_text(settings.settings(a.preset, run))


def run_dir(a, run):
    return TUTORIAL / "runs" / a.preset / ("study" if a.study else "") / run


def run_one(a, run):
    """Set up (unless its set-up ended), continue or keep one run."""
    d = run_dir(a, run)
    if (d / "runTime").is_file():
        print(f"    {run}: finished before, kept", flush=True)
        return
    append = False
    if not (d / "initialised").is_file():
        # A kill during the set-up leaves the mesh without particles
        if d.exists():
            shutil.rmtree(d)
        d.mkdir(parents=True)
        for name in ("0.orig", "constant", "system"):
            shutil.copytree(TUTORIAL / name, d / name)
        shutil.copytree(TUTORIAL / "0.orig", d / "0")
        (d / "system" / "caseSettings").write_text(settings_text(a, run)
                                                   + "\n")
        stages.run_logged(["blockMesh"], d, "log.blockMesh")
        stages.run_logged(package_command(TUTORIAL, "shear.case", "init",
                                          "."), d, "log.python.init")
        (d / "initialised").touch()
    else:
        print(f"    {run}: continuing from the last written time",
              flush=True)
        # A write cut off by a kill is set aside (OpenFOAM would stop on it)
        said = io.StringIO()
        with contextlib.redirect_stdout(said):
            times.set_aside_incomplete_times(d)
        for line in said.getvalue().splitlines():
            print(f"    {run}: {line}", flush=True)
        append = True
    wall = stages.run_solver(d, [foam_bin("aggloPimpleFoam")], run,
                             settings.progress, a.every, append=append)
    (d / "runTime").write_text(f"{round(wall)}\n")
    print(f"    {run}: done in {round(wall)} s", flush=True)


def work(a):
    if a.study:
        settings.presets()
        runs = [f"{v}/{r}" for v, r in study.run_list(a.preset)]
    else:
        runs = a.runs.split()
    # The preset and the runs checked before anything starts
    try:
        for run in runs:
            settings_text(a, run)
    except (SystemExit, KeyError, ValueError) as e:
        sys.stderr.write(f"Allrun: {e}\n")
        return 1

    start = time.monotonic()
    whole = not a.post and not any(run_dir(a, r).exists() for r in runs)
    job = f"shearFlowValidation {a.preset}" + (" study" if a.study else "")
    if not a.post:
        print(f"shearFlowValidation: preset {a.preset}, runs: "
              f"{' '.join(runs)}, {a.j} at a time", flush=True)

        def one(run):
            print(f"    {run}: started (log: "
                  f"{run_dir(a, run).relative_to(TUTORIAL)}/"
                  "log.aggloPimpleFoam)", flush=True)
            run_one(a, run)
        with stages.one_run(TUTORIAL / "runs" / a.preset,
                            f"shearFlowValidation -preset {a.preset}"):
            failed = stages.pool(runs, one, a.j)
        if failed:
            sys.stderr.write("Allrun: a run failed\n")
            return 1

    # Where the report goes: apart from the committed reference unless asked
    print()
    if a.study:
        out = f"runs/{a.preset}/study/report"
        if a.reference:
            out = "results/study" if a.preset == "small" \
                else f"results/study-{a.preset}"
        status = study.post(a.preset, None, out)
        print(runtimes.line(job, time.monotonic() - start, whole))
        return status

    out = f"runs/{a.preset}/report" if not a.reference \
        else f"results/{a.preset}"
    status = settings.main(["post", a.preset, "", out])
    # The collision-event logs replayed through EAM and MAM at three e_n,
    # and the first contacts as logged and spinless
    print()
    try:
        from shear.post import replay
        replay.replay(a.preset, None, out)
        print()
        from shear.post import contacts
        contacts.measure(a.preset, None, out)
    except Exception:
        traceback.print_exc()
        status = 1
    print()
    print(f"Results: {TUTORIAL / out} (regression.txt, summary.json, *.png)")
    print(runtimes.line(job, time.monotonic() - start, whole))
    return status


def main(argv):
    """The driver (python -m shear, ./Allrun) on the options argv."""
    return stages.drive(TUTORIAL, options, work, argv)
