"""verticalChannel: the paper's downward turbulent channel flow with
four-way coupled 12/4 um quartz particles (doc/cases.md Part A).

    ./Allrun [-preset NAME] [-configs "C1 C2 ..."]
             [-matrix] [-np N] [-post] [-every S] [-reference]

  -preset   (default small) a preset of the presets file: smoke (the
            tests'), small, regime64 (the paper's regime: comparisons
            with the paper), printed (the paper's printed resolution),
            medium, paper, and the regime study's variants; README.md
            says what each resolves, 'Run times' what each costs
  -configs  (default C1) configurations of the presets file:
            C1 C2 C3 C4 (Table D.6) R80 R60 (restitution variation),
            C1sgs C1lift C1shearLift C1rotationLift C2noSgs C2noLift
            C2oneWay (C2's sub-models split: preset subModelProbe);
            one-way configurations joined with '+' (R80+R60) run as
            clouds of one LES (channel.case.groups): the fluid solved
            once for all of them, each its own clouds (runs/<preset>/
            R80+R60/, clouds R80 R60, then R80EAM R80MAM R60EAM R60MAM);
            each configuration runs once: named twice, or run before
            under another name (alone, in another group), it stops the
            call before anything starts
  -matrix   the paper's, EAM and MAM each: -configs "C1+R80+R60 C2 C3
            C4", the one-way ones (C1, R80, R60) as clouds of one LES,
            each cloud what its run alone gives, byte for byte (at
            regime64 about 84 CPU hours instead of 103 run alone:
            -configs "C1 C2 C3 C4 R80 R60", README.md)
  -np       MPI ranks of every solver run (default 1: serial); a stage
            finished on another number of ranks is kept as it is
  -post     only the post-processing of what has been run
  -every    seconds between progress lines (default 60)
  -reference  write the report into results/<preset>/, the committed
            reference, instead of runs/<preset>/report/

Stages, each a run of aggloPimpleFoam under runs/<preset>/:
  unladen/                  single-phase LES from a perturbed profile
  <config>/dispersion/      release (all particles at once, cloud
                            "particles") and dispersion: collisions on,
                            agglomeration off
  <config>/agglomeration/   from the end of dispersion, counters zeroed:
                            clouds EAM and MAM in one run (one-way
                            coupled: both see the same LES), or
  <config>/agglomeration-EAM/, -MAM/   one run per model (two-way)
A preset with `stagesFrom NAME` (presets) runs its agglomeration stages
only, branched from runs/NAME/<config>/dispersion once NAME has finished
it. A stage that is interrupted continues from its last written time when
Allrun is called again; finished stages are kept (remove runs/<preset>
to redo). Then channel.post writes the report runs/<preset>/report/:
summary.json, regression.txt (printed), plots, a pyvista picture and
comparison.txt (against the committed reference results/<preset>/,
which only -reference rewrites); the VTK files of
the last time are under runs/<preset>/<config>/.../VTK (foamToVTK);
channel.post.replay replays the agglomeration stages' collision-event logs
(replay.json, replay.txt, alphaReplay<config><cloud>.png).
channel.post.dispersion reports how each configuration's particles reach
the walls in its release and dispersion (dispersion.txt, dispersion.json;
nothing for a preset that branches from another's dispersion).
A preset with break-up: channel.post.breakup (breakup.txt, breakup.json,
breakupHistory.png, breakupSizes.png).
Ctrl-C stops every run it started (exit status 130).
Run times on the 2-core development machine: README.md.
"""

import contextlib
import io
import shutil
import subprocess
import sys
import time
from pathlib import Path

from aggloTools import progress as prog, runtimes, stages, times
from aggloTools.runner import CommandError, package_command

from channel import TUTORIAL
from channel.case import groups, particles, settings

#: The Table D.6 matrix and the restitution pair, the one-way
#: configurations in one LES (groups)
MATRIX = "C1+R80+R60 C2 C3 C4"


def options(argv):
    p = stages.Parser("verticalChannel", __doc__)
    p.add_argument("-preset", default="small")
    p.add_argument("-configs", default="C1")
    p.add_argument("-matrix", action="store_true")
    p.add_argument("-np", type=stages.positive("-np"), default=1)
    p.add_argument("-post", action="store_true")
    p.add_argument("-every", type=stages.positive("-every"), default=60)
    p.add_argument("-reference", action="store_true")
    a = p.parse_args(argv)
    stages.within_cores(p, a.np)
    if a.matrix:
        a.configs = MATRIX
    return a


def progress(case):
    """One line: stage, T*, fraction done and ETA from the solver log."""
    case = Path(case)
    s = settings.read_settings(case)
    p = settings.preset(s["preset"])
    t_end = float(s["endTime"])
    now = prog.solver_progress(case / "log.aggloPimpleFoam", t_end,
                               p["deltaT"])
    if now is None:
        return "starting"
    t, frac, eta = now
    return (f"{s['stage']}: T* = {t / p['tScale']:.2f}, stage ends at "
            f"{t_end / p['tScale']:.2f} " + prog.line(frac, eta))


class Channel:
    """The stages of one call: the preset, the ranks, the progress."""

    def __init__(self, a):
        self.a = a
        self.base = Path("runs") / a.preset
        self.whole = True   # every stage run from its start in this call
        # where the stages before agglomeration are: runs/<stagesFrom>
        self.shared = settings.preset(a.preset)["stagesFrom"] or a.preset
        self.stages_base = Path("runs") / self.shared

    def settings(self, d, config, stage, models=()):
        (d / "system" / "caseSettings").write_text(
            settings.settings(self.a.preset, config, stage, tuple(models),
                             self.a.np))
        # a group's clouds: their cloud properties (each configuration's
        # sub-models and collision coefficients)
        groups.properties(d, config, stage, models or settings.preset(
            self.a.preset)["models"])

    def python(self, d, suffix, module, *args):
        """python -m module args in the case d, logged (log.python.*)."""
        stages.run_logged(package_command(TUTORIAL, module, *args),
                          d, f"log.python.{suffix}")

    def stage(self, d, stage, config, models=()):
        """The solver run of one stage in d (serial or on np ranks),
        decomposed first and reconstructed after on np > 1 ranks; skipped
        when done before."""
        np = self.a.np
        tag = f"{d} [{stage}{' ' + ' '.join(models) if models else ''}]"
        if (d / f"done.{stage}").is_file():
            print(f"    {tag}: finished before, kept", flush=True)
            self.whole = False
            return
        self.settings(d, config, stage, models)
        if np > 1 and not stages.decomposed(d):
            stages.decompose(d)
        # A write cut off by a kill is set aside (OpenFOAM would stop on it)
        said = io.StringIO()
        with contextlib.redirect_stdout(said):
            times.set_aside_incomplete_times(d)
        for line in said.getvalue().splitlines():
            print(f"    {tag}: {line}", flush=True)
        if continued(d / "processor0" if np > 1 else d,
                     settings.preset(self.a.preset), stage):
            self.whole = False
        print(f"    {tag}: started ({time.strftime('%H:%M:%S')}, log: "
              f"{d}/log.aggloPimpleFoam)", flush=True)
        cmd = ["aggloPimpleFoam"]
        if np > 1:
            cmd = ["mpirun", "-n", str(np), "aggloPimpleFoam", "-parallel"]
        try:
            wall = stages.run_solver(d, cmd, tag, progress,
                                     self.a.every, append=True)
        except stages.StoppedOnRequest:
            raise                   # says so: not finished, run again
        except CommandError:
            raise CommandError(f"aggloPimpleFoam failed, see "
                               f"{d}/log.aggloPimpleFoam") from None
        if np > 1:
            stages.run_logged(["reconstructPar", "-latestTime"], d,
                              "log.reconstructPar")
        (d / f"done.{stage}").write_text(f"{round(wall)}\n")
        print(f"    {tag}: done in {round(wall)} s", flush=True)

    def unladen(self):
        """The single-phase LES shared by every configuration."""
        if self.shared != self.a.preset:
            print(f"    unladen: preset {self.shared}'s "
                  f"({self.stages_base}/unladen)", flush=True)
            self.whole = False
            return
        d = self.base / "unladen"
        if (d / "done.unladen").is_file():
            print("    unladen: finished before, kept", flush=True)
            self.whole = False
            return
        if not (d / "constant" / "polyMesh").is_dir():
            stages.fresh_case(d, {"system": "system",
                                  "constant": "constant", "0": "0.orig"})
            self.settings(d, "C1", "unladen")
            stages.run_logged(["blockMesh"], d, "log.blockMesh")
            stages.run_logged(["postProcess", "-func", "writeCellCentres",
                               "-time", "0"], d, "log.postProcess")
            self.python(d, "init", "channel.case", "init", ".")
        self.stage(d, "unladen", "C1")

    def configuration(self, c):
        """Release, dispersion and agglomeration of one configuration."""
        np = self.a.np
        d = self.stages_base / c / "dispersion"
        if self.shared != self.a.preset:
            self.whole = False
            if not (d / "done.dispersion").is_file():
                raise CommandError(
                    f"{d} has not finished its dispersion stage, which this"
                    f" preset branches from (stagesFrom {self.shared}): "
                    f"./Allrun -preset {self.shared} -configs {c} first")
            print(f"    {c}: release and dispersion: preset {self.shared}'s"
                  f" ({d})", flush=True)
        elif not (d / "released").is_file():
            t = stages.branch_case(self.base / "unladen", d, np,
                                   extra_constant=Path("constant"))
            self.settings(d, c, "release")
            stages.run_logged(["postProcess", "-func", "writeCellCentres",
                               "-time", t], d, "log.postProcess")
            # On several ranks the particles go straight into the processor
            # folders: the fluid is decomposed first, if not copied so
            if np > 1 and not stages.decomposed(d):
                stages.decompose(d)
            self.python(d, "release", "channel.case.particles", "release",
                        ".")
            (d / "released").touch()
        if self.shared == self.a.preset:
            self.stage(d, "release", c)
            self.stage(d, "dispersion", c)

        p = settings.preset(self.a.preset)
        seeded = p["seededPairs"]
        # a group's configurations are one-way (groups.members)
        two_way = bool(settings.configuration(groups.lead(c))["twoWay"])
        # two-way coupled: one run per model (each model's cloud moves the
        # fluid its own way); one-way: the models' clouds in one run
        for models in (tuple((m,) for m in p["models"]) if two_way
                       else (p["models"],)):
            adir = self.base / c / ("agglomeration-" + models[0]
                                    if two_way else "agglomeration")
            if not (adir / "branched").is_file():
                # The smoke preset's seeded pairs are added to the serial
                # case (decomposePar then runs at the start of the stage)
                t = stages.branch_case(d, adir, np, serial=seeded > 0,
                                       extra_constant=Path("constant"))
                # Each model's cloud starts from the same end-of-dispersion
                # state; the counters (statistics state) start from zero
                particles.branch_clouds(adir, t,
                                        groups.branches(c, models))
                sys.stdout.flush()
                stages.run_logged(["postProcess", "-func",
                                   "writeCellCentres", "-time", t], adir,
                                  "log.postProcess")
                self.python(adir, "seedPairs", "channel.case.particles",
                            "seedPairs", ".",
                            *groups.clouds(c, "agglomeration", models))
                (adir / "branched").touch()
            self.stage(adir, "agglomeration", c, models)
            self.vtk(adir)

    @staticmethod
    def vtk(d):
        """foamToVTK of the stage's last time into d/VTK, once: a marker
        written after it succeeded; a run cut off or failed leaves no
        VTK/ (the next call writes it again) and fails the call."""
        done = d / "VTK" / "done.foamToVTK"
        if done.is_file():
            return
        shutil.rmtree(d / "VTK", ignore_errors=True)
        try:
            with contextlib.redirect_stdout(io.StringIO()):
                stages.run_logged(
                    ["foamToVTK", "-latestTime", "-excludePatches",
                     "(inlet outlet front back)"], d, "log.foamToVTK")
        except CommandError:
            shutil.rmtree(d / "VTK", ignore_errors=True)
            raise
        done.write_text("foamToVTK -latestTime\n")


def run_stages(run, configs):
    """The unladen stage and each configuration's stages; 1 if one
    failed (said which), else 0."""
    a = run.a
    print(f"verticalChannel: preset {a.preset}, configurations: "
          f"{' '.join(configs)}, {a.np} MPI rank(s)", flush=True)
    try:
        run.unladen()
    except CommandError as e:
        print(f"    unladen: {e}", flush=True)
        sys.stderr.write("Allrun: the unladen stage failed\n")
        return 1
    for c in configs:
        try:
            run.configuration(c)
        except CommandError as e:
            print(f"    {c}: {e}", flush=True)
            sys.stderr.write(f"Allrun: configuration {c} failed\n")
            return 1
    return 0


def work(a):
    configs = a.configs.split()
    if not configs:
        sys.stderr.write("Allrun: -configs names no configuration (see "
                         "./Allrun -help)\n")
        return 1
    # The preset and the configurations checked before anything starts
    try:
        for c in configs:
            settings.settings(a.preset, c, "unladen", (), a.np)
    except SystemExit as e:
        sys.stderr.write(f"{e}\n")
        return 1
    # no configuration run twice (alone and in a group, or in two groups)
    again = [] if a.post else groups.twice(
        configs, groups.runs_before(Path("runs") / a.preset))
    for line in again:
        sys.stderr.write(f"Allrun: {line}\n")
    if again:
        return 1
    start = time.monotonic()
    run = None
    if not a.post:
        run = Channel(a)
        with stages.one_run(run.base, f"verticalChannel -preset {a.preset}"):
            status = run_stages(run, configs)
        if status:
            return status

    # The regression, the collision-event logs replayed through EAM and
    # MAM at three e_n, how the particles reached the walls before the
    # agglomeration stage and, where the preset breaks agglomerates, the
    # break-ups; the regression's status, or 1 if another report failed
    reports = ["channel.post", "channel.post.replay",
               "channel.post.dispersion"]
    if settings.preset(a.preset)["breakup"] != "none":
        reports.append("channel.post.breakup")
    ref = ["--reference"] if a.reference else []
    rcs = []
    for module in reports:
        print(flush=True)
        rcs.append(subprocess.call([sys.executable, "-m", module, a.preset,
                                    *ref]))
    status = 1 if any(rcs[1:]) else rcs[0]
    report = f"results/{a.preset}" if a.reference \
        else f"runs/{a.preset}/report"
    print()
    if not (TUTORIAL / report / "regression.txt").is_file():
        sys.stderr.write(f"Allrun: no report written ({TUTORIAL / report})\n")
        return 1
    print(f"Report: {TUTORIAL / report}/regression.txt")
    print("        (summary.json, the plots *.png and, for a run,"
          " comparison.txt against the committed reference"
          f" results/{a.preset}, beside it);")
    print(f"cases and VTK files: {TUTORIAL / 'runs' / a.preset}/")
    print(run_time(a, configs, run, time.monotonic() - start))
    return status


def continued(d, p, stage):
    """Whether a stage of preset p in the case d continues from a write of
    its own: a time folder after the stage's start, the end of the stage
    before it (the release's writes share the dispersion's folder)."""
    k = settings.STAGES.index(stage)
    start = settings.end_time(p, settings.STAGES[k - 1]) if k else 0.0
    ts = times.time_dirs(d)
    return bool(ts) and float(ts[-1].name) > start + 0.5 * p["deltaT"]


def run_time(a, configs, run, seconds):
    """This call's wall time beside README.md's for the same job."""
    job = f"verticalChannel {a.preset} {' '.join(configs)} -np {a.np}"
    return runtimes.line(job, seconds, run is not None and run.whole)


def main(argv):
    """The driver (python -m channel, ./Allrun) on the options argv."""
    return stages.drive(TUTORIAL, options, work, argv)
