"""The processes a tutorial's driver starts: a command run with its log,
an OpenFOAM solver run with progress lines that writes the step it is in
and stops on request (WRITE_AND_STOP), and Ctrl-C or SIGTERM stopping
every process started, the solvers after that write (exit status 130,
nothing after it runs). The drivers reach them through aggloTools.stages.
"""

import contextlib
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

from . import runlock
from .runner import CommandError

#: The signal on which an OpenFOAM solver started by run_solver writes
#: the time step it is in and stops (OpenFOAM's stopAtWriteNowSignal,
#: given on its command line): an interrupted driver sends it, so that
#: the run continues from that step and not from its last regular write;
#: a user may send it too (kill -USR2 to the solver, or to mpirun, which
#: passes SIGUSR2 on to its ranks)
WRITE_AND_STOP = signal.SIGUSR2
#: The longest an interrupted driver waits for its solvers' last write
#: (the step they are in, then the write) before it stops them unwritten
WRITE_WAIT = 300

_children = set()
_writers = set()            # the children asked to write on interrupt
_stopping = threading.Event()
_lock = threading.RLock()   # the handler may run while main holds it


# --------------------------------------------------------------- processes

def _park():
    """Wait for the interrupt handler's exit: a thread of the driver
    that would start a process, or take a solver's stop on request for
    the end of its run, once the driver is being stopped."""
    while True:
        time.sleep(3600)


def share_as_driver(pid):
    """Give the session of process pid (a solver started in a session of
    its own) the driver's niceness: where the kernel groups processes by
    session (/proc/sys/kernel/sched_autogroup_enabled), nice weighs only
    within a group and each group has a nice of its own, 0 when made, so
    without this `nice ./Allrun` would leave its solvers an equal share
    beside every other session's. Nothing where the driver is not niced
    or the kernel has no such groups."""
    n = os.nice(0)
    if n <= 0:
        return
    try:
        with open(f"/proc/{pid}/autogroup", "w") as f:
            f.write(str(n))
    except OSError:
        pass


@contextlib.contextmanager
def _started(cmd, cwd, log, append, writes=False):
    """cmd started in cwd with its output in cwd/log (appended with
    append) and no input, known to the interrupt handler while it runs.
    A solver that writes on WRITE_AND_STOP (writes) runs in a session of
    its own: a terminal's Ctrl-C reaches the driver only, which asks it
    to write before it stops."""
    cwd = Path(cwd)
    with open(cwd / log, "a" if append else "w") as out:
        if _stopping.is_set():
            _park()
        proc = subprocess.Popen(
            [str(c) for c in cmd], cwd=cwd, stdout=out,
            stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
            env=dict(os.environ, PWD=str(cwd)), start_new_session=writes)
        if writes:
            share_as_driver(proc.pid)
        with _lock:
            _children.add(proc)
            if writes:
                _writers.add(proc)
        runlock.register(proc.pid)
        try:
            yield proc
        finally:
            with _lock:
                _children.discard(proc)
                _writers.discard(proc)


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


#: What an OpenFOAM solver's log says when it received WRITE_AND_STOP
STOPPED_ON_REQUEST = "sigStopAtWriteNow : setting up write and stop"


class StoppedOnRequest(CommandError):
    """A solver that wrote and stopped on WRITE_AND_STOP which the driver
    did not send: the run is not finished, it continues from that write
    when run again."""


def run_solver(case, cmd, label, progress, every, append=False,
               log="log.aggloPimpleFoam"):
    """Run the OpenFOAM solver command in case with a progress line every
    `every` seconds ('    <label>: <progress(case)>'); the log appended
    with append (a continued run). The solver writes its time step and
    stops on WRITE_AND_STOP (its -opt-switch stopAtWriteNowSignal): a
    driver interrupted meanwhile exits (interruptible), and a stop that
    the driver did not ask for raises StoppedOnRequest, not the end of
    the run (it continues from that write when called again); a solver
    that fails or does not end with End among the last 20 lines of the
    log raises CommandError. Returns the wall time in seconds."""
    case = Path(case)
    t0 = time.time()
    app = Path(str(cmd[0])).name
    if app == "mpirun":             # mpirun -n N [options] app -parallel
        args = [str(c) for c in cmd]
        n = args[args.index("-np" if "-np" in args else "-n") + 1]
        app = f"{Path(args[args.index('-parallel') - 1]).name} ({n} processes)"
    print(f"Running {app} on {case}", flush=True)
    logged = (case / log).stat().st_size \
        if append and (case / log).is_file() else 0
    cmd = list(cmd) + ["-opt-switch",
                       f"stopAtWriteNowSignal={int(WRITE_AND_STOP)}"]
    with _started(cmd, case, log, append, writes=True) as proc:
        last = t0
        while proc.poll() is None:
            time.sleep(0.5)
            if time.time() - last >= every:
                last = time.time()
                print(f"    {label}: {progress(case)}", flush=True)
    name = Path(str(cmd[0])).name
    with open(case / log, "rb") as f:
        f.seek(logged)
        text = f.read().decode(errors="replace")
    if STOPPED_ON_REQUEST in text:
        if _stopping.is_set():
            _park()
        raise StoppedOnRequest(f"{label}: {name} wrote its time step and "
                           f"stopped on {WRITE_AND_STOP.name} before its "
                           f"end; run again to continue, see {case / log}")
    if proc.returncode != 0:
        raise CommandError(f"{label}: {name} failed, see {case / log}")
    if "End" not in text.splitlines()[-20:]:
        raise CommandError(f"{label}: {name} did not finish, see "
                           f"{case / log}")
    return time.time() - t0


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


def _ended(pid):
    """True once the child pid has ended (reaped here with waitpid: the
    interrupted Popen.wait of the main thread holds the Popen's lock)."""
    try:
        return os.waitpid(pid, os.WNOHANG)[0] != 0
    except ChildProcessError:
        return True


def _interrupted(*_):
    """The first Ctrl-C or SIGTERM: the solvers are asked to write the
    time step they are in and stop (WRITE_AND_STOP), and are waited for
    up to WRITE_WAIT seconds; then every process still running is
    stopped (_stop_now). A second Ctrl-C or SIGTERM stops them at once."""
    signal.signal(signal.SIGINT, _stop_now)
    signal.signal(signal.SIGTERM, _stop_now)
    with _lock:
        _stopping.set()
        writers = list(_writers)
    if not writers:
        _stop_now()
    sys.stderr.write("Allrun: interrupted; the solvers write the time "
                     "step they are in and stop (Ctrl-C again: stop at "
                     "once, without that write)\n")
    for p in writers:
        try:
            os.kill(p.pid, WRITE_AND_STOP)
        except ProcessLookupError:
            pass
    deadline = time.time() + WRITE_WAIT
    while not all(_ended(p.pid) for p in writers) \
            and time.time() < deadline:
        time.sleep(0.1)
    _stop_now()


def _stop_now(*_):
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    _stopping.set()
    sys.stderr.write("Allrun: interrupted; stopping every run it "
                     "started\n")
    with _lock:
        procs = list(_children)
    for p in procs:
        _stop_tree(p.pid)
    for p in procs:
        deadline = time.time() + 30
        try:
            while not _ended(p.pid):
                if time.time() > deadline:
                    os.kill(p.pid, signal.SIGKILL)
                    os.waitpid(p.pid, 0)
                    break
                time.sleep(0.05)
        except (ChildProcessError, ProcessLookupError):
            pass
    # every process it started has ended: its run folders are free
    runlock.release_all()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(130)


def interruptible(main):
    """Run main() so that Ctrl-C (SIGINT) or SIGTERM stops every process
    it started (solvers, mpirun and its ranks, however deep), the
    solvers after writing the time step they are in (a second Ctrl-C:
    at once), then the driver with exit status 130: nothing after it
    (post-processing) runs. An interrupted run continues from its last
    complete write when the driver is called again. Returns main()'s
    exit status."""
    signal.signal(signal.SIGINT, _interrupted)
    signal.signal(signal.SIGTERM, _interrupted)
    return main()
