"""Bad input stops with a clear error: every dictionary of the cloud
rejects unknown entries, out-of-range coefficients and unknown model names,
and invalid particle fields stop the run when read, each with an OpenFOAM
fatal (IO) error that names the offending entry or field.

Each case edits one entry of a valid scripted box case (two 12 um quartz
primaries, EAM, smooth walls) and asserts a non-zero exit status and that
the message after "FOAM FATAL" names the entry. The unedited case runs
(test_valid_case_runs), so every failure below is caused by its edit.
hardSphereCollide's input is checked in test_collideInput, the tutorials'
presets and case settings in tests/tutorials/test_tutorialInput."""

import pytest

from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.foamfile import edit, strip_comments
from cloudBoxCases import PAIR, L, assert_fatal_naming

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
FRAG = ("mode erosion; direction extensional; gap 1e-3; tries 6;"
        " spin conserveL;")
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
    "rho0Negative": ("rho0 2200; } particleCollision",
                     "rho0 -2200; } particleCollision", "rho0"),
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
    # deposition takes no coefficients
    "stickCoeffsEntry": (WALL, "wallModel stick; stickCoeffs { en 0.5; }",
                         "en"),
    "stickMisspelt": (WALL, WALL.replace("smooth;", "stik;"), "stik"),
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
    # a count that only bounds memory: 1e8 bins took about 23 GB
    "statisticsBinsHuge": (STATS, STATS.replace("}", "profiles true; "
                           "direction (0 1 0); nBins 100000000; }"),
                           "nBins = 100000000 is out of range [1, 100000]"),
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
    # a mechanism named twice, negative seeds of the keyed random numbers
    "breakupMechanismTwice": (ROT, ROT + " breakupModel stressThreshold;"
                              " stressThresholdCoeffs { "
                              + BRK.replace("(rotation)",
                                            "(rotation rotation)")
                              + " }", "named twice"),
    "breakupSeedNegative": (ROT, ROT + " breakupModel stressThreshold;"
                            " stressThresholdCoeffs { "
                            + BRK.replace("mode erosion;", FRAG)
                            + " randomSeed -3; }", "randomSeed"),
    "wallSeedNegative": (EAM, EAM + " randomSeed -3;", "randomSeed"),
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
    "PozorskiApteSeed": ("dispersionModel none;", "dispersionModel "
                         "PozorskiApte; PozorskiApteCoeffs { kSgsSource nut;"
                         " wallReflection true; seed -3; }", "seed"),
}


def edited_case(case_dir, old, new):
    """The pair's box case whose cloud dictionary, written on one line
    (comments removed, white space one blank), has its text old replaced
    by new."""
    box_case(case_dir, L=(L, L, L), particles=PAIR, hard_sphere=kernel("EAM"),
             dt=1e-5, end_time=2e-5)
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = " ".join(strip_comments(f.read_text()).split())
    assert old in text, old
    f.write_text(text.replace(old, new, 1) + "\n")


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
    edit(f, EAM, "agglomerationModel none;")
    assert_fatal_naming(run_case(case_dir, check=False), "breakupModel")


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
