"""The OpenFOAM environment and the project binaries work: blockMesh and
checkMesh on a small mesh, the solver and the utility load with a clear
error on bad input."""

import json
import re
import shutil

from conftest import ROOT, foam_bin, run

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
    import subprocess
    res = subprocess.run([foam_bin("aggloPimpleFoam"), "-help"],
                         capture_output=True, text=True)
    assert res.returncode == 0
    assert "-cloud" in res.stdout


def test_library_loads_in_stock_utility(case_dir, foam_env):
    """foamDictionary with libs(...) dlopens the library: it resolves all
    symbols against Debian's OpenFOAM libraries."""
    shutil.copytree(CHANNEL / "system", case_dir / "system")
    shutil.copytree(CHANNEL / "constant", case_dir / "constant")
    res = run([foam_bin("foamDictionary"), "-entry", "libs", "-value",
               "system/controlDict"], case_dir, "log.foamDictionary")
    assert "libagglomerationHardSphere.so" in res.stdout
    import ctypes
    lib = ROOT / "platforms" / foam_env["WM_OPTIONS"] / "lib" / \
        "libagglomerationHardSphere.so"
    ctypes.CDLL(str(lib))
