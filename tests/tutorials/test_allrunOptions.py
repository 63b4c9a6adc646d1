"""The tutorials' Allrun scripts refuse a bad option at once: an option
without its value (which looped forever), a count that is not a positive
number (-np 0 ran serially, -np abc gave a traceback, -j 0 busy-looped).
Each call must end within seconds with exit status 1 and a message
naming the option, before anything is run."""

import os
import subprocess

import pytest

from aggloTools.runner import project_dir

TUT = project_dir() / "tutorials"

CASES = [
    ("verticalChannel", ["-preset"], "-preset needs a value"),
    ("verticalChannel", ["-np"], "-np needs a value"),
    ("verticalChannel", ["-np", "-post"], "-np needs a value"),
    ("verticalChannel", ["-np", "0"], "not a positive number"),
    ("verticalChannel", ["-np", "-2"], "-np needs a value"),
    ("verticalChannel", ["-np", "abc"], "not a positive number"),
    ("verticalChannel", ["-np", "1000"], "-np 1000 is more than the"),
    ("shearFlowValidation", ["-preset"], "-preset needs a value"),
    ("shearFlowValidation", ["-j", "0"], "not a positive number"),
    ("shearFlowValidation", ["-every", "x"], "not a positive number"),
    ("bendDeposition", ["-np", "1000"], "-np 1000 is more than the"),
    ("bendDeposition", ["-preset", "bogus"], "invalid choice: 'bogus'"),
]


@pytest.mark.parametrize("tutorial, args, words", CASES,
                         ids=[f"{t}{''.join(a)}" for t, a, _ in CASES])
def test_bad_option_stops_at_once(tutorial, args, words, foam_env):
    res = subprocess.run(["./Allrun", *args], cwd=TUT / tutorial,
                         capture_output=True, text=True, timeout=60,
                         env=dict(os.environ, PWD=str(TUT / tutorial)))
    assert res.returncode == 1, res.stdout + res.stderr
    assert words in res.stderr
    assert not (TUT / tutorial / "runs" / "None").exists()


@pytest.mark.parametrize("script", ["Allrun",
                                    "tutorials/verticalChannel/Allrun",
                                    "tutorials/shearFlowValidation/Allrun"])
def test_help_from_anywhere(tmp_path, foam_env, script):
    """-help prints the script's header from any folder (it read its own
    file by a path relative to the folder it had changed into), exits 0
    and runs nothing."""
    res = subprocess.run([str(project_dir() / script), "-help"],
                         cwd=tmp_path, capture_output=True, text=True,
                         timeout=60)
    assert res.returncode == 0, res.stdout + res.stderr
    assert "can't read" not in res.stderr and "Main job" not in res.stdout
    assert len(res.stdout.splitlines()) > 10


def test_main_job_refused_option_says_failed(foam_env):
    """The main job after a refused option says that it failed, with the
    tutorial's exit status, and names no report (it named runs/small's,
    whatever ran, after 'Main job done')."""
    res = subprocess.run(["./Allrun", "-np", "0"], cwd=project_dir(),
                         capture_output=True, text=True, timeout=600)
    assert res.returncode == 1, res.stdout + res.stderr
    assert "Main job failed (exit status 1)" in res.stdout
    assert "Main job done" not in res.stdout and "Report:" not in res.stdout


@pytest.mark.parametrize("tutorial, preset", [
    ("verticalChannel", "smoke"), ("shearFlowValidation", "ci")])
def test_second_driver_on_a_run_folder_refused(tmp_path, foam_env,
                                               tutorial, preset):
    """A run folder in use (a live run's lock) refuses a second driver
    before it touches anything, naming the holder: two drivers on one
    folder appended to one event log (992 events against the run's 496)
    and reported PASS from doubled counts."""
    import shutil
    from runLocks import lock_text
    tut = tmp_path / tutorial
    shutil.copytree(TUT / tutorial, tut, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    base = tut / "runs" / preset
    base.mkdir(parents=True)
    holder = subprocess.Popen(["sleep", "60"])
    try:
        (base / ".aggloRun.lock").write_text(lock_text(holder.pid))
        res = subprocess.run(["./Allrun", "-preset", preset], cwd=tut,
                             capture_output=True, text=True, timeout=120)
    finally:
        holder.kill()
        holder.wait()
    assert res.returncode == 1, res.stdout[-2000:]
    assert "is in use by another run" in res.stderr
    assert f"process {holder.pid} runs" in res.stderr
    assert sorted(p.name for p in base.iterdir()) == [".aggloRun.lock"]


@pytest.mark.parametrize("script", ["Allrun",
                                    "tutorials/verticalChannel/Allrun",
                                    "tutorials/shearFlowValidation/Allrun",
                                    "tutorials/breakupShear/Allrun",
                                    "tutorials/bendDeposition/Allrun"])
def test_started_by_bash_or_through_a_link(tmp_path, foam_env, script):
    """`bash Allrun` and a link to an Allrun start in the script's own
    folder (they failed: 'cd: Allrun: Not a directory', or ran in the
    link's folder)."""
    target = project_dir() / script
    res = subprocess.run(["bash", target.name, "-help"], cwd=target.parent,
                         capture_output=True, text=True, timeout=60)
    assert res.returncode == 0, res.stderr
    assert "-preset" in res.stdout
    link = tmp_path / "Allrun"
    link.symlink_to(target)
    res = subprocess.run([str(link), "-help"], cwd=tmp_path,
                         capture_output=True, text=True, timeout=60)
    assert res.returncode == 0, res.stderr
    assert "-preset" in res.stdout
