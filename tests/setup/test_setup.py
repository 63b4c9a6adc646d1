"""bin/aggloSetup: unsupported systems stop at their first step with a clear
message; a second run on a set-up machine finds every step done and
changes nothing."""

import hashlib
import os
import subprocess

from aggloTools.runner import project_dir

ROOT = project_dir()

SETUP = ROOT / "bin" / "aggloSetup"


def _clean_env(**extra):
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("WM_", "FOAM_"))}
    env.update(extra)
    return env


def test_unsupported_system_stops_with_message(tmp_path):
    fake = tmp_path / "os-release"
    fake.write_text('ID=ubuntu\nVERSION_ID="22.04"\n')
    res = subprocess.run([str(SETUP)], capture_output=True, text=True,
                         env=_clean_env(AGGLO_OS_RELEASE=str(fake)))
    assert res.returncode == 1
    # it stopped before its first step (nothing checked or installed)
    assert "Debian packages" not in res.stdout + res.stderr
    assert "ubuntu 22.04" in res.stderr
    assert "Debian 12" in res.stderr
    assert "etc/bashrc" in res.stderr      # how to use an own OpenFOAM


def _digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() \
        else None


def test_second_run_changes_nothing():
    prefs = ROOT / "etc" / "prefs.sh"
    stamp = ROOT / ".venv" / ".aggloRequirements"
    before = (_digest(prefs), _digest(stamp), prefs.stat().st_mtime)
    res = subprocess.run([str(SETUP)], capture_output=True, text=True,
                         env=_clean_env())
    assert res.returncode == 0, res.stderr
    # every step found done: nothing installed, fetched, built or created
    for word in ("installing", "fetching", "building", "making", "creating"):
        assert word not in res.stdout, (word, res.stdout)
    assert "Debian packages: present" in res.stdout
    assert (_digest(prefs), _digest(stamp), prefs.stat().st_mtime) == before
    assert "installing" not in res.stdout
