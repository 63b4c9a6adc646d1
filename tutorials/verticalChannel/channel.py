#!/usr/bin/env python3
"""verticalChannel: set-up and post-processing of the paper's main case
(downward turbulent channel flow; doc/cases.md Part A).

    channel.py settings [-np N] PRESET CONFIG STAGE [MODEL ...]
                                  caseSettings of one stage (stdout) for
                                  N MPI ranks (default 1)
    channel.py init CASE          initial flow: mean profile plus seeded
                                  divergence-free perturbations (at time 0)
    channel.py release CASE       the particles of the case's configuration
                                  at its latest time: seeded uniform random
                                  non-overlapping positions at least d/2
                                  from the walls, the local fluid velocity,
                                  no spin, ids 0..N-1 (doc/cases.md A.1);
                                  into the processor folders of a
                                  decomposed case (no decomposePar)
    channel.py seedPairs CASE CLOUD ...
                                  the seeded pairs of the smoke preset
                                  (doc/cases.md A.11) at the latest time

The stages are run by channelRuns.py (./Allrun), which calls
branch_clouds, progress, preset and configuration directly.

Post-processing: channelPost.py PRESET.

Stages: unladen (single phase), release and dispersion (one cloud
"particles", collisions on, agglomeration off), agglomeration (clouds EAM
and MAM in one run for one-way coupled configurations, one per run for the
two-way coupled ones; counters zeroed at its start).
"""

import math
import re
import shutil
import sys
import time as time_module
from pathlib import Path

import numpy as np

from aggloTools import cloud, fields, placement, progress as prog, times
from aggloTools import casesettings

HERE = Path(__file__).resolve().parent


def report_dir(pname, reference=False):
    """Where the post-processing of a preset writes: its runs' report
    (runs/<preset>/report), or the committed reference (results/<preset>)
    with reference."""
    return (HERE / "results" / pname if reference
            else HERE / "runs" / pname / "report")

STAGES = ("unladen", "release", "dispersion", "agglomeration")
MODELS = ("EAM", "MAM")
N_PAPER = 6.0e6
#: AB16 Tab. D.6: f_col, f_agg per model (per T*, the paper's 6e6
#: particles)
TABLE_D6 = {
    "C1": {"fcol": {"EAM": 8.14e4, "MAM": 7.79e4},
           "fagg": {"EAM": 6.67e2, "MAM": 5.39e2}},
    "C2": {"fcol": {"EAM": 5.85e4, "MAM": 5.83e4},
           "fagg": {"EAM": 1.72e2, "MAM": 1.29e2}},
    "C3": {"fcol": {"EAM": 3.91e4, "MAM": 3.88e4},
           "fagg": {"EAM": 1.93e2, "MAM": 1.39e2}},
    "C4": {"fcol": {"EAM": 1.24e3, "MAM": 1.23e3},
           "fagg": {"EAM": 2.1e1, "MAM": 1.36e1}},
}
PI = math.pi


# ---------------------------------------------------------------- settings

def _nums(v):
    """A parsed list value such as ['(128', 128, '128)'] as floats."""
    if not isinstance(v, list):
        v = [v]
    return [float(str(x).strip("()")) for x in v if str(x).strip("()")]


COMMON_KEYS = {"delta", "Ubar", "nu", "rhoInf", "rhoParticle", "perturb",
               "ddtScheme", "seed", "writeFormat", "writePositions",
               "purgeWrite", "eventLog"}
PRESET_KEYS = {"n", "yGrading", "dtStar", "nParticles", "couplingScale",
               "unladen", "release", "dispersion", "agglomeration", "window",
               "writeStar", "profileBins", "seededPairs"} | COMMON_KEYS
CONFIGURATION_KEYS = {"subModels", "wall", "d", "en"}


def read_presets():
    """The presets file, every entry checked."""
    return casesettings.read_presets(
        HERE / "presets", PRESET_KEYS, {"common": COMMON_KEYS},
        {"configurations": CONFIGURATION_KEYS})


def preset(name):
    """The merged settings of a preset (common values first)."""
    p = casesettings.merged(read_presets(), name, "channel.py",
                            exclude=("configurations",))
    p["name"] = name
    p.setdefault("seededPairs", 0)
    p["n"] = [int(x) for x in _nums(p["n"])]
    p["window"] = _nums(p["window"])
    p["tScale"] = p["delta"] / p["Ubar"]            # delta/U_B [s]
    p["deltaT"] = p["dtStar"] * p["tScale"]
    p["L"] = (2 * PI * p["delta"], 2 * p["delta"], PI * p["delta"])
    choices = {"writeFormat": ("ascii", "binary"),
               "writePositions": ("on", "off"), "eventLog": ("on", "off")}
    for key, valid in choices.items():
        casesettings.choice(p[key], valid,
                            f"channel.py: presets/{name}: {key}")
    if not isinstance(p["purgeWrite"], int) or p["purgeWrite"] < 0:
        sys.exit(f"channel.py: presets/{name}: purgeWrite '{p['purgeWrite']}'"
                 " must be an integer >= 0 (0 keeps every write)")
    return p


def configuration(name):
    c = dict(casesettings.named(read_presets()["configurations"], name,
                                "configuration", "channel.py"))
    c["name"] = name
    c["twoWay"] = c["subModels"] == "on"
    return c


def steps(p, stage):
    """Cumulative step number at the end of a stage."""
    n = 0
    for s in STAGES:
        n += int(round(p[s] / p["dtStar"]))
        if s == stage:
            return n
    raise ValueError(stage)


def end_time(p, stage):
    return steps(p, stage) * p["deltaT"]


def settings(pname, cname, stage, models=(), nprocs=1):
    p, c = preset(pname), configuration(cname)
    casesettings.choice(stage, STAGES, "channel.py: stage")
    for m in models:
        casesettings.choice(m, MODELS, "channel.py: model")
    if stage == "agglomeration":
        if not models:
            models = ("EAM",) if c["twoWay"] else MODELS
        if c["twoWay"] and len(models) != 1:
            sys.exit("channel.py: a two-way coupled configuration runs one"
                     " agglomeration model per run")
        clouds = "(" + " ".join(models) + ")"
    elif stage == "unladen":
        clouds = "()"
    else:
        clouds = "(particles)"
    on = c["twoWay"]
    forces = ("SchillerNaumannDrag; SaffmanMeiLiftForce { U U; }"
              " rotationLift { model OesterleBuiDinh; } gravity;"
              if on else "SchillerNaumannDrag; gravity;")
    if c["wall"] == "rough":
        wall = ("wallModel sandgrain; sandgrainCoeffs { en 0.9; et 0.3;"
                " muSt 0.5; muKin 0.4; Rz 10e-6; CSurface 3; }")
    else:
        wall = (f"wallModel smooth; smoothCoeffs {{ en {c['en']}; et 0.44;"
                " muSt 0.94; muKin 0.092; }")
    Lx, Ly, Lz = p["L"]
    nx, ny, nz = p["n"]
    write_steps = max(1, int(round(p["writeStar"] / p["dtStar"])))
    return f"""\
/*--------------------------------*- C++ -*----------------------------------*\\
| agglomerationHardSphere: verticalChannel                                    |
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "system";
    object      caseSettings;
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// The parameters of one stage of one run, in one place: written by
//     channel.py settings {pname} {cname} {stage} {' '.join(models)}
// (./Allrun does it) from the presets and configurations files and
// #included by the other dictionaries. Times in s; delta/U_B = {p['tScale']:.6g} s.

preset          {pname};
configuration   {cname};
stage           {stage};

// Mesh: 2 pi delta x 2 delta x pi delta, wall-graded in y
Lx              {Lx:.10g};
Ly              {Ly:.10g};
Lz              {Lz:.10g};
nx              {nx};
ny              {ny};
nz              {nz};
yGrading        {p['yGrading']};
yGradingInv     {1 / p['yGrading']:.10g};

// Time: dt* = {p['dtStar']}; this stage ends at T* = {steps(p, stage) * p['dtStar']:.6g}
deltaT          {p['deltaT']:.10g};
endTime         {end_time(p, stage):.10g};
writeSteps      {write_steps};
writeFormat     {p['writeFormat']};
purgeWrite      {p['purgeWrite']};      // keep the last N writes (0: all)
writePositions  {1 if p['writePositions'] == 'on' else 0};  // legacy positions too
ddtScheme       {p['ddtScheme']};

// Flow (Re_b = 11900)
Ubar            {p['Ubar']};
nProcs          {nprocs};

// Particles: configuration {cname}
dParticle       {c['d']};
nParticles      {int(p['nParticles'])};
seed            {p['seed']};
subModels       {c['subModels']};    // two-way coupling + lift + SGS
coupled         {'true' if on else 'false'};
couplingScale   {p['couplingScale'] if on else 1};
cloudForces     {{ {forces} }}
dispersionModel {'PozorskiApte' if on else 'none'};
enParticle      {c['en']};
wallType        {c['wall']};
wallCoeffs      {{ {wall} }}
profileBins     {p['profileBins']};

// Clouds of this stage: none (unladen), particles (release, dispersion:
// no agglomeration), then one cloud per agglomeration model
clouds          {clouds};

// The collision-event log of the agglomeration stage (doc/eventLog.md)
eventLog        {p['eventLog'] if stage == 'agglomeration' else 'off'};

// ************************************************************************* //
"""


# ------------------------------------------------------------ mesh helpers

SETTINGS_KEYS = {"preset", "configuration", "stage", "Lx", "Ly", "Lz", "nx",
                 "ny", "nz", "yGrading", "yGradingInv", "deltaT", "endTime",
                 "writeSteps", "writeFormat", "purgeWrite",
                 "writePositions", "ddtScheme", "Ubar", "nProcs",
                 "dParticle", "nParticles", "seed", "subModels", "coupled",
                 "couplingScale", "cloudForces", "dispersionModel",
                 "enParticle", "wallType", "wallCoeffs", "profileBins",
                 "clouds", "eventLog"}


def read_settings(case):
    """The caseSettings of a stage, every entry checked."""
    return casesettings.read_settings(case, SETTINGS_KEYS)


def cell_centres(case, time="0"):
    """Cell centres (postProcess -func writeCellCentres must have run)."""
    return fields.read_internal(Path(case) / time / "C")


class Grid:
    """The structured blockMesh grid: cells ordered x fastest, then y, z."""

    def __init__(self, C, n):
        self.n = n
        nx, ny, nz = n
        C = C.reshape(nz, ny, nx, 3)
        self.xc = C[0, 0, :, 0]
        self.yc = C[0, :, 0, 1]
        self.zc = C[:, 0, 0, 2]

    @staticmethod
    def _nearest(c, v):
        mid = 0.5 * (c[1:] + c[:-1])
        return np.searchsorted(mid, v)

    def cell(self, x):
        nx, ny, nz = self.n
        i = self._nearest(self.xc, x[:, 0])
        j = self._nearest(self.yc, x[:, 1])
        k = self._nearest(self.zc, x[:, 2])
        return i + nx * (j + ny * k)


# ------------------------------------------------------------------- init

def init(case):
    """Initial flow at time 0: the 1/7 power-law profile with bulk velocity
    U_B plus seeded perturbations of amplitude perturb*U_B: three
    streamwise vortices psi = f(y) sin(kz z + phase) (v = dpsi/dz,
    w = -dpsi/dy: divergence free) and three streak modes
    u' = f(y) sin(kx x + phase) cos(kz z) with the w' that makes them
    divergence free, f = (1 - (y/delta - 1)^2)^2, plus 5 % white noise
    (removed by the first pressure projection)."""
    case = Path(case)
    s = read_settings(case)
    p = preset(s["preset"])
    C = cell_centres(case)
    d, Ub, A = p["delta"], p["Ubar"], p["perturb"]
    Lx, _, Lz = p["L"]
    x, y, z = C[:, 0], C[:, 1], C[:, 2]
    eta = np.clip(1 - np.abs(y - d) / d, 0, 1)      # 0 at walls, 1 centre
    U = np.zeros_like(C)
    U[:, 0] = Ub * 8 / 7 * eta**(1 / 7)
    rng = np.random.default_rng(int(p["seed"]))
    yy = (y - d) / d
    f = (1 - yy**2)**2
    dfdy = -4 * yy * (1 - yy**2) / d
    amp = A * Ub / 3
    for kz_n, kx_n in ((4, 2), (6, 3), (8, 1)):
        ph = rng.uniform(0, 2 * PI, 2)
        kz, kx = 2 * PI * kz_n / Lz, 2 * PI * kx_n / Lx
        U[:, 1] += amp * f * np.cos(kz * z + ph[0])
        U[:, 2] -= amp / kz * dfdy * np.sin(kz * z + ph[0])
        U[:, 0] += amp * f * np.sin(kx * x + ph[1]) * np.cos(kz * z)
        U[:, 2] -= (amp * f * kx / kz * np.cos(kx * x + ph[1])
                    * np.sin(kz * z))
    U += A * Ub * 0.05 * rng.standard_normal(U.shape) * f[:, None]
    fields.set_internal_vector_field(case / "0/U", U)


# ----------------------------------------------------------------- release

def place(N, dp, L, rng):
    """N non-overlapping positions (centre distance at least 1.001 dp) in
    the channel [0, Lx) x [dp/2 1.001, Ly - dp/2 1.001] x [0, Lz),
    periodic in x and z (aggloTools.placement)."""
    Lx, Ly, Lz = L
    try:
        return placement.place(N, dp * 1.001, (0, dp / 2 * 1.001, 0),
                               (Lx, Ly - dp / 2 * 1.001, Lz),
                               (Lx, None, Lz), rng)
    except RuntimeError as e:
        sys.exit(f"channel.py release: {e}")


def mesh_lines(case):
    """The face coordinates along x, y and z of the one-block blockMesh
    grid (points ordered x fastest, then y, z)."""
    pts = cloud.read_lagrangian(Path(case) / "constant/polyMesh/points")
    s = read_settings(case)
    nx, ny = int(s["nx"]), int(s["ny"])
    return (pts[:nx + 1, 0], pts[:(nx + 1) * (ny + 1):nx + 1, 1],
            pts[::(nx + 1) * (ny + 1), 2])


def containing_cell(lines, x):
    """Index of the cell that contains each position (x, y, z)."""
    ijk = [np.clip(np.searchsorted(f, x[:, a], "right") - 1, 0, len(f) - 2)
           for a, f in enumerate(lines)]
    nx, ny = len(lines[0]) - 1, len(lines[1]) - 1
    return ijk[0] + nx * (ijk[1] + ny * ijk[2])


def release(case, time=None):
    """Release the particles into the latest time (or time) of the case:
    serially, or straight into the processor folders of a decomposed case
    (each particle into the processor that holds its cell, with its
    global id: the same particles as a serial release, and none goes
    through decomposePar). A particle starts with the fluid velocity of
    the cell whose centre is nearest along each axis."""
    case = Path(case)
    s = read_settings(case)
    p = preset(s["preset"])
    c = configuration(s["configuration"])
    if time is None:
        time = times.time_dirs(case)[-1].name
    C = cell_centres(case, time)
    grid = Grid(C, p["n"])
    U = fields.read_internal(case / time / "U")
    N, dp = int(p["nParticles"]), float(c["d"])
    rng = np.random.default_rng(int(p["seed"]) + 1000)
    t0 = time_module.time()
    x = place(N, dp, p["L"], rng)
    t1 = time_module.time()
    Up = U[grid.cell(x)]
    procs = sorted(case.glob("processor[0-9]*"),
                   key=lambda d: int(d.name[9:]))
    if not procs:
        cloud.write_cloud(case, x, dp, p["rhoParticle"], U=Up,
                           cloud="particles", time=time)
    else:
        owner = np.empty(len(C), np.int64)
        for rank, d in enumerate(procs):
            owner[cloud.read_lagrangian(
                d / "constant/polyMesh/cellProcAddressing").astype(
                    np.int64)] = rank
        rank = owner[containing_cell(mesh_lines(case), x)]
        for r, d in enumerate(procs):
            mine = np.nonzero(rank == r)[0]
            cloud.write_cloud(d, x[mine], dp, p["rhoParticle"], U=Up[mine],
                               cloud="particles", time=time, ids=mine,
                               count=N, totals=(N, N, len(procs)))
    t2 = time_module.time()
    where = f" into {len(procs)} processor folders" if procs else ""
    print(f"released {N} particles of {dp * 1e6:g} um at t = {time}{where}"
          f" (seed {int(p['seed']) + 1000}): placed in {t1 - t0:.1f} s,"
          f" written in {t2 - t1:.1f} s")


# ------------------------------------------------------------- branching

def branch_clouds(case, time, models):
    """Agglomeration branch: the released cloud `particles` of the time
    (in the case and in each processor folder) becomes one cloud per
    model with the same particles, cloudProperties, record of the
    particles (hardSphereCloudState) and source fields; the statistics
    state is not copied (the counters start from zero)."""
    case = Path(case)
    for r in [case / time] + sorted(case.glob(f"processor*/{time}")):
        src = r / "lagrangian/particles"
        if not src.is_dir():
            continue
        sources = sorted(r.glob("particles:*"))
        for m in models:
            shutil.copytree(src, r / "lagrangian" / m)
            (r / "uniform/lagrangian" / m).mkdir(parents=True)
            for f in ("cloudProperties", cloud.RECORD):
                shutil.copy(r / "uniform/lagrangian/particles" / f,
                            r / "uniform/lagrangian" / m)
            # the record names the clouds of the case: now the models'
            rec = r / "uniform/lagrangian" / m / cloud.RECORD
            rec.write_text(re.sub(
                r"clouds\s+\d+\s*\([^)]*\);",
                f"clouds {len(models)} ( {' '.join(models)} );",
                rec.read_text()))
            for f in sources:
                shutil.copy(f, r / f"{m}:{f.name.split(':', 1)[1]}")
        shutil.rmtree(src)
        shutil.rmtree(r / "uniform/lagrangian/particles")
        for f in sources:
            f.unlink()


# ------------------------------------------------------------ seeded pairs

def seed_pairs(case, clouds):
    """Add the smoke preset's seeded pairs (doc/cases.md A.11) to the clouds of
    the case's latest time: nPairs pairs in |y| < delta/4 with a centre gap
    of 1 nm along a random direction n; the partners move with the fluid
    velocity at the midpoint -/+ du/2 n (head-on approach): du = 0.3 mm/s
    (must agglomerate) for the even pairs, 20 mm/s (must rebound) for the
    odd ones. The first five straddle the periodic plane x = 0, the next
    five the mid plane z = Lz/2 (the processor boundary of the 2-rank
    run). Ids continue after the released particles. The cloud is
    rewritten with the legacy positions file (located on reading)."""
    case = Path(case)
    s = read_settings(case)
    p = preset(s["preset"])
    n_pairs = int(p.get("seededPairs", 0))
    if not n_pairs:
        return
    time = times.time_dirs(case)[-1].name
    grid = Grid(cell_centres(case, time), p["n"])
    Uf = fields.read_internal(case / time / "U")
    dp = float(configuration(s["configuration"])["d"])
    Lx, Ly, Lz = p["L"]
    d = p["delta"]
    rng = np.random.default_rng(int(p["seed"]) + 2000)
    nvec = rng.standard_normal((n_pairs, 3))
    nvec /= np.linalg.norm(nvec, axis=1)[:, None]
    mid = rng.uniform((0, 0.75 * d, 0), (Lx, 1.25 * d, Lz), (n_pairs, 3))
    mid[:5, 0] = 0.0
    mid[5:10, 2] = 0.5 * Lz
    h = 0.5 * dp + 0.5e-9
    du = np.where(np.arange(n_pairs) % 2 == 0, 0.3e-3, 20e-3)
    xa, xb = mid - h * nvec, mid + h * nvec
    for x in (xa, xb):
        x[:, 0] %= Lx
    mid_in = mid.copy()
    mid_in[:, 0] %= Lx
    um = Uf[grid.cell(mid_in)]
    ua = um + 0.5 * du[:, None] * nvec
    ub = um - 0.5 * du[:, None] * nvec
    x_new = np.empty((2 * n_pairs, 3))
    u_new = np.empty((2 * n_pairs, 3))
    x_new[0::2], x_new[1::2] = xa, xb
    u_new[0::2], u_new[1::2] = ua, ub
    for name in clouds:
        ids = cloud.read_lagrangian(case / time / "lagrangian" / name
                                    / "origId").astype(int)
        new = {"U": u_new, "d": np.full(2 * n_pairs, dp),
               "dTarget": np.full(2 * n_pairs, dp),
               "rho": np.full(2 * n_pairs, p["rhoParticle"]),
               "nParticle": np.ones(2 * n_pairs),
               "nPrimary": np.ones(2 * n_pairs), "active": np.ones(
                   2 * n_pairs), "origId": ids.max() + 1 + np.arange(
                   2 * n_pairs), "lastPartnerId": -np.ones(2 * n_pairs),
               "lastPartnerProc": -np.ones(2 * n_pairs),
               "lastContactTime": np.full(2 * n_pairs, -1e15)}
        n0 = cloud.append_particles(case, time, name, x_new, new)
        print(f"{name}: {n_pairs} seeded pairs added to {n0} particles"
              f" (ids {ids.max() + 1}..{ids.max() + 2 * n_pairs})")


# ---------------------------------------------------------------- progress

def progress(case):
    """One line: stage, T*, fraction done and ETA from the solver log."""
    case = Path(case)
    s = read_settings(case)
    p = preset(s["preset"])
    t_end = float(s["endTime"])
    now = prog.solver_progress(case / "log.aggloPimpleFoam", t_end,
                               p["deltaT"])
    if now is None:
        return "starting"
    t, frac, eta = now
    return (f"{s['stage']}: T* = {t / p['tScale']:.2f}, stage ends at "
            f"{t_end / p['tScale']:.2f} " + prog.line(frac, eta))


# ------------------------------------------------------------------- main

def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 1
    cmd = argv[1]
    if cmd == "settings":
        args = argv[2:]
        nprocs = 1
        if args[:1] == ["-np"]:
            if len(args) < 2 or not args[1].isdigit() or int(args[1]) < 1:
                sys.exit("channel.py settings: -np needs a positive"
                         " number of ranks")
            nprocs = int(args[1])
            args = args[2:]
        if len(args) < 3:
            print(__doc__)
            return 1
        sys.stdout.write(settings(args[0], args[1], args[2],
                                  tuple(args[3:]), nprocs))
    elif cmd == "init":
        init(argv[2])
    elif cmd == "release":
        release(argv[2])
    elif cmd == "seedPairs":
        seed_pairs(argv[2], argv[3:])
    else:
        print(__doc__)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
