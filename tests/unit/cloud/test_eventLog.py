"""The collision-event log (doc/eventLog.md) of a running cloud and its
replay: the log holds exactly the counted events (the statistics'
counters by category), the run's own kernel replayed by hardSphereReplay
reproduces every logged outcome, serially and on 2 ranks; a restart from
an earlier write neither repeats nor loses an event; a kernel variant
equal to the run's kernel pairs with it on every event; with eventLog off
nothing is written. The replay as a gate and its bad input:
test_eventReplayGate.py."""

import shutil

import numpy as np
import pytest

from aggloTools import eventlog
from aggloTools.boxcase import run_case
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows
from aggloTools.times import time_dirs
from cloudBoxCases import D, primaries_gas as gas


def check_log_against_stats(case):
    ev = eventlog.read_events(case)
    last = stats_rows(case)[-1]
    assert last["nCol"] > 20 and last["nAgg"] > 0
    assert len(ev) == last["nCol"]
    for k, col in enumerate(("nColFirst", "nColRepeat", "nColOverlapStart")):
        assert np.sum(ev["category"] == k) == last[col], col
    assert np.sum(ev["agglomerates"]) == last["nAgg"]
    # partner 1 has the lower global id; primaries as the cloud has them
    assert np.all((ev["proc1"] < ev["proc2"]) | ((ev["proc1"] == ev["proc2"])
                                                 & (ev["id1"] < ev["id2"])))
    assert np.all(ev["nPrimary1"] >= 1) and np.all(ev["d1"] >= D * 0.999)
    # the partners touch at the contact (overlapping ones at step start)
    gap = np.linalg.norm(ev["x2"] - ev["x1"], axis=1) \
        - 0.5 * (ev["d1"] + ev["d2"])
    touching = ev["category"] != 2
    assert np.all(np.abs(gap[touching]) < 1e-9 * D)
    assert np.all(gap[~touching] < 0)
    return ev, last


@pytest.mark.parametrize("ranks", [0, 2])
def test_replay_reproduces_the_run(case_dir, foam_env, ranks):
    c = gas(case_dir / "gas", decompose=(2, 1, 1))
    run_case(c, parallel=ranks)
    ev, last = check_log_against_stats(c)
    files = sorted(eventlog.folder(c).glob("events*.bin"))
    assert len(files) == (2 if ranks else 1)
    res = eventlog.replay(c, check=True)
    run_ = res["configurations"][0]
    assert run_["events"] == len(ev)
    assert run_["compared"] == run_["matches"] == len(ev)
    assert run_["agglomerations"] == last["nAgg"]
    assert sum(run_["branches"].values()) == len(ev)


def test_serial_and_parallel_logs_agree(case_dir, foam_env):
    logs = {}
    for ranks in (0, 2):
        c = gas(case_dir / f"np{ranks}", decompose=(2, 1, 1))
        run_case(c, parallel=ranks)
        logs[ranks] = eventlog.read_events(c)
    a, b = logs[0], logs[2]
    assert len(a) == len(b) > 20
    for f in ("timeIndex", "category", "branch", "agglomerates", "proc1",
              "id1", "proc2", "id2", "nPrimary1", "nPrimary2"):
        assert np.array_equal(a[f], b[f]), f
    for f in ("U1", "U2", "x1", "x2", "time"):
        np.testing.assert_allclose(a[f], b[f], rtol=1e-9, atol=1e-15,
                                   err_msg=f)


def test_restart_neither_repeats_nor_loses(case_dir, foam_env):
    """The uninterrupted run against a copy restarted from its write at
    step 20 (after the run had gone on to step 40 and logged it: the
    restart cuts the log back first)."""
    full = gas(case_dir / "full")
    run_case(full)
    half = case_dir / "half"
    shutil.copytree(full, half)
    for t in time_dirs(half):
        if float(t.name) > 2.05e-3:
            shutil.rmtree(t)
    run([foam_bin("aggloPimpleFoam")], half, "log.aggloPimpleFoam.restart")
    log = (half / "log.aggloPimpleFoam.restart").read_text()
    assert "events after it removed" in log
    a, b = eventlog.read_events(full), eventlog.read_events(half)
    assert len(a) == len(b) > 20
    assert np.any(a["timeIndex"] > 20) and np.any(a["timeIndex"] <= 20)
    for f in a.dtype.names:
        if f == "time":
            # OpenFOAM re-reads the time from the folder name on restart
            np.testing.assert_allclose(a[f], b[f], rtol=1e-12, atol=0)
        else:
            assert np.array_equal(a[f], b[f]), f


def test_variants_pair_with_the_run(case_dir, foam_env):
    """A variant that sets the run's own entries pairs with the run on
    every event (ratio 1, no discordant event); a variant that changes
    the model changes outcomes, and the paired counts add up."""
    c = gas(case_dir / "gas")
    run_case(c)
    res = eventlog.replay(c, {
        "same": {"agglomerationModel": "EAM",
                 "particleCollision": {"en": 0.97}},
        "MAM": {"agglomerationModel": "MAM"},
        "elastic": {"agglomerationModel": "none",
                    "particleCollision": {"en": 1}}})
    conf = {r["name"]: r for r in res["configurations"]}
    pairs = {p["b"]: p for p in res["paired"]}
    assert conf["same"]["agglomerations"] == conf["run"]["agglomerations"]
    assert pairs["same"]["onlyA"] == pairs["same"]["onlyB"] == 0
    assert pairs["same"]["ratio"] == pytest.approx(1.0, rel=1e-12)
    assert conf["elastic"]["agglomerations"] == 0
    a = conf["run"]["agglomerations"]
    p = pairs["MAM"]
    assert p["both"] + p["onlyA"] == a
    assert p["both"] + p["onlyB"] == conf["MAM"]["agglomerations"]
    # the first contacts alone: the first-contact ensemble of the stats
    first = eventlog.replay(c, events="first")
    assert first["events"] == stats_rows(c)[-1]["nColFirst"]


def test_variant_with_an_unknown_entry_is_fatal(case_dir, foam_env):
    c = gas(case_dir / "gas", end=2e-4, write=1)
    run_case(c)
    with pytest.raises(Exception, match="enn"):
        eventlog.replay(c, {"bad": {"particleCollision": {"enn": 0.8}}})


def test_no_log_when_off(case_dir, foam_env):
    c = gas(case_dir / "gas", log=False)
    run_case(c)
    assert stats_rows(c)[-1]["nCol"] > 0
    assert not eventlog.folder(c).exists()
