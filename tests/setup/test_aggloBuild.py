"""bin/aggloBuild, the start of ./Allrun and ./Alltest: its first line
within a second (the set-up and the build were silent for minutes on a
fresh clone), a line at least every AGGLO_HEARTBEAT seconds while a step
runs, the build's log named, and a failed step's status passed on."""

import os
import subprocess
import time

from aggloTools.runner import project_dir

ROOT = project_dir()


def test_first_line_at_once_and_a_line_while_building(foam_env):
    t0 = time.time()
    proc = subprocess.Popen([str(ROOT / "bin" / "aggloBuild"), "Test"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True,
                            env=dict(os.environ, AGGLO_HEARTBEAT="1"))
    first = proc.stdout.readline()
    assert time.time() - t0 < 1.0
    assert first.startswith("Test: set-up (bin/aggloSetup")
    rest = proc.stdout.read().splitlines()
    assert proc.wait() == 0
    assert any(ln.startswith("Test: building (log: log.Allwmake")
               for ln in rest)
    beats = [ln for ln in rest if "still running" in ln]
    built = [ln for ln in rest if ln.startswith("Test: built in ")]
    assert len(built) == 1
    seconds = int(built[0].split()[3])
    assert len([b for b in beats if "build" in b]) >= seconds - 1


def test_failed_build_names_its_log(tmp_path, foam_env):
    """A build that fails: the log's tail, the log named, exit status 1
    (a copy of the script in a tree whose Allwmake fails)."""
    (tmp_path / "bin").mkdir()
    (tmp_path / "bin" / "aggloBuild").write_bytes(
        (ROOT / "bin" / "aggloBuild").read_bytes())
    (tmp_path / "bin" / "aggloSetup").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "Allwmake").write_text("#!/bin/sh\necho broken; exit 2\n")
    for f in ("bin/aggloBuild", "bin/aggloSetup", "Allwmake"):
        (tmp_path / f).chmod(0o755)
    res = subprocess.run([str(tmp_path / "bin" / "aggloBuild"), "Test"],
                         capture_output=True, text=True, timeout=60)
    assert res.returncode == 1
    assert "broken" in res.stdout
    assert "Test: the build failed; the full log is in log.Allwmake" \
        in res.stderr
