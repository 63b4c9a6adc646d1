#!/usr/bin/env python3
"""Case-file I/O of aggloTools against foamlib (the maintained OpenFOAM
file library on PyPI), on the sizes of the issue: a 1e6-particle cloud
(ASCII and binary lagrangian fields, the legacy positions file) and a
128^3 volume vector field (ASCII and binary), read and written. Prints
the seconds of each and the ratio foamlib/aggloTools (below 1: foamlib is
faster), and whether both give the exact numbers.

    .venv/bin/pip install foamlib==1.7.10     # optional, not a dependency
    .venv/bin/python bench/caseFileIO.py [N [CELLS]]

Without foamlib only aggloTools is timed. About 3 minutes with foamlib
(its legacy positions read is stopped after 300 s); files under
bench/runs/caseFileIO (about 0.4 GB). The figures of the decision:
bench/results/caseFileIO.txt."""

import argparse
import shutil
import signal
import sys
import time

import numpy as np

from aggloTools import cloud, fields, foamfile
from aggloTools.runner import project_dir

try:
    import foamlib
except ImportError:
    foamlib = None

OUT = project_dir() / "bench" / "runs" / "caseFileIO"
LIMIT = 300         # seconds for one foamlib operation


class TimeOut(Exception):
    pass


def _alarm(*_):
    raise TimeOut()


def timed(f):
    """(seconds, result) of f(), or (None, reason) if it raised or ran
    past LIMIT seconds."""
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(LIMIT)
    t = time.perf_counter()
    try:
        r = f()
    except TimeOut:
        return None, f"stopped after {LIMIT} s"
    except Exception as e:          # report, go on with the next one
        return None, f"{type(e).__name__}: {str(e)[:60]}"
    finally:
        signal.alarm(0)
    return time.perf_counter() - t, r


def binary_file(path, cls, a, dtype):
    """An OpenFOAM binary list file (the layout the solver writes)."""
    a = np.ascontiguousarray(a, dtype)
    head = ("FoamFile\n{\n    version 2.0;\n    format binary;\n"
            '    arch "LSB;label=32;scalar=64";\n'
            f"    class {cls};\n    location \"0\";\n"
            f"    object {path.name};\n}}\n\n")
    path.write_bytes(head.encode() + f"{len(a)}\n(".encode() + a.tobytes()
                     + b")\n")


def volume_file(path, fmt, V):
    head = ("FoamFile\n{\n    version 2.0;\n"
            f"    format {fmt};\n"
            + ('    arch "LSB;label=32;scalar=64";\n' if fmt == "binary"
               else "")
            + "    class volVectorField;\n    location \"0\";\n"
              "    object U;\n}\n\ndimensions [0 1 -1 0 0 0 0];\n\n")
    if fmt == "binary":
        data = (f"internalField nonuniform List<vector> {len(V)}\n("
                .encode() + V.tobytes() + b")\n;\n")
    else:
        data = (f"internalField nonuniform List<vector>\n{len(V)}\n(\n"
                + ("(%.17g %.17g %.17g)\n" * len(V))
                % tuple(V.ravel().tolist()) + ")\n;\n").encode()
    path.write_bytes(head.encode() + data + b"\nboundaryField\n{\n"
                     b"    walls { type noSlip; }\n}\n")


def main():
    ap = argparse.ArgumentParser(
        prog="caseFileIO.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("N", nargs="?", type=float, default=1e6,
                    help="particles (default 1e6)")
    ap.add_argument("CELLS", nargs="?", type=int, default=128,
                    help="cells per direction of the field (default 128)")
    a = ap.parse_args()
    N, M = int(a.N), a.CELLS
    if OUT.exists():
        shutil.rmtree(OUT)
    OUT.mkdir(parents=True)
    rng = np.random.default_rng(1)
    x, U = rng.random((N, 3)), rng.standard_normal((N, 3))
    d, V = rng.random(N) * 1e-5, rng.standard_normal((M**3, 3))
    cloud.write_cloud(OUT / "case", x, d, 2500.0, U=U)
    C = OUT / "case/0/lagrangian/kinematicCloud"
    (OUT / "bin").mkdir()
    binary_file(OUT / "bin/d", "scalarField", d, "<f8")
    binary_file(OUT / "bin/U", "vectorField", U, "<f8")
    volume_file(OUT / "Uascii", "ascii", V)
    volume_file(OUT / "Ubinary", "binary", V)
    uniform = OUT / "Uuniform"
    uniform.write_text((OUT / "Uascii").read_text().split(
        "internalField")[0] + "internalField uniform (0 0 0);\n"
        "boundaryField\n{\n    walls { type noSlip; }\n}\n")

    def fl_field(path):
        return foamlib.FoamFile(path)[None]

    def fl_write(path, a, cls):
        f = foamlib.FoamFile(path)
        f.path.write_text("")
        with f:
            f.format, f.class_ = "ascii", cls
            f.location, f.object_ = '"0"', path.name
            f[None] = a

    def ours_write(path, a, cls):
        foamfile.write_foamfile(path, cls, "0", path.name,
                                foamfile.list_body(a, "%.17g"))

    def set_ours(path, a):
        shutil.copy(uniform, path)
        fields.set_internal_vector_field(path, a)

    def set_fl(path, a):
        shutil.copy(OUT / "Uascii", path)
        foamlib.FoamFieldFile(path).internal_field = a

    cases = [
        ("read ascii scalar field (d)", V, d,
         lambda: cloud.read_lagrangian(C / "d"), lambda: fl_field(C / "d")),
        ("read ascii vector field (U)", None, U,
         lambda: cloud.read_lagrangian(C / "U"), lambda: fl_field(C / "U")),
        ("read legacy positions", None, x,
         lambda: cloud.read_positions(C / "positions"),
         lambda: np.array([r[0] for r in fl_field(C / "positions")])),
        ("read binary scalar field", None, d,
         lambda: cloud.read_lagrangian(OUT / "bin/d"),
         lambda: fl_field(OUT / "bin/d")),
        ("read binary vector field", None, U,
         lambda: cloud.read_lagrangian(OUT / "bin/U"),
         lambda: fl_field(OUT / "bin/U")),
        (f"read ascii volVectorField {M}^3", None, V,
         lambda: fields.read_internal(OUT / "Uascii"),
         lambda: foamlib.FoamFieldFile(OUT / "Uascii").internal_field),
        (f"read binary volVectorField {M}^3", None, V,
         lambda: fields.read_internal(OUT / "Ubinary"),
         lambda: foamlib.FoamFieldFile(OUT / "Ubinary").internal_field),
    ]
    print(f"case-file I/O, N = {N:g} particles, {M}^3 cells"
          + ("" if foamlib else " (foamlib not installed: aggloTools only)"))
    print(f"{'operation':36s} {'aggloTools':>11s} {'foamlib':>11s}"
          f" {'ratio':>7s}  exact (ours/foamlib)")

    def report(name, ta, oka, tb, okb):
        ratio = f"{tb / ta:7.2f}" if ta and isinstance(tb, float) else \
            "      -"
        fb = f"{tb:9.2f} s" if isinstance(tb, float) else f"{'-':>11s}"
        print(f"{name:36s} {ta:9.2f} s {fb} {ratio}  {oka}/{okb}")

    for name, _, ref, ours, theirs in cases:
        ta, ra = timed(ours)
        oka = ta is not None and np.array_equal(
            np.asarray(ra, float).reshape(ref.shape), ref)
        tb, okb = None, "n/a"
        if foamlib:
            tb, rb = timed(theirs)
            okb = (np.array_equal(np.asarray(rb, float).reshape(ref.shape),
                                  ref) if tb is not None else rb)
        report(name, ta, oka, tb, okb)
    w = OUT / "written"
    w.mkdir()
    for name, a, cls in (("write ascii scalar field", d, "scalarField"),
                         ("write ascii vector field", U, "vectorField")):
        ta, _ = timed(lambda: ours_write(w / f"ours{cls}", a, cls))
        oka = np.array_equal(cloud.read_lagrangian(w / f"ours{cls}"), a)
        tb, okb = None, "n/a"
        if foamlib:
            tb, _ = timed(lambda: fl_write(w / f"fl{cls}", a, cls))
            okb = tb is not None and np.array_equal(
                cloud.read_lagrangian(w / f"fl{cls}"), a)
        report(name, ta, oka, tb, okb)
    ta, _ = timed(lambda: set_ours(w / "Uours", 2 * V))
    oka = np.array_equal(fields.read_internal(w / "Uours"), 2 * V)
    tb, okb = None, "n/a"
    if foamlib:
        tb, _ = timed(lambda: set_fl(w / "Ufl", 2 * V))
        okb = tb is not None and np.array_equal(
            fields.read_internal(w / "Ufl"), 2 * V)
    report(f"write ascii volVectorField {M}^3", ta, oka, tb, okb)
    return 0


if __name__ == "__main__":
    sys.exit(main())
