"""aggloTools.processes: a failing command or a solver whose log lacks End
raises; a solver run through mpirun is named with its ranks; SIGINT to a
driver stops its whole process tree and exits 130 without running what
follows, its solvers (in sessions of their own) first asked to write
(SIGUSR2, their stopAtWriteNowSignal), a second SIGINT at once; a stop
on SIGUSR2 that the driver did not ask for is not taken for the end of
the run; a niced driver gives its solvers' sessions its niceness."""

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from aggloTools import processes
from aggloTools.runner import CommandError


def test_run_logged_and_solver(tmp_path):
    processes.run_logged([sys.executable, "-c", "print('hello')"], tmp_path,
                      "log.hello")
    assert (tmp_path / "log.hello").read_text() == "hello\n"
    with pytest.raises(CommandError, match="failed"):
        processes.run_logged([sys.executable, "-c", "raise SystemExit(3)"],
                          tmp_path, "log.fail")
    # a solver log without End: did not finish
    with pytest.raises(CommandError, match="did not finish"):
        processes.run_solver(tmp_path, [sys.executable, "-c", "print(1)"],
                          "x", lambda c: "", 60)
    lines = []
    wall = processes.run_solver(
        tmp_path, [sys.executable, "-c",
                   "import time; time.sleep(1.2); print('End')"],
        "x", lambda c: lines.append(c) or "p", 0.5, append=True)
    assert 1 <= wall < 30
    assert len(lines) >= 1            # at least one progress line
    assert (tmp_path / "log.aggloPimpleFoam").read_text().endswith(
        "1\nEnd\n")                   # appended to the first run's log


@pytest.mark.parametrize("options", [[], ["--oversubscribe"]])
def test_solver_on_ranks_named(tmp_path, capsys, options):
    """A solver run through mpirun is announced by its name and ranks,
    with or without mpirun's own options before it (with them, the
    option was taken for the solver's name)."""
    mpirun = tmp_path / "mpirun"
    mpirun.write_text("#!/bin/sh\necho End\n")
    mpirun.chmod(0o755)
    processes.run_solver(tmp_path, [str(mpirun), "-np", "2", *options,
                                 "/opt/bin/aggloPimpleFoam", "-parallel"],
                      "x", lambda c: "", 60)
    assert f"Running aggloPimpleFoam (2 processes) on {tmp_path}" in \
        capsys.readouterr().out


def test_sigint_stops_the_tree_and_exits_130(tmp_path):
    marker = tmp_path / "after"
    child = tmp_path / "child.pid"
    driver = tmp_path / "driver.py"
    driver.write_text(textwrap.dedent(f"""
        import sys
        from aggloTools import processes
        def main():
            processes.run_logged(["bash", "-c",
                               "echo $$ > {child}; sleep 60 & wait"],
                              "{tmp_path}", "log.sleep")
            open("{marker}", "w").write("ran")
            return 0
        sys.exit(processes.interruptible(main))
    """))
    proc = subprocess.Popen([sys.executable, str(driver)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    t0 = time.time()
    while not child.exists() or not child.read_text().strip():
        assert time.time() - t0 < 30
        time.sleep(0.1)
    bash = int(child.read_text())
    os.kill(proc.pid, signal.SIGINT)      # the driver only, not its group
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, out + err
    assert "interrupted" in err
    assert not marker.exists()
    time.sleep(0.5)
    with pytest.raises(ProcessLookupError):
        os.kill(bash, 0)


# ---------------------------------------------------- write now and stop

#: A solver that behaves as OpenFOAM's on its stopAtWriteNowSignal (the
#: -opt-switch run_solver gives): on SIGUSR2 it writes (the file
#: 'written'), says so as OpenFOAM does, ends with End; with 'deaf' it
#: ignores the signal and runs on
FAKE_SOLVER = textwrap.dedent("""
    import signal, sys, time
    assert sys.argv[-2:] == ["-opt-switch", "stopAtWriteNowSignal=12"]
    def write_and_stop(*_):
        time.sleep(0.5)                         # the step, then the write
        open("written", "w").write("t")
        print("sigStopAtWriteNow : setting up write and stop at end of "
              "the next iteration", flush=True)
        print("End", flush=True)
        sys.exit(0)
    deaf = "deaf" in sys.argv
    signal.signal(signal.SIGUSR2,
                  signal.SIG_IGN if deaf else write_and_stop)
    open("solver.pid", "w").write(str(__import__("os").getpid()))
    print("Time = 1", flush=True)
    time.sleep(120)
    print("End", flush=True)
""")


def _driver(tmp_path, *solver_args, prefix=()):
    (tmp_path / "solver.py").write_text(FAKE_SOLVER)
    driver = tmp_path / "driver.py"
    driver.write_text(textwrap.dedent(f"""
        import sys
        from aggloTools import processes
        def main():
            processes.run_solver("{tmp_path}", [sys.executable,
                              "{tmp_path}/solver.py", *{list(solver_args)}],
                              "x", lambda c: "", 60)
            open("{tmp_path}/done", "w").write("done")
            return 0
        sys.exit(processes.interruptible(main))
    """))
    proc = subprocess.Popen([*prefix, sys.executable, str(driver)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    pid = tmp_path / "solver.pid"
    t0 = time.time()
    while not pid.exists() or not pid.read_text().strip():
        assert proc.poll() is None and time.time() - t0 < 30
        time.sleep(0.1)
    return proc, int(pid.read_text())


def test_interrupt_asks_the_solver_to_write(tmp_path):
    """Ctrl-C to the driver's process group (as a terminal gives it): the
    solver, in a session of its own, gets SIGUSR2 only, writes and ends;
    the driver exits 130 and does not take the run for finished."""
    proc, solver = _driver(tmp_path)
    assert os.getsid(solver) != os.getsid(proc.pid)
    os.killpg(proc.pid, signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, out + err
    assert "write the time step they are in" in err
    assert (tmp_path / "written").is_file()
    assert not (tmp_path / "done").exists()
    log = (tmp_path / "log.aggloPimpleFoam").read_text()
    assert log.endswith("iteration\nEnd\n")


def autogroup_nice(pid):
    """The nice of the process's session group, as the kernel keeps it
    ('/autogroup-N nice K')."""
    return int(Path(f"/proc/{pid}/autogroup").read_text().split()[-1])


@pytest.mark.parametrize("niceness", [0, 7])
def test_the_solvers_session_gets_the_drivers_niceness(tmp_path,
                                                       niceness):
    """`nice -n 7 ./Allrun`: the solver, in a session of its own, gets a
    session group of its own where the kernel groups by session, whose
    nice the kernel makes 0 (an equal share beside every other session,
    whatever the driver's niceness); the driver sets it to its own, 7.
    Not niced: it stays 0."""
    if not Path("/proc/self/autogroup").exists():
        pytest.skip("n/r: this kernel groups no processes by session (no "
                    "/proc/<pid>/autogroup)")
    proc, solver = _driver(tmp_path, prefix=("nice", "-n", str(niceness)))
    try:
        assert os.getsid(solver) != os.getsid(proc.pid)
        assert Path(f"/proc/{solver}/autogroup").read_text().split()[0] \
            != Path(f"/proc/{proc.pid}/autogroup").read_text().split()[0]
        assert os.getpriority(os.PRIO_PROCESS, solver) == niceness
        t0 = time.time()
        while autogroup_nice(solver) != niceness and time.time() - t0 < 5:
            time.sleep(0.1)
        assert autogroup_nice(solver) == niceness
    finally:
        os.killpg(proc.pid, signal.SIGINT)
        proc.communicate(timeout=60)
    assert proc.returncode == 130


def test_second_interrupt_stops_at_once(tmp_path):
    """A solver that does not write on the signal: the second Ctrl-C
    stops it (SIGTERM) without the write, exit 130 within seconds."""
    proc, solver = _driver(tmp_path, "deaf")
    os.kill(proc.pid, signal.SIGINT)
    time.sleep(1.5)
    assert proc.poll() is None            # waiting for the write
    t0 = time.time()
    os.kill(proc.pid, signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130 and time.time() - t0 < 30, out + err
    assert not (tmp_path / "written").exists()
    time.sleep(0.5)
    with pytest.raises(ProcessLookupError):
        os.kill(solver, 0)


def test_stop_not_asked_by_the_driver_is_not_the_end(tmp_path):
    """SIGUSR2 sent to the solver by someone else: the run stopped
    before its end, refused as finished (the driver's status 1, its
    message says to run again), the step after it not run."""
    proc, solver = _driver(tmp_path)
    os.kill(solver, signal.SIGUSR2)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 1, out + err
    assert "StoppedOnRequest" in err
    assert "stopped on SIGUSR2 before its end; run again" in err
    assert (tmp_path / "written").is_file()
    assert not (tmp_path / "done").exists()


def test_interrupted_driver_gives_its_lock_back(tmp_path):
    """A driver holding its run folder's lock, interrupted while its
    solver runs: the solver writes and ends, the driver exits 130 and the
    lock is gone (it was left for the next call to take over as stale),
    so a second driver takes the folder without a word about it."""
    (tmp_path / "solver.py").write_text(FAKE_SOLVER)
    runs = tmp_path / "runs"
    driver = tmp_path / "driver.py"
    driver.write_text(textwrap.dedent(f"""
        import sys
        from pathlib import Path
        from aggloTools import processes, runlock
        def main():
            with runlock.held(Path("{runs}"), "test driver"):
                processes.run_solver("{tmp_path}", [sys.executable,
                                  "{tmp_path}/solver.py"], "x",
                                  lambda c: "", 60)
            return 0
        sys.exit(processes.interruptible(main))
    """))
    proc = subprocess.Popen([sys.executable, str(driver)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    pid = tmp_path / "solver.pid"
    t0 = time.time()
    while not pid.exists() or not pid.read_text().strip():
        assert proc.poll() is None and time.time() - t0 < 30
        time.sleep(0.1)
    assert (runs / ".aggloRun.lock").is_file()
    os.kill(proc.pid, signal.SIGTERM)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, out + err
    assert (tmp_path / "written").is_file()
    assert not (runs / ".aggloRun.lock").exists()
