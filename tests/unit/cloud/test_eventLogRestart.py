"""Restarts against what an event log holds: a log deleted or moved is
named as such (it was reported as 'a run from an earlier time has cut
the log back'); a run with its log switched off refuses to start where
the log holds an earlier run's events after its start time (they stayed
in the log beside a history without them), for the collision log and
the break-up log alike, and starts where it holds none after it."""

import shutil

from aggloTools import eventlog
from aggloTools.boxcase import run_case
from aggloTools.runner import foam_bin, run
from aggloTools.foamfile import edit
from cloudBoxCases import primaries_gas as gas


def _restart(c, start, end, log):
    ctl = ["foamDictionary", "system/controlDict", "-entry"]
    for k, v in (("startFrom", "startTime"), ("startTime", start),
                 ("endTime", end)):
        run([foam_bin(ctl[0]), *ctl[1:], k, "-set", v], c, "log.fd")
    return run([foam_bin("aggloPimpleFoam")], c, log, check=False)


def test_deleted_log_named(case_dir, foam_env):
    c = gas(case_dir / "gas")
    run_case(c)
    shutil.rmtree(eventlog.folder(c))
    res = _restart(c, "0.003", "0.004", "log.deleted")
    assert res.returncode != 0
    assert "has no events file" in res.stdout
    assert "deleted or moved" in res.stdout


def test_log_off_with_later_events_refused(case_dir, foam_env):
    c = gas(case_dir / "gas")
    run_case(c)
    n = len(eventlog.read_events(c))
    later = int((eventlog.read_events(c)["timeIndex"] > 30).sum())
    assert 0 < later < n
    f = c / "constant" / "kinematicCloudProperties"
    edit(f, "eventLog true;", "", 1)
    res = _restart(c, "0.003", "0.004", "log.off")
    assert res.returncode != 0, res.stdout[-1500:]
    assert f"holds {later} events after time 0.003" in res.stdout
    # from the last write there is nothing after the start: it runs, and
    # leaves the log as it was
    before = (eventlog.folder(c) / "events0.bin").read_bytes()
    res = _restart(c, "0.004", "0.005", "log.offEnd")
    assert res.returncode == 0, res.stdout[-1500:]
    assert (eventlog.folder(c) / "events0.bin").read_bytes() == before
