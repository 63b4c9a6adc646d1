"""Lagrangian clouds: a complete initial cloud of basicAgglomerateParcels
written in the legacy `positions` form, the cloud's fields read (ASCII or
binary IOFields), the Cartesian positions read from the `positions` file
or from the barycentric `coordinates` file and the mesh, and particles
appended to a written cloud."""

import re
from pathlib import Path

import numpy as np

from .foamfile import (binary_arch, field_class, is_binary, list_body,
                       read_list_file as read_lagrangian, write_foamfile)
from .mesh import Mesh


#: The record a hard-sphere cloud keeps beside its particles
#: (clouds/hardSphereCloudState): a restart checks the files against it
RECORD = "hardSphereCloudState"


def write_record(case, time, cloud, n, n_total=None, n_primaries=None,
                 n_procs=1, clouds=None):
    """The record of the particles written at time: n on this rank (case:
    the case or one processor folder), n_total and n_primaries over all
    n_procs ranks (default: this rank's, primaries only); clouds: the
    clouds of the case that the record names (default: this one)."""
    n_total = n if n_total is None else n_total
    n_primaries = n_total if n_primaries is None else n_primaries
    clouds = list(clouds) if clouds else [cloud]
    write_foamfile(Path(case) / str(time) / "uniform" / "lagrangian" / cloud
                   / RECORD, "dictionary",
                   f"{time}/uniform/lagrangian/{cloud}", RECORD,
                   f"writer          aggloTools;\ncomplete        true;\n"
                   f"clouds          {len(clouds)} ( {' '.join(clouds)} );\n"
                   f"nProcs          {n_procs};"
                   f"\nnParticles      {n};\n"
                   f"nParticlesTotal {n_total};\n"
                   f"nPrimariesTotal {n_primaries};")


def read_record(case, time, cloud):
    """The record of a written cloud as a dict (None if absent): the
    counts as ints, writer, complete (bool; true if not written, as by
    earlier versions) and clouds (the names; [] if not written)."""
    from .foamfile import read_dict
    f = Path(case) / str(time) / "uniform" / "lagrangian" / cloud / RECORD
    if not f.is_file():
        return None
    out = {"complete": True, "clouds": []}
    for k, v in read_dict(f).items():
        if k == "writer":
            out[k] = v
        elif k == "complete":
            out[k] = v in ("true", "on", "yes", 1)
        elif k == "clouds":
            out[k] = [w for w in (v if isinstance(v, list) else [v])
                      if isinstance(w, str) and w not in "()"]
        else:
            out[k] = int(v)
    return out


#: What left a hard-sphere cloud through the boundary, per patch
#: (clouds/cloudMassBalance)
BALANCE = "cloudMassBalance"


def read_mass_balance(case, time, cloud="kinematicCloud"):
    """The mass balance of a written cloud (None if absent): massStart
    (float), nPrimariesStart (int) and, under 'deposited' and 'escaped',
    {patch: {"nParcels": int, "nPrimaries": int, "mass": float}}."""
    from .foamfile import read_dict
    f = Path(case) / str(time) / "uniform" / "lagrangian" / cloud / BALANCE
    if not f.is_file():
        return None
    d = read_dict(f)
    out = {"massStart": float(d["massStart"]),
           "nPrimariesStart": int(d["nPrimariesStart"])}
    for way in ("deposited", "escaped"):
        out[way] = {patch: {"nParcels": int(v["nParcels"]),
                            "nPrimaries": int(v["nPrimaries"]),
                            "mass": float(v["mass"])}
                    for patch, v in (d.get(way) or {}).items()}
    return out


def write_cloud(case, positions, d, rho, U=None, omega=None, n_primary=None,
                cloud="kinematicCloud", time="0", ids=None, count=None,
                totals=None):
    """Write a complete initial cloud (one particle per parcel) for the
    basicAgglomerateParcel: the legacy positions file (cell -1: located on
    reading) plus every field, with origProcId 0 and origId 0..N-1 or ids
    (decomposition-independent ids); count (default: the largest id + 1)
    is the particleCount from which new particles are numbered. The
    cloud's record (write_record) goes with it: totals = (particles,
    primaries, ranks) over all ranks when case is one processor folder
    of several."""
    loc = f"{time}/lagrangian/{cloud}"
    out = Path(case) / loc
    x = np.asarray(positions, float)
    N = len(x)
    zeros = np.zeros((N, 3))
    U = zeros if U is None else np.asarray(U, float)
    omega = zeros if omega is None else np.asarray(omega, float)
    d = np.broadcast_to(np.asarray(d, float), (N,))
    rho = np.broadcast_to(np.asarray(rho, float), (N,))
    n_primary = (np.ones(N, int) if n_primary is None
                 else np.asarray(n_primary, int))
    ids = np.arange(N) if ids is None else np.asarray(ids, int)
    if count is None:
        count = int(ids.max()) + 1 if N else 0

    def field(name, cls, a, fmt="%.17g"):
        write_foamfile(out / name, cls, loc, name, list_body(a, fmt))

    write_foamfile(out / "positions", "Cloud<basicAgglomerateParcel>", loc,
                   "positions",
                   f"{N}\n(\n" + "(%.17g %.17g %.17g) -1\n" * N
                   % tuple(x.ravel().tolist()) + ")")
    field("origProcId", "labelField", np.zeros(N, int), "%d")
    field("origId", "labelField", ids, "%d")
    field("active", "labelField", np.ones(N, int), "%d")
    field("typeId", "labelField", np.zeros(N, int), "%d")
    field("nParticle", "scalarField", np.ones(N))
    field("d", "scalarField", d)
    field("dTarget", "scalarField", d)
    field("rho", "scalarField", rho)
    field("age", "scalarField", np.zeros(N))
    field("tTurb", "scalarField", np.zeros(N))
    field("U", "vectorField", U)
    field("UTurb", "vectorField", zeros)
    field("omega", "vectorField", omega)
    field("nPrimary", "labelField", n_primary, "%d")
    # no previous partner (the values the cloud gives a missing field)
    field("lastPartnerProc", "labelField", -np.ones(N, int), "%d")
    field("lastPartnerId", "labelField", -np.ones(N, int), "%d")
    field("lastContactTime", "scalarField", np.full(N, -1e15))
    t_n, t_prim, t_procs = totals or (N, int(n_primary.sum()), 1)
    write_record(case, time, cloud, N, t_n, t_prim, t_procs)
    write_foamfile(Path(case) / time / "uniform" / "lagrangian" / cloud
                   / "cloudProperties", "dictionary",
                   f"{time}/uniform/lagrangian/{cloud}", "cloudProperties",
                   f"geometry positions;\nprocessor0 {{ particleCount "
                   f"{count}; }}")


def _binary_records(path, data, rec, n, start):
    """The n binary particle records of dtype rec from start, each in
    parentheses and followed by a newline, the list closed after them; a
    file cut off or another layout stops."""
    end = start + n * rec.itemsize
    if len(data) < end or data[end:].lstrip()[:1] != b")":
        raise ValueError(f"{path}: {n} binary records announced, the file "
                         "ends before them or their list does not close "
                         "after them (a file cut off?)")
    a = np.frombuffer(data, rec, n, start)
    if n and not ((a["open"] == ord("(")).all()
                  and (a["close"] == ord(")")).all()
                  and (a["nl"] == ord("\n")).all()):
        raise ValueError(f"{path}: unexpected binary record layout")
    return a


def read_positions(path):
    """Cartesian positions from the legacy `positions` file (ASCII rows
    `(x y z) celli`, or binary records: the position and the cell label
    as one raw block in parentheses, then a newline)."""
    return _particle_list(path, 3, 1)[0]


def _particle_list(path, ncomp, nlabels):
    """The rows of a particle list file (positions, coordinates): a vector
    of ncomp scalars and nlabels labels each, ASCII `(c1 ... cn) l1 ...`
    or binary records (the vector and the labels as one raw block in
    parentheses, then a newline): (vectors (n, ncomp) float, labels (n,
    nlabels) int64). A file cut off, a wrong count or another layout
    stops."""
    data = Path(path).read_bytes()
    hend = data.index(b"}") + 1
    head = data[:hend]
    if is_binary(head):
        label, scalar = binary_arch(head)
        m = re.compile(rb"(\s|//[^\n]*)*(\d+)\s*\(\n?").match(data, hend)
        n = int(m.group(2))
        rec = np.dtype([("open", "u1"), ("v", scalar, ncomp),
                        ("labels", label, nlabels), ("close", "u1"),
                        ("nl", "u1")])
        a = _binary_records(path, data, rec, n, m.end())
        return (a["v"].astype(float).reshape(n, ncomp),
                a["labels"].astype(np.int64).reshape(n, nlabels))
    rows = _ascii_rows(path, data[hend:].decode(),
                       r"\s+".join([r"-?\d+"] * nlabels), ncomp)
    return (np.array([r[0] for r in rows], float).reshape(-1, ncomp),
            np.array([r[1] for r in rows], np.int64).reshape(-1, nlabels))


def _ascii_rows(path, text, labels, ncomp):
    """The rows `(c1 ... cn) labels` of an ASCII particle list after its
    header, each vector with exactly ncomp components, their number the
    list's count and the list closed: (components, label strings) per row.
    A file cut off, a wrong count or a vector of another size stops."""
    body = re.sub(r"//[^\n]*", "", text)
    m = re.match(r"\s*(\d+)\s*\(", body)
    rows = re.findall(r"\(([-+0-9.eEnaifNAIF ]+)\)\s+(" + labels + r")",
                      body)
    if m is None or int(m.group(1)) != len(rows) \
            or not body.rstrip().endswith(")"):
        raise ValueError(f"{path}: {len(rows)} rows for the "
                         f"{m.group(1) if m else 'missing'} the list "
                         "announces (a file cut off?)")
    out = []
    for k, (vec, lab) in enumerate(rows):
        comps = vec.split()
        if len(comps) != ncomp:
            raise ValueError(f"{path}: row {k} has {len(comps)} components"
                             f" ({vec.strip()}), not {ncomp}")
        out.append((comps, lab.split()))
    return out


def append_particles(case, time, cloud, x, new):
    """Append len(x) particles at the Cartesian positions x to the written
    cloud `cloud` of `time`: every field file of the cloud gets the values
    of new (field name -> array) or zeros; the cloud is rewritten in the
    legacy positions form (located on reading: any `coordinates` file is
    removed and cloudProperties says `geometry positions`). Returns the
    number of particles that were there before. The cloud may have been
    written with or without the legacy positions file."""
    cdir = Path(case) / str(time) / "lagrangian" / cloud
    x0 = cloud_positions(case, time, cloud)
    n0, n = len(x0), len(x)
    loc = f"{time}/lagrangian/{cloud}"
    for f in sorted(cdir.iterdir()):
        if f.name in ("positions", "coordinates"):
            continue
        cls = field_class(f)
        old = read_lagrangian(f)
        vec = cls.startswith("vector")
        if not len(old):
            old = np.zeros((0, 3)) if vec else np.zeros(0)
        add = new.get(f.name, np.zeros((n, 3)) if vec else np.zeros(n))
        vals = np.concatenate((old, add))
        if vec:
            lines = ["(%.17g %.17g %.17g)" % tuple(r) for r in vals]
        elif cls.startswith("label"):
            lines = ["%d" % v for v in vals]
        else:
            lines = ["%.17g" % v for v in vals]
        write_foamfile(f, cls, loc, f.name,
                       f"{len(vals)}\n(\n" + "\n".join(lines) + "\n)")
    xs = np.concatenate((x0, x))
    write_foamfile(
        cdir / "positions", "Cloud<basicAgglomerateParcel>", loc,
        "positions", f"{len(xs)}\n(\n" + "\n".join(
            "(%.17g %.17g %.17g) -1" % tuple(r) for r in xs) + "\n)")
    (cdir / "coordinates").unlink(missing_ok=True)
    cp = (Path(case) / str(time) / "uniform/lagrangian" / cloud
          / "cloudProperties")
    cp.write_text(re.sub(r"geometry\s+\w+;", "geometry positions;",
                         cp.read_text()))
    rec = read_record(case, time, cloud)
    if rec is not None:
        prim = int(np.sum(new.get("nPrimary", np.ones(n))))
        write_record(case, time, cloud, rec["nParticles"] + n,
                     rec["nParticlesTotal"] + n,
                     rec["nPrimariesTotal"] + prim, rec["nProcs"],
                     rec["clouds"])
    return n0


def cloud_dir(case, time, cloud="kinematicCloud"):
    """The folder <case>/<time>/lagrangian/<cloud>."""
    return Path(case) / str(time) / "lagrangian" / cloud


def read_cloud(case, time, cloud="kinematicCloud", names=None):
    """The fields of a written cloud (default: every field file; the
    position files excepted) as a dict name -> numpy array; the Cartesian
    positions under 'positions' when the legacy file was written."""
    d = cloud_dir(case, time, cloud)
    if names is None:
        names = [f.name for f in sorted(d.iterdir())
                 if f.name not in ("positions", "coordinates")]
    out = {n: read_lagrangian(d / n) for n in names if (d / n).exists()}
    if (d / "positions").exists():
        out["positions"] = read_positions(d / "positions")
    sizes = {n: len(v) for n, v in out.items()}
    if len(set(sizes.values())) > 1:
        raise ValueError(f"{d}: fields of different lengths {sizes}")
    return out


def read_coordinates(path):
    """The barycentric `coordinates` file of a cloud (ASCII or binary):
    (coordinates (n, 4), celli, tetFacei, tetPti). Binary records are the
    particle's raw barycentric and three labels (particle::sizeofPosition),
    each followed by a newline."""
    b, lab = _particle_list(path, 4, 3)
    return b, lab[:, 0], lab[:, 1], lab[:, 2]


def cloud_positions(case, time, cloud="kinematicCloud"):
    """Cartesian positions of a written cloud: from the legacy `positions`
    file where one was written (InfoSwitch writeLagrangianPositions on),
    else from the barycentric `coordinates` and the case's mesh (a
    processor folder is a case of its own)."""
    d = cloud_dir(case, time, cloud)
    if (d / "positions").exists():
        return read_positions(d / "positions")
    b, cell, face, pt = read_coordinates(d / "coordinates")
    return Mesh(case).positions(b, cell, face, pt)
