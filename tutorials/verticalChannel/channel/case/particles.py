"""verticalChannel: the particles of a stage's case (doc/cases.md A.1,
A.11).

    channel.case.particles release CASE
                        the particles of the case's configuration (of
                        each of a group's, the same) at its latest
                        time: seeded uniform random non-overlapping
                        positions at least d/2 from the walls, the local
                        fluid velocity, no spin, ids 0..N-1; into the
                        processor folders of a decomposed case (no
                        decomposePar)
    channel.case.particles seedPairs CASE CLOUD ...
                        the seeded pairs of the smoke preset at the latest
                        time

The driver (channel.case.runs) calls branch_clouds directly: the released
cloud becomes one cloud per agglomeration model (in a group of
configurations, each configuration's cloud one per model: groups)."""

import argparse
import re
import shutil
import sys
import time as time_module
from pathlib import Path

import numpy as np

from channel.case import groups, settings
from aggloTools import cloud, fields, placement, times


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
        sys.exit(f"channel.case.particles release: {e}")


def mesh_lines(case):
    """The face coordinates along x, y and z of the one-block blockMesh
    grid (points ordered x fastest, then y, z)."""
    pts = cloud.read_lagrangian(Path(case) / "constant/polyMesh/points")
    s = settings.read_settings(case)
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
    s = settings.read_settings(case)
    config = str(s["configuration"])
    # a group's configurations share their particles (groups.check): the
    # same particles in each one's cloud
    p = settings.preset(s["preset"], groups.lead(config))
    c = settings.configuration(groups.lead(config))
    names = groups.clouds(config, "release", ())
    if time is None:
        time = times.time_dirs(case)[-1].name
    C = settings.cell_centres(case, time)
    grid = Grid(C, p["n"])
    U = fields.read_internal(case / time / "U")
    # the run's own number (caseSettings: the preset's, or its
    # perConfiguration entry's for this configuration)
    N, dp = int(s["nParticles"]), float(c["d"])
    rng = np.random.default_rng(int(p["seed"]) + 1000)
    t0 = time_module.time()
    x = place(N, dp, p["L"], rng)
    t1 = time_module.time()
    Up = U[grid.cell(x)]
    procs = sorted(case.glob("processor[0-9]*"),
                   key=lambda d: int(d.name[9:]))
    if not procs:
        for name in names:
            cloud.write_cloud(case, x, dp, p["rhoParticle"], U=Up,
                               cloud=name, time=time)
    else:
        owner = np.empty(len(C), np.int64)
        for rank, d in enumerate(procs):
            owner[cloud.read_lagrangian(
                d / "constant/polyMesh/cellProcAddressing").astype(
                    np.int64)] = rank
        rank = owner[containing_cell(mesh_lines(case), x)]
        for r, d in enumerate(procs):
            mine = np.nonzero(rank == r)[0]
            for name in names:
                cloud.write_cloud(d, x[mine], dp, p["rhoParticle"],
                                   U=Up[mine], cloud=name, time=time,
                                   ids=mine, count=N,
                                   totals=(N, N, len(procs)))
    t2 = time_module.time()
    where = f" into {len(procs)} processor folders" if procs else ""
    each = f" (each of the clouds {' '.join(names)})" if len(names) > 1 \
        else ""
    print(f"released {N} particles{each} of {dp * 1e6:g} um at t = "
          f"{time}{where}"
          f" (seed {int(p['seed']) + 1000}): placed in {t1 - t0:.1f} s,"
          f" written in {t2 - t1:.1f} s")


# ------------------------------------------------------------- branching

def branch_clouds(case, time, branches):
    """Agglomeration branch: each released cloud of the time (in the case
    and in each processor folder) becomes the clouds that branches (cloud
    -> the released cloud it starts from: groups.branches) name, with
    the same particles, cloudProperties, record of the particles
    (hardSphereCloudState) and source fields; the statistics state is not
    copied (the counters start from zero)."""
    case = Path(case)
    made = list(branches)
    for r in [case / time] + sorted(case.glob(f"processor*/{time}")):
        for name in sorted(set(branches.values())):
            src = r / "lagrangian" / name
            if not src.is_dir():
                continue
            sources = sorted(r.glob(f"{name}:*"))
            for m in (m for m in made if branches[m] == name):
                shutil.copytree(src, r / "lagrangian" / m)
                (r / "uniform/lagrangian" / m).mkdir(parents=True)
                for f in ("cloudProperties", cloud.RECORD):
                    shutil.copy(r / "uniform/lagrangian" / name / f,
                                r / "uniform/lagrangian" / m)
                # the record names the clouds of the case: now these
                rec = r / "uniform/lagrangian" / m / cloud.RECORD
                rec.write_text(re.sub(
                    r"clouds\s+\d+\s*\([^)]*\);",
                    f"clouds {len(made)} ( {' '.join(made)} );",
                    rec.read_text()))
                for f in sources:
                    shutil.copy(f, r / f"{m}:{f.name.split(':', 1)[1]}")
            shutil.rmtree(src)
            shutil.rmtree(r / "uniform/lagrangian" / name)
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
    s = settings.read_settings(case)
    lead = groups.lead(str(s["configuration"]))
    p = settings.preset(s["preset"], lead)
    n_pairs = int(p.get("seededPairs", 0))
    if not n_pairs:
        return
    time = times.time_dirs(case)[-1].name
    grid = Grid(settings.cell_centres(case, time), p["n"])
    Uf = fields.read_internal(case / time / "U")
    dp = float(settings.configuration(lead)["d"])
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


# ------------------------------------------------------------------- main

def main(argv):
    ap = argparse.ArgumentParser(
        prog="channel.case.particles", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("release", help="the configuration's particles at "
                       "the case's latest time")
    r.add_argument("case", help="the release stage's case folder")
    s = sub.add_parser("seedPairs", help="the smoke preset's seeded pairs "
                       "at the case's latest time")
    s.add_argument("case", help="the agglomeration stage's case folder")
    s.add_argument("clouds", nargs="*", help="the clouds (EAM, MAM)")
    a = ap.parse_args(argv[1:])
    if a.cmd == "release":
        release(a.case)
    else:
        seed_pairs(a.case, a.clouds)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
