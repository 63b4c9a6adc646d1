"""A restart refuses a time whose files disagree with what the cloud wrote
(clouds/hardSphereCloudState): particle files missing or cut off, the
cloud's uniform folder lost, a processor folder without its particles.
Each case is a written time of the agglomerating box gas with files
removed as a killed write or a careless hand would leave them; the
expectation is a fatal error naming what is missing, never a run that
continues with fewer particles, primaries or counters. The intact time
restarts (test_cloudReproducibility.test_restart_equals_continuous_run
checks that it continues exactly)."""

import re
import shutil

import pytest

from aggloTools import times
from aggloTools.boxcase import run_case
from aggloTools.runner import foam_bin, run
from cloudBoxCases import add_cloud, primaries_gas

def gas(case, decompose=(1, 1, 1)):
    """300 quartz primaries, periodic in x and z, walls in y, EAM: 40
    steps with agglomerates, written at steps 20 and 40 (no event log)."""
    return primaries_gas(case, log=False, decompose=decompose, write=20,
                      seed=13)


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


def test_fields_without_their_record_refused(written, case_dir):
    """The parcel's own fields without the record: the record was lost
    with its uniform folder (or never written). Refused by the solver and
    by the tools alike, whatever wrote the time: a record-less time cannot
    be told from a loss."""
    c = copy(written, case_dir)
    for f in c.glob("*/uniform/lagrangian/kinematicCloud/"
                    "hardSphereCloudState"):
        f.unlink()
    assert times.incomplete_time(c) == c / "0.004"
    fails_naming(restart(c), "hardSphereCloudState", "is missing",
                 "write_record")


@pytest.mark.parametrize("parallel", [0, 2])
def test_time_without_uniform_folder_refused(case_dir, foam_env, parallel):
    """The whole uniform folder of the time removed (its time index, the
    cloud's counters and record with it): refused, serial and on 2 ranks,
    instead of a restart at time index 0 that cuts the event log back."""
    c = gas(case_dir / "gas", decompose=(2, 1, 1) if parallel else (1, 1, 1))
    run_case(c, parallel=parallel)
    roots = sorted(c.glob("processor*")) if parallel else [c]
    for root in roots:
        shutil.rmtree(root / "0.004" / "uniform")
    fails_naming(restart(c, parallel=parallel), "0.004",
                 "hardSphereCloudState", "is missing")


def two_clouds(case):
    """The gas with a second cloud 'second' (the same particles and
    settings), both listed in constant/cloudProperties."""
    gas(case)
    return add_cloud(case, "second")


@pytest.fixture(scope="module")
def written_two(tmp_path_factory, foam_env):
    """A serial two-cloud run to 0.004, each cloud's record naming both."""
    case = two_clouds(tmp_path_factory.mktemp("restartRecord2") / "gas")
    run_case(case)
    for cloud in ("kinematicCloud", "second"):
        rec = (case / "0.004" / "uniform" / "lagrangian" / cloud
               / "hardSphereCloudState").read_text()
        assert re.search(r"clouds\s+2\s*\(\s*kinematicCloud\s+second\s*\)",
                         rec) and re.search(r"complete\s+true;", rec), rec
    return case


def test_two_clouds_intact_restart(written_two, case_dir):
    c = case_dir / "gas"
    shutil.copytree(written_two, c)
    res = restart(c)
    assert res.returncode == 0, res.stdout[-2000:]


def test_cut_off_write_of_the_second_cloud(written_two, case_dir):
    """A write cut off while the second cloud writes: the first cloud and
    the fluid complete, the second's files missing, its record as the
    solver writes it when the write begins. Refused, by the solver (not
    read as an empty cloud) and by the tools."""
    c = case_dir / "gas"
    shutil.copytree(written_two, c)
    shutil.rmtree(c / "0.004" / "lagrangian" / "second")
    rec = c / "0.004" / "uniform" / "lagrangian" / "second" / \
        "hardSphereCloudState"
    text = re.sub(r"complete\s+true;", "complete false;", rec.read_text())
    rec.write_text("\n".join(l for l in text.splitlines()
                             if not l.startswith(("nP", "nProcs"))) + "\n")
    assert times.incomplete_time(c) == c / "0.004"
    fails_naming(restart(c), "second", "began but did not end")


def test_second_cloud_never_written(written_two, case_dir):
    """The second cloud's files and record all missing (its write never
    began, or removed by hand): the first cloud's record names it, so the
    time is refused instead of read with the second cloud empty."""
    c = case_dir / "gas"
    shutil.copytree(written_two, c)
    shutil.rmtree(c / "0.004" / "lagrangian" / "second")
    shutil.rmtree(c / "0.004" / "uniform" / "lagrangian" / "second")
    assert times.incomplete_time(c) == c / "0.004"
    fails_naming(restart(c), "second", "names this cloud")


def test_write_that_failed_is_refused(written_two, case_dir):
    """A write of the second cloud that failed (its particle folder cannot
    be made: a file is in its way; OpenFOAM's write fails silently and the
    run ends with exit status 0): the restart from that time is refused,
    by the solver and by the tools, instead of continuing without the
    second cloud's particles."""
    c = case_dir / "gas"
    shutil.copytree(written_two, c)
    blocked = c / "0.006" / "lagrangian" / "second"
    blocked.parent.mkdir(parents=True)
    blocked.write_text("in the way\n")
    for entry, value in (("startFrom", "startTime"), ("startTime", "0.004")):
        run([foam_bin("foamDictionary"), "-entry", entry, "-set", value,
             "system/controlDict"], c, "log.foamDictionary")
    res = restart(c)
    assert res.returncode == 0, res.stdout[-2000:]
    blocked.unlink()
    assert times.incomplete_time(c) == c / "0.006"
    for entry, value in (("startFrom", "latestTime"), ("endTime", "0.008")):
        run([foam_bin("foamDictionary"), "-entry", entry, "-set", value,
             "system/controlDict"], c, "log.foamDictionary")
    res = run([foam_bin("aggloPimpleFoam")], c, "log.again", check=False)
    fails_naming(res, "second", "particles read, but", "0.006")
