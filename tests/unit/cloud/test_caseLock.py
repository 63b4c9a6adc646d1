"""One aggloPimpleFoam at a time in a case (caseLock.H): a second solver
started in a case where one runs stops with a fatal error naming it and
writes nothing (two solvers appended to one event log: 992 events for a
run of 496); the first goes on undisturbed; a lock left by a solver that
has ended (killed) is taken over, and a finished run leaves none."""

import re
import signal
import subprocess
import time

from aggloTools import eventlog
from aggloTools.boxcase import run_case
from aggloTools.runner import foam_bin
from aggloTools.times import set_aside_incomplete_times, time_dirs
from cloudBoxCases import primaries_gas as gas

LOCK = ".aggloPimpleFoam.lock"


def test_second_solver_refused(case_dir, foam_env):
    c = gas(case_dir / "gas", end=4.0, write=10)     # 40,000 steps
    subprocess.run([foam_bin("blockMesh")], cwd=c, capture_output=True,
                   check=True)
    first = subprocess.Popen([foam_bin("aggloPimpleFoam")], cwd=c,
                             stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
    try:
        t0 = time.time()
        while len(time_dirs(c)) < 3:              # it has written twice
            assert first.poll() is None and time.time() - t0 < 120
            time.sleep(0.2)
        second = subprocess.run([foam_bin("aggloPimpleFoam")], cwd=c,
                                capture_output=True, text=True, timeout=60)
        assert second.returncode != 0
        out = second.stdout + second.stderr
        assert "FOAM FATAL" in out, out[-2000:]
        fatal = out.split("FOAM FATAL", 1)[1]
        assert f"Another aggloPimpleFoam (process {first.pid})" in fatal
        assert first.poll() is None                  # undisturbed
        assert f"pid {first.pid} " in (c / LOCK).read_text()
    finally:
        first.send_signal(signal.SIGKILL)
        first.wait()
    # The killed solver's lock is stale: the next run takes it over,
    # runs to its end and gives it back
    set_aside_incomplete_times(c)           # a write the kill cut off
    ctl = c / "system" / "controlDict"
    last = float(time_dirs(c)[-1].name)
    text = ctl.read_text()
    assert "endTime 4.0;" in text
    ctl.write_text(text.replace("endTime 4.0;", f"endTime {last + 2e-3!r};"))
    res = subprocess.run([foam_bin("aggloPimpleFoam")], cwd=c,
                         capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stdout[-2000:]
    assert "of a run that has ended" in res.stdout
    assert not (c / LOCK).exists()
    n = len(eventlog.read_events(c))
    rec = c / time_dirs(c)[-1].name / "uniform/lagrangian/kinematicCloud" \
        / "collisionEventLog"
    assert re.search(rf"nEvents\s+{n};", rec.read_text())


def test_finished_run_leaves_no_lock(case_dir, foam_env):
    c = gas(case_dir / "gas", log=False)
    run_case(c)
    assert not (c / LOCK).exists()
