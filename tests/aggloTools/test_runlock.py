"""aggloTools.runlock: one run at a time per run folder. A lock whose
processes run refuses a second holder and names the first; one whose
processes have all ended (a driver killed with kill -9) is stale and
taken over; a lock whose driver is gone while a process it started still
runs is not stale; a process number used again by another process (its
start time differs) does not keep a lock alive."""

import os
import subprocess
import sys

import pytest

from aggloTools import runlock
from runLocks import lock_text


@pytest.fixture
def sleeper():
    p = subprocess.Popen(["sleep", "60"])
    yield p
    p.kill()
    p.wait()


def test_live_lock_refuses(tmp_path, sleeper):
    (tmp_path / runlock.NAME).write_text(lock_text(sleeper.pid))
    with pytest.raises(runlock.Busy, match=f"process {sleeper.pid} runs"):
        with runlock.held(tmp_path, "second"):
            pass
    assert (tmp_path / runlock.NAME).read_text() == lock_text(sleeper.pid)


def test_lock_taken_and_given_back(tmp_path, capsys):
    with runlock.held(tmp_path, "first") as lock:
        text = lock.read_text()
        assert f"process {os.getpid()} " in text
        with pytest.raises(runlock.Busy, match="test_runlock|first"):
            with runlock.held(tmp_path, "second"):
                pass
    assert not lock.exists()
    assert capsys.readouterr().out == ""


def test_stale_lock_taken_over(tmp_path, capsys):
    p = subprocess.Popen(["true"])
    p.wait()
    start = "12345"                  # the ended process's record
    (tmp_path / runlock.NAME).write_text(lock_text(p.pid, starts=[start]))
    with runlock.held(tmp_path, "next") as lock:
        assert f"process {os.getpid()} " in lock.read_text()
    assert "stale lock" in capsys.readouterr().out


def test_started_process_keeps_the_lock_alive(tmp_path, sleeper):
    """The driver (here: a process that has ended) is gone, the solver it
    started (registered) still runs: not stale."""
    gone = subprocess.Popen(["true"])
    gone.wait()
    (tmp_path / runlock.NAME).write_text(
        lock_text(gone.pid, sleeper.pid,
                  starts=["1", runlock._started(sleeper.pid)]))
    with pytest.raises(runlock.Busy):
        with runlock.held(tmp_path, "second"):
            pass


def test_reused_process_number_is_not_the_holder(tmp_path, sleeper):
    """The recorded process number runs, but started at another time: a
    process that took the number of the ended holder."""
    (tmp_path / runlock.NAME).write_text(
        lock_text(sleeper.pid, starts=["1"]))
    with runlock.held(tmp_path, "next"):
        pass


def test_register_adds_started_processes(tmp_path, sleeper):
    with runlock.held(tmp_path, "driver") as lock:
        runlock.register(sleeper.pid)
        assert f"process {sleeper.pid} {runlock._started(sleeper.pid)}" \
            in lock.read_text()


def test_two_drivers_one_folder(tmp_path):
    """Two processes race for one folder: exactly one holds it."""
    code = ("import sys, time\nfrom aggloTools import runlock\n"
            "try:\n    with runlock.held(sys.argv[1], 'race'):\n"
            "        time.sleep(2)\nexcept runlock.Busy:\n    sys.exit(3)\n")
    procs = [subprocess.Popen([sys.executable, "-c", code, str(tmp_path)])
             for _ in range(2)]
    assert sorted(p.wait() for p in procs) == [0, 3]
