"""Every user-facing command answers -h (or -help) with what it does and
its options, exit status 0, and runs nothing: the Allruns, Allcleans and
Alltest of the project and its tutorials, the set-up, the tutorials'
Python drivers, the benchmarks and the solver and utilities. (-h of an
Allclean cleaned the build; the channel's post-processing took -h for a
preset; its settings and particles commands exited 1.)"""

import subprocess
import sys

import pytest

from aggloTools.runner import foam_bin, project_dir

ROOT = project_dir()
TUT = ROOT / "tutorials"

#: (folder, command, words the help must hold)
SHELL = [
    (ROOT, ["./Allrun", "-help"], "-preset"),
    (ROOT, ["./Allclean", "-help"], "No options"),
    (ROOT, ["./Allwmake", "-help"], "wmake"),
    (ROOT, ["bin/aggloSetup", "-h"], "aggloSetup"),
] + [(TUT / t, ["./Allrun", "-help"], w) for t, w in (
    ("verticalChannel", "-preset"), ("shearFlowValidation", "-preset"),
    ("breakupShear", "-preset"), ("bendDeposition", "-preset"),
    ("laminarChannel", "no options"))] + [
    (TUT / t, ["./Allclean", "-help"], "No options") for t in (
        "verticalChannel", "shearFlowValidation", "breakupShear",
        "bendDeposition", "laminarChannel")]

PYTHON = [
    ("verticalChannel", "-m channel.case", "settings"),
    ("verticalChannel", "-m channel.case.particles", "release"),
    ("verticalChannel", "-m channel.post", "--reference"),
    ("verticalChannel", "-m channel.regime", "post"),
    ("verticalChannel", "-m channel.post.replay", "--reference"),
    ("verticalChannel", "-m channel.post.dispersion", "--span"),
    ("verticalChannel", "-m channel", "-preset"),
    ("shearFlowValidation", "-m shear.case", "settings"),
    ("shearFlowValidation", "-m shear.post", "rejudge"),
    ("shearFlowValidation", "-m shear.post.replay", "preset"),
    ("shearFlowValidation", "-m shear.post.contacts", "runs"),
    ("shearFlowValidation", "-m shear.study", "list"),
    ("shearFlowValidation", "-m shear", "-preset"),
    ("breakupShear", "breakupShear.py", "-preset"),
    ("bendDeposition", "bendDeposition.py", "-preset"),
    ("laminarChannel", "checkPoiseuille.py", "usage"),
]
#: The benchmarks a user starts (bench/; the others are their modules)
BENCH = ["caseFileIO.py", "channelCosts.py", "channelCostsVs.py",
         "channelSolverSettings.py", "hardSphereCloud.py"]

APPS = ["aggloPimpleFoam", "hardSphereReplay", "breakupReplay",
        "hardSphereCollide"]


def _ids(rows):
    return [f"{d.name}/{' '.join(c)}" for d, c, _ in rows]


@pytest.mark.parametrize("folder, cmd, words", SHELL, ids=_ids(SHELL))
def test_shell_commands(foam_env, folder, cmd, words):
    before = sorted(p.name for p in folder.iterdir())
    res = subprocess.run(cmd, cwd=folder, capture_output=True, text=True,
                         timeout=120)
    assert res.returncode == 0, res.stdout[-1000:] + res.stderr[-1000:]
    assert words in res.stdout + res.stderr
    assert sorted(p.name for p in folder.iterdir()) == before


@pytest.mark.parametrize("tutorial, script, words", PYTHON,
                         ids=[s for _, s, _ in PYTHON])
def test_python_drivers(foam_env, tutorial, script, words):
    folder = TUT / tutorial
    before = sorted(p.name for p in folder.iterdir())
    res = subprocess.run([sys.executable, *script.split(), "-h"], cwd=folder,
                         capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stdout[-1000:] + res.stderr[-1000:]
    assert words in res.stdout
    assert sorted(p.name for p in folder.iterdir()) == before


@pytest.mark.parametrize("script", BENCH)
def test_benchmarks(foam_env, script):
    folder = ROOT / "bench"
    before = sorted(p.name for p in folder.iterdir())
    res = subprocess.run([sys.executable, *script.split(), "-h"], cwd=folder,
                         capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stdout[-1000:] + res.stderr[-1000:]
    assert res.stdout.startswith("usage:")
    assert sorted(p.name for p in folder.iterdir()) == before


@pytest.mark.parametrize("app", APPS)
def test_applications(foam_env, app, tmp_path):
    res = subprocess.run([foam_bin(app), "-help"], cwd=tmp_path,
                         capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stdout[-1000:]
    assert "Usage:" in res.stdout and "-case" in res.stdout
    assert list(tmp_path.iterdir()) == []
