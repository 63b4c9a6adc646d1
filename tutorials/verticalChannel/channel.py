#!/usr/bin/env python3
"""verticalChannel: set-up and post-processing of the paper's main case
(downward turbulent channel flow; doc/cases.md Part A).

    channel.py settings PRESET CONFIG STAGE [MODEL ...]
                                  caseSettings of one stage (stdout)
    channel.py init CASE          initial flow: mean profile plus seeded
                                  divergence-free perturbations (at time 0)
    channel.py release CASE       the particles of the case's configuration
                                  at its latest time: seeded uniform random
                                  non-overlapping positions at least d/2
                                  from the walls, the local fluid velocity,
                                  no spin, ids 0..N-1 (doc/cases.md A.1);
                                  into the processor folders of a
                                  decomposed case (no decomposePar)
    channel.py branchClouds CASE TIME MODEL ...
                                  the released cloud becomes one cloud per
                                  model (agglomeration stage branch)
    channel.py seedPairs CASE CLOUD ...
                                  the seeded pairs of the smoke preset
                                  (doc/cases.md A.11) at the latest time
    channel.py progress CASE      stage, simulated time and ETA of a run
    channel.py settle CASE        set aside a last time folder whose write
                                  was cut off (before a restart)
    channel.py post PRESET        results/PRESET: summary.json,
                                  regression.txt, plots (exit 1 on a FAIL)

Stages: unladen (single phase), release and dispersion (one cloud
"particles", collisions on, agglomeration off), agglomeration (clouds EAM
and MAM in one run for one-way coupled configurations, one per run for the
two-way coupled ones; counters zeroed at its start).
"""

import json
import math
import os
import re
import shutil
import sys
import time as time_module
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(Path(os.environ.get("AGGLO_PROJECT_DIR",
                                           HERE.parents[1])) / "tools"))

from aggloTools import foamio  # noqa: E402

STAGES = ("unladen", "release", "dispersion", "agglomeration")
MODELS = ("EAM", "MAM")
N_PAPER = 6.0e6
PI = math.pi


# ---------------------------------------------------------------- settings

def _nums(v):
    """A parsed list value such as ['(128', 128, '128)'] as floats."""
    if not isinstance(v, list):
        v = [v]
    return [float(str(x).strip("()")) for x in v if str(x).strip("()")]


COMMON_KEYS = {"delta", "Ubar", "nu", "rhoInf", "rhoParticle", "perturb",
               "ddtScheme", "seed", "writeFormat", "writePositions",
               "purgeWrite"}
PRESET_KEYS = {"n", "yGrading", "dtStar", "nParticles", "couplingScale",
               "unladen", "release", "dispersion", "agglomeration", "window",
               "writeStar", "profileBins", "seededPairs"} | COMMON_KEYS
CONFIGURATION_KEYS = {"subModels", "wall", "d", "en"}


def read_presets():
    """The presets file, every entry checked."""
    d = foamio.read_dict(HERE / "presets")
    for name, p in d.items():
        if name == "configurations":
            for c, cd in p.items():
                foamio.check_keys(cd, CONFIGURATION_KEYS,
                                  f"presets/configurations/{c}")
        else:
            foamio.check_keys(p, COMMON_KEYS if name == "common"
                              else PRESET_KEYS, f"presets/{name}")
    return d


def preset(name):
    """The merged settings of a preset (common values first)."""
    d = read_presets()
    if name not in d or name in ("common", "configurations"):
        valid = [k for k in d if k not in ("common", "configurations")]
        sys.exit(f"channel.py: unknown preset '{name}'; valid: "
                 + " ".join(valid))
    p = dict(d["common"])
    p.update(d[name])
    p["name"] = name
    p["n"] = [int(x) for x in _nums(p["n"])]
    p["window"] = _nums(p["window"])
    p["tScale"] = p["delta"] / p["Ubar"]            # delta/U_B [s]
    p["deltaT"] = p["dtStar"] * p["tScale"]
    p["L"] = (2 * PI * p["delta"], 2 * p["delta"], PI * p["delta"])
    choices = {"writeFormat": ("ascii", "binary"),
               "writePositions": ("on", "off")}
    for key, valid in choices.items():
        if p[key] not in valid:
            sys.exit(f"channel.py: presets/{name}: {key} '{p[key]}' is not"
                     f" one of: " + " ".join(valid))
    if not isinstance(p["purgeWrite"], int) or p["purgeWrite"] < 0:
        sys.exit(f"channel.py: presets/{name}: purgeWrite '{p['purgeWrite']}'"
                 " must be an integer >= 0 (0 keeps every write)")
    return p


def configuration(name):
    d = read_presets()["configurations"]
    if name not in d:
        sys.exit(f"channel.py: unknown configuration '{name}'; valid: "
                 + " ".join(d))
    c = dict(d[name])
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
    if stage not in STAGES:
        sys.exit(f"channel.py: unknown stage '{stage}'; valid: "
                 + " ".join(STAGES))
    for m in models:
        if m not in MODELS:
            sys.exit(f"channel.py: unknown model '{m}'; valid: EAM MAM")
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
                 "clouds"}


def read_settings(case):
    """The caseSettings of a stage, every entry checked."""
    f = Path(case) / "system" / "caseSettings"
    s = foamio.read_dict(f)
    foamio.check_keys(s, SETTINGS_KEYS, str(f))
    return s


def cell_centres(case, time="0"):
    """Cell centres (postProcess -func writeCellCentres must have run)."""
    return foamio.read_internal(Path(case) / time / "C")


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
    foamio.set_internal_vector_field(case / "0/U", U)


# ----------------------------------------------------------------- release

def _overlaps(x, dmin, Lx, Lz, query=None):
    """Sorted indices max(i, j) of the pairs closer than dmin, periodic in
    x (period Lx) and z (Lz) by minimum image, among the pairs with i in
    query (default: all particles). Vectorised grid search: cells of at
    least dmin (about one particle per cell) that tile the periods, the
    particles counting-sorted by cell, the 27 neighbour cells of every
    queried particle looked up directly."""
    n = len(x)
    q = np.arange(n) if query is None else np.asarray(query, np.int64)
    h = max(dmin, (Lx * np.ptp(x[:, 1]) * Lz / max(n, 1))**(1 / 3))
    nx, nz = max(1, int(Lx // h)), max(1, int(Lz // h))
    y0 = x[:, 1].min()
    ny = int((x[:, 1].max() - y0) // h) + 1
    i = np.floor(x[:, 0] / (Lx / nx)).astype(np.int64) % nx
    j = np.minimum(np.floor((x[:, 1] - y0) / h).astype(np.int64), ny - 1)
    k = np.floor(x[:, 2] / (Lz / nz)).astype(np.int64) % nz
    key = i + nx * (j + ny * k)
    order = np.argsort(key, kind="stable")
    count = np.bincount(key, minlength=nx * ny * nz)
    start = np.concatenate(([0], np.cumsum(count)[:-1]))
    bad = []
    for a in (-1, 0, 1):
        for b in (-1, 0, 1):
            jb = j[q] + b
            inside = (jb >= 0) & (jb < ny)
            for c in (-1, 0, 1):
                sel = q[inside]
                nk = ((i[sel] + a) % nx
                      + nx * (jb[inside] + ny * ((k[sel] + c) % nz)))
                cnt, st = count[nk], start[nk]
                for m in range(int(cnt.max(initial=0))):
                    has = cnt > m
                    sel, cnt, st = sel[has], cnt[has], st[has]
                    other = order[st + m]
                    ok = other != sel
                    s1, o1 = sel[ok], other[ok]
                    r = x[s1] - x[o1]
                    r[:, 0] -= Lx * np.round(r[:, 0] / Lx)
                    r[:, 2] -= Lz * np.round(r[:, 2] / Lz)
                    close = np.einsum("ij,ij->i", r, r) < dmin**2
                    bad.append(np.maximum(s1[close], o1[close]))
    return np.unique(np.concatenate(bad)) if bad else np.zeros(0, int)


def place(N, dp, L, rng):
    """N non-overlapping positions (centre distance at least 1.001 dp) in
    the channel [0, Lx) x [dp/2 1.001, Ly - dp/2 1.001] x [0, Lz),
    periodic in x and z: uniform random draws; of every overlapping pair
    the particle of the higher index is drawn again, and only the redrawn
    particles are checked again (the others do not overlap each other)."""
    Lx, Ly, Lz = L
    lo = np.array([0, dp / 2 * 1.001, 0])
    hi = np.array([Lx, Ly - dp / 2 * 1.001, Lz])
    x = rng.uniform(lo, hi, (N, 3))
    query = None
    for _ in range(100):
        bad = _overlaps(x, dp * 1.001, Lx, Lz, query)
        if not len(bad):
            return x
        x[bad] = rng.uniform(lo, hi, (len(bad), 3))
        query = bad
    sys.exit("channel.py release: could not place the particles")


def mesh_lines(case):
    """The face coordinates along x, y and z of the one-block blockMesh
    grid (points ordered x fastest, then y, z)."""
    pts = foamio.read_lagrangian(Path(case) / "constant/polyMesh/points")
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
        time = foamio.time_dirs(case)[-1].name
    C = cell_centres(case, time)
    grid = Grid(C, p["n"])
    U = foamio.read_internal(case / time / "U")
    N, dp = int(p["nParticles"]), float(c["d"])
    rng = np.random.default_rng(int(p["seed"]) + 1000)
    t0 = time_module.time()
    x = place(N, dp, p["L"], rng)
    t1 = time_module.time()
    Up = U[grid.cell(x)]
    procs = sorted(case.glob("processor[0-9]*"),
                   key=lambda d: int(d.name[9:]))
    if not procs:
        foamio.write_cloud(case, x, dp, p["rhoParticle"], U=Up,
                           cloud="particles", time=time)
    else:
        owner = np.empty(len(C), np.int64)
        for rank, d in enumerate(procs):
            owner[foamio.read_lagrangian(
                d / "constant/polyMesh/cellProcAddressing").astype(
                    np.int64)] = rank
        rank = owner[containing_cell(mesh_lines(case), x)]
        for r, d in enumerate(procs):
            mine = np.nonzero(rank == r)[0]
            foamio.write_cloud(d, x[mine], dp, p["rhoParticle"], U=Up[mine],
                               cloud="particles", time=time, ids=mine,
                               count=N)
    t2 = time_module.time()
    where = f" into {len(procs)} processor folders" if procs else ""
    print(f"released {N} particles of {dp * 1e6:g} um at t = {time}{where}"
          f" (seed {int(p['seed']) + 1000}): placed in {t1 - t0:.1f} s,"
          f" written in {t2 - t1:.1f} s")


# ------------------------------------------------------------- branching

def branch_clouds(case, time, models):
    """Agglomeration branch: the released cloud `particles` of the time
    (in the case and in each processor folder) becomes one cloud per
    model with the same particles, cloudProperties and source fields; the
    statistics state is not copied (the counters start from zero)."""
    case = Path(case)
    for r in [case / time] + sorted(case.glob(f"processor*/{time}")):
        src = r / "lagrangian/particles"
        if not src.is_dir():
            continue
        sources = sorted(r.glob("particles:*"))
        for m in models:
            shutil.copytree(src, r / "lagrangian" / m)
            (r / "uniform/lagrangian" / m).mkdir(parents=True)
            shutil.copy(r / "uniform/lagrangian/particles/cloudProperties",
                        r / "uniform/lagrangian" / m)
            for f in sources:
                shutil.copy(f, r / f"{m}:{f.name.split(':', 1)[1]}")
        shutil.rmtree(src)
        shutil.rmtree(r / "uniform/lagrangian/particles")
        for f in sources:
            f.unlink()


# ------------------------------------------------------------ seeded pairs

def _field_class(path):
    m = re.search(r"class\s+(\S+);", Path(path).read_text()[:2000])
    return m.group(1) if m else ""


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
    time = foamio.time_dirs(case)[-1].name
    grid = Grid(cell_centres(case, time), p["n"])
    Uf = foamio.read_internal(case / time / "U")
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
    for cloud in clouds:
        cdir = case / time / "lagrangian" / cloud
        ids = foamio.read_lagrangian(cdir / "origId").astype(int)
        x0 = foamio.read_positions(cdir / "positions")
        n0 = len(x0)
        new = {"U": u_new, "d": np.full(2 * n_pairs, dp),
               "dTarget": np.full(2 * n_pairs, dp),
               "rho": np.full(2 * n_pairs, p["rhoParticle"]),
               "nParticle": np.ones(2 * n_pairs),
               "nPrimary": np.ones(2 * n_pairs), "active": np.ones(
                   2 * n_pairs), "origId": ids.max() + 1 + np.arange(
                   2 * n_pairs), "lastPartnerId": -np.ones(2 * n_pairs),
               "lastPartnerProc": -np.ones(2 * n_pairs),
               "lastContactTime": np.full(2 * n_pairs, -1e15)}
        for f in sorted(cdir.iterdir()):
            if f.name in ("positions", "coordinates"):
                continue
            cls = _field_class(f)
            old = foamio.read_lagrangian(f)
            vec = cls.startswith("vector")
            if not len(old):
                old = np.zeros((0, 3)) if vec else np.zeros(0)
            add = new.get(f.name, np.zeros((2 * n_pairs, 3)) if vec
                          else np.zeros(2 * n_pairs))
            vals = np.concatenate((old, add))
            if vec:
                lines = ["(%.17g %.17g %.17g)" % tuple(r) for r in vals]
            elif cls.startswith("label"):
                lines = ["%d" % v for v in vals]
            else:
                lines = ["%.17g" % v for v in vals]
            loc = f"{time}/lagrangian/{cloud}"
            foamio.write_foamfile(f, cls, loc, f.name,
                                  f"{len(vals)}\n(\n" + "\n".join(lines)
                                  + "\n)")
        xs = np.concatenate((x0, x_new))
        foamio.write_foamfile(
            cdir / "positions", "Cloud<basicAgglomerateParcel>",
            f"{time}/lagrangian/{cloud}", "positions",
            f"{len(xs)}\n(\n" + "\n".join(
                "(%.17g %.17g %.17g) -1" % tuple(r) for r in xs) + "\n)")
        (cdir / "coordinates").unlink(missing_ok=True)
        cp = case / time / "uniform/lagrangian" / cloud / "cloudProperties"
        cp.write_text(re.sub(r"geometry\s+\w+;", "geometry positions;",
                             cp.read_text()))
        print(f"{cloud}: {n_pairs} seeded pairs added to {n0} particles"
              f" (ids {ids.max() + 1}..{ids.max() + 2 * n_pairs})")


# ---------------------------------------------------------------- progress

def progress(case):
    """One line: stage, T*, fraction done and ETA from the solver log."""
    case = Path(case)
    s = read_settings(case)
    p = preset(s["preset"])
    log = case / "log.aggloPimpleFoam"
    if not log.exists():
        return "starting"
    text = log.read_text(errors="replace")
    times = re.findall(r"^Time = ([-+0-9.eE]+)", text, re.M)
    if not times:
        return "starting"
    t = float(times[-1])
    t_end = float(s["endTime"])
    # the start of this invocation: the last "Starting time loop"
    start = text.rfind("Starting time loop")
    first = re.search(r"^Time = ([-+0-9.eE]+)", text[start:], re.M)
    t0 = float(first.group(1)) - p["deltaT"] if first else t
    cpu = re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", text[start:])
    frac = (t - t0) / max(t_end - t0, 1e-30)
    eta = ""
    if cpu and frac > 0:
        el = float(cpu[-1])
        eta = f", ETA {_hms(el * (1 - frac) / frac)}"
    return (f"{s['stage']}: T* = {t / p['tScale']:.2f}, stage ends at "
            f"{t_end / p['tScale']:.2f} ({100 * min(frac, 1):.0f} % of this"
            f" run{eta})")


def _hms(sec):
    sec = int(sec)
    return (f"{sec // 3600}h{sec % 3600 // 60:02d}m" if sec >= 3600
            else f"{sec // 60}m{sec % 60:02d}s")


# ------------------------------------------------------------------- main

def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 1
    cmd = argv[1]
    if cmd == "settings":
        nprocs = int(os.environ.get("CHANNEL_NPROCS", "1"))
        sys.stdout.write(settings(argv[2], argv[3], argv[4],
                                  tuple(argv[5:]), nprocs))
    elif cmd == "init":
        init(argv[2])
    elif cmd == "release":
        release(argv[2])
    elif cmd == "branchClouds":
        branch_clouds(argv[2], argv[3], argv[4:])
    elif cmd == "seedPairs":
        seed_pairs(argv[2], argv[3:])
    elif cmd == "progress":
        print(progress(argv[2]))
    elif cmd == "settle":
        foamio.set_aside_incomplete_times(argv[2])
    elif cmd == "post":
        import channelPost
        return channelPost.post(argv[2])
    else:
        print(__doc__)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
