"""Deposition on curved walls of a mesh that is not Cartesian (the O-grid
pipe of aggloTools.bendmesh), fluid at rest, no forces, so particles fly
straight: aimed from the axis of the straight pipe, each deposits on the
face its line crosses; launched along the centreline's tangent in the
bend, on the outer wall face where the line leaves the torus (hand
geometry); on two ranks that cut the pipe lengthwise (hierarchical:
scotch is a dummy library in Debian's v1912) the same parcels deposit on
the same faces with the same mass."""

import math
import re

import numpy as np

from aggloTools import bendmesh, boxcase
from aggloTools.cloud import read_mass_balance
from aggloTools.fields import read_patch
from aggloTools.mesh import Mesh
from aggloTools.times import last_time

D = 12e-6
M1 = 2200 * math.pi / 6 * D ** 3
STICK = boxcase.kernel(walls={'".*"': {"wallModel": "stick"}})
ESCAPE = {"patchInteractionModel": "localInteraction",
          "localInteractionCoeffs": {
              "patches": '( "(inlet|outlet)" { type escape; } '
                         '".*Pipe|bend" { type rebound; e 1; mu 0; } )'}}


def faces_of(case, patch):
    text = (case / "constant/polyMesh/boundary").read_text()
    m = re.search(r"\b" + patch + r"\s*\{[^}]*?nFaces\s+(\d+);[^}]*?"
                  r"startFace\s+(\d+);", text)
    n, start = int(m.group(1)), int(m.group(2))
    Cf, _ = Mesh(case).face_centres_and_areas()
    return Cf[start:start + n]


def deposits(case, patch):
    t = last_time(case)
    n = len(faces_of(case, patch))
    return read_patch(case / t / "kinematicCloud:depositedMass", patch, n)


def run(case, g, particles, ranks=0, **kw):
    """ranks 2: the pipe cut along y = 0 (through every cross-section)."""
    bendmesh.pipe_case(case, g, particles=particles, hard_sphere=STICK,
                       cloud={"subModels": ESCAPE},
                       ranks=(1, 2, 1) if ranks == 2 else (1, 1, 1), **kw)
    bendmesh.run_pipe_case(case, g, parallel=ranks)
    return case


def test_deposit_where_aimed_in_the_pipe(case_dir, foam_env):
    """Four primaries from the axis of a straight pipe (a = 1 mm) at
    0.5 m/s in four directions: each deposits on the wall face its line
    crosses, nothing else is deposited."""
    g = bendmesh.Geometry(a=1e-3, R=0, L_in=2e-3, L_out=2e-3)
    zc, v = 1.7e-3, 0.5
    angles = np.radians([10, 100, 200, 290])
    parts = [dict(x=(0, 0, zc), U=(v * math.cos(t), v * math.sin(t), 0),
                  id=i) for i, t in enumerate(angles)]
    run(case_dir, g, parts, n=8, n_ring=4, n_axial=(10, 10), dt=1e-4,
        end_time=3e-3, write_interval=30)
    bal = read_mass_balance(case_dir, last_time(case_dir))
    assert set(bal["deposited"]) == {"inletPipe"}
    assert bal["deposited"]["inletPipe"]["nParcels"] == 4
    Cf = faces_of(case_dir, "inletPipe")
    hits = np.array([(g.a * math.cos(t), g.a * math.sin(t), zc)
                     for t in angles])
    expected = sorted(int(np.argmin(np.linalg.norm(Cf - h, axis=1)))
                      for h in hits)
    m = deposits(case_dir, "inletPipe")
    assert sorted(np.nonzero(m)[0]) == expected
    np.testing.assert_allclose(m[expected], M1, rtol=1e-14)


def test_deposit_on_the_outer_wall_of_the_bend(case_dir, foam_env):
    """A primary on the bend's centreline at 30 degrees, launched along
    the tangent: it leaves the torus where the distance from the bend's
    axis reaches R + a, after s = sqrt((R + a)^2 - R^2), and deposits on
    the bend's wall face there."""
    g = bendmesh.Geometry(a=1e-3, R=5e-3, L_in=2e-3, L_out=2e-3)
    phi = math.radians(30)
    c = np.array([g.R * (1 - math.cos(phi)), 0, g.L_in + g.R * math.sin(phi)])
    t = np.array([math.sin(phi), 0, math.cos(phi)])
    parts = [dict(x=tuple(c), U=tuple(0.5 * t), id=0)]
    run(case_dir, g, parts, n=8, n_ring=4, n_axial=(6, 24, 6), dt=1e-4,
        end_time=1e-2, write_interval=100)
    bal = read_mass_balance(case_dir, last_time(case_dir))
    assert set(bal["deposited"]) == {"bend"}
    s = math.sqrt((g.R + g.a) ** 2 - g.R ** 2)
    exit_point = c + s * t
    Cf = faces_of(case_dir, "bend")
    face = int(np.argmin(np.linalg.norm(Cf - exit_point, axis=1)))
    m = deposits(case_dir, "bend")
    assert list(np.nonzero(m)[0]) == [face]


def test_two_ranks_deposit_alike(case_dir, foam_env):
    """60 primaries in random directions from random places in the bend:
    serial and 2 ranks (the pipe cut along y = 0) deposit the same
    parcels on the same faces."""
    g = bendmesh.Geometry(a=1e-3, R=5e-3, L_in=2e-3, L_out=2e-3)
    rng = np.random.default_rng(4)
    parts = []
    for i in range(60):
        phi = rng.uniform(0.1, 1.4)
        r, th = 0.6 * g.a * math.sqrt(rng.uniform()), rng.uniform(0, 6.28)
        x = bendmesh.map_to_bend(np.array([[r * math.cos(th),
                                            r * math.sin(th),
                                            g.L_in + g.R * phi]]), g)[0]
        u = rng.normal(size=3)
        parts.append(dict(x=tuple(x), U=tuple(0.4 * u / np.linalg.norm(u)),
                          id=i))
    runs = {}
    for name, ranks in (("serial", 0), ("ranks", 2)):
        runs[name] = run(case_dir / name, g, parts, ranks=ranks, n=8,
                         n_ring=4, n_axial=(6, 24, 6), dt=1e-4,
                         end_time=1e-2, write_interval=100)
    a = read_mass_balance(runs["serial"], "0.01")
    b = read_mass_balance(runs["ranks"], "0.01")
    assert sum(v["nParcels"] for v in a["deposited"].values()) > 30
    for way in ("deposited", "escaped"):
        assert a[way].keys() == b[way].keys()
        for patch, v in a[way].items():
            assert v["nParcels"] == b[way][patch]["nParcels"]
    for patch in a["deposited"]:
        np.testing.assert_allclose(deposits(runs["ranks"], patch),
                                   deposits(runs["serial"], patch),
                                   rtol=1e-14, atol=0)
