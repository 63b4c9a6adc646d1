"""Running a tutorial's cases from its Python driver: the driver's
options checked before anything runs, the cases (new, branched from
another's latest time, decomposed), several runs at a time, one driver
per run folder; and, from aggloTools.processes, a command run with its
log, a solver run with progress lines (ETA from the wall clock), and
Ctrl-C or SIGTERM stopping every process started (exit status 130,
nothing after it runs), the solvers after writing the step they reached.
A run continues from its last complete write when called again.

    parser = stages.Parser("shearFlowValidation", __doc__)
    parser.add_argument("-j", type=stages.positive("-j"), default=2)
    args = parser.parse_args(argv)
    stages.interruptible(lambda: work(args))
"""

import argparse
import contextlib
import os
import re
import shutil
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import runlock, times
from .processes import (  # noqa: F401 (the drivers' names for them)
    WRITE_AND_STOP, StoppedOnRequest, interruptible, run_logged,
    run_solver)
from .runner import CommandError

# ------------------------------------------------------------------ options

class Parser(argparse.ArgumentParser):
    """argparse with OpenFOAM-style single-dash options, -help beside -h,
    and its refusals in the words of the tutorials' Allrun: 'Allrun:
    -preset needs a value (see ./Allrun -help)', exit status 1."""

    def __init__(self, prog, doc):
        super().__init__(prog="Allrun", description=doc, add_help=False,
                         formatter_class=argparse.RawDescriptionHelpFormatter,
                         allow_abbrev=False)
        self.add_argument("-h", "-help", action="help",
                          help="this text")

    def parse_args(self, args=None, namespace=None):
        """As argparse, but an option's value may not start with '-' (as
        the shell Allrun had it: '-np -2' is an option without value)."""
        args = list(sys.argv[1:] if args is None else args)
        for i, tok in enumerate(args):
            act = self._option_string_actions.get(tok)
            if act is not None and act.nargs is None and (
                    i + 1 == len(args) or args[i + 1].startswith("-")):
                self._refuse(f"{tok} needs a value")
        return super().parse_args(args, namespace)

    def error(self, message):
        if "expected one argument" in message:
            opt = message.split(":")[0].replace("argument ", "")
            message = f"{opt.split('/')[0]} needs a value"
        elif message.startswith("unrecognized arguments"):
            message = "unknown option " + message.split(": ", 1)[1]
        self._refuse(message)

    @staticmethod
    def _refuse(message):
        sys.stderr.write(f"Allrun: {message} (see ./Allrun -help)\n")
        sys.exit(1)


def positive(name):
    """An argparse type: a positive whole number, else the refusal
    "<name> '<text>' is not a positive number"."""
    def parse(text):
        if not text.isdigit() or int(text) == 0:
            raise argparse.ArgumentTypeError(
                f"{name} '{text}' is not a positive number")
        return int(text)
    return parse


def within_cores(parser, np):
    """Refuse (parser.error) more ranks than the cores this process may
    use: Open MPI refuses to start them, but only inside the solver's
    log, after the stages before it."""
    cores = len(os.sched_getaffinity(0))
    if np > cores:
        parser.error(f"-np {np} is more than the {cores} cores this run "
                     "may use (Open MPI refuses to start more ranks than "
                     "cores)")


# ------------------------------------------------------------------- cases

def fresh_case(case, folders):
    """A new case folder (an old one removed) holding a copy of each
    template folder: folders maps a name in the case to its source."""
    case = Path(case)
    if case.exists():
        shutil.rmtree(case)
    case.mkdir(parents=True)
    for name, src in folders.items():
        shutil.copytree(src, case / name)


def branch_case(src, dst, nprocs=1, serial=False, extra_constant=None):
    """A new case dst from the latest time of src (not 0): its system,
    the mesh and that time, without the function objects' state; the
    files (not folders) of extra_constant into its constant; on nprocs > 1
    ranks also the processor folders of that time where src has nprocs of
    them, unless serial (the new case then decomposes at its next solver
    run). Returns the time's name."""
    src, dst = Path(src), Path(dst)
    later = [t for t in times.time_dirs(src) if float(t.name) != 0]
    if not later:
        raise CommandError(f"no time in {src}")
    t = later[-1].name
    if dst.exists():
        shutil.rmtree(dst)
    (dst / "constant").mkdir(parents=True)
    shutil.copytree(src / "system", dst / "system")
    if extra_constant is not None:
        for f in Path(extra_constant).iterdir():
            if f.is_file():
                shutil.copy2(f, dst / "constant" / f.name)
    shutil.copytree(src / "constant" / "polyMesh",
                    dst / "constant" / "polyMesh")
    shutil.copytree(src / t, dst / t)
    shutil.rmtree(dst / t / "uniform" / "functionObjects",
                  ignore_errors=True)
    procs = sorted(src.glob("processor*"))
    if nprocs > 1 and not serial and len(procs) == nprocs \
            and (src / "processor0" / t).is_dir():
        for p in procs:
            for part in ("constant", t):
                shutil.copytree(p / part, dst / p.name / part)
            shutil.rmtree(dst / p.name / t / "uniform" / "functionObjects",
                          ignore_errors=True)
        (dst / DECOMPOSED).write_text(f"{nprocs}\n")
    return t


#: The marker of a case whose processor folders are complete: written
#: when decomposePar has succeeded or the folders have been copied whole
DECOMPOSED = "done.decomposePar"


def decomposed(case):
    """True if the case's processor folders are complete (a decomposePar
    killed half-way leaves processor0 without the marker)."""
    return (Path(case) / DECOMPOSED).is_file()


def decompose(case, log="log.decomposePar"):
    """decomposePar of the case's latest time, the one its run starts
    from, named (-latestTime): plain decomposePar takes the time OpenFOAM
    v1912's Time starts at, which is not the folder where the run raised
    the digits of its names past timePrecision and v1912 does not find it
    (as for 16.333317 at 2 digits; aggloPimpleFoam's restoreStartTime.H),
    and then writes none of its fields and succeeds. decomposePar writes
    barycentric coordinates but copies the uniform cloudProperties that
    announce a legacy positions file: they announce coordinates. The
    marker DECOMPOSED is written last (decomposed()): a decomposition cut
    off by a kill is done again, not taken for complete."""
    (Path(case) / DECOMPOSED).unlink(missing_ok=True)
    run_logged(["decomposePar", "-force", "-latestTime"], case, log)
    procs = list(Path(case).glob("processor[0-9]*"))
    for f in Path(case).glob("processor*/*/uniform/lagrangian/*/"
                             "cloudProperties"):
        text = f.read_text()
        f.write_text(re.sub(r"geometry *positions;",
                            "geometry coordinates;", text))
    (Path(case) / DECOMPOSED).write_text(f"{len(procs)}\n")


def pool(items, work, jobs):
    """work(item) for every item, up to jobs at a time, each printing its
    own lines; returns the items whose work raised (its message printed
    as '    <item>: <message>')."""
    failed = []

    def one(item):
        try:
            work(item)
        except CommandError as e:
            print(f"    {item}: {e}", flush=True)
            failed.append(item)

    with ThreadPoolExecutor(max_workers=jobs) as ex:
        for f in [ex.submit(one, i) for i in items]:
            f.result()
    return failed


def drive(here, options, work, argv):
    """A tutorial driver's main: in its folder here, the options parsed
    (refused in the Allrun words), then work(options) interruptible;
    returns the exit status."""
    os.chdir(here)
    a = options(argv)
    return interruptible(lambda: work(a))


@contextlib.contextmanager
def one_run(folder, what):
    """The run folder's lock held while the block runs (runlock): a
    second driver on the folder is refused with the holder named, exit
    status 1 (raised as SystemExit)."""
    try:
        with runlock.held(folder, what):
            yield
    except runlock.Busy as e:
        sys.stderr.write(f"Allrun: {e}\n")
        raise SystemExit(1) from None


