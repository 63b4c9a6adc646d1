"""hardSphereReplay as a gate (doc/eventLog.md) and its bad input: -check
exits 1 where the run's kernel does not reproduce the log; bad
arguments, failing writes and targets that are not plain files leave
earlier outputs as they were; a corrupt, cut-back or cut-off log is
refused; a variant of the other model drops the run's coefficients;
the per-event output. The logs come from cloudBoxCases.primaries_gas."""

import re
import shutil

import numpy as np
import pytest

from aggloTools import eventlog
from aggloTools.boxcase import run_case
from aggloTools.runner import foam_bin, run
from aggloTools.foamfile import edit
from cloudBoxCases import primaries_gas as gas

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
    edit(f, "en 0.97;", "en 0.5;", 1)
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
    ("wallDistance", 0, float("nan"), "<f", "wall distance nan"),
    ("proc1", 0, -5, "<i", "origProc -5"),
    ("id2", 0, -1, "<i", "origId -1"),
], ids=["nanDiameter", "hugeDiameter", "tinyDensity", "hugeVelocity",
        "infiniteSpin", "farPosition", "category", "branch",
        "agglomerates", "nPrimary", "timeIndex", "nanWallDistance",
        "origProc", "origId"])
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
    edit(f,
         "agglomerationModel EAM;",
         "agglomerationModel EAM; EAMCoeffs { impactVelocity full; }", 1)
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


def test_log_count_and_foreign_targets(case_dir, foam_env):
    """A log with more or fewer events than the run recorded at its
    latest write is refused (two runs appending to one log doubled it and
    -check passed); -json onto another cloud's event log is refused and
    leaves it as it was (it was overwritten: 1.3 MB -> 330 B)."""
    c = gas(case_dir / "gas")
    run_case(c)
    log = eventlog.folder(c) / "events0.bin"
    whole = log.read_bytes()
    n = len(eventlog.read_events(c))
    head = len(whole) - n * eventlog.DTYPE.itemsize
    for bad, count, words in ((whole + whole[head:], 2 * n,
                               "more than one run appended"),
                              (whole[:head], 0, "cut back or emptied")):
        log.write_bytes(bad)
        res = _replay_cmd(c, "-check")
        assert res.returncode == 1, res.stdout[-1500:]
        assert f"holds {count} events, but the run recorded {n}" \
            in res.stdout and words in res.stdout
    log.write_bytes(whole)
    assert _replay_cmd(c, "-check").returncode == 0

    other = c / "postProcessing" / "otherCollisionEvents"
    other.mkdir()
    shutil.copy(log, other / "events0.bin")
    res = _replay_cmd(c, "-json", str(other / "events0.bin"))
    assert res.returncode == 1
    assert "is not an earlier output of -json" in res.stdout
    assert (other / "events0.bin").read_bytes() == whole


def test_variants_named_twice_or_wrong(case_dir, foam_env):
    """-variants: a name given twice is refused; a variant's bad entry is
    reported under the variants file and the variant's name (it named
    the cloud's dictionary, whose entries the variant is merged over)."""
    c = gas(case_dir / "gas")
    run_case(c)
    v = c / "variants"
    v.write_text("x { agglomerationModel MAM; }\n"
                 "x { agglomerationModel EAM; }\n")
    res = _replay_cmd(c, "-variants", str(v))
    assert res.returncode == 1 and "duplicate entry: x" in res.stdout
    v.write_text("y { particleCollision { en 1.5; } }\n")
    res = _replay_cmd(c, "-variants", str(v))
    assert res.returncode == 1
    fatal = res.stdout.split("FOAM FATAL", 1)[1]
    assert "en" in fatal and f"{v}/y/particleCollision" in fatal, \
        fatal[:1500]
