"""channel.regime.study's runner (the regime study's variants, one Allrun
each), its dropped variants, and channel.regime.analysis's progress of an
unfinished variant (the concentration between writes:
post/test_channelConcentration.py); the study's post-processing is tested
on the smoke runs in post/test_channelSmokeOutputs.py."""

import json
import threading

import numpy as np
import pytest

from channelTestRuns import script, write_dispersion


def test_regime_study_runs_side_by_side(monkeypatch, tmp_path):
    """channel.regime run -j 2: two variants' Allruns at once (each waits
    for the other at a barrier: run one after the other, the barrier
    breaks), each with the ranks asked for and its output in its own
    log; the exit status is the first failed variant's, in the order
    given, and 0 when all finish."""
    regime = script("channel.regime.study")
    monkeypatch.setattr(regime, "TUTORIAL", tmp_path)
    meet = threading.Barrier(2, timeout=10)
    calls = []

    def fake_call(cmd, cwd, stdout=None, stderr=None):
        calls.append(cmd)
        meet.wait()
        stdout.write(f"ran {cmd[2]}\n")
        return {"regime32": 0, "regime48": 3, "regime64": 5}[cmd[2]]

    monkeypatch.setattr(regime.subprocess, "call", fake_call)
    assert regime.main(["channel.regime", "run", "-np", "1", "-j", "2",
                        "regime32", "regime48"]) == 3
    assert sorted(c[2] for c in calls) == ["regime32", "regime48"]
    assert all(c[3:] == ["-np", "1"] for c in calls)
    for n in ("regime32", "regime48"):
        assert (tmp_path / "runs" / f"{n}.log").read_text() == f"ran {n}\n"
    assert regime.main(["channel.regime", "run", "-j", "2", "regime64",
                        "regime48"]) == 5
    meet.reset()
    assert regime.main(["channel.regime", "run", "-j", "2", "regime32",
                        "regime32"]) == 0
    with pytest.raises(SystemExit):
        regime.main(["channel.regime", "run", "-j", "0", "regime32"])


END = "\n// ****************************************************** //\n"


def write_time(case, t, complete=True):
    d = case / f"{t:.12g}"
    (d / "uniform").mkdir(parents=True)
    (d / "U").write_text("FoamFile {}\n" + (END if complete else "(1 2"))
    (d / "uniform" / "time").write_text("value " + str(t) + ";" + END)


def test_progress_of_an_unfinished_variant(tmp_path):
    """An unfinished variant: unladen done (writes at 0 and its end),
    release done and the dispersion written 0.5 and 1.5 T* after the
    release, a third write cut off: the last complete writes in T* are
    the unladen end and release + 1.5 (the cut-off write is not
    counted), the stages' ends and the markers as written; the history
    of the dispersion folder comes with it, and once the dispersion is
    done the concentration at the start of agglomeration. A variant with
    no folder has no progress."""
    settings = script("channel.case.settings")
    regime = script("channel.regime.analysis")
    p = settings.preset("regime64")
    base = tmp_path / "regime64"
    un = base / "unladen"
    tu = settings.end_time(p, "unladen")
    write_time(un, 0.0)
    write_time(un, tu)
    (un / "done.unladen").write_text("1\n")
    disp = base / "C1" / "dispersion"
    t0 = write_dispersion(p, disp)
    for T in (0.5, 1.5):
        write_time(disp, t0 + T * p["tScale"])
    write_time(disp, t0 + 2.5 * p["tScale"], complete=False)
    (disp / "done.release").write_text("1\n")
    g = regime.progress("regime64", tmp_path)
    T0 = tu / p["tScale"]
    assert set(g["stages"]) == {"unladen", "C1/dispersion"}
    assert g["stages"]["unladen"]["lastWrite_Tstar"] == pytest.approx(T0)
    assert g["stages"]["unladen"]["done"] == ["unladen"]
    assert g["stages"]["C1/dispersion"]["lastWrite_Tstar"] == \
        pytest.approx(T0 + 1.5)
    assert g["stages"]["C1/dispersion"]["end_Tstar"] == pytest.approx(
        sum(p[k] for k in ("unladen", "release", "dispersion")))
    assert g["stages"]["C1/dispersion"]["done"] == ["release"]
    assert [x["nearWallOverCentre"] for x in g["history"]] == \
        pytest.approx([1, 3])
    assert g["agglomeration"] == {}
    # the start of agglomeration is not known before the dispersion ends
    assert g["concentration"] is None
    assert regime.progress("regime48", tmp_path) is None
    # the dispersion done: its last write's running average, (10 + 20 x
    # 3) / 30 = 7/3, as for a finished variant, and the report says it
    (disp / "done.dispersion").write_text("1\n")
    g = regime.progress("regime64", tmp_path)
    assert g["concentration"]["nearWallOverCentre"] == pytest.approx(7 / 3)
    report = script("channel.regime.report")
    text = "\n".join(report._agglomeration_lines(
        {"variants": [{"name": "regime64", "result": None, "progress": g}]}))
    assert "regime64       c_w/c_0 at the start of agglomeration (the " \
        "dispersion done): 2.33" in text


def test_stage_times_count_every_resumed_segment(tmp_path):
    """A stage resumed once (-append: the second segment counts from zero
    again) on 2 ranks and a serial stage: each folder's wall-clock is the
    sum of its segments' last ClockTime, the CPU the sum of the last
    ExecutionTimes times the ranks (hand sums)."""
    regime = script("channel.regime.analysis")

    def log(d, segments, ranks=1):
        d.mkdir(parents=True)
        for k in range(ranks):
            (d / f"processor{k}").mkdir()
        text = ""
        for seg in segments:
            text += "Create time\n"
            for cpu, wall in seg:
                text += (f"ExecutionTime = {cpu} s  ClockTime = {wall} s"
                         "\n\n")
        (d / "log.aggloPimpleFoam").write_text(text)

    base = tmp_path / "regime64"
    log(base / "unladen", [[(1.5, 2), (3.0, 4)]])
    log(base / "C1" / "dispersion",
        [[(10.0, 11), (20.0, 22)], [(5.0, 6), (7.5, 9)]], ranks=2)
    t = regime.stage_times(base)
    assert t["wall_s"] == {"unladen": 4.0, "C1/dispersion": 31.0}
    assert t["wallTotal_s"] == 35.0
    assert t["cpu_s"] == pytest.approx(3.0 + 2 * (20.0 + 7.5))


def write_agglomeration(p, case, cloud, Tmax, col_rate, agg_rate):
    """stats.dat of one cloud of an agglomeration stage: a row per T*agg
    0, 1, ..., Tmax with nCol = col_rate T*agg and nAgg = agg_rate
    T*agg (steady rates)."""
    settings = script("channel.case.settings")
    t0 = settings.end_time(p, "dispersion")
    d = case / "postProcessing" / f"{cloud}HardSphere" / f"{t0:.12g}"
    d.mkdir(parents=True)
    rows = [f"{t0 + T * p['tScale']:.17g} {col_rate * T:g} {agg_rate * T:g}"
            for T in range(Tmax + 1)]
    (d / "stats.dat").write_text("# Time nCol nAgg\n" + "\n".join(rows)
                                 + "\n")
    return t0


def test_agglomeration_stage_so_far(tmp_path):
    """regime64 (window 100-200) cut at its write T*agg 150, stats.dat
    already at 160: the rows past the write are left out; EAM N_col 300,
    N_agg 15 at 150; over the window's part 100-150 f_col 2 and f_agg
    0.1 per T* (steady: batch means 0, so the Poisson sigma sqrt(100) /
    50), times s^2 = 3600; alpha_f 0.05. MAM has no stats.dat: left out.
    Cut at T*agg 105 the window's part (5 T*) is too short for rates."""
    settings = script("channel.case.settings")
    regime = script("channel.regime.analysis")
    p = settings.preset("regime64")
    adir = tmp_path / "agg"
    t0 = write_agglomeration(p, adir, "EAM", 160, 2.0, 0.1)
    T0 = t0 / p["tScale"]
    x = regime.agglomeration_so_far(p, adir, T0 + 150)
    assert set(x) == {"EAM"}
    e = x["EAM"]
    assert e["TstarAgg"] == pytest.approx(150)
    assert (e["nCol"], e["nAgg"]) == pytest.approx((300, 15))
    assert e["alpha"] == pytest.approx(0.05)
    assert e["window"] == pytest.approx([100, 150])
    assert e["f_col_scaled"] == pytest.approx(2 * 3600)
    assert e["sigma_col_scaled"] == pytest.approx(10 / 50 * 3600)
    assert e["f_agg_scaled"] == pytest.approx(0.1 * 3600)
    assert e["alpha_f"] == pytest.approx(0.05)
    assert e["colFactorToPaper"] == pytest.approx(7200 / 81400, rel=1e-3)
    early = regime.agglomeration_so_far(p, adir, T0 + 105)["EAM"]
    assert early["TstarAgg"] == pytest.approx(105)
    assert "window" not in early and "f_col_scaled" not in early
    report = script("channel.regime.report")
    res = {"variants": [
        {"name": "regime64", "result": None,
         "progress": {"agglomeration": x}},
        {"name": "regime48", "result": None,
         "progress": {"agglomeration": {"EAM": early}}}]}
    text = "\n".join(report._agglomeration_lines(res))
    assert "regime64       EAM   T*agg 150: N_col 300, N_agg 15, alpha " \
        "0.05; window 100-150: f_col x s^2 7200 +- 720 (x paper " \
        "0.0885), f_agg x s^2 360, alpha_f 0.05 (x paper 6.1)" in text
    short = [ln for ln in text.splitlines() if ln.startswith("regime48")]
    assert len(short) == 1 and "T*agg 105: N_col 210" in short[0]
    assert "window" not in short[0]


def test_contacts_by_wall_distance():
    """Six contacts at y/delta 0.01, 0.01, 0.03, 0.3, 0.7 and 1.0 (the
    centre, in the last bin), agglomerating the 2nd, 4th and 5th: per bin
    by hand 2/1, 1/0, 0, 0, 1/1, 2/1; the medians of |u_n| (m/s in, mm/s
    out) 15, 30, -, -, 2, 1.5."""
    contacts = script("channel.post.contacts")
    un = np.array([0.010, 0.020, 0.030, 0.002, 0.001, 0.002])
    yw = np.array([0.01, 0.01, 0.03, 0.3, 0.7, 1.0])
    agg = np.array([False, True, False, True, True, False])
    b = contacts.by_wall_distance(un, yw, agg)
    assert b["n"] == [2, 1, 0, 0, 1, 2]
    assert b["nAgg"] == [1, 0, 0, 0, 1, 1]
    assert b["alpha"] == [0.5, 0.0, None, None, 1.0, 0.5]
    assert b["unMedian_mm_s"] == pytest.approx([15, 30, None, None, 2,
                                                1.5])


def test_post_refuses_a_wrong_runs_folder(tmp_path):
    """post --runs of a folder that does not exist, or holds no variant's
    runs, stops before writing (it exited 0 and rewrote the committed
    regime.json with 'not run' rows, 95 KB -> 2.5 KB); without
    --reference it writes beside the runs, not into results/regime."""
    regime = script("channel.regime.study")
    committed = regime.TUTORIAL / "results" / "regime"
    before = {f: (committed / f).read_bytes()
              for f in ("regime.json", "regime.txt", "regime.png")}
    for runs in (tmp_path / "missing", tmp_path):
        with pytest.raises(SystemExit) as e:
            regime.main(["channel.regime", "post", "--runs", str(runs)])
        assert str(runs) in str(e.value)
    assert not (tmp_path / "report-regime").exists()
    assert {f: (committed / f).read_bytes() for f in before} == before
    assert regime.post_folder(tmp_path) == tmp_path / "report-regime"
    assert regime.post_folder(tmp_path, reference=True) == committed
    with pytest.raises(SystemExit):               # one place or the other
        regime.main(["channel.regime", "post", "--reference", "--out",
                     str(tmp_path)])


def test_earlier_results_kept_beside_other_configurations(tmp_path):
    """post --earlier: a variant whose folder holds other configurations'
    runs (the matrix's C2 at regime64, an unladen LES at regime48) but no
    C1 keeps its finished C1 result from the earlier regime.json, marked
    with where it came from, so that the time-step pair regime64dt2 over
    regime64 is judged; a variant whose C1 is being run again is
    reported as that run stands."""
    regime = script("channel.regime.study")
    earlier = regime.TUTORIAL / "results" / "regime" / "regime.json"
    runs = tmp_path / "runs"
    (runs / "regime64" / "C2" / "dispersion").mkdir(parents=True)
    (runs / "regime48" / "unladen").mkdir(parents=True)
    (runs / "regime32" / "C1" / "dispersion").mkdir(parents=True)
    res = regime.run_post(runs, tmp_path / "out", earlier=earlier)
    v = {x["name"]: x for x in res["variants"]}
    kept = regime.earlier_results(regime.earlier_variants(earlier))
    for name in ("regime64", "regime48", "small"):
        assert v[name]["result"] == kept[name]
        assert v[name]["from"] == str(earlier)
    assert v["regime32"]["result"] is None and "from" not in v["regime32"]
    assert "progress" in v["regime32"]


def test_dropped_variant_said_and_not_run_by_default(monkeypatch,
                                                     tmp_path, capsys):
    """regime48n3 is dropped: the report says so with the reason where it
    has no result, and with an earlier report keeps how far its runs had
    come then (their folder gone); 'run' without names runs every variant
    but it, by name it still runs; 'list' says it is dropped."""
    regime = script("channel.regime.study")
    report = script("channel.regime.report")
    assert "regime48n3" in regime.DROPPED
    runs = tmp_path / "runs"
    (runs / "regime32" / "C1").mkdir(parents=True)
    res = regime.run_post(runs, tmp_path / "out",
                          names=["regime32", "regime48n3"])
    v = {x["name"]: x for x in res["variants"]}
    assert v["regime48n3"]["dropped"] == regime.DROPPED["regime48n3"]
    assert "dropped" not in v["regime32"]
    text = (tmp_path / "out" / "regime.txt").read_text()
    assert f"regime48n3     dropped, not run in {runs / 'regime48n3'}; " \
        f"{regime.DROPPED['regime48n3']}" in text
    assert report._where(v["regime48n3"]).startswith("dropped, not run")
    # no finished or growing variant: no picture, and the report written
    assert not (tmp_path / "out" / "regime.png").exists()
    earlier = tmp_path / "earlier.json"
    begun = {"stages": {"C1/dispersion": {"lastWrite_Tstar": 280.0,
                                          "end_Tstar": 860.0, "done": []}},
             "history": [], "concentration": None, "agglomeration": {}}
    earlier.write_text(json.dumps({"variants": [
        {"name": "regime48n3", "result": None, "progress": begun}]}))
    res = regime.run_post(runs, tmp_path / "out",
                          names=["regime32", "regime48n3"],
                          earlier=earlier)
    v = {x["name"]: x for x in res["variants"]}
    assert v["regime48n3"]["progress"] == begun
    assert v["regime48n3"]["from"] == str(earlier)
    assert "progress" not in v["regime32"] or \
        v["regime32"]["progress"] != begun
    assert report._where(v["regime48n3"]) == (
        "dropped, not finished: C1/dispersion at T* 280 of 860; "
        + regime.DROPPED["regime48n3"])
    ran = []
    monkeypatch.setattr(regime, "run_variants",
                        lambda names, np_, j: ran.append(names) or 0)
    monkeypatch.setattr(regime, "TUTORIAL", tmp_path)
    assert regime.main(["channel.regime", "run"]) == 0
    known = [n for n, _ in regime.VARIANTS]
    assert ran[-1] == [n for n in known if n != "regime48n3"]
    assert regime.main(["channel.regime", "run", "regime48n3"]) == 0
    assert ran[-1] == ["regime48n3"]
    capsys.readouterr()
    assert regime.main(["channel.regime", "list"]) == 0
    assert "regime48n3" in [ln.split()[0] for ln in
                            capsys.readouterr().out.splitlines()
                            if "(dropped: " in ln]
