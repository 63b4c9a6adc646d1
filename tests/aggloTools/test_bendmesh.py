"""aggloTools.bendmesh: the O-grid pipe with a 90-degree bend. Every wall
point lies on the pipe's circle (straight parts) or on the torus (the
bend), to round-off; the volume is the cross-section polygon's area
times the centreline's length, within the chords' bound; checkMesh
passes; the patches are those named."""

import math
import re

import numpy as np
import pytest

from aggloTools import bendmesh
from aggloTools.mesh import Mesh
from aggloTools.runner import foam_bin, run

G = bendmesh.Geometry(a=2.5e-3, R=14e-3, L_in=10e-3, L_out=8e-3)


def patch_points(case, patch):
    text = (case / "constant/polyMesh/boundary").read_text()
    m = re.search(patch + r"\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+"
                  r"(\d+);", text)
    n, start = int(m.group(1)), int(m.group(2))
    mesh = Mesh(case)
    labels = np.unique(np.concatenate([mesh.face(i) for i in
                                       range(start, start + n)]))
    return mesh.points[labels], n


def distance_to_centreline(p, g):
    """The distance of points to the centreline of the bent pipe."""
    x, y, z = p.T
    d = np.empty(len(p))
    before = z <= g.L_in
    after = x >= g.R
    bend = ~before & ~after
    d[before] = np.hypot(x[before], y[before])
    d[after] = np.hypot(z[after] - (g.L_in + g.R), y[after])
    rho = np.hypot(x[bend] - g.R, z[bend] - g.L_in)
    d[bend] = np.hypot(rho - g.R, y[bend])
    return d


@pytest.fixture(scope="module")
def bent(tmp_path_factory, foam_env):
    case = tmp_path_factory.mktemp("bend") / "case"
    bendmesh.pipe_case(case, G, n=8, n_ring=4, n_axial=(10, 30, 8))
    run([foam_bin("blockMesh")], case, "log.blockMesh")
    bendmesh.bend_points(case, G)
    return case


def test_wall_points_on_the_pipe(bent):
    for patch in ("inletPipe", "bend", "outletPipe"):
        p, n = patch_points(bent, patch)
        assert n == 32 * {"inletPipe": 10, "bend": 30, "outletPipe": 8}[
            patch]
        np.testing.assert_allclose(distance_to_centreline(p, G), G.a,
                                   rtol=1e-12)


def test_volume_and_check_mesh(bent):
    res = run([foam_bin("checkMesh")], bent, "log.checkMesh")
    assert "Mesh OK." in res.stdout
    V = float(re.search(r"Total volume = (\S+)\.", res.stdout).group(1))
    polygon = 16 * G.a ** 2 * math.sin(2 * math.pi / 32)
    length = G.L_in + G.bend_length + G.L_out
    # the bend's axial edges are chords of 3 degrees: volume short by at
    # most (1 - sin(x)/x) with x the half-angle, about 1.2e-4
    assert V == pytest.approx(polygon * length, rel=3e-4)
    assert V < polygon * length * (1 + 1e-6)   # checkMesh prints 6 digits


def test_straight_pipe_is_unchanged(tmp_path, foam_env):
    """Without a bend, the points are blockMesh's."""
    g = bendmesh.Geometry(a=1e-3, R=0, L_in=4e-3, L_out=4e-3)
    p = np.random.default_rng(1).uniform(-1, 1, (50, 3))
    np.testing.assert_array_equal(bendmesh.map_to_bend(p, g), p)
    assert g.stations == (0.0, 4e-3, 8e-3)


def test_developed_inlet(tmp_path, foam_env):
    """The Poiseuille inflow at the inlet's face centres: its flux is the
    mean velocity times the inlet's area (to round-off), its peak within
    the midpoint rule's 2 % of 2 U, axial, 0 nowhere inside."""
    g = bendmesh.Geometry(a=2.5e-3, R=0, L_in=5e-3, L_out=5e-3)
    case = tmp_path / "case"
    bendmesh.pipe_case(case, g, n=8, n_ring=6, n_axial=(4, 4),
                       inlet_velocity=(0, 0, 3.0))
    run([foam_bin("blockMesh")], case, "log.blockMesh")
    Q = bendmesh.developed_inlet(case, g, 3.0)
    polygon = 16 * g.a ** 2 * math.sin(2 * math.pi / 32)
    assert Q == pytest.approx(3.0 * polygon, rel=1e-12)
    from aggloTools.fields import read_patch
    U = read_patch(case / "0" / "U", "inlet", 256)
    assert U[:, 2].max() == pytest.approx(6.0, rel=0.02)
    assert (U[:, :2] == 0).all() and U[:, 2].min() > 0
