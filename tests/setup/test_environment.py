"""The OpenFOAM environment and the project binaries work: blockMesh and
checkMesh on a small mesh, the solver and the utility load with a clear
error on bad input."""

import os
import re
import shutil
import subprocess

from aggloTools.runner import foam_bin, project_dir, run

ROOT = project_dir()

CHANNEL = ROOT / "tutorials" / "laminarChannel"


def test_blockmesh_checkmesh(case_dir, foam_env):
    shutil.copytree(CHANNEL / "system", case_dir / "system")
    shutil.copytree(CHANNEL / "constant", case_dir / "constant")
    run([foam_bin("blockMesh")], case_dir, "log.blockMesh")
    res = run([foam_bin("checkMesh")], case_dir, "log.checkMesh")
    assert "Mesh OK." in res.stdout
    # 4 x 20 x 1 hexahedra from the blockMeshDict
    m = re.search(r"cells:\s+(\d+)", res.stdout)
    assert m and int(m.group(1)) == 80
    assert re.search(r"hexahedra:\s+80\b", res.stdout)


def test_solver_loads_and_rejects_empty_case(case_dir, foam_env):
    res = run([foam_bin("aggloPimpleFoam")], case_dir, "log.solver",
              check=False)
    # OpenFOAM banner, then the fatal error about the missing case files
    assert "OpenFOAM: The Open Source CFD Toolbox" in res.stdout
    assert re.search(r"^Exec\s+:\s+\S*aggloPimpleFoam\s*$", res.stdout, re.M)
    assert res.returncode != 0
    assert "FOAM FATAL" in res.stdout
    assert "controlDict" in res.stdout


def test_solver_help_lists_cloud_option(foam_env):
    res = subprocess.run([foam_bin("aggloPimpleFoam"), "-help"],
                         capture_output=True, text=True)
    assert res.returncode == 0
    assert "-cloud" in res.stdout


def test_library_loads_in_stock_utility(case_dir, foam_env):
    """A stock utility (checkMesh) loads the library named by the
    controlDict's libs entry and runs its static initialisers (the
    run-time selection tables): glibc's loader trace shows the init call,
    and OpenFOAM reports no library it could not load."""
    shutil.copytree(CHANNEL / "system", case_dir / "system")
    shutil.copytree(CHANNEL / "constant", case_dir / "constant")
    run([foam_bin("blockMesh")], case_dir, "log.blockMesh")
    env = dict(os.environ, LD_DEBUG="files", PWD=str(case_dir))
    res = subprocess.run([foam_bin("checkMesh")], cwd=case_dir, env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    assert res.returncode == 0, res.stdout[-3000:]
    lib = ROOT / "platforms" / foam_env["WM_OPTIONS"] / "lib" / \
        "libagglomerationHardSphere.so"
    assert re.search(r"calling init: " + re.escape(str(lib)) + r"\s*$",
                     res.stdout, re.M), res.stdout[-3000:]
    assert "Could not load" not in res.stdout
