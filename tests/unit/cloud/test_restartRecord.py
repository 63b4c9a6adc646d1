"""A restart refuses a time whose files disagree with what the cloud wrote
(clouds/hardSphereCloudState): particle files missing or cut off, the
cloud's uniform folder lost, a processor folder without its particles.
Each case is a written time of the agglomerating box gas with files
removed as a killed write or a careless hand would leave them; the
expectation is a fatal error naming what is missing, never a run that
continues with fewer particles, primaries or counters. The intact time
restarts (test_hardSphereCloud.test_restart_equals_continuous_run checks
that it continues exactly)."""

import re
import shutil

import numpy as np
import pytest

from aggloTools import placement, times
from aggloTools.boxcase import box_case, run_case
from aggloTools.runner import foam_bin, run

D, LB, N = 12e-6, 2e-4, 300


def gas(case, decompose=(1, 1, 1)):
    """300 quartz primaries, periodic in x and z, walls in y, EAM: 40
    steps with agglomerates, written at steps 20 and 40."""
    rng = np.random.default_rng(13)
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0),
                         (LB, LB - 0.6 * D, LB), (LB, None, LB), rng)
    U = rng.normal(0, 1.5e-3, (N, 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    box_case(case, L=(LB,) * 3, n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=4e-3, write_interval=20, agglomeration="EAM",
             decompose=decompose)
    return case


def restart(case, parallel=0):
    """Continue the run to 0.006 from its latest time; the result."""
    run([foam_bin("foamDictionary"), "-entry", "endTime", "-set", "0.006",
         "system/controlDict"], case, "log.foamDictionary")
    cmd = [foam_bin("aggloPimpleFoam")]
    if parallel:
        cmd = ["mpirun", "-np", str(parallel), "--oversubscribe"] + cmd \
            + ["-parallel"]
    return run(cmd, case, "log.restart", check=False)


@pytest.fixture(scope="module")
def written(tmp_path_factory, foam_env):
    """A serial run to 0.004 (kept; each test works on a copy)."""
    case = gas(tmp_path_factory.mktemp("restartRecord") / "gas")
    run_case(case)
    nagg = (case / "0.004" / "uniform" / "lagrangian" / "kinematicCloud"
            / "hardSphereCloudState").read_text()
    assert re.search(r"nPrimariesTotal\s+300;", nagg) and not re.search(
        r"nParticlesTotal\s+300;", nagg), "the gas must hold agglomerates"
    return case


def copy(written, case_dir):
    c = case_dir / "gas"
    shutil.copytree(written, c)
    return c


def fails_naming(res, *words):
    assert res.returncode != 0, res.stdout[-2000:]
    for w in words:
        assert w in res.stdout, (w, res.stdout[-2000:])


def test_intact_time_restarts(written, case_dir):
    res = restart(copy(written, case_dir))
    assert res.returncode == 0, res.stdout[-2000:]


def test_lagrangian_folder_missing(written, case_dir):
    c = copy(written, case_dir)
    shutil.rmtree(c / "0.004" / "lagrangian")
    fails_naming(restart(c), "particles read, but", "were written",
                 "0.004")


@pytest.mark.parametrize("field", ["nPrimary", "omega", "lastPartnerId",
                                   "lastContactTime"])
def test_own_field_missing(written, case_dir, field):
    c = copy(written, case_dir)
    (c / "0.004" / "lagrangian" / "kinematicCloud" / field).unlink()
    fails_naming(restart(c), field, "are missing")


def test_uniform_state_missing(written, case_dir):
    c = copy(written, case_dir)
    shutil.rmtree(c / "0.004" / "uniform" / "lagrangian")
    fails_naming(restart(c), "hardSphereCloudState", "is missing")


def test_incomplete_time_found_by_the_tools(written, case_dir):
    """aggloTools.times finds the same cut-off write, also when it is the
    first one after the initial time (the tutorials set it aside)."""
    c = copy(written, case_dir)
    shutil.rmtree(c / "0.004")
    assert times.incomplete_time(c) is None
    (c / "0.002" / "lagrangian" / "kinematicCloud" / "nPrimary").unlink()
    assert times.incomplete_time(c) == c / "0.002"


def test_processor_without_particles(case_dir, foam_env):
    c = gas(case_dir / "gas", decompose=(2, 1, 1))
    run_case(c, parallel=2)
    # one processor folder without its particles: fewer in all than written
    shutil.rmtree(c / "processor1" / "0.004" / "lagrangian")
    fails_naming(restart(c, parallel=2), "particles read, but")


def test_time_of_a_version_without_the_record(written, case_dir):
    """A time written before the record existed (the cloud's uniform
    folder there, the record not) restarts, with a warning."""
    c = copy(written, case_dir)
    for f in c.glob("*/uniform/lagrangian/kinematicCloud/"
                    "hardSphereCloudState"):
        f.unlink()
    assert times.incomplete_time(c) is None
    res = restart(c)
    assert res.returncode == 0, res.stdout[-2000:]
    assert "written by a version without it" in res.stdout
