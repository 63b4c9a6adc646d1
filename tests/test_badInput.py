"""Bad input stops with a clear error: every dictionary this project defines
rejects unknown entries, out-of-range coefficients and unknown model names
with an OpenFOAM fatal (IO) error that names the offending entry; the
tutorials' presets files reject unknown entries; hardSphereCollide insists
on its one argument.

Each case edits one entry of a valid scripted box case (two 12 um quartz
primaries, EAM, smooth walls) and asserts a non-zero exit status and that
the message after "FOAM FATAL" names the entry. The unedited case runs
(test_valid_case_runs), so every failure below is caused by its edit."""

import shutil
import subprocess
import sys

import pytest

from conftest import ROOT, foam_bin
from hscase import box_case, run_case

L = 1e-4
PAIR = [dict(x=(0.4 * L, 0.5 * L, 0.5 * L), U=(1e-3, 0, 0), id=0),
        dict(x=(0.6 * L, 0.5 * L, 0.5 * L), U=(-1e-3, 0, 0), id=1)]

EAM = "agglomerationModel EAM;"
STRUCT = "structureModel CSM;"
PC = "particleCollision { en 0.97; et 0.44; muSt 0.94; muKin 0.092; }"
MAT = "material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9;"
SMOOTH = "smoothCoeffs { en 0.8; et 0.4; muSt 0.3; muKin 0.15; }"
WALL = "wallModel smooth; " + SMOOTH
SAND = ("wallModel sandgrain; sandgrainCoeffs { en 0.9; et 0.3; "
        "muSt 0.5; muKin 0.4; Rz 10e-6; CSurface 3; }")
MAM = "agglomerationModel MAM;"
ROT = "rotationModel none;"
COLL = "collisionModel hardSphere;"
STATS = "hardSphereStatistics { type hardSphereStatistics; }"
SOL = "cellValueSourceCorrection off;"

# name: (old text, new text, word the message must name)
CASES = {
    # misspelt optional entries of hardSphereCoeffs (were silently ignored)
    "overlapTreatmnet": (EAM, EAM + " overlapTreatmnet separate;",
                         "overlapTreatmnet"),
    "encounterMemroy": (EAM, EAM + " encounterMemroy 1;", "encounterMemroy"),
    "capAgglomerateSpn": (EAM, EAM + " capAgglomerateSpn true;",
                          "capAgglomerateSpn"),
    "wallContct": (EAM, EAM + " wallContct centre;", "wallContct"),
    "EAMCoefs": (EAM, EAM + " EAMCoefs { impactVelocity full; }",
                 "EAMCoefs"),
    "randomSeeed": (EAM, EAM + " randomSeeed 3;", "randomSeeed"),
    "pairSerch": (EAM, EAM + " pairSerch bruteForce;", "pairSerch"),
    "MAMCoeffsUnderEAM": (EAM, EAM + " MAMCoeffs { closure table4; }",
                          "MAMCoeffs"),
    # sub-dictionaries of the kernel
    "muKn": (PC, PC.replace("muKin", "muKn"), "muKn"),
    "particleCollisionExtra": (PC, PC.replace("}", "mu 0.3; }"), "mu"),
    "materialExtra": (MAT, MAT + " Hamaker 1e-20;", "Hamaker"),
    "EAMvariant": (EAM, EAM + " EAMCoeffs { variant alletto2014; }",
                   "EAMAlletto2014"),
    "EAMCoeffsUnknown": (EAM, EAM + " EAMCoeffs { impactVelocty full; }",
                         "impactVelocty"),
    "EAMimpactVelocity": (EAM, EAM + " EAMCoeffs { impactVelocity fast; }",
                          "fast"),
    "EAMprojection": (EAM, EAM + " EAMCoeffs { tangentialProjection "
                      "diagonal; }", "diagonal"),
    "MAMclosre": (EAM, MAM + " MAMCoeffs { closre table4; }", "closre"),
    "MAMclosure": (EAM, MAM + " MAMCoeffs { closure linear; }", "linear"),
    "MAMtable4": (EAM, MAM + " MAMCoeffs { table4Coeffs { Cg 2; ag 0.3;"
                  " bg 1; } }", "bg"),
    "MAMCg": (EAM, MAM + " MAMCoeffs { table4Coeffs { Cg -2; ag 0.3; } }",
              "Cg"),
    "MAMsliding": (EAM, MAM + " MAMCoeffs { slidingCriterion sometimes; }",
                   "sometimes"),
    "MAMfriction": (EAM, MAM + " MAMCoeffs { frictionContactTime long; }",
                    "long"),
    "CSMfPackLarg": (STRUCT, STRUCT + " CSMCoeffs { fPackLarg 0.5; }",
                     "fPackLarg"),
    "CSMfPackLarge": (STRUCT, STRUCT + " CSMCoeffs { fPackLarge 1.5; }",
                      "fPackLarge"),
    "VSMCoeffs": (STRUCT, "structureModel VSM; VSMCoeffs { fPack 1; }",
                  "fPack"),
    "structureModelName": (STRUCT, "structureModel CSN;", "CSN"),
    "structureModelMissing": (STRUCT, "", "structureModel"),
    "agglomerationModelName": (EAM, "agglomerationModel MAN;", "MAN"),
    "agglomerationModelMissing": (EAM, "", "agglomerationModel"),
    # material and coefficient ranges
    "enZero": (PC, PC.replace("en 0.97", "en 0"), "en"),
    "etLarge": (PC, PC.replace("et 0.44", "et 1.5"), "et"),
    "muStNegative": (PC, PC.replace("muSt 0.94", "muSt -1"), "muSt"),
    "nuHalf": (MAT, MAT.replace("nu 0.17", "nu 0.5"), "nu"),
    "Hzero": (MAT, MAT.replace("H 6.3e-20", "H 0"), "H"),
    "Emissing": (MAT, MAT.replace("E 7.2e10; ", ""), "E"),
    "pMaxAndSigmaY": (MAT, MAT + " sigmaY 1.1e9;", "sigmaY"),
    "delta0Zero": ("delta0 2e-10;", "delta0 0;", "delta0"),
    "rho0Negative": ("rho0 2200; }\n    particleCollision",
                     "rho0 -2200; }\n    particleCollision", "rho0"),
    # the collision model's own options
    "overlapTreatment": (EAM, EAM + " overlapTreatment apart;", "apart"),
    "encounterMemory": (EAM, EAM + " encounterMemory -1;",
                        "encounterMemory"),
    "encounterRelease": (EAM, EAM + " encounterRelease never;",
                         "encounterRelease"),
    "collisionResponse": (EAM, EAM + " collisionResponse gost;", "gost"),
    "ghostWithEAM": (EAM, EAM + " collisionResponse ghost;", "ghost"),
    "wallContact": (EAM, EAM + " wallContact surface;", "surface"),
    "wallPositionCorrection": (EAM, EAM + " wallPositionCorrection push;",
                               "push"),
    "pairSearch": (EAM, EAM + " pairSearch octree;", "octree"),
    # walls
    "wallEntryExtra": (WALL, WALL + " roughness 1;", "roughness"),
    "wallModelName": (WALL, WALL.replace("smooth;", "rough;"), "rough"),
    "smoothCoeffsExtra": (SMOOTH, SMOOTH.replace("}", "mu 1; }"), "mu"),
    "smoothCoeffsMissing": (SMOOTH, "", "smoothCoeffs"),
    "smoothEn": (SMOOTH, SMOOTH.replace("en 0.8", "en 1.1"), "en"),
    "sandgrainCSurfce": (WALL, SAND.replace("CSurface", "CSurfce"),
                         "CSurfce"),
    "sandgrainRzMissing": (WALL, SAND.replace("Rz 10e-6; ", ""), "Rz"),
    "sandgrainSigmaGamma": (WALL, SAND.replace("}", "sigmaGamma 95; }"),
                            "sigmaGamma"),
    "sandgrainShadow": (WALL, SAND.replace("}", "shadowMode none; }"),
                        "none"),
    "wallPatchMissing": ('walls { ".*"', 'walls { "nothing"', "xMin"),
    # cloud submodels
    "collisionModelName": (COLL, "collisionModel hardSpher;", "hardSpher"),
    "collisionModelMissing": (COLL, "", "collisionModel"),
    "rotationModelName": (ROT, "rotationModel fluidTorq;", "fluidTorq"),
    "rotationModelMissing": (ROT, "", "rotationModel"),
    "statisticsKey": (STATS, STATS.replace("}", "profile true; }"),
                      "profile"),
    "statisticsBins": (STATS, STATS.replace("}", "profiles true; "
                       "direction (0 1 0); nBins 0; }"), "nBins"),
    "statisticsDirection": (STATS, STATS.replace("}", "profiles true; "
                            "direction (0 0 0); nBins 4; }"), "direction"),
    "couplingScaleZero": (SOL, SOL + " couplingScale 0;", "couplingScale"),
    "couplingScaleNegative": (SOL, SOL + " couplingScale -6;",
                              "couplingScale"),
}

# Cases needing other sub-models in the case (forces, dispersion)
SUBMODEL_CASES = {
    "rotationLiftKey": ("particleForces {}", "particleForces { rotationLift"
                        " { model OesterleBuiDinh; Uc U; } }", "Uc"),
    "rotationLiftModel": ("particleForces {}", "particleForces "
                          "{ rotationLift { model Magnus; } }", "Magnus"),
    "PozorskiApteKey": ("dispersionModel none;", "dispersionModel "
                        "PozorskiApte; PozorskiApteCoeffs { kSgsSource nut;"
                        " Ckk 0.094; wallReflection true; }", "Ckk"),
    "PozorskiApteCk": ("dispersionModel none;", "dispersionModel "
                       "PozorskiApte; PozorskiApteCoeffs { kSgsSource nut;"
                       " Ck -1; wallReflection true; }", "Ck"),
}


def edited_case(case_dir, old, new):
    box_case(case_dir, L=(L, L, L), particles=PAIR, agglomeration="EAM",
             dt=1e-5, end_time=2e-5)
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    assert old in text, old
    f.write_text(text.replace(old, new, 1))


def assert_fatal_naming(res, word):
    assert res.returncode != 0
    assert "FOAM FATAL" in res.stdout, res.stdout[-2000:]
    assert word in res.stdout.split("FOAM FATAL", 1)[1], \
        res.stdout[-2000:]


def test_valid_case_runs(case_dir, foam_env):
    """The unedited case (and one with every sub-model entry used by the
    cases below spelt right) runs to the end."""
    edited_case(case_dir, "particleForces {}", "particleForces { "
                "rotationLift { model OesterleBuiDinh; U U; } }")
    res = run_case(case_dir, check=False)
    assert res.returncode == 0, res.stdout[-2000:]
    assert "End" in res.stdout


@pytest.mark.parametrize("name", list(CASES) + list(SUBMODEL_CASES))
def test_bad_cloud_input(case_dir, foam_env, name):
    old, new, word = {**CASES, **SUBMODEL_CASES}[name]
    edited_case(case_dir, old, new)
    assert_fatal_naming(run_case(case_dir, check=False), word)


# ------------------------------------------------------- hardSphereCollide

COLLIDE = """FoamFile { version 2.0; format ascii; class dictionary;
object collide; }
material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9; delta0 2e-10;
           rho0 2200; }
particleCollision { en 0.97; et 0.44; muSt 0.94; muKin 0.092; }
agglomerationModel EAM;
structureModel CSM;
particle1 { position (0 0 0); U (5e-4 0 0); d 12e-6; rho 2200; }
particle2 { position (12e-6 0 0); U (-5e-4 0 0); d 12e-6; rho 2200; }
"""


def collide(tmp_path, args, text=COLLIDE):
    f = tmp_path / "collide"
    f.write_text(text)
    return subprocess.run([foam_bin("hardSphereCollide")] + args,
                          cwd=tmp_path, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=60)


def test_collide_valid(tmp_path, foam_env):
    res = collide(tmp_path, ["collide"])
    assert res.returncode == 0, res.stdout
    assert '"agglomerate": true' in res.stdout


@pytest.mark.parametrize("args", [[], ["collide", "extra"]])
def test_collide_needs_one_argument(tmp_path, foam_env, args):
    """No argument used to abort with 'new cannot satisfy memory request'
    (exit 134); extra arguments were ignored."""
    res = collide(tmp_path, args)
    assert res.returncode not in (0, 134)
    assert "dictFile" in res.stdout
    assert "memory" not in res.stdout


@pytest.mark.parametrize("old,new,word", [
    ("particle1 {", "partcle1 {", "partcle1"),
    ("d 12e-6; rho 2200; }\nparticle2",
     "d 12e-6; rho 2200; diameter 1; }\nparticle2", "diameter"),
    ("structureModel CSM;", "structureModel CSM; contactTolerence 1;",
     "contactTolerence"),
])
def test_collide_unknown_entries(tmp_path, foam_env, old, new, word):
    assert old in COLLIDE
    res = collide(tmp_path, ["collide"], COLLIDE.replace(old, new, 1))
    assert_fatal_naming(res, word)


# ------------------------------------------------- tutorial presets files

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
