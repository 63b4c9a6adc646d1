"""The collision-event log (doc/eventLog.md) of a running cloud and its
replay: the log holds exactly the counted events (the statistics'
counters by category), the run's own kernel replayed by hardSphereReplay
reproduces every logged outcome, serially and on 2 ranks; a restart from
an earlier write neither repeats nor loses an event; a kernel variant
equal to the run's kernel pairs with it on every event; with eventLog off
nothing is written."""

import re
import shutil

import numpy as np
import pytest

from aggloTools import eventlog, placement
from aggloTools.boxcase import box_case, run_case
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows
from aggloTools.times import time_dirs

D, LB, N = 12e-6, 2e-4, 300


def gas(case, model="EAM", log=True, decompose=(1, 1, 1), end=4e-3,
        write=10):
    """300 quartz primaries at about 2 mm/s, periodic in x and z, walls in
    y: collisions of every category and agglomerates within 40 steps."""
    rng = np.random.default_rng(11)
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0),
                         (LB, LB - 0.6 * D, LB), (LB, None, LB), rng)
    U = rng.normal(0, 1.5e-3, (N, 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    box_case(case, L=(LB,) * 3, n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=end, write_interval=write, agglomeration=model,
             decompose=decompose)
    if log:
        f = case / "constant" / "kinematicCloudProperties"
        old = "agglomerationModel " + model + ";"
        f.write_text(f.read_text().replace(old, old + " eventLog true;", 1))
    return case


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


# ------------------------------------ the replay as a gate, its bad input

def _replay_cmd(c, *args):
    return run([foam_bin("hardSphereReplay"), "-case", str(c), *args], c,
               "log.hardSphereReplay.gate", check=False)


def test_check_fails_when_outcomes_differ(case_dir, foam_env):
    """-check exits with status 1 when the run's kernel does not reproduce
    the log (the run's e_n changed after the run), 0 when it does; the
    Python wrapper raises."""
    c = gas(case_dir / "gas")
    run_case(c)
    assert _replay_cmd(c, "-check").returncode == 0
    f = c / "constant" / "kinematicCloudProperties"
    f.write_text(f.read_text().replace("en 0.97;", "en 0.5;", 1))
    res = _replay_cmd(c, "-check")
    assert res.returncode == 1, res.stdout[-1500:]
    assert "does not reproduce" in res.stdout
    with pytest.raises(Exception, match="rc 1"):
        eventlog.replay(c, check=True)


def test_bad_arguments_leave_earlier_results(case_dir, foam_env):
    """-base naming no configuration, a -json folder that does not exist
    and a variant named twice are fatal before anything is written; an
    earlier replay.json stays as it was."""
    c = gas(case_dir / "gas")
    run_case(c)
    out = c / "r.json"
    assert _replay_cmd(c, "-json", str(out)).returncode == 0
    before = out.read_text()
    res = _replay_cmd(c, "-json", str(out), "-base", "nosuch")
    assert res.returncode == 1 and "nosuch" in res.stdout
    assert out.read_text() == before
    res = _replay_cmd(c, "-json", "/nonexistent/dir/r.json")
    assert res.returncode == 1 and "does not exist" in res.stdout
    v = c / "twice"
    v.write_text("a { agglomerationModel MAM; }\n"
                 "a { agglomerationModel none; }\n")
    res = _replay_cmd(c, "-json", str(out), "-variants", str(v))
    assert res.returncode == 1 and "a" in res.stdout
    assert out.read_text() == before


def _replay_limited(c, *args):
    """The replay with a file size limit of 0 and SIGXFSZ ignored (as a
    shell that ignores it leaves it): every write fails with EFBIG."""
    import resource
    import signal
    import subprocess

    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (0, 0))
    return subprocess.run([foam_bin("hardSphereReplay"), "-case", str(c),
                           *args], cwd=c, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=120,
                          preexec_fn=limit)


def test_outputs_are_never_lost_or_misplaced(case_dir, foam_env):
    """The replay's outputs: a write that fails (file size limit 0) exits
    with status 1 and leaves the earlier replay.json and CSV as they were;
    the run's own log, a folder, a FIFO and a link are refused as targets
    before anything is written, and stay what they were."""
    import os
    c = gas(case_dir / "gas")
    run_case(c)
    out, csv = c / "r.json", c / "e.csv"
    assert _replay_cmd(c, "-json", str(out), "-eventsOut",
                       str(csv)).returncode == 0
    before, before_csv = out.read_bytes(), csv.read_bytes()
    assert len(before) > 100 and len(before_csv) > 100

    res = _replay_limited(c, "-json", str(out))
    assert res.returncode == 1 and "failed" in res.stdout, res.stdout[-1500:]
    assert out.read_bytes() == before
    res = _replay_limited(c, "-json", str(out), "-eventsOut", str(csv))
    assert res.returncode == 1
    assert out.read_bytes() == before and csv.read_bytes() == before_csv
    assert not list(c.glob("*.tmp"))

    log = eventlog.folder(c) / "events0.bin"
    log_bytes = log.read_bytes()
    res = _replay_cmd(c, "-eventsOut", str(log))
    assert res.returncode == 1 and "log" in res.stdout, res.stdout[-1500:]
    assert log.read_bytes() == log_bytes

    d = c / "adir"
    d.mkdir()
    for opt in ("-json", "-eventsOut"):
        res = _replay_cmd(c, opt, str(d))
        assert res.returncode == 1 and "is a folder" in res.stdout
        assert list(d.iterdir()) == []

    fifo = c / "fifo"
    os.mkfifo(fifo)
    link = c / "link.json"
    link.symlink_to(out)
    for target in (fifo, link):
        res = _replay_cmd(c, "-json", str(target))
        assert res.returncode == 1 and "not a regular" in res.stdout
    assert fifo.is_fifo() and link.is_symlink()
    assert out.read_bytes() == before


@pytest.mark.parametrize("field, index, value, fmt, words", [
    ("d1", 0, float("nan"), "<d", "d nan"),
    ("d1", 0, 1e300, "<d", "d 1e+300"),
    ("rho1", 0, 1e-300, "<d", "rho 1e-300"),
    ("U1", 0, 1e308, "<d", "velocity"),
    ("omega2", 2, float("inf"), "<d", "spin"),
    ("x1", 1, -1e7, "<d", "position"),
    ("category", 0, 3, "B", "category 3"),
    ("branch", 0, 9, "B", "branch 9"),
    ("agglomerates", 0, 7, "B", "agglomerates 7"),
    ("nPrimary1", 0, -5, "<i", "nPrimary -5"),
    ("timeIndex", 0, -3, "<i", "time index -3"),
], ids=["nanDiameter", "hugeDiameter", "tinyDensity", "hugeVelocity",
        "infiniteSpin", "farPosition", "category", "branch",
        "agglomerates", "nPrimary", "timeIndex"])
def test_corrupt_record_is_fatal(case_dir, foam_env, field, index, value,
                                 fmt, words):
    """A record that cannot be a logged collision stops the replay with a
    message naming the file, the record and the value: no SIGFPE from
    values whose products overflow (a velocity of 1e308, a diameter of
    1e300, a density of 1e-300). The Python reader refuses the same
    record with the same words."""
    import struct
    c = gas(case_dir / "gas")
    run_case(c)
    f = eventlog.folder(c) / "events0.bin"
    data = bytearray(f.read_bytes())
    k = 3
    offset = eventlog.DTYPE.fields[field][1] + 8 * index
    pos = eventlog.HEADER_BYTES + k * eventlog.DTYPE.itemsize + offset
    struct.pack_into(fmt, data, pos, value)
    f.write_bytes(bytes(data))
    res = _replay_cmd(c, "-check")
    assert res.returncode == 1, res.stdout[-1500:]
    assert "sigFpe" not in res.stdout
    assert f"record {k}" in res.stdout and words in res.stdout, \
        res.stdout[-1500:]
    with pytest.raises(ValueError, match=rf"record {k}: .*{re.escape(words)}"):
        eventlog.read_events(c)


def test_variant_of_the_other_model_drops_the_run_coefficients(
        case_dir, foam_env):
    """A run with EAMCoeffs in its kernel replays a MAM variant (the
    EAM's coefficients are not the MAM's: they are left out)."""
    c = gas(case_dir / "gas")
    f = c / "constant" / "kinematicCloudProperties"
    f.write_text(f.read_text().replace(
        "agglomerationModel EAM;",
        "agglomerationModel EAM; EAMCoeffs { impactVelocity full; }", 1))
    run_case(c)
    res = eventlog.replay(c, {"MAM": {"agglomerationModel": "MAM"}},
                          check=True)
    conf = {r["name"]: r for r in res["configurations"]}
    assert conf["MAM"]["events"] == conf["run"]["events"] > 20


def test_log_cut_back_by_an_earlier_run_is_refused(case_dir, foam_env):
    """Run to step 40; re-run a copy from step 20 to 30; then continue
    from the latest time (step 40, a folder of the older run): the log
    was cut back to step 20 and holds only the re-run's events since, so
    the start at step 40 is refused instead of counting on a log that
    lost events. Starting from the re-run's own end (step 30) works."""
    full = gas(case_dir / "full")
    run_case(full)
    ctl = ["foamDictionary", "system/controlDict", "-entry"]
    for k, v in (("startFrom", "startTime"), ("startTime", "0.002"),
                 ("endTime", "0.003")):
        run([foam_bin(ctl[0]), *ctl[1:], k, "-set", v], full, "log.fd")
    run([foam_bin("aggloPimpleFoam")], full, "log.rerun")
    for k, v in (("startFrom", "latestTime"), ("endTime", "0.005")):
        run([foam_bin(ctl[0]), *ctl[1:], k, "-set", v], full, "log.fd")
    res = run([foam_bin("aggloPimpleFoam")], full, "log.latest",
              check=False)
    assert res.returncode == 1, res.stdout[-1500:]
    assert "has cut the log back" in res.stdout
    shutil.rmtree(full / "0.004")
    run([foam_bin("aggloPimpleFoam")], full, "log.latest2")
    rec = (full / "0.005" / "uniform" / "lagrangian" / "kinematicCloud"
           / "collisionEventLog").read_text()
    n = len(eventlog.read_events(full))
    assert n > 20 and re.search(rf"nEvents\s+{n};", rec)


@pytest.mark.parametrize("keep", [0, 0.5])
def test_cut_off_log_record_is_refused(case_dir, foam_env, keep):
    """The log's record of a written time (nEvents) empty or cut off: the
    count cannot be checked, so the restart stops naming it (it was read
    as absent, and the run continued unchecked)."""
    c = gas(case_dir / "gas")
    run_case(c)
    rec = (c / "0.004" / "uniform" / "lagrangian" / "kinematicCloud"
           / "collisionEventLog")
    text = rec.read_bytes()
    rec.write_bytes(text[:int(keep * len(text))])
    run([foam_bin("foamDictionary"), "system/controlDict", "-entry",
         "endTime", "-set", "0.005"], c, "log.fd")
    res = run([foam_bin("aggloPimpleFoam")], c, "log.restart", check=False)
    assert res.returncode != 0, res.stdout[-1500:]
    assert "empty or cut off" in res.stdout and "collisionEventLog" in \
        res.stdout, res.stdout[-1500:]


def test_per_event_output(case_dir, foam_env):
    """-eventsOut: one line per event; the run's own kernel gives every
    logged outcome; the pair state is the log's (u_n from the logged
    states, by hand); a model that never agglomerates agrees with the
    run on every rebound and the per-event agglomerations add up to the
    JSON's counts."""
    c = gas(case_dir / "gas")
    run_case(c)
    res, ev = eventlog.replay_events(c, {
        "elastic": {"agglomerationModel": "none",
                    "particleCollision": {"en": 1}}})
    log = eventlog.read_events(c)
    assert len(ev["event"]) == len(log) > 20
    assert np.array_equal(ev["run.branch"], log["branch"])
    assert np.array_equal(ev["run.agglomerates"], log["agglomerates"])
    n = log["x2"] - log["x1"]
    n /= np.linalg.norm(n, axis=1)[:, None]
    un = np.einsum("ij,ij->i", log["U2"] - log["U1"], n)
    np.testing.assert_allclose(ev["un"], un, rtol=1e-8, atol=1e-15)
    conf = {r["name"]: r for r in res["configurations"]}
    assert ev["elastic.agglomerates"].sum() == 0
    # no agglomeration: the Wilson interval starts at 0 exactly
    assert conf["elastic"]["agglomerations"] == 0
    assert conf["elastic"]["alphaLow"] == 0
    assert ev["run.agglomerates"].sum() == conf["run"]["agglomerations"]
    # the codes of the log and of the run's kernel name the same branches,
    # those of the run's model (EAM)
    assert (res["loggedBranches"] == list(conf["run"]["branches"])
            == list(eventlog.branches(c))
            == ["eq21", "eq65", "caseI", "caseII"])
    # EAM intermediates wherever the EAM decided (Eq. 21 terms finite)
    eam = ev["run.branch"] >= 0
    assert np.all(np.isfinite(ev["run.dEvdW"][eam]))
