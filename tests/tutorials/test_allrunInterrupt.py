"""A tutorial's Allrun stopped by Ctrl-C stops everything it started (the
solvers run in the background, where a non-interactive shell ignores
SIGINT), its solvers after writing the step they reached (they run in
sessions of their own and get SIGUSR2, their stopAtWriteNowSignal), and
writes no result; a run folder whose set-up was cut off (the
mesh there, the initial particles not) is set up again instead of run
with no particles. The shear study's `ci` preset in a copy of the
tutorial, one variant; each call is stopped within a minute."""

import os
import shutil
import signal
import subprocess
import time

import pytest

from aggloTools.runner import project_dir
from aggloTools.times import time_dirs

TUT = project_dir() / "tutorials" / "shearFlowValidation"

STUDY = "matrix { impactVelocity (normal); fluidTorque (on); }\n"


def _inside(folder):
    """The processes whose working folder lies in folder."""
    out = []
    for p in os.listdir("/proc"):
        if p.isdigit():
            try:
                cwd = os.readlink(f"/proc/{p}/cwd")
            except OSError:
                continue
            if cwd == str(folder) or cwd.startswith(f"{folder}/"):
                out.append(int(p))
    return out


def _running(pgid):
    """The processes of the process group pgid still alive."""
    out = []
    for p in os.listdir("/proc"):
        if p.isdigit():
            try:
                if os.getpgid(int(p)) == pgid:
                    out.append(int(p))
            except ProcessLookupError:
                pass
    return out


def _wait_for(path, timeout=300):
    t0 = time.time()
    while not path.exists():
        if time.time() - t0 > timeout:
            raise TimeoutError(path)
        time.sleep(0.2)


@pytest.fixture
def tut(tmp_path):
    t = tmp_path / "shearFlowValidation"
    shutil.copytree(TUT, t, ignore=shutil.ignore_patterns(
        "runs", "__pycache__"))
    (t / "study").write_text(STUDY)
    shutil.rmtree(t / "results")
    return t


def _terminal_signals():
    """SIGINT as a terminal gives it: a harness that runs the tests in
    the background hands SIGINT on ignored, and a shell cannot trap a
    signal ignored on entry."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _start(tut):
    return subprocess.Popen(["./Allrun", "-study", "-preset", "ci", "-j",
                             "2"], cwd=tut, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True,
                            start_new_session=True,
                            preexec_fn=_terminal_signals)


def test_ctrl_c_stops_the_study(tut, foam_env):
    proc = _start(tut)
    logs = sorted((tut / "runs" / "ci" / "study").glob("*/*/"
                                                       "log.aggloPimpleFoam"))
    t0 = time.time()
    while not logs or "Time =" not in logs[0].read_text():
        assert proc.poll() is None, proc.stdout.read()[-2000:]
        assert time.time() - t0 < 300
        time.sleep(0.5)
        logs = sorted((tut / "runs" / "ci" / "study").glob(
            "*/*/log.aggloPimpleFoam"))
    os.killpg(proc.pid, signal.SIGINT)
    out, _ = proc.communicate(timeout=60)
    t1 = time.time()
    while _running(proc.pid) and time.time() - t1 < 30:
        time.sleep(0.5)
    assert _running(proc.pid) == [], out[-2000:]
    assert _inside(tut) == [], out[-2000:]
    assert proc.returncode == 130, out[-2000:]
    assert "interrupted" in out
    assert not (tut / "results").exists(), out[-2000:]
    # the solver wrote the step it stopped at: its last time is written
    log = logs[0].read_text()
    assert "sigStopAtWriteNow : setting up write and stop" in log, log[-2000:]
    last = log.rsplit("\nTime = ", 1)[1].split()[0]
    assert float(last) == pytest.approx(
        float(time_dirs(logs[0].parent)[-1].name), rel=1e-9)
    assert log.rstrip().endswith("End")


def test_uninitialised_run_is_set_up_again(tut, foam_env):
    """A kill during the set-up left the mesh without particles: the next
    call sets the run up again (its init runs) instead of continuing."""
    res = subprocess.run([str(project_dir() / ".venv/bin/python"),
                          "-m", "shear.study", "list", "ci"], cwd=tut,
                         capture_output=True, text=True, check=True)
    variant, run = res.stdout.split()[:2]
    d = tut / "runs" / "ci" / "study" / variant / run
    (d / "constant" / "polyMesh").mkdir(parents=True)
    proc = _start(tut)
    try:
        _wait_for(d / "log.aggloPimpleFoam")
        assert (d / "log.python.init").is_file()
        assert list((d / "0" / "lagrangian").glob("*/coordinates")) \
            or list((d / "0" / "lagrangian").glob("*/positions"))
    finally:
        os.killpg(proc.pid, signal.SIGINT)
        proc.communicate(timeout=60)
