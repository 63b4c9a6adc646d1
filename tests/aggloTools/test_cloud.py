"""aggloTools' readers and writers on real solver output: a box case whose
cloud aggloTools writes is run by aggloPimpleFoam twice, writing ASCII and
binary (mesh, fields, clouds in both position forms); every reader gives
the same numbers from both, the written input reads back exactly, the
barycentric coordinates located in the mesh give the positions the solver
wrote (serially and in each processor folder), the mesh's cell centres
are OpenFOAM's, and stats.dat of a restarted run reads as the
uninterrupted run."""

import shutil

import numpy as np
import pytest

from aggloTools import boxcase, cloud, fields, stats, times
from aggloTools.mesh import Mesh
from aggloTools.runner import foam_bin, run

L = (1e-3, 8e-4, 6e-4)
DT, STEPS = 1e-4, 3


def particles(n=40, seed=3):
    rng = np.random.default_rng(seed)
    x = np.random.default_rng(seed).uniform((5e-5,) * 3,
                                            np.array(L) - 5e-5, (n, 3))
    return [dict(x=tuple(p), U=tuple(rng.normal(0, 0.05, 3)),
                 omega=tuple(rng.normal(0, 100, 3)),
                 d=float(rng.uniform(8e-6, 20e-6)), rho=2200.0,
                 nPrimary=int(rng.integers(1, 5)), id=int(i) + 7)
            for i, p in enumerate(x)]


def make(case, fmt, decompose=(1, 1, 1)):
    boxcase.box_case(case, L=L, n=(5, 4, 3), particles=particles(),
                     kinds=("cyclic", "wall", "cyclic"), dt=DT,
                     end_time=STEPS * DT, write_interval=1,
                     write_format=fmt, hard_sphere=boxcase.kernel("EAM"),
                     decompose=decompose)
    return case


@pytest.fixture(scope="module")
def runs(tmp_path_factory, foam_env):
    base = tmp_path_factory.mktemp("aggloToolsCloud")
    out = {}
    for fmt in ("ascii", "binary"):
        c = make(base / fmt, fmt)
        boxcase.run_case(c)
        run([foam_bin("postProcess"), "-func", "writeCellCentres",
             "-latestTime"], c, "log.writeCellCentres")
        out[fmt] = c
    return out


def test_written_input_reads_back_exactly(tmp_path):
    P = particles()
    c = boxcase.box_case(tmp_path / "c", L=L, particles=P)
    st = cloud.read_cloud(c, "0")
    assert np.array_equal(st["positions"], [p["x"] for p in P])
    assert np.array_equal(st["U"], [p["U"] for p in P])
    assert np.array_equal(st["omega"], [p["omega"] for p in P])
    assert np.array_equal(st["d"], [p["d"] for p in P])
    assert np.array_equal(st["nPrimary"], [p["nPrimary"] for p in P])
    assert np.array_equal(st["origId"], [p["id"] for p in P])
    # constant fields are written as uniform lists and read as arrays
    assert b"40{2200}" in (cloud.cloud_dir(c, "0") / "rho").read_bytes()
    assert np.array_equal(st["rho"], np.full(len(P), 2200.0))


def test_ascii_and_binary_output_read_the_same(runs):
    t = times.last_time(runs["ascii"])
    assert t == times.last_time(runs["binary"])
    a, b = (cloud.cloud_dir(runs[f], t) for f in ("ascii", "binary"))
    assert b"format      binary" in (b / "U").read_bytes()[:1000]
    names = sorted(f.name for f in a.iterdir() if f.name != "coordinates")
    assert {"U", "omega", "d", "nPrimary", "origId", "positions"} <= set(names)
    for name in names:
        reader = cloud.read_positions if name == "positions" \
            else cloud.read_lagrangian
        x, y = reader(a / name), reader(b / name)
        assert x.shape == y.shape and len(x) == 40 - \
            stats.stats_rows(runs["ascii"])[-1]["nAgg"], name
        assert np.array_equal(x, y), name
    ca, cb = cloud.read_coordinates(a / "coordinates"), \
        cloud.read_coordinates(b / "coordinates")
    for u, v in zip(ca, cb):
        assert np.array_equal(u, v)
    for f in ("U", "p", "C"):
        assert np.array_equal(fields.read_internal(runs["ascii"] / t / f),
                              fields.read_internal(runs["binary"] / t / f))
    # the binary run's mesh was written in binary too
    faces = runs["binary"] / "constant/polyMesh/faces"
    assert b"faceCompactList" in faces.read_bytes()[:1000]


@pytest.mark.parametrize("fmt", ["ascii", "binary"])
def test_cell_centres_are_openfoams(runs, fmt):
    c = runs[fmt]
    C = fields.read_internal(c / times.last_time(c) / "C")
    mine = Mesh(c).cell_centres()
    assert mine.shape == C.shape == (60, 3)
    np.testing.assert_allclose(mine, C, rtol=0, atol=1e-15 * max(L))


@pytest.mark.parametrize("fmt", ["ascii", "binary"])
def test_coordinates_locate_the_written_positions(runs, fmt):
    c = runs[fmt]
    t = times.last_time(c)
    d = cloud.cloud_dir(c, t)
    x = cloud.read_positions(d / "positions")
    b, cell, face, pt = cloud.read_coordinates(d / "coordinates")
    assert np.allclose(b.sum(axis=1), 1, rtol=0, atol=1e-12)
    np.testing.assert_allclose(Mesh(c).positions(b, cell, face, pt), x,
                               rtol=0, atol=1e-12 * max(L))
    # without the legacy file the positions come from the coordinates
    copy = c.parent / f"{fmt}NoPositions"
    shutil.copytree(c, copy)
    (cloud.cloud_dir(copy, t) / "positions").unlink()
    np.testing.assert_allclose(cloud.cloud_positions(copy, t), x, rtol=0,
                               atol=1e-12 * max(L))


def test_particles_appended_to_a_cloud_without_positions(runs, tmp_path):
    """A cloud written without the legacy positions file (writePositions
    off): appended particles follow the particles located from the
    barycentric coordinates, which become a positions file."""
    c = tmp_path / "case"
    shutil.copytree(runs["binary"], c)
    t = times.last_time(c)
    d = cloud.cloud_dir(c, t)
    x = cloud.read_positions(d / "positions")
    (d / "positions").unlink()
    new = np.array([(1e-4, 2e-4, 3e-4)])
    assert cloud.append_particles(c, t, "kinematicCloud", new,
                                  {"d": np.array([1e-5])}) == len(x)
    np.testing.assert_allclose(cloud.read_positions(d / "positions"),
                               np.vstack((x, new)), rtol=0,
                               atol=1e-12 * max(L))
    assert cloud.read_lagrangian(d / "d")[-1] == 1e-5


def test_coordinates_in_processor_folders(tmp_path, foam_env):
    """Each processor folder locates its particles in its own mesh: the
    positions its legacy file holds."""
    c = make(tmp_path / "par", "binary", decompose=(2, 1, 1))
    boxcase.run_case(c, parallel=2, check=True)
    t = times.last_time(c / "processor0")
    n = 0
    for p in sorted(c.glob("processor*")):
        x = cloud.read_positions(cloud.cloud_dir(p, t) / "positions")
        b, cell, face, pt = cloud.read_coordinates(
            cloud.cloud_dir(p, t) / "coordinates")
        np.testing.assert_allclose(Mesh(p).positions(b, cell, face, pt), x,
                                   rtol=0, atol=1e-12 * max(L))
        n += len(x)
    assert 0 < n <= 40


def test_stats_of_a_restarted_run(runs, tmp_path):
    """A restart from an earlier write starts a new stats.dat folder whose
    rows overlap the old one's; read_stats joins them (the later folder
    wins), giving the rows of the uninterrupted run."""
    src = runs["ascii"]
    c = tmp_path / "restart"
    shutil.copytree(src, c)
    tdirs = times.time_dirs(c)
    shutil.rmtree(tdirs[-1])
    shutil.rmtree(tdirs[-2])
    run([foam_bin("aggloPimpleFoam")], c, "log.aggloPimpleFoam.restart")
    folders = sorted(f.parent.name for f in (
        c / "postProcessing/kinematicCloudHardSphere").glob("*/stats.dat"))
    assert folders == ["0", "0.0001"]
    a, b = stats.read_stats(src), stats.read_stats(c)
    assert len(b["Time"]) == STEPS and np.all(np.diff(b["Time"]) > 0)
    for col in a:
        np.testing.assert_allclose(b[col], a[col], rtol=1e-12, atol=0,
                                   err_msg=col)
