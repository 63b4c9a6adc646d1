"""The scripted boxes of the cloud tests (tests/unit/cloud): 12 um
quartz primaries in a 100 um box, a pair approaching at a given angle,
a hard-sphere gas, an agglomerating gas and the 300-primaries gas of
the event-log and restart-record tests, and the particle state of a
written cloud. The box cases themselves are aggloTools.boxcase."""

import math
import shutil

import numpy as np

from aggloTools import placement
from aggloTools.boxcase import box_case, kernel
from aggloTools.cloud import read_cloud
from aggloTools.foamfile import edit

STATE = ("U", "omega", "d", "rho", "nPrimary", "origId", "origProcId",
         "lastPartnerId", "lastContactTime")


def cloud_state(case, time):
    """The particle state of a written cloud (numpy arrays)."""
    return read_cloud(case, time, names=STATE)


D = 12e-6
L = 1e-4
C = 0.5 * L


def pair_particles(v, theta_deg, gap=1e-6, centre=(C, C, C), spin=None):
    """Two 12 um primaries approaching along x with relative speed v; the
    impact parameter gives the angle theta between -u_r and the contact
    normal."""
    b = D * math.sin(math.radians(theta_deg))
    X = D * math.cos(math.radians(theta_deg)) + gap
    cx, cy, cz = centre
    p1 = dict(x=(cx - 0.5 * X, cy - 0.5 * b, cz), U=(0.5 * v, 0, 0), id=0)
    p2 = dict(x=(cx + 0.5 * X, cy + 0.5 * b, cz), U=(-0.5 * v, 0, 0), id=1)
    if spin:
        p1["omega"], p2["omega"] = spin
    return [p1, p2]


def gas_particles(N, Lbox, phi, sigma, seed):
    """N equal spheres of volume fraction phi, uniform and non-overlapping
    (gap 5 % of d) in the periodic box, with Gaussian velocities of
    standard deviation sigma and zero mean."""
    rng = np.random.default_rng(seed)
    d = Lbox * (6 * phi / (math.pi * N)) ** (1 / 3)
    xs = placement.place(N, 1.05 * d, (0, 0, 0), (Lbox,) * 3, (Lbox,) * 3,
                         rng)
    U = rng.normal(0, sigma, (N, 3))
    U -= U.mean(axis=0)
    parts = [dict(x=tuple(x), U=tuple(u), d=d, rho=2200, id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    return parts, d, U


def gas_kernel(en):
    """A frictionless gas: normal restitution en, no agglomeration, no
    walls (the structure model's entry left out)."""
    return kernel(walls={}, structureModel=None,
                  material={"pMax": 1.6e9},
                  particleCollision={"en": en, "et": 1, "muSt": 0,
                                     "muKin": 0})


def agglomerating_gas(case_dir, end_time, write_interval, decompose=(1,1,1),
                      hard_sphere=None, cloud=None):
    """300 quartz primaries at about 2 mm/s in a box periodic in x and z,
    walls in y: collisions, agglomerates (under EAM and MAM: seed 13) and
    wall impacts within 40 steps; cloud: changes to the cloud's
    properties (boxcase.cloud_properties)."""
    rng = np.random.default_rng(13)
    Lb, N = 2e-4, 300
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0), (Lb, Lb - 0.6 * D, Lb),
                         (Lb, None, Lb), rng)
    U = rng.normal(0, 1.5e-3, (N, 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    box_case(case_dir, L=(Lb, Lb, Lb), n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=end_time, write_interval=write_interval,
             hard_sphere=hard_sphere or kernel("EAM"),
             decompose=decompose, cloud=cloud)


def add_cloud(case, name, edit=None):
    """A second cloud `name` in a box case: kinematicCloud's properties
    (edit: a function of their text, e.g. another cellOrderInterval) and
    particles, both clouds listed in constant/cloudProperties."""
    text = (case / "constant" / "kinematicCloudProperties").read_text() \
        .replace("kinematicCloudProperties", f"{name}Properties")
    (case / "constant" / f"{name}Properties").write_text(
        edit(text) if edit else text)
    (case / "constant" / "cloudProperties").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary;"
        f" object cloudProperties; }}\nclouds (kinematicCloud {name});\n")
    for d in ("lagrangian", "uniform/lagrangian"):
        src = case / "0" / d / "kinematicCloud"
        if src.is_dir():
            shutil.copytree(src, case / "0" / d / name)
    return case


def add_hard_sphere_entries(case_dir, entries):
    """Add entries to the hardSphereCoeffs dictionary of a box case (before
    its agglomerationModel entry)."""
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    old = "agglomerationModel "
    assert old in text
    f.write_text(text.replace(old, entries + " " + old, 1))


#: A head-on pair at 1 mm/s each, 20 um apart, in the middle of the box
PAIR = [dict(x=(0.4 * L, 0.5 * L, 0.5 * L), U=(1e-3, 0, 0), id=0),
        dict(x=(0.6 * L, 0.5 * L, 0.5 * L), U=(-1e-3, 0, 0), id=1)]


def assert_fatal_naming(res, word):
    """A run that stopped with a fatal error whose message names word."""
    assert res.returncode != 0
    assert "FOAM FATAL" in res.stdout, res.stdout[-2000:]
    assert word in res.stdout.split("FOAM FATAL", 1)[1], \
        res.stdout[-2000:]


def primaries_gas(case, model="EAM", log=True, decompose=(1, 1, 1),
               end=4e-3, write=10, seed=11):
    """300 quartz primaries at about 2 mm/s in a 200 um box, periodic in
    x and z, walls in y, agglomeration model, the collision-event log on
    unless log is False: collisions of every category and agglomerates
    within 40 steps."""
    N, LB = 300, 2e-4
    rng = np.random.default_rng(seed)
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0),
                         (LB, LB - 0.6 * D, LB), (LB, None, LB), rng)
    U = rng.normal(0, 1.5e-3, (N, 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    box_case(case, L=(LB,) * 3, n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=end, write_interval=write, hard_sphere=kernel(model),
             decompose=decompose)
    if log:
        f = case / "constant" / "kinematicCloudProperties"
        old = "agglomerationModel " + model + ";"
        edit(f, old, old + " eventLog true;", 1)
    return case
