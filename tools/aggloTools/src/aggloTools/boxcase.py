"""Small box cases of the hard-sphere cloud: a one-block box mesh (walls
or cyclic pairs per direction), a frozen fluid at rest or a given velocity
field, optional particle forces, and a scripted initial particle state
written as lagrangian fields at time 0. With no forces the particles move
in straight lines, so every collision and wall impact can be predicted by
hand or with hardSphereCollide. Every dictionary is a nested dict
written by aggloTools.foamfile.dict_text; a case changes the defaults by
nested dicts merged in (foamfile.merged):

    from aggloTools import boxcase
    case = boxcase.box_case(tmp, particles=[
        {"x": (3e-4, 5e-4, 5e-4), "U": (1, 0, 0), "d": 12e-6},
        {"x": (7e-4, 5e-4, 5e-4), "U": (-1, 0, 0), "d": 12e-6}],
        hard_sphere=boxcase.kernel("EAM", structureModel="VSM"),
        cloud={"subModels": {"particleForces": boxcase.DRAG,
                             "rotationModel": "fluidTorque"}})
    boxcase.run_case(case)
"""

from pathlib import Path

import numpy as np

from .cloud import write_cloud
from .fields import set_internal_vector_field
from .foamfile import dict_text, merged, vec, write_foamfile as foamfile
from .runner import foam_bin, run

#: Quartz, 12 um, Tab. 1 (doc/models.md 0.6): the kernel of the utility
#: tests
MATERIAL = {"H": 6.3e-20, "E": 7.2e10, "nu": 0.17, "pMax": 1.612985e9,
            "delta0": 2e-10, "rho0": 2200}
PARTICLE_COLLISION = {"en": 0.97, "et": 0.44, "muSt": 0.94,
                      "muKin": 0.092}
#: A smooth wall: the walls entry of every wall patch by default
WALL = {"wallModel": "smooth",
        "smoothCoeffs": {"en": 0.8, "et": 0.4, "muSt": 0.3, "muKin": 0.15}}
#: Stokes drag with Schiller-Naumann's correction: particleForces
DRAG = {"SchillerNaumannDrag": ""}


def kernel(agglomeration="none", walls=None, **changes):
    """The body of the collision model's hardSphereCoeffs: the quartz
    kernel, the agglomeration model, walls (default: every patch WALL;
    {} for none) and changes merged in (foamfile.merged: e.g.
    structureModel="VSM", material={"H": 1e-21})."""
    k = {"material": MATERIAL, "particleCollision": PARTICLE_COLLISION,
         "structureModel": "CSM", "agglomerationModel": agglomeration,
         "walls": {'".*"': WALL} if walls is None else walls}
    return merged(k, changes)


def cloud_properties(hard_sphere=None, cloud=None):
    """kinematicCloudProperties as a nested dict: a one-way cloud with no
    forces, injection, dispersion or rotation, the hard-sphere collision
    model (hard_sphere: its coefficients, default kernel(); "none": no
    collision model) and the statistics function object, with cloud
    merged in (foamfile.merged: e.g. {"subModels": {"rotationModel":
    "fluidTorque", "particleForces": DRAG}})."""
    if hard_sphere == "none":
        collision = {"collisionModel": "none"}
    else:
        collision = {"collisionModel": "hardSphere",
                     "hardSphereCoeffs": hard_sphere or kernel()}
    base = {
        "solution": {
            "active": True, "coupled": False, "transient": "yes",
            "cellValueSourceCorrection": "off", "maxCo": 1,
            "sourceTerms": {"schemes": {"U": "semiImplicit 1"}},
            "interpolationSchemes": {"rho": "cell", "U": "cellPoint",
                                     "mu": "cell", "curlUcDt": "cellPoint"},
            "integrationSchemes": {"U": "Euler"}},
        "constantProperties": {"rho0": 2200},
        "subModels": {
            "particleForces": {}, "injectionModels": {},
            "dispersionModel": "none", "patchInteractionModel": "none",
            "surfaceFilmModel": "none", "stochasticCollisionModel": "none",
            "rotationModel": "none", **collision},
        "cloudFunctions": {
            "hardSphereStatistics": {"type": "hardSphereStatistics"}},
    }
    return merged(base, cloud)


def box_case(case, L=(1e-3, 1e-3, 1e-3), n=(4, 4, 4),
             kinds=("wall", "wall", "wall"), particles=(), dt=1e-4,
             end_time=1e-3, write_interval=None, write_format="ascii",
             decompose=(1, 1, 1), wall_velocity=None, gravity=(0, 0, 0),
             nu=1.5e-5, rho_f=1.2, frozen=True, tol=1e-8, turbulence=None,
             hard_sphere=None, cloud=None):
    """Write a complete case. kinds: 'wall', 'cyclic' or 'patch' (open)
    per direction; wall_velocity: {patch: U} of moving walls.
    particles: dicts with x, U, d (optional omega, rho, nPrimary, id).
    frozen: the fluid is not solved (PIMPLE's frozenFlow); turbulence:
    constant/turbulenceProperties (default laminar). hard_sphere and
    cloud: kinematicCloudProperties as cloud_properties() writes it
    (the statistics function object is always on)."""
    case = Path(case)
    steps = round(end_time / dt)
    for kind in kinds:
        if kind not in ("wall", "cyclic", "patch"):
            raise ValueError(f"box kind '{kind}': wall, cyclic or patch")
    write = _dictionary_writer(case)
    write("system/blockMeshDict", block_mesh(L, n, kinds))
    write("system/controlDict", {
        "application": "aggloPimpleFoam", "startFrom": "latestTime",
        "startTime": 0, "stopAt": "endTime", "endTime": float(end_time),
        "deltaT": float(dt), "writeControl": "timeStep",
        "writeInterval": write_interval or steps, "purgeWrite": 0,
        "writeFormat": write_format, "writePrecision": 17,
        "writeCompression": "off", "timeFormat": "general",
        "timePrecision": 12, "runTimeModifiable": False})
    write("system/fvSchemes", SCHEMES)
    write("system/fvSolution", solution(tol, frozen))
    write("system/decomposeParDict", {
        "numberOfSubdomains": int(np.prod(decompose)), "method": "simple",
        "coeffs": {"n": tuple(decompose)}})
    write("constant/transportProperties", {
        "transportModel": "Newtonian", "nu": float(nu),
        "rhoInf": float(rho_f)})
    write("constant/turbulenceProperties",
          turbulence or {"simulationType": "laminar"})
    foamfile(case / "constant/g", "uniformDimensionedVectorField",
             "constant", "g", "dimensions [0 1 -2 0 0 0 0];\n"
             f"value {vec(gravity)};\n")
    boundary_fields(case, kinds, wall_velocity)
    write("constant/kinematicCloudProperties",
          cloud_properties(hard_sphere, cloud))
    write_particles(case, particles)
    return case


def _dictionary_writer(case):
    """write(relative path, nested dict): the file as a dictionary."""
    def write(rel, d):
        loc, obj = rel.split("/")
        foamfile(case / rel, "dictionary", loc, obj, dict_text(d))
    return write


#: The box cases' schemes: second order in space, Euler in time
SCHEMES = {
    "ddtSchemes": {"default": "Euler"},
    "gradSchemes": {"default": "Gauss linear"},
    "divSchemes": {"default": "none", "div(phi,U)": "Gauss linear",
                   "div((nuEff*dev2(T(grad(U)))))": "Gauss linear"},
    "laplacianSchemes": {"default": "Gauss linear corrected"},
    "interpolationSchemes": {"default": "linear"},
    "snGradSchemes": {"default": "corrected"},
}


def solution(tol, frozen):
    """fvSolution: PCG for p, PBiCGStab for U to the absolute tolerance
    tol, PIMPLE with two pressure correctors; frozen: the fluid is not
    solved."""
    return {
        "solvers": {
            "p": {"solver": "PCG", "preconditioner": "DIC",
                  "tolerance": float(tol), "relTol": 0},
            "pFinal": {"$p": ""},
            '"(U|UFinal)"': {"solver": "PBiCGStab",
                             "preconditioner": "DILU",
                             "tolerance": float(tol), "relTol": 0}},
        "PIMPLE": {"nOuterCorrectors": 1, "nCorrectors": 2,
                   "nNonOrthogonalCorrectors": 0, "pRefCell": 0,
                   "pRefValue": 0, "frozenFlow": "yes" if frozen else "no"},
    }


#: The box's faces per direction (low, high), by the blocks' vertices
FACES = {"x": ((0, 4, 7, 3), (1, 2, 6, 5)),
         "y": ((0, 1, 5, 4), (3, 7, 6, 2)),
         "z": ((0, 3, 2, 1), (4, 5, 6, 7))}


def block_mesh(L, n, kinds):
    """blockMeshDict of the one-block box: its patches xMin ... zMax, of
    type kinds per direction (a cyclic pair names its neighbour)."""
    Lx, Ly, Lz = (float(c) for c in L)
    pts = [(0, 0, 0), (Lx, 0, 0), (Lx, Ly, 0), (0, Ly, 0),
           (0, 0, Lz), (Lx, 0, Lz), (Lx, Ly, Lz), (0, Ly, Lz)]
    patches = {}
    for k, kind in zip("xyz", kinds):
        for side, other, face in zip(("Min", "Max"), ("Max", "Min"),
                                     FACES[k]):
            p = {"type": kind}
            if kind == "cyclic":
                p["neighbourPatch"] = f"{k}{other}"
            patches[f"{k}{side}"] = {**p, "faces": (face,)}
    boundary = "".join(f"    {name} {{ {dict_text(p).replace(chr(10), ' ')}"
                       "}\n" for name, p in patches.items())
    return {"scale": 1, "vertices": pts,
            "blocks": "(hex (0 1 2 3 4 5 6 7) " + vec_int(n)
                      + " simpleGrading (1 1 1))",
            "boundary": "(\n" + boundary + ")"}


def vec_int(n):
    return "(" + " ".join(str(int(c)) for c in n) + ")"


def boundary_fields(case, kinds, wall_velocity=None):
    """0/U and 0/p: fluid at rest; walls no-slip (or moving, by
    wall_velocity), open patches p = 0 with zero-gradient U, cyclic
    pairs cyclic."""
    ub, pb = {}, {}
    for k, kind in zip("xyz", kinds):
        for side in ("Min", "Max"):
            name = f"{k}{side}"
            if kind == "cyclic":
                ub[name] = pb[name] = {"type": "cyclic"}
            elif kind == "patch":
                ub[name] = {"type": "zeroGradient"}
                pb[name] = {"type": "fixedValue", "value": "uniform 0"}
            else:
                uw = (wall_velocity or {}).get(name, (0, 0, 0))
                ub[name] = {"type": "fixedValue",
                            "value": "uniform " + vec(uw)}
                pb[name] = {"type": "zeroGradient"}
    for name, cls, dims, zero, bnd in (
            ("U", "volVectorField", "[0 1 -1 0 0 0 0]", "(0 0 0)", ub),
            ("p", "volScalarField", "[0 2 -2 0 0 0 0]", "0", pb)):
        foamfile(case / "0" / name, cls, "0", name,
                 dict_text({"dimensions": dims,
                            "internalField": "uniform " + zero,
                            "boundaryField": bnd}))


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
