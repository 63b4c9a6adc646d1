"""Short LES of the paper's vertical channel on a coarse mesh with every
sub-model on: Smagorinsky (C_s = 0.065) with the vanDriestDamped
delta, constant mass flux through meanVelocityForce, gravity along +x on
the particles only, two-way coupling, Schiller-Naumann drag, Saffman-Mei
and rotation lift, fluid torque, Pozorski-Apte SGS velocity, EAM, sandgrain
rough walls. Serial and on 2 MPI ranks.

Checks: the bulk velocity stays within 0.1 % of U_B (computed from the
written U and the cell volumes), the driving gradient is reported, the
particle mass and the primaries are conserved."""

import math

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.cloud import cloud_dir, read_lagrangian, read_positions
from aggloTools.foamfile import dict_text
from aggloTools.fields import read_internal
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows
from aggloTools.times import last_time

DELTA, UB = 0.02, 9.051
L = (2 * math.pi * DELTA, 2 * DELTA, math.pi * DELTA)
N = (12, 16, 8)
DT, STEPS = 2e-4, 30


def channel_case(case, n_particles=1000):
    f = boxcase.foamfile
    Lx, Ly, Lz = L
    pts = [(0, 0, 0), (Lx, 0, 0), (Lx, Ly, 0), (0, Ly, 0),
           (0, 0, Lz), (Lx, 0, Lz), (Lx, Ly, Lz), (0, Ly, Lz)]
    f(case / "system/blockMeshDict", "dictionary", "system", "blockMeshDict",
      "scale 1;\nvertices (" + " ".join(boxcase.vec(p) for p in pts) + ");\n"
      f"blocks (hex (0 1 2 3 4 5 6 7) ({N[0]} {N[1]} {N[2]}) simpleGrading"
      " (1 ((0.5 0.5 4) (0.5 0.5 0.25)) 1));\nboundary\n(\n"
      " bottomWall { type wall; faces ((0 1 5 4)); }\n"
      " topWall { type wall; faces ((3 7 6 2)); }\n"
      " inlet { type cyclic; neighbourPatch outlet; faces ((0 4 7 3)); }\n"
      " outlet { type cyclic; neighbourPatch inlet; faces ((1 2 6 5)); }\n"
      " front { type cyclic; neighbourPatch back; faces ((0 3 2 1)); }\n"
      " back { type cyclic; neighbourPatch front; faces ((4 5 6 7)); }\n);\n")
    f(case / "system/controlDict", "dictionary", "system", "controlDict",
      "application aggloPimpleFoam;\nstartFrom latestTime;\nstartTime 0;\n"
      f"stopAt endTime;\nendTime {STEPS * DT!r};\ndeltaT {DT!r};\n"
      f"writeControl timeStep;\nwriteInterval {STEPS};\npurgeWrite 0;\n"
      "writeFormat ascii;\nwritePrecision 17;\nwriteCompression off;\n"
      "timeFormat general;\ntimePrecision 12;\nrunTimeModifiable false;\n")
    f(case / "system/fvSchemes", "dictionary", "system", "fvSchemes",
      "ddtSchemes { default backward; }\ngradSchemes { default Gauss linear; }"
      "\ndivSchemes { default none; div(phi,U) Gauss linear;\n"
      "    div((nuEff*dev2(T(grad(U))))) Gauss linear; }\n"
      "laplacianSchemes { default Gauss linear corrected; }\n"
      "interpolationSchemes { default linear; }\n"
      "snGradSchemes { default corrected; }\nwallDist { method meshWave; }\n")
    f(case / "system/fvSolution", "dictionary", "system", "fvSolution",
      "solvers { p { solver PCG; preconditioner DIC; tolerance 1e-8;"
      " relTol 0.01; } pFinal { $p; relTol 0; }\n"
      "\"(U|UFinal)\" { solver smoothSolver; smoother symGaussSeidel;"
      " tolerance 1e-8; relTol 0; } }\n"
      "PIMPLE { nOuterCorrectors 1; nCorrectors 2;"
      " nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }\n")
    f(case / "system/decomposeParDict", "dictionary", "system",
      "decomposeParDict", "numberOfSubdomains 2;\nmethod simple;\n"
      "coeffs { n (2 1 1); }\n")
    f(case / "system/fvOptions", "dictionary", "system", "fvOptions",
      "momentumSource { type meanVelocityForce; selectionMode all;"
      f" fields (U); Ubar ({UB} 0 0); }}\n")
    f(case / "constant/transportProperties", "dictionary", "constant",
      "transportProperties",
      "transportModel Newtonian;\nnu 1.5212e-5;\nrhoInf 1.2128;\n")
    f(case / "constant/turbulenceProperties", "dictionary", "constant",
      "turbulenceProperties",
      "simulationType LES;\nLES\n{\n    LESModel Smagorinsky;\n"
      "    turbulence on;\n    printCoeffs on;\n"
      "    SmagorinskyCoeffs { Ck 0.02655; Ce 1.048; }\n"
      "    delta vanDriestDamped;\n    vanDriestDampedCoeffs\n    {\n"
      "        delta cubeRootVol;\n"
      "        cubeRootVolCoeffs { deltaCoeff 1; }\n"
      "        Aplus 25;\n    }\n}\n")
    f(case / "constant/g", "uniformDimensionedVectorField", "constant", "g",
      "dimensions [0 1 -2 0 0 0 0];\nvalue (9.81 0 0);\n")
    cyc = '"(inlet|outlet|front|back)" { type cyclic; }'
    f(case / "0/U", "volVectorField", "0", "U",
      "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform "
      f"({UB} 0 0);\nboundaryField\n{{\n    {cyc}\n"
      "    \".*Wall\" { type noSlip; }\n}\n")
    f(case / "0/p", "volScalarField", "0", "p",
      "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\n"
      f"boundaryField\n{{\n    {cyc}\n"
      "    \".*Wall\" { type zeroGradient; }\n}\n")
    f(case / "0/nut", "volScalarField", "0", "nut",
      "dimensions [0 2 -1 0 0 0 0];\ninternalField uniform 0;\n"
      f"boundaryField\n{{\n    {cyc}\n"
      "    \".*Wall\" { type zeroGradient; }\n}\n")

    rough = {"wallModel": "sandgrain",
             "sandgrainCoeffs": {"en": 0.9, "et": 0.3, "muSt": 0.5,
                                 "muKin": 0.4, "Rz": 10e-6, "CSurface": 3}}
    coeffs = boxcase.kernel("EAM", walls={'".*Wall"': rough}, randomSeed=1)
    f(case / "constant/kinematicCloudProperties", "dictionary", "constant",
      "kinematicCloudProperties",
      "solution\n{\n    active true;\n    coupled true;\n"
      "    transient yes;\n    cellValueSourceCorrection off;\n"
      "    maxCo 1;\n    sourceTerms { schemes { U semiImplicit 1; } }\n"
      "    interpolationSchemes { rho cell; U cellPoint; mu cell;"
      " curlUcDt cellPoint; }\n"
      "    integrationSchemes { U analytical; }\n}\n"
      "constantProperties { rho0 2200; }\n"
      "subModels\n{\n    particleForces\n    {\n"
      "        SchillerNaumannDrag;\n        SaffmanMeiLiftForce { U U; }\n"
      "        rotationLift { model OesterleBuiDinh; }\n"
      "        gravity;\n    }\n"
      "    injectionModels {}\n    dispersionModel PozorskiApte;\n"
      "    PozorskiApteCoeffs { kSgsSource nut; Ck 0.094; CT 1; betaC 1;"
      " seed 1; wallReflection true; }\n"
      "    patchInteractionModel none;\n    surfaceFilmModel none;\n"
      "    stochasticCollisionModel none;\n"
      "    rotationModel fluidTorque;\n"
      "    collisionModel hardSphere;\n"
      "    hardSphereCoeffs\n    {\n" + dict_text(coeffs, 8) + "    }\n}\n"
      "cloudFunctions { hardSphereStatistics"
      " { type hardSphereStatistics; } }\n")

    rng = np.random.default_rng(7)
    X = rng.uniform((0, 2e-4, 0), (Lx, Ly - 2e-4, Lz), (n_particles, 3))
    parts = [dict(x=tuple(x), U=(UB, 0, 0), d=12e-6, rho=2200.0, id=i)
             for i, x in enumerate(X)]
    boxcase.write_particles(case, parts)


def bulk_velocity(case, t):
    run([foam_bin("postProcess"), "-func", "writeCellVolumes", "-time", t],
        case, "log.writeCellVolumes")
    V = read_internal(case / t / "V")
    U = read_internal(case / t / "U")
    return float((V * U[:, 0]).sum() / V.sum())


@pytest.mark.parametrize("ranks", [0, 2])
def test_les_channel_all_submodels(case_dir, foam_env, ranks):
    channel_case(case_dir)
    boxcase.run_case(case_dir, parallel=ranks)
    t = last_time(case_dir)
    assert float(t) == pytest.approx(STEPS * DT)
    log = (case_dir / "log.aggloPimpleFoam").read_text()
    for line in ("vanDriestDamped delta", "PozorskiApte SGS model",
                 "sandgrain wall", "rotationLift: model OesterleBuiDinh",
                 "particleRotation: fluid torque"):
        assert line in log, line
    grads = [float(x) for x in __import__("re").findall(
        r"pressure gradient = ([-0-9.eE+]+)", log)]
    assert len(grads) >= STEPS * 2 and all(math.isfinite(g) for g in grads)

    ub = bulk_velocity(case_dir, t)
    assert abs(ub / UB - 1) < 1e-3, ub

    rows = stats_rows(case_dir)
    assert len(rows) == STEPS
    m0 = rows[0]["mass"]
    assert all(abs(r["mass"] / m0 - 1) < 1e-12 for r in rows)
    assert all(r["nPrimaries"] == 1000 for r in rows)
    assert all(r["nParticles"] == 1000 - r["nAgg"] for r in rows)
    # the walls are reached (at one radius, or by the centre fallback when
    # the wall-normal step exceeds the radius), and no particle ends
    # closer to a wall than its radius
    assert rows[-1]["nWall"] + rows[-1]["nWallCentre"] > 0
    c = cloud_dir(case_dir, t)
    y = read_positions(c / "positions")[:, 1]
    r = 0.5 * read_lagrangian(c / "d")
    assert len(y) == len(r) == rows[-1]["nParticles"]
    gap = np.minimum(y, L[1] - y) - r
    assert gap.min() > -1e-3 * r.max(), gap.min()
