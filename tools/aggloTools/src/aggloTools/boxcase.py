"""Small box cases of the hard-sphere cloud: a one-block box mesh (walls
or cyclic pairs per direction), a frozen fluid at rest or a given velocity
field, optional particle forces, and a scripted initial particle state
written as lagrangian fields at time 0. With no forces the particles move
in straight lines, so every collision and wall impact can be predicted by
hand or with hardSphereCollide.

    from aggloTools import boxcase
    case = boxcase.box_case(tmp, particles=[
        {"x": (3e-4, 5e-4, 5e-4), "U": (1, 0, 0), "d": 12e-6},
        {"x": (7e-4, 5e-4, 5e-4), "U": (-1, 0, 0), "d": 12e-6}])
    boxcase.run_case(case)
"""

from pathlib import Path

import numpy as np

from .cloud import write_cloud
from .fields import set_internal_vector_field
from .foamfile import vec, write_foamfile as foamfile
from .runner import foam_bin, run

# Quartz, 12 um, Tab. 1 (doc/models.md 0.6): the kernel of the utility tests
KERNEL = """
    material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9; delta0 2e-10;
               rho0 2200; }
    particleCollision { en 0.97; et 0.44; muSt 0.94; muKin 0.092; }
    structureModel CSM;
"""

WALL = "{ wallModel smooth; smoothCoeffs { en 0.8; et 0.4; muSt 0.3; " \
       "muKin 0.15; } }"


def box_case(case, L=(1e-3, 1e-3, 1e-3), n=(4, 4, 4),
             kinds=("wall", "wall", "wall"), particles=(), dt=1e-4,
             end_time=1e-3, write_interval=None, hard_sphere="",
             agglomeration="none", write_format="ascii",
             decompose=(1, 1, 1), wall_velocity=None, cloud_extra="",
             forces="{}", gravity=(0, 0, 0), rotation=False,
             dispersion="dispersionModel none;", coupled=False,
             turbulence="simulationType laminar;", nu=1.5e-5, rho_f=1.2,
             frozen=True, tol=1e-8, source_scheme="semiImplicit 1",
             patch_interaction="patchInteractionModel none;", breakup="",
             integration="Euler"):
    """Write a complete case. kinds: 'wall', 'cyclic' or 'patch' (open)
    per direction.
    particles: dicts with x, U, d (optional omega, rho, nPrimary, id).
    hard_sphere: the body of the collision model's hardSphereCoeffs
    (default: KERNEL, the agglomeration model and smooth walls), or "none"
    for collisionModel none; the statistics function object is always on.
    rotation: rotationModel fluidTorque (else none); dispersion: the
    dispersionModel entry (plus its coefficients); turbulence: the body
    of constant/turbulenceProperties; breakup: the breakupModel entry and
    its coefficients (default: none, by its absence); integration: the
    particle velocity's scheme (Euler, or analytical for particles whose
    relaxation time is below the step)."""
    case = Path(case)
    steps = round(end_time / dt)
    write_interval = write_interval or steps
    names = "xyz"
    for kind in kinds:
        if kind not in ("wall", "cyclic", "patch"):
            raise ValueError(f"box kind '{kind}': wall, cyclic or patch")
    Lx, Ly, Lz = L
    pts = [(0, 0, 0), (Lx, 0, 0), (Lx, Ly, 0), (0, Ly, 0),
           (0, 0, Lz), (Lx, 0, Lz), (Lx, Ly, Lz), (0, Ly, Lz)]
    faces = {
        "x": ("(0 4 7 3)", "(1 2 6 5)"),
        "y": ("(0 1 5 4)", "(3 7 6 2)"),
        "z": ("(0 3 2 1)", "(4 5 6 7)"),
    }
    bnd = []
    for k, kind in zip(names, kinds):
        lo, hi = faces[k]
        if kind == "cyclic":
            bnd.append(f"{k}Min {{ type cyclic; neighbourPatch {k}Max; "
                       f"faces ({lo}); }}")
            bnd.append(f"{k}Max {{ type cyclic; neighbourPatch {k}Min; "
                       f"faces ({hi}); }}")
        else:
            bnd.append(f"{k}Min {{ type {kind}; faces ({lo}); }}")
            bnd.append(f"{k}Max {{ type {kind}; faces ({hi}); }}")
    foamfile(case / "system/blockMeshDict", "dictionary", "system",
             "blockMeshDict",
             "scale 1;\nvertices (" + " ".join(vec(p) for p in pts) + ");\n"
             f"blocks (hex (0 1 2 3 4 5 6 7) ({n[0]} {n[1]} {n[2]}) "
             "simpleGrading (1 1 1));\nboundary\n(\n    "
             + "\n    ".join(bnd) + "\n);\n")

    foamfile(case / "system/controlDict", "dictionary", "system",
             "controlDict",
             f"application aggloPimpleFoam;\nstartFrom latestTime;\n"
             f"startTime 0;\nstopAt endTime;\nendTime {end_time!r};\n"
             f"deltaT {dt!r};\nwriteControl timeStep;\n"
             f"writeInterval {write_interval};\npurgeWrite 0;\n"
             f"writeFormat {write_format};\nwritePrecision 17;\n"
             "writeCompression off;\ntimeFormat general;\n"
             "timePrecision 12;\nrunTimeModifiable false;\n")
    foamfile(case / "system/fvSchemes", "dictionary", "system", "fvSchemes",
             "ddtSchemes { default Euler; }\n"
             "gradSchemes { default Gauss linear; }\n"
             "divSchemes { default none; div(phi,U) Gauss linear;\n"
             "    div((nuEff*dev2(T(grad(U))))) Gauss linear; }\n"
             "laplacianSchemes { default Gauss linear corrected; }\n"
             "interpolationSchemes { default linear; }\n"
             "snGradSchemes { default corrected; }\n")
    foamfile(case / "system/fvSolution", "dictionary", "system",
             "fvSolution",
             "solvers { p { solver PCG; preconditioner DIC;"
             f" tolerance {tol!r}; relTol 0; }} pFinal {{ $p; }}\n"
             "\"(U|UFinal)\" { solver PBiCGStab; preconditioner DILU;"
             f" tolerance {tol!r}; relTol 0; }} }}\n"
             "PIMPLE { nOuterCorrectors 1; nCorrectors 2;"
             " nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0;"
             f" frozenFlow {'yes' if frozen else 'no'}; }}\n")
    foamfile(case / "system/decomposeParDict", "dictionary", "system",
             "decomposeParDict",
             f"numberOfSubdomains {decompose[0]*decompose[1]*decompose[2]};"
             f"\nmethod simple;\ncoeffs {{ n ({decompose[0]} {decompose[1]}"
             f" {decompose[2]}); }}\n")
    foamfile(case / "constant/transportProperties", "dictionary",
             "constant", "transportProperties",
             f"transportModel Newtonian;\nnu {nu!r};\nrhoInf {rho_f!r};\n")
    foamfile(case / "constant/turbulenceProperties", "dictionary",
             "constant", "turbulenceProperties", turbulence + "\n")
    foamfile(case / "constant/g", "uniformDimensionedVectorField",
             "constant", "g", "dimensions [0 1 -2 0 0 0 0];\n"
             f"value {vec(gravity)};\n")

    ub, pb = [], []
    for k, kind in zip(names, kinds):
        for side in ("Min", "Max"):
            if kind == "cyclic":
                ub.append(f"{k}{side} {{ type cyclic; }}")
                pb.append(f"{k}{side} {{ type cyclic; }}")
            elif kind == "patch":
                ub.append(f"{k}{side} {{ type zeroGradient; }}")
                pb.append(f"{k}{side} {{ type fixedValue; "
                          "value uniform 0; }")
            else:
                uw = (wall_velocity or {}).get(f"{k}{side}", (0, 0, 0))
                ub.append(f"{k}{side} {{ type fixedValue; "
                          f"value uniform {vec(uw)}; }}")
                pb.append(f"{k}{side} {{ type zeroGradient; }}")
    foamfile(case / "0/U", "volVectorField", "0", "U",
             "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);"
             "\nboundaryField\n{\n    " + "\n    ".join(ub) + "\n}\n")
    foamfile(case / "0/p", "volScalarField", "0", "p",
             "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\n"
             "boundaryField\n{\n    " + "\n    ".join(pb) + "\n}\n")

    walls = f'walls {{ ".*" {WALL} }}'
    hs = hard_sphere or (
        KERNEL + f"    agglomerationModel {agglomeration};\n    {walls}\n")
    collision = ("    collisionModel none;\n" if hs == "none" else
                 "    collisionModel hardSphere;\n"
                 "    hardSphereCoeffs\n    {\n" + hs + "    }\n")
    foamfile(case / "constant/kinematicCloudProperties", "dictionary",
             "constant", "kinematicCloudProperties",
             "solution\n{\n    active true;\n"
             f"    coupled {'true' if coupled else 'false'};\n"
             "    transient yes;\n    cellValueSourceCorrection off;\n"
             "    maxCo 1;\n"
             "    sourceTerms { schemes { U " + source_scheme + "; } }\n"
             "    interpolationSchemes { rho cell; U cellPoint; mu cell;"
             " curlUcDt cellPoint; }\n"
             f"    integrationSchemes {{ U {integration}; }}\n}}\n"
             "constantProperties { rho0 2200; }\n"
             "subModels\n{\n    particleForces " + forces + "\n"
             "    injectionModels {}\n    " + dispersion + "\n"
             "    " + patch_interaction + "\n    surfaceFilmModel none;\n"
             "    stochasticCollisionModel none;\n"
             "    rotationModel "
             + ("fluidTorque" if rotation else "none") + ";\n"
             + collision + ("    " + breakup + "\n" if breakup else "")
             + "}\n"
             "cloudFunctions\n{\n    hardSphereStatistics"
             " { type hardSphereStatistics; }\n}\n"
             + cloud_extra)
    write_particles(case, particles)
    return case


def box_cell_centres(L, n):
    """Cell centres of the uniform box mesh (blockMesh order: x fastest,
    then y, z) as an (n, 3) array."""
    axes = [(np.arange(m) + 0.5) * length / m for length, m in zip(L, n)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    return np.stack((x.ravel(), y.ravel(), z.ravel()), axis=1)


def write_internal_U(case, L, n, func, name="U"):
    """Replace the uniform internal field of 0/<name> by func(x, y, z) at
    the cell centres of the uniform box mesh."""
    C = box_cell_centres(L, n)
    set_internal_vector_field(Path(case) / "0" / name,
                              np.array([func(*c) for c in C], float))


def write_particles(case, particles):
    """The particles (dicts with x, U, d and optional omega, rho,
    nPrimary, id) as the time-0 cloud kinematicCloud."""
    P = list(particles)
    x = np.array([p["x"] for p in P], float).reshape(-1, 3)
    write_cloud(
        case, x, [p.get("d", 12e-6) for p in P],
        [p.get("rho", 2200) for p in P],
        U=np.array([p["U"] for p in P], float).reshape(-1, 3),
        omega=np.array([p.get("omega", (0, 0, 0)) for p in P],
                       float).reshape(-1, 3),
        n_primary=[p.get("nPrimary", 1) for p in P],
        ids=[p.get("id", i) for i, p in enumerate(P)])


def run_case(case, parallel=0, check=True, after_mesh=None):
    """blockMesh (then after_mesh(), if given: e.g. a mapping of the
    points), then the solver (serial, or decomposed on N ranks and
    reconstructed)."""
    run([foam_bin("blockMesh")], case, "log.blockMesh")
    if after_mesh:
        after_mesh()
    if parallel:
        # decomposePar writes barycentric coordinates but copies the
        # uniform cloudProperties that announce the legacy positions file:
        # the cloud reads whichever form is there
        run([foam_bin("decomposePar"), "-force"], case, "log.decomposePar")
        res = run(["mpirun", "-np", str(parallel), "--oversubscribe",
                   foam_bin("aggloPimpleFoam"), "-parallel"], case,
                  "log.aggloPimpleFoam", check=check)
        if check:
            run([foam_bin("reconstructPar"), "-latestTime"], case,
                "log.reconstructPar")
        return res
    return run([foam_bin("aggloPimpleFoam")], case, "log.aggloPimpleFoam",
               check=check)
