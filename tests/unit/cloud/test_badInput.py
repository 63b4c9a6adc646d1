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

import numpy as np
import pytest

from aggloTools import placement, times
from aggloTools.boxcase import box_case, run_case
from aggloTools.cloud import cloud_dir, read_cloud, read_positions
from aggloTools.runner import foam_bin, project_dir, run, tutorial_module
from aggloTools.stats import stats_rows as stats

ROOT = project_dir()

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
BRK = ("strength { rumpfPrefactor 1.125; coordination exactSmallRumpf; }"
       " stresses { mechanisms (rotation); rotationFactor 0.0625; }"
       " fragmentation { mode erosion; }")
FRAG = "mode erosion; direction extensional; gap 1e-3; spin conserveL;"

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
    # an entry that names no wall patch, or one shadowed by another entry,
    # was silently ignored
    "wallEntryMisspelt": ('walls { ".*"', 'walls { yMinn { ' + SAND
                          + ' } ".*"', "yMinn"),
    "wallEntryShadowed": ('walls { ".*"', 'walls { "(xMin|yMin)" { '
                          'wallModel foo; } ".*"', "foo"),
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
    # break-up (absent: none): a misspelt key would leave it off
    "breakupModelName": (ROT, ROT + " breakupModel stressTreshold;",
                         "stressTreshold"),
    "breakUpModelKey": (ROT, ROT + " breakUpModel stressThreshold;",
                        "breakUpModel"),
    "breakupCoeffsKey": (ROT, ROT + " breakupModel stressThreshold;"
                         " stressThresholdCoeffs { " + BRK + " seed 1; }",
                         "seed"),
    "breakupStrengthMissing": (ROT, ROT + " breakupModel stressThreshold;"
                               " stressThresholdCoeffs { "
                               + BRK[BRK.index("stresses"):] + " }",
                               "strength"),
    "breakupMechanism": (ROT, ROT + " breakupModel stressThreshold;"
                         " stressThresholdCoeffs { "
                         + BRK.replace("(rotation)", "(centrifugal)")
                         + " }", "centrifugal"),
    # the wall-impact coefficient without its mechanism, and out of range
    "breakupCwOff": (ROT, ROT + " breakupModel stressThreshold;"
                     " stressThresholdCoeffs { "
                     + BRK.replace("rotationFactor 0.0625;",
                                   "rotationFactor 0.0625; Cw 1;")
                     + " }", "Cw"),
    "breakupCwZero": (ROT, ROT + " breakupModel stressThreshold;"
                      " stressThresholdCoeffs { "
                      + BRK.replace("(rotation); rotationFactor 0.0625;",
                                    "(wallImpact); Cw 0;")
                      + " }", "Cw"),
    "breakupEventLogWord": (ROT, ROT + " breakupModel stressThreshold;"
                            " stressThresholdCoeffs { "
                            + BRK.replace("mode erosion;", FRAG)
                            + " eventLog maybe; }", "maybe"),
    "couplingScaleZero": (SOL, SOL + " couplingScale 0;", "couplingScale"),
    "couplingScaleNegative": (SOL, SOL + " couplingScale -6;",
                              "couplingScale"),
    # misspelt entries of the cloud's solution dictionary (were ignored)
    "cellOrderIntervall": (SOL, SOL + " cellOrderIntervall 5;",
                           "cellOrderIntervall"),
    "couplingScal": (SOL, SOL + " couplingScal 2;", "couplingScal"),
    # injected particles take constantProperties' rho0: another density
    # than the material's passed, and the run's own restart was refused
    "injectedRho0": ("constantProperties { rho0 2200; }",
                     "constantProperties { rho0 1000; }",
                     "constantProperties"),
}

# Cases needing other sub-models in the case (forces, dispersion)
SUBMODEL_CASES = {
    "SchillerNaumannKey": ("particleForces {}", "particleForces "
                           "{ SchillerNaumannDrag { Cd 0.44; } }", "Cd"),
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


def test_breakup_needs_agglomeration(case_dir, foam_env):
    """Break-up takes the bond force and the fragments' sizes from the
    agglomeration and structure models: without agglomeration it stops."""
    edited_case(case_dir, ROT, ROT + " breakupModel stressThreshold;"
                " stressThresholdCoeffs { " + BRK + " }")
    f = case_dir / "constant" / "kinematicCloudProperties"
    f.write_text(f.read_text().replace(EAM, "agglomerationModel none;"))
    assert_fatal_naming(run_case(case_dir, check=False), "breakupModel")


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


# ------------------------------------------------- particle fields on read

def field_text(case_dir, name):
    return (case_dir / "0/lagrangian/kinematicCloud" / name).read_text()


def set_field(case_dir, name, body):
    """Replace the list of a lagrangian field file of the box case."""
    f = case_dir / "0/lagrangian/kinematicCloud" / name
    text = f.read_text()
    head = text[:text.index("}") + 1]
    f.write_text(head + "\n" + body + "\n")


def binary_scalar_field(case_dir, name, values):
    """Write a binary scalarField (OpenFOAM's layout: N (raw doubles))."""
    import struct
    f = case_dir / "0/lagrangian/kinematicCloud" / name
    head = ("FoamFile { version 2.0; format binary; class scalarField;"
            f" location \"0/lagrangian/kinematicCloud\"; object {name}; }}\n")
    f.write_bytes(head.encode() + f"{len(values)}\n(".encode()
                  + struct.pack(f"<{len(values)}d", *values) + b")\n")


FIELD_CASES = {
    "dNegative": ("d", "2(1.2e-05 -1.2e-05)", "d"),
    "dZero": ("d", "2(1.2e-05 0)", "d"),
    "rhoZero": ("rho", "2(2200 0)", "rho"),
    "rhoNegative": ("rho", "2(-2200 2200)", "rho"),
    "nPrimaryZero": ("nPrimary", "2(1 0)", "nPrimary"),
    "nPrimaryEmpty": ("nPrimary", "0()", "nPrimary"),
    "omegaShort": ("omega", "1((0 0 0))", "omega"),
    "positionsEmpty": ("positions", "0()", "positions"),
    # a primary of another density than the material's rho0 (2200): the
    # structure model would build its agglomerates from rho0, silently
    "rhoNotRho0": ("rho", "2(2200 1000)", "rho0 = 2200"),
}


@pytest.mark.parametrize("name", list(FIELD_CASES))
def test_bad_particle_field(case_dir, foam_env, name):
    """Invalid particle fields stop the run when read, naming the field,
    the particle and the value (d < 0 used to run to the end with mass 0;
    d = 0 or rho = 0 crashed later without naming a field; an empty
    nPrimary list ran with nPrimary = 1, an empty positions list with no
    particles)."""
    field, body, word = FIELD_CASES[name]
    edited_case(case_dir, EAM, EAM)
    set_field(case_dir, field, body)
    assert_fatal_naming(run_case(case_dir, check=False), word)


def test_nan_in_binary_field(case_dir, foam_env):
    edited_case(case_dir, EAM, EAM)
    binary_scalar_field(case_dir, "d", [12e-6, float("nan")])
    res = run_case(case_dir, check=False)
    assert_fatal_naming(res, "particle 1 has d = nan")


# ------------------------------------------------ position forms, parallel

def cloud_totals(case_dir, t):
    st = read_cloud(case_dir, t, names=("d", "rho", "nPrimary"))
    d = [float(x) for x in st["d"]]
    rho = [float(x) for x in st["rho"]]
    mass = sum(r * 3.141592653589793 / 6 * x**3 for x, r in zip(d, rho))
    return len(d), sum(int(n) for n in st["nPrimary"]), mass, stats(case_dir)


def gas(case_dir):
    rng = np.random.default_rng(5)
    Lb = 2e-4
    xs = placement.place(300, 14.4e-6, (8e-6,) * 3, (Lb - 8e-6,) * 3,
                         (None,) * 3, rng)
    U = rng.normal(0, 1.5e-3, (len(xs), 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i) for i, (x, u)
             in enumerate(zip(xs, U))]
    box_case(case_dir, L=(Lb,) * 3, n=(6, 6, 6), particles=parts,
             kinds=("cyclic", "wall", "cyclic"), dt=1e-4, end_time=4e-3,
             agglomeration="EAM", decompose=(2, 1, 1))
    return len(parts)


def test_positions_file_without_uniform_properties(case_dir, foam_env):
    """A hand-written positions file without the uniform cloudProperties
    (which says 'geometry positions') used to give 0 particles."""
    n = gas(case_dir)
    shutil.rmtree(case_dir / "0/uniform")
    run_case(case_dir)
    assert cloud_totals(case_dir, "0.004")[1] == n


def test_parallel_round_trip_loses_nothing(case_dir, foam_env):
    """serial -> decomposePar -> 2 ranks -> reconstructPar -> serial with a
    hand-written cloud in the positions form: particles, primaries, mass
    and counters as in the serial run (decomposePar writes coordinates but
    keeps 'geometry positions': 0 particles on both ranks before)."""
    serial, mpi = case_dir / "serial", case_dir / "mpi"
    n = gas(serial)
    gas(mpi)
    run_case(serial)
    run_case(mpi, parallel=2)
    assert times.last_time(mpi) == times.last_time(serial) == "0.004"
    ns, ps, ms, rows_s = cloud_totals(serial, "0.004")
    nm, pm, mm, rows_m = cloud_totals(mpi, "0.004")
    assert ps == pm == n
    assert rows_s[-1]["nAgg"] > 0 and rows_s[-1]["nCol"] > 5
    assert nm == ns == n - int(rows_s[-1]["nAgg"])
    assert mm == pytest.approx(ms, rel=1e-12)
    keys = ("nParticles", "nPrimaries", "nCol", "nAgg", "nWall")
    assert [[r[k] for k in keys] for r in rows_m] == \
        [[r[k] for k in keys] for r in rows_s]
    # and back: the reconstructed cloud restarts serially with everything
    run([foam_bin("foamDictionary"), "-entry", "endTime", "-set", "0.008",
         "system/controlDict"], mpi, "log.foamDictionary")
    run([foam_bin("aggloPimpleFoam")], mpi, "log.aggloPimpleFoam.serial")
    assert cloud_totals(mpi, "0.008")[1] == n


def test_displacement_beyond_half_a_period(case_dir, foam_env):
    """A particle moving more than the periodic length in one step collided
    with the wrong image and the pair ended overlapping, without a warning:
    now the reach of the search along each axis is checked against half
    the period along it."""
    parts = [dict(x=(0.2 * L, 0.5 * L, 0.5 * L), U=(2.0, 0, 0), id=0),
             dict(x=(0.6 * L, 0.5 * L, 0.5 * L), U=(0, 0, 0), id=1)]
    box_case(case_dir, L=(L, L, L), particles=parts, dt=1e-4, end_time=2e-4,
             kinds=("cyclic", "wall", "wall"))
    res = run_case(case_dir, check=False)
    assert_fatal_naming(res, "more than half the periodic length along x")


def test_vtkcloud_writes_every_parcel_field(case_dir, foam_env):
    """The vtkCloud function object writes lastPartnerProc, lastPartnerId
    and lastContactTime (the README promises it; only omega and nPrimary
    were registered): after the head-on rebound the partners name each
    other."""
    import re
    parts = [dict(x=(0.4 * L, 0.5 * L, 0.5 * L), U=(0.1, 0, 0), id=0),
             dict(x=(0.6 * L, 0.5 * L, 0.5 * L), U=(-0.1, 0, 0), id=1)]
    box_case(case_dir, L=(L, L, L), particles=parts, dt=1e-5, end_time=1e-4)
    # keep the last partner after the pair has separated
    f = case_dir / "constant" / "kinematicCloudProperties"
    f.write_text(f.read_text().replace(
        "agglomerationModel none;",
        "agglomerationModel none; encounterRelease none;", 1))
    cd = case_dir / "system" / "controlDict"
    cd.write_text(cd.read_text() + """
functions
{
    cloudVtk
    {
        type            vtkCloud;
        libs            ("liblagrangianFunctionObjects.so");
        cloud           kinematicCloud;
        fields          (nPrimary lastPartnerProc lastPartnerId
                         lastContactTime origId);
        format          ascii;
        writeControl    writeTime;
    }
}
""")
    run_case(case_dir)
    vtps = sorted((case_dir / "postProcessing" / "cloudVtk").rglob("*.vtp"))
    assert vtps
    text = vtps[-1].read_text()
    for name in ("nPrimary", "lastPartnerProc", "lastPartnerId",
                 "lastContactTime"):
        assert f"Name='{name}'" in text, name
    def values(name):
        return [int(float(x)) for x in re.search(
            rf"Name='{name}'[^>]*>([^<]*)<", text).group(1).split()]

    # in whatever order the cloud holds them (cell order)
    assert dict(zip(values("origId"), values("lastPartnerId"))) == \
        {0: 1, 1: 0}


def test_unhandled_wall_is_fatal(case_dir, foam_env):
    """collisionModel none with patchInteractionModel none: a particle that
    reached a wall looped forever in tracking; now the set-up is refused,
    naming both entries."""
    box_case(case_dir, L=(L, L, L), particles=PAIR, dt=1e-5, end_time=2e-5,
             hard_sphere="none")
    res = run_case(case_dir, check=False)
    assert_fatal_naming(res, "patchInteractionModel")
    assert "collisionModel" in res.stdout.split("FOAM FATAL", 1)[1]


# ------------------------------------------------------------ fault tests

def test_fast_pair_on_two_ranks_one_contact_time(case_dir, foam_env):
    """A head-on pair crossing the processor plane within the step (six
    cells per step each): both partners store the same contact time, the
    one of the serial run; the rebound velocities are the serial ones."""
    Lx = 1e-3
    parts = [dict(x=(0.2 * Lx, 0.5e-4, 0.5e-4), U=(6.0, 0, 0), id=0),
             dict(x=(0.8 * Lx, 0.5e-4, 0.5e-4), U=(-6.0, 0, 0), id=1)]
    out = {}
    for ranks in (0, 2):
        c = case_dir / f"np{ranks}"
        box_case(c, L=(Lx, 1e-4, 1e-4), n=(10, 1, 1), particles=parts,
                 dt=1e-4, end_time=1e-4, decompose=(2, 1, 1),
                 kinds=("wall", "wall", "wall"))
        run_case(c, parallel=ranks)
        assert stats(c)[-1]["nCol"] == 1
        out[ranks] = read_cloud(c, "0.0001",
                                names=("origId", "U", "lastContactTime"))
    serial, mpi = out[0], out[2]
    tc = mpi["lastContactTime"]
    assert tc[0] == tc[1]
    assert tc[0] == pytest.approx(serial["lastContactTime"][0], rel=1e-12)
    order = lambda st: [u for _, u in sorted(zip(st["origId"], st["U"]))]
    for us, um in zip(order(serial), order(mpi)):
        assert um == pytest.approx(us, rel=1e-12)


def test_restart_after_a_cut_off_write(case_dir, foam_env):
    """A kill -9 during a write leaves a half-written last time folder that
    stops OpenFOAM's restart (it reads the latest time). The tutorials'
    resume (aggloTools.times.set_aside_incomplete_times, called by both
    Allruns before continuing) sets it aside and says so; the run then
    continues from the previous write and ends where an uninterrupted run
    ends."""
    import re
    n = gas(case_dir)
    run([foam_bin("foamDictionary"), "-entry", "writeInterval", "-set",
         "10", "system/controlDict"], case_dir, "log.foamDictionary")
    run_case(case_dir)
    full = stats(case_dir)[-1]
    # cut off the last write: truncate one particle field, then restart
    last = case_dir / "0.004"
    assert (last / "uniform" / "time").is_file()
    f = last / "lagrangian" / "kinematicCloud" / "U"
    f.write_text(f.read_text()[: len(f.read_text()) // 2])
    assert times.incomplete_time(case_dir) == last
    plain = subprocess.run([foam_bin("aggloPimpleFoam")], cwd=case_dir,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True)
    assert plain.returncode != 0           # OpenFOAM's own behaviour
    moved = times.set_aside_incomplete_times(case_dir)
    assert [m.name for m in moved] == ["incomplete.0.004"]
    assert times.incomplete_time(case_dir) is None
    run([foam_bin("aggloPimpleFoam")], case_dir, "log.aggloPimpleFoam.2")
    log = (case_dir / "log.aggloPimpleFoam.2").read_text()
    assert re.search(r"Starting time loop", log)
    assert cloud_totals(case_dir, "0.004")[1] == n
    again = stats(case_dir)[-1]
    assert again.pop("Time") == pytest.approx(full.pop("Time"), rel=1e-12)
    assert again == full


def test_agglomerate_at_wall_across_processor_plane(case_dir, foam_env):
    """An agglomerate formed next to a wall, whose centre of mass lies on
    the other processor than its lower-id partner, overlaps the wall and is
    moved out to one radius: at the same place on 2 ranks as in serial (it
    ended 20 nm off on 2 ranks: the wall faces were looked up around the
    partner, on the partner's processor)."""
    Lx = 4e-4
    D2 = 24e-6
    y1, y2 = 6.5e-6, 12.5e-6
    # particle 1 (the heavier, higher id) is across the plane x = Lx/2
    R = 0.5 * (12e-6 + D2)
    dx = ((R + 2e-9) ** 2 - (y2 - y1) ** 2) ** 0.5
    parts = [dict(x=(0.5 * Lx - 15e-6, y1, 5e-5), U=(1.5e-4, 0, 0), id=0),
             dict(x=(0.5 * Lx - 15e-6 + dx, y2, 5e-5), U=(-1.5e-4, 0, 0),
                  d=D2, nPrimary=8, id=1)]
    out = {}
    for ranks in (0, 2):
        c = case_dir / f"np{ranks}"
        box_case(c, L=(Lx, 1e-4, 1e-4), n=(8, 2, 2), particles=parts,
                 dt=1e-5, end_time=1e-5, decompose=(2, 1, 1),
                 agglomeration="MAM", kinds=("wall", "wall", "wall"))
        run_case(c, parallel=ranks)
        assert stats(c)[-1]["nAgg"] == 1
        out[ranks] = read_positions(cloud_dir(c, "1e-05") / "positions")
    assert len(out[0]) == len(out[2]) == 1
    assert out[2][0] == pytest.approx(out[0][0], rel=0, abs=1e-12)


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
