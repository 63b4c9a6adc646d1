"""Running a tutorial's cases from its Python driver: a command run with
its log, a solver run with progress lines (ETA from the wall clock), a
run continued from its last complete write, several runs at a time, the
driver's options checked before anything runs, and Ctrl-C or SIGTERM
stopping every process started (exit status 130, nothing after it runs).

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
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import runlock, times
from .runner import CommandError

_children = set()
_lock = threading.Lock()


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


# --------------------------------------------------------------- processes

@contextlib.contextmanager
def _started(cmd, cwd, log, append):
    """cmd started in cwd with its output in cwd/log (appended with
    append) and no input, known to the interrupt handler while it runs."""
    cwd = Path(cwd)
    with open(cwd / log, "a" if append else "w") as out:
        proc = subprocess.Popen([str(c) for c in cmd], cwd=cwd, stdout=out,
                                stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL,
                                env=dict(os.environ, PWD=str(cwd)))
        with _lock:
            _children.add(proc)
        runlock.register(proc.pid)
        try:
            yield proc
        finally:
            with _lock:
                _children.discard(proc)


def run_logged(cmd, cwd, log, append=False):
    """Run cmd in cwd with its output in cwd/log (appended with append),
    as OpenFOAM's runApplication does; CommandError if it fails."""
    cwd = Path(cwd)
    print(f"Running {cmd[0]} on {cwd}", flush=True)
    with _started(cmd, cwd, log, append) as proc:
        rc = proc.wait()
    if rc != 0:
        raise CommandError(f"{Path(str(cmd[0])).name} failed (rc {rc}), "
                           f"see {cwd / log}")


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


def run_solver(case, cmd, label, progress, every, append=False,
               log="log.aggloPimpleFoam"):
    """Run the solver command in case with a progress line every `every`
    seconds ('    <label>: <progress(case)>'); the log appended with
    append (a continued run); CommandError unless the solver ends with
    End among the last 20 lines of the log.
    Returns the wall time in seconds."""
    case = Path(case)
    t0 = time.time()
    app = Path(str(cmd[0])).name
    if app == "mpirun":             # mpirun -n N [options] app -parallel
        args = [str(c) for c in cmd]
        n = args[args.index("-np" if "-np" in args else "-n") + 1]
        app = f"{Path(args[args.index('-parallel') - 1]).name} ({n} processes)"
    print(f"Running {app} on {case}", flush=True)
    with _started(cmd, case, log, append) as proc:
        last = t0
        while proc.poll() is None:
            time.sleep(0.5)
            if time.time() - last >= every:
                last = time.time()
                print(f"    {label}: {progress(case)}", flush=True)
    if proc.returncode != 0:
        raise CommandError(f"{label}: {Path(str(cmd[0])).name} failed, "
                           f"see {case / log}")
    tail = (case / log).read_text(errors="replace").splitlines()[-20:]
    if "End" not in tail:
        raise CommandError(f"{label}: {Path(str(cmd[0])).name} did not "
                           f"finish, see {case / log}")
    return time.time() - t0


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


# ------------------------------------------------------------- interrupts

def _stop_tree(pid):
    """SIGTERM to pid, then to its children, however deep (each process
    before its children, so that nothing starts anew meanwhile)."""
    try:
        kids = []
        for task in Path(f"/proc/{pid}/task").iterdir():
            kids += (task / "children").read_text().split()
    except OSError:
        kids = []
    try:
        os.kill(pid, signal.SIGTERM)
    except ProcessLookupError:
        pass
    for k in kids:
        _stop_tree(int(k))


def _interrupted(*_):
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    sys.stderr.write("Allrun: interrupted; stopping every run it "
                     "started\n")
    with _lock:
        procs = list(_children)
    for p in procs:
        _stop_tree(p.pid)
    # Reaped here with waitpid: the interrupted Popen.wait of the main
    # thread holds the Popen's own lock
    for p in procs:
        deadline = time.time() + 30
        try:
            while os.waitpid(p.pid, os.WNOHANG)[0] == 0:
                if time.time() > deadline:
                    os.kill(p.pid, signal.SIGKILL)
                    os.waitpid(p.pid, 0)
                    break
                time.sleep(0.05)
        except (ChildProcessError, ProcessLookupError):
            pass
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(130)


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


def interruptible(main):
    """Run main() so that Ctrl-C (SIGINT) or SIGTERM stops every process
    it started (solvers, mpirun and its ranks, however deep), then the
    driver with exit status 130: nothing after it (post-processing) runs.
    An interrupted run continues from its last complete write when the
    driver is called again. Returns main()'s exit status."""
    signal.signal(signal.SIGINT, _interrupted)
    signal.signal(signal.SIGTERM, _interrupted)
    return main()
