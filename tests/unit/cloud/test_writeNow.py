"""A run asked to write now and stop (OpenFOAM's stopAtWriteNowSignal, as
the tutorials' drivers start the solver, or stopAt writeNow) writes at
the end of the first step whose time index is a multiple of the clouds'
stop interval, the least common multiple of the start positions' 20
steps and cellOrderInterval (aggloPimpleFoam's writeNowStep.H), and,
continued from there, ends as the uninterrupted run does: every written
field, the cloud's record and statistics state (its profiles add over
the parcels in list order), the last step's profiles and the statistics
rows, byte for byte. A cloud that never sorts (interval 0) stops after
20 steps; two clouds stop at a step of both. The agglomerating box gas
(cloudBoxCases) with profiles across the walls, 100 steps, serial and on
2 ranks."""

import math
import signal
import subprocess
import time

import pytest

from aggloTools.boxcase import run_case
from aggloTools.foamfile import edit
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows
from aggloTools.times import time_dirs
from cloudBoxCases import add_cloud, agglomerating_gas

DT = 1e-4
STEPS = 100


def cloud(interval):
    return {"solution": {"cellOrderInterval": interval},
            "cloudFunctions": {"hardSphereStatistics": {
                "type": "hardSphereStatistics", "profiles": True,
                "direction": (0, 1, 0), "nBins": 6}}}


def solver(case, log, *args):
    return subprocess.run([foam_bin("aggloPimpleFoam"), *args], cwd=case,
                          stdout=open(case / log, "w"),
                          stderr=subprocess.STDOUT).returncode


def files(case, t):
    """Every file of the written time t and its statistics output, by
    path (the time value, read back on restart, is compared apart)."""
    out = {}
    for root in (case / t, case / "postProcessing"):
        for f in sorted(root.rglob("*")):
            if f.is_file() and (root == case / t or t in f.parts):
                out[str(f.relative_to(case))] = f.read_bytes()
    return out


def stopped_case(tmp, interval, name, ranks=0):
    c = tmp / name
    agglomerating_gas(c, STEPS * DT, 50, cloud=cloud(interval),
                      decompose=(ranks or 1, 1, 1))
    edit(c / "system/controlDict", "stopAt endTime;", "stopAt writeNow;")
    run_case(c, parallel=ranks)
    return c


@pytest.mark.parametrize("ranks", [0, 2])
def test_stopped_run_continues_exactly(ranks, case_dir, foam_env):
    """Serial, and on 2 ranks (the request reduced over the ranks; the
    run continued from the processor folders, then reconstructed)."""
    whole = case_dir / "whole"
    agglomerating_gas(whole, STEPS * DT, 50, cloud=cloud(8),
                      decompose=(ranks or 1, 1, 1))
    run_case(whole, parallel=ranks)

    part = stopped_case(case_dir, 8, "part", ranks)
    log = (part / "log.aggloPimpleFoam").read_text()
    assert "writing at the end of step 40 and stopping" in log
    written = [t.name for t in time_dirs(part)]
    assert [float(t) for t in written] == pytest.approx([0, 40 * DT],
                                                        rel=1e-12)
    edit(part / "system/controlDict", "stopAt writeNow;", "stopAt endTime;")
    if ranks:
        run(["mpirun", "-np", str(ranks), "--oversubscribe",
             foam_bin("aggloPimpleFoam"), "-parallel"], part, "log.restart")
        run([foam_bin("reconstructPar"), "-latestTime"], part,
            "log.reconstructPar.restart")
    else:
        assert solver(part, "log.restart") == 0

    end = time_dirs(whole)[-1].name
    assert time_dirs(part)[-1].name == end
    a, b = files(whole, end), files(part, end)
    assert a.keys() == b.keys() and len(a) > 10
    differ = [k for k in a if a[k] != b[k]]
    assert differ == [], differ
    # the statistics rows of every step after the stop
    ra = [r for r in stats_rows(whole) if r["Time"] > 40.5 * DT]
    rb = [r for r in stats_rows(part) if r["Time"] > 40.5 * DT]
    assert len(ra) == STEPS - 40 and ra == rb
    assert ra[-1]["nCol"] > 5 and ra[-1]["nAgg"] > 0


def test_cloud_that_never_sorts_stops_after_20_steps(case_dir, foam_env):
    part = stopped_case(case_dir, 0, "never")
    assert [float(t.name) for t in time_dirs(part)] == \
        pytest.approx([0, 20 * DT], rel=1e-12)
    assert "writing at the end of step 20 and stopping" in \
        (part / "log.aggloPimpleFoam").read_text()


def test_signal_writes_and_stops(case_dir, foam_env):
    """stopAtWriteNowSignal as the drivers give it: SIGUSR2 writes a time
    after the signal at a multiple of the stop interval (140 steps with
    cellOrderInterval 7) and ends with End."""
    c = case_dir / "signal"
    agglomerating_gas(c, 4000 * DT, 4000, cloud=cloud(7))
    run([foam_bin("blockMesh")], c, "log.blockMesh")
    with open(c / "log.aggloPimpleFoam", "w") as out:
        proc = subprocess.Popen(
            [foam_bin("aggloPimpleFoam"), "-opt-switch",
             "stopAtWriteNowSignal=12"], cwd=c, stdout=out,
            stderr=subprocess.STDOUT)
        t0 = time.time()
        while "Time = 0.001" not in (c / "log.aggloPimpleFoam").read_text():
            assert proc.poll() is None and time.time() - t0 < 120
            time.sleep(0.05)
        proc.send_signal(signal.SIGUSR2)
        assert proc.wait(timeout=120) == 0
    log = (c / "log.aggloPimpleFoam").read_text()
    assert "setting up write and stop" in log and "\nEnd\n" in log
    last = time_dirs(c)[-1].name
    step = round(float(last) / DT)
    assert step % 140 == 0 and 10 <= step < 4000


def two_clouds(case, intervals):
    """The gas with a second cloud 'second' (the same particles), each
    cloud with its own cellOrderInterval, both in cloudProperties."""
    agglomerating_gas(case, 200 * DT, 200, cloud=cloud(intervals[0]))
    old = f"cellOrderInterval {intervals[0]};"

    def other_interval(text):
        assert text.count(old) == 1
        return text.replace(old, f"cellOrderInterval {intervals[1]};")
    return add_cloud(case, "second", other_interval)


def test_two_clouds_stop_at_a_step_of_both(case_dir, foam_env):
    """Two clouds with cellOrderInterval 8 and 12 (stop intervals 40 and
    60): the run stops after the first step both allow, their least
    common multiple 120, and continued from there ends as the
    uninterrupted run does."""
    period = math.lcm(20, 8, 20, 12)
    whole = two_clouds(case_dir / "whole", (8, 12))
    run_case(whole)

    part = two_clouds(case_dir / "part", (8, 12))
    edit(part / "system/controlDict", "stopAt endTime;", "stopAt writeNow;")
    run_case(part)
    log = (part / "log.aggloPimpleFoam").read_text()
    assert f"stop at the end of step {period} (a multiple of {period}:" \
        in log
    assert [float(t.name) for t in time_dirs(part)] == \
        pytest.approx([0, period * DT], rel=1e-12)
    edit(part / "system/controlDict", "stopAt writeNow;", "stopAt endTime;")
    assert solver(part, "log.restart") == 0

    end = time_dirs(whole)[-1].name
    assert time_dirs(part)[-1].name == end
    a, b = files(whole, end), files(part, end)
    assert any("second" in k for k in a) and len(a) > 20
    assert a.keys() == b.keys()
    differ = [k for k in a if a[k] != b[k]]
    assert differ == [], differ
