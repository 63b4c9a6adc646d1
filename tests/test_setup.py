"""bin/aggloSetup: unsupported systems stop at once with a clear message;
a second run on a set-up machine changes nothing and is fast."""

import hashlib
import os
import subprocess
import time

from conftest import ROOT

SETUP = ROOT / "bin" / "aggloSetup"


def _clean_env(**extra):
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("WM_", "FOAM_"))}
    env.update(extra)
    return env


def test_unsupported_system_stops_with_message(tmp_path):
    fake = tmp_path / "os-release"
    fake.write_text('ID=ubuntu\nVERSION_ID="22.04"\n')
    t0 = time.time()
    res = subprocess.run([str(SETUP)], capture_output=True, text=True,
                         env=_clean_env(AGGLO_OS_RELEASE=str(fake)))
    assert res.returncode == 1
    assert time.time() - t0 < 5
    assert "ubuntu 22.04" in res.stderr
    assert "Debian 12" in res.stderr
    assert "etc/bashrc" in res.stderr      # how to use an own OpenFOAM


def _digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() \
        else None


def test_second_run_is_fast_and_changes_nothing():
    prefs = ROOT / "etc" / "prefs.sh"
    stamp = ROOT / ".venv" / ".aggloRequirements"
    before = (_digest(prefs), _digest(stamp), prefs.stat().st_mtime)
    t0 = time.time()
    res = subprocess.run([str(SETUP)], capture_output=True, text=True,
                         env=_clean_env())
    elapsed = time.time() - t0
    assert res.returncode == 0, res.stderr
    assert elapsed < 15
    assert (_digest(prefs), _digest(stamp), prefs.stat().st_mtime) == before
    assert "installing" not in res.stdout
