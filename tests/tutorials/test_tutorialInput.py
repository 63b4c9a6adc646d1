"""The tutorials' input files reject what they do not know: a misspelt
entry of a presets file or of a generated caseSettings stops the
tutorial's script naming the entry, and the shear tutorial's step
dt*gammaDot out of its range stops its set-up naming the range."""

import re
import shutil
import subprocess
import sys

import pytest

from aggloTools.runner import project_dir, tutorial_module

ROOT = project_dir()
#: The channel tutorial's settings command, in its folder
CHANNEL_CASE = ["-m", "channel.case"]
#: The shear tutorial's settings command, in its folder
SHEAR_CASE = ["-m", "shear.case"]


@pytest.mark.parametrize("tutorial,script,args,block", [
    ("shearFlowValidation", SHEAR_CASE, ["settings", "ci", "EAM"],
     "ci\n{"),
    ("shearFlowValidation", SHEAR_CASE, ["settings", "ci", "EAM"],
     "common\n{"),
    ("verticalChannel", CHANNEL_CASE, ["settings", "smoke", "C1",
                                       "unladen"], "smoke\n{"),
    ("verticalChannel", CHANNEL_CASE, ["settings", "smoke", "C1",
                                       "unladen"], "common\n{"),
    ("verticalChannel", CHANNEL_CASE, ["settings", "smoke", "C1",
                                       "unladen"], "C1  {"),
])
def test_presets_reject_unknown_entries(tmp_path, foam_env, tutorial,
                                        script, args, block):
    """A misspelt preset entry (nParticels) stops the script with a message
    naming it, instead of being ignored."""
    case = tmp_path / tutorial
    shutil.copytree(ROOT / "tutorials" / tutorial, case,
                    ignore=shutil.ignore_patterns("runs", "results"))
    good = subprocess.run([sys.executable, *script] + args, cwd=case,
                          capture_output=True, text=True)
    assert good.returncode == 0, good.stderr
    presets = case / "presets"
    text = presets.read_text()
    assert block in text
    presets.write_text(text.replace(block, block + " nParticels 10;", 1))
    bad = subprocess.run([sys.executable, *script] + args, cwd=case,
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
    args = [*SHEAR_CASE, "settings", "ci", "detect" if "detect" in entry
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


@pytest.mark.parametrize("tutorial,cmd,script,args", [
    ("shearFlowValidation", SHEAR_CASE, "shear.case.settings",
     ["settings", "ci", "EAM"]),
    ("verticalChannel", CHANNEL_CASE, "channel.case.settings",
     ["settings", "smoke", "C1", "unladen"]),
])
def test_case_settings_reject_unknown_entries(tmp_path, foam_env, tutorial,
                                              cmd, script, args):
    """The generated caseSettings pass; a misspelt entry added by hand
    stops the tutorial's scripts that read it, naming the entry."""
    tut = ROOT / "tutorials" / tutorial
    text = subprocess.run([sys.executable, *cmd] + args, cwd=tut,
                          capture_output=True, text=True, check=True).stdout
    (tmp_path / "system").mkdir()
    f = tmp_path / "system" / "caseSettings"
    f.write_text(text)
    module = tutorial_module(tutorial, script)
    assert len(module.read_settings(tmp_path)) > 10
    f.write_text(text + "\nnParticels 10;\n")
    with pytest.raises(SystemExit, match="nParticels"):
        module.read_settings(tmp_path)


def _edited(tmp_path, tutorial, block, entry, value):
    """A copy of the tutorial whose presets file has entry set to value in
    block (a preset or common)."""
    case = tmp_path / tutorial
    shutil.copytree(ROOT / "tutorials" / tutorial, case,
                    ignore=shutil.ignore_patterns("runs", "results"))
    presets = case / "presets"
    text = presets.read_text()
    start = text.index(block)
    end = text.index("}", start)
    body = text[start:end]
    lines = [ln for ln in body.splitlines()
             if ln.strip().split(" ")[0] == entry]
    new = (body.replace(lines[0], f"    {entry} {value};", 1) if lines
           else body + f"    {entry} {value};\n")
    presets.write_text(text[:start] + new + text[end:])
    return case


@pytest.mark.parametrize("block, entry, value, words", [
    ("smoke\n{", "dtStar", "abc", "'abc' is not a number"),
    ("smoke\n{", "dtStar", "0", "'0' is out of range (0, 1]"),
    ("smoke\n{", "nParticles", "abc", "'abc' is not a number"),
    ("smoke\n{", "nParticles", "-5", "'-5' is out of range [1, inf)"),
    ("smoke\n{", "nParticles", "2000.7", "'2000.7' is not a whole number"),
    ("smoke\n{", "n", "(16 16)", "needs 3 numbers"),
    ("smoke\n{", "window", "(0.6 0)", "window (0.6 0) must lie inside"),
    ("smoke\n{", "window", "(0 5)", "window (0 5) must lie inside"),
    ("smoke\n{", "release", "-1", "'-1' is out of range [0, inf)"),
    ("smoke\n{", "profileBins", "1e8", "out of range [1, 100000]"),
    ("common\n{", "seed", "1.5", "'1.5' is not a whole number"),
])
def test_channel_preset_values_checked(tmp_path, foam_env, block, entry,
                                       value, words):
    """A preset value of the wrong type or out of range stops the settings
    command before anything runs, naming the preset, the entry and what it
    must be: before, 'abc', 0 and '(16 16)' ended in tracebacks, -5
    particles failed after the unladen stage, 2000.7 was truncated, and a
    reversed window or a negative phase was accepted."""
    case = _edited(tmp_path, "verticalChannel", block, entry, value)
    res = subprocess.run([sys.executable, *CHANNEL_CASE, "settings", "smoke",
                          "C1", "agglomeration"], cwd=case,
                         capture_output=True, text=True)
    assert res.returncode == 1, res.stdout[-500:]
    assert "Traceback" not in res.stderr, res.stderr
    assert entry in res.stderr and words in res.stderr, res.stderr


@pytest.mark.parametrize("entry, value, words", [
    ("subModels", "onn", "'onn' is not one of: on off, or a list of "
     "(twoWayCoupling sgsDispersion shearLift rotationLift)"),
    ("subModels", "()", "'()' is not one of: on off, or a list of"),
    ("subModels", "(sgsDispersion lfit)", "(sgsDispersion lfit): "
     "sub-model 'lfit' is not one of: twoWayCoupling sgsDispersion "
     "shearLift rotationLift"),
    ("subModels", "(shearLift sgsDispersion shearLift)", "shearLift named "
     "twice"),
    ("wall", "rouhg", "'rouhg' is not one of: smooth rough"),
    ("en", "1.5", "'1.5' is out of range [0, 1]"),
    ("d", "-1e-6", "out of range (0, inf)"),
])
def test_channel_configuration_values_checked(tmp_path, foam_env, entry,
                                              value, words):
    """A configuration's entries are checked as the presets' are: a
    misspelt subModels switched the sub-models off silently."""
    case = tmp_path / "verticalChannel"
    shutil.copytree(ROOT / "tutorials" / "verticalChannel", case,
                    ignore=shutil.ignore_patterns("runs", "results"))
    presets = case / "presets"
    text = presets.read_text()
    line = [ln for ln in text.splitlines() if ln.startswith("    C2  {")][0]
    new = re.sub(rf"\b{entry} [^;]*;", f"{entry} {value};", line)
    assert new != line
    presets.write_text(text.replace(line, new, 1))
    res = subprocess.run([sys.executable, *CHANNEL_CASE, "settings", "smoke",
                          "C2", "agglomeration"], cwd=case,
                         capture_output=True, text=True)
    assert res.returncode == 1
    assert "Traceback" not in res.stderr, res.stderr
    assert "configurations/C2" in res.stderr and entry in res.stderr
    assert words in res.stderr, res.stderr


@pytest.mark.parametrize("entry, value, words", [
    ("writes", "0", "'0' is out of range [1, inf)"),
    ("nParticles", "abc", "'abc' is not a number"),
    ("nx", "10.5", "'10.5' is not a whole number"),
])
def test_shear_preset_values_checked(tmp_path, foam_env, entry, value,
                                     words):
    """The shear tutorial's presets likewise (writes 0 divided by zero)."""
    case = _edited(tmp_path, "shearFlowValidation", "ci\n{", entry, value)
    res = subprocess.run([sys.executable, *SHEAR_CASE, "settings", "ci",
                          "EAM"], cwd=case, capture_output=True, text=True)
    assert res.returncode == 1, res.stdout[-500:]
    assert "Traceback" not in res.stderr, res.stderr
    assert f"presets/ci: {entry}" in res.stderr and words in res.stderr, \
        res.stderr


def test_presets_entry_given_twice(tmp_path, foam_env):
    """An entry given twice in one preset is refused (the later value
    replaced the earlier one silently), naming the entry and the file."""
    case = _edited(tmp_path, "verticalChannel", "smoke\n{", "nParticles",
                   "2000;\n    nParticles 3000")
    res = subprocess.run([sys.executable, *CHANNEL_CASE, "settings", "smoke",
                          "C1", "unladen"], cwd=case, capture_output=True,
                         text=True)
    assert res.returncode == 1 and "Traceback" not in res.stderr
    assert "entry 'nParticles' given twice" in res.stderr
    assert "presets" in res.stderr


def test_channel_replay_refusals(foam_env):
    """channel.post.replay: an unknown preset exits 1 naming the valid ones
    (it exited 0 with 'no collision event logs under runs/bogus'); -h
    prints its options and exits 0."""
    tut = ROOT / "tutorials" / "verticalChannel"
    replay = [sys.executable, "-m", "channel.post.replay"]
    res = subprocess.run(replay + ["bogus"], cwd=tut, capture_output=True,
                         text=True)
    assert res.returncode == 1 and "unknown preset 'bogus'" in res.stderr
    assert "smoke" in res.stderr
    res = subprocess.run(replay + ["-h"], cwd=tut, capture_output=True,
                         text=True)
    assert res.returncode == 0 and "--reference" in res.stdout


def test_channel_empty_configs_refused(tmp_path, foam_env):
    """-configs "" ran the unladen stage and reported nothing: it is
    refused before anything runs."""
    tut = tmp_path / "verticalChannel"
    shutil.copytree(ROOT / "tutorials" / "verticalChannel", tut,
                    ignore=shutil.ignore_patterns("runs", "results"))
    res = subprocess.run(["./Allrun", "-preset", "smoke", "-configs", ""],
                         cwd=tut, capture_output=True, text=True, timeout=60)
    assert res.returncode == 1
    assert "-configs names no configuration" in res.stderr
    assert not (tut / "runs").exists()
