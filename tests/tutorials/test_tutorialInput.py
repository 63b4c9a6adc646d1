"""The tutorials' input files reject what they do not know: a misspelt
entry of a presets file or of a generated caseSettings stops the
tutorial's script naming the entry, and the shear tutorial's step
dt*gammaDot out of its range stops its set-up naming the range."""

import shutil
import subprocess
import sys

import pytest

from aggloTools.runner import project_dir, tutorial_module

ROOT = project_dir()


@pytest.mark.parametrize("tutorial,script,args,block", [
    ("shearFlowValidation", "shearFlow.py", ["settings", "ci", "EAM"],
     "ci\n{"),
    ("shearFlowValidation", "shearFlow.py", ["settings", "ci", "EAM"],
     "common\n{"),
    ("verticalChannel", "channel.py", ["settings", "smoke", "C1",
                                        "unladen"], "smoke\n{"),
    ("verticalChannel", "channel.py", ["settings", "smoke", "C1",
                                        "unladen"], "common\n{"),
    ("verticalChannel", "channel.py", ["settings", "smoke", "C1",
                                        "unladen"], "C1  {"),
])
def test_presets_reject_unknown_entries(tmp_path, foam_env, tutorial,
                                        script, args, block):
    """A misspelt preset entry (nParticels) stops the script with a message
    naming it, instead of being ignored."""
    case = tmp_path / tutorial
    shutil.copytree(ROOT / "tutorials" / tutorial, case,
                    ignore=shutil.ignore_patterns("runs", "results"))
    good = subprocess.run([sys.executable, script] + args, cwd=case,
                          capture_output=True, text=True)
    assert good.returncode == 0, good.stderr
    presets = case / "presets"
    text = presets.read_text()
    assert block in text
    presets.write_text(text.replace(block, block + " nParticels 10;", 1))
    bad = subprocess.run([sys.executable, script] + args, cwd=case,
                         capture_output=True, text=True)
    assert bad.returncode != 0
    assert "nParticels" in bad.stderr + bad.stdout


@pytest.mark.parametrize("entry, value", [
    ("dtGamma", "-0.02"), ("dtGamma", "1e-9"), ("dtGamma", "0.5"),
    ("detectDtGamma", "0"),
])
def test_shear_step_out_of_range(tmp_path, foam_env, entry, value):
    """dt*gammaDot out of its range stops the set-up naming the entry and
    the range: a negative step ran the solver backwards in time (and the
    Allrun waited forever), 1e-9 meant about 2e10 steps."""
    case = tmp_path / "shearFlowValidation"
    shutil.copytree(ROOT / "tutorials" / "shearFlowValidation", case,
                    ignore=shutil.ignore_patterns("runs", "results"))
    args = ["shearFlow.py", "settings", "ci", "detect" if "detect" in entry
            else "EAM"]
    good = subprocess.run([sys.executable] + args, cwd=case,
                          capture_output=True, text=True)
    assert good.returncode == 0, good.stderr
    presets = case / "presets"
    text = presets.read_text()
    old = [line for line in text.splitlines()
           if line.strip().startswith(entry + " ")][0]
    presets.write_text(text.replace(old, f"    {entry} {value};", 1))
    bad = subprocess.run([sys.executable] + args, cwd=case,
                         capture_output=True, text=True)
    assert bad.returncode != 0
    assert entry in bad.stderr and "[0.0001, 0.1]" in bad.stderr, \
        bad.stderr


@pytest.mark.parametrize("tutorial,script,args", [
    ("shearFlowValidation", "shearFlow", ["settings", "ci", "EAM"]),
    ("verticalChannel", "channel", ["settings", "smoke", "C1", "unladen"]),
])
def test_case_settings_reject_unknown_entries(tmp_path, foam_env, tutorial,
                                              script, args):
    """The generated caseSettings pass; a misspelt entry added by hand
    stops the tutorial's scripts that read it, naming the entry."""
    tut = ROOT / "tutorials" / tutorial
    text = subprocess.run([sys.executable, f"{script}.py"] + args, cwd=tut,
                          capture_output=True, text=True, check=True).stdout
    (tmp_path / "system").mkdir()
    f = tmp_path / "system" / "caseSettings"
    f.write_text(text)
    for sibling in {"shearFlow": ["shearTheory", "shearCase"]}.get(
            script, []):
        tutorial_module(tutorial, sibling)   # imported by the script
    module = tutorial_module(tutorial, script)
    assert len(module.read_settings(tmp_path)) > 10
    f.write_text(text + "\nnParticels 10;\n")
    with pytest.raises(SystemExit, match="nParticels"):
        module.read_settings(tmp_path)
