"""Break-up in the main case: a preset names a model of breakupModels
(`breakup stressThreshold;`), the agglomeration stage runs it and the
stages before it do not; a name that is not there is refused naming the
valid ones. The smoke preset's C2 with break-up (serial, about 40 s):
the break-up counters in stats.dat of the agglomeration stage only, every
agglomerate of every step checked (the log's count against stats.dat's
nAgglomerates of the step), and the largest ratio of load to
strength far below 1 (about 4e-4: the quartz doublets' van der Waals
bond against this flow's stresses), so nothing breaks and the primaries
are kept; the driver's break-up report says so from the same files, and
the statistics equal those of the smoke run without break-up."""

import json
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

from aggloTools import breakuplog
from aggloTools.stats import read_stats
from channelTestRuns import TUTORIAL, script

channel = script("channel.case.settings")


def copy(tmp_path, breakup):
    case = tmp_path / "verticalChannel"
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    presets = case / "presets"
    text = presets.read_text()
    new = text.replace("    seededPairs     50;",
                       f"    seededPairs     50;\n    breakup {breakup};", 1)
    assert new != text
    presets.write_text(new)
    return case


def settings(case, stage):
    res = subprocess.run([sys.executable, "-m", "channel.case", "settings",
                          "smoke", "C2", stage], cwd=case,
                         capture_output=True, text=True)
    return res


def test_breakup_only_in_the_agglomeration_stage(tmp_path):
    case = copy(tmp_path, "stressThreshold")
    for stage in ("unladen", "release", "dispersion"):
        res = settings(case, stage)
        assert res.returncode == 0, res.stderr
        assert re.search(r"breakup\n\{\n    breakupModel    none;\n\}",
                         res.stdout)
    res = settings(case, "agglomeration")
    assert "breakupModel    stressThreshold;" in res.stdout
    assert "mechanisms (turbulence drag rotation)" in res.stdout


def test_unknown_breakup_model_refused(tmp_path):
    res = settings(copy(tmp_path, "stressTreshold"), "agglomeration")
    assert res.returncode == 1
    assert "breakup 'stressTreshold' is not one of: none stressThreshold" \
        in res.stderr


@pytest.mark.slow
def test_smoke_C2_with_breakup(tmp_path, smoke_runs):
    case = copy(tmp_path, "stressThreshold")
    res = subprocess.run(["./Allrun", "-preset", "smoke", "-configs", "C2",
                          "-np", "1", "-every", "600"], cwd=case,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    runs = case / "runs" / "smoke" / "C2"
    agg = runs / "agglomeration-EAM"
    st = read_stats(agg, "EAM")
    for col in ("nBreakupTurbulence", "nBreakupDrag", "nBreakupRotation"):
        assert col in st and (st[col] == 0).all()
    assert "nBreakupTurbulence" not in read_stats(runs / "dispersion",
                                                  "particles")
    log = (agg / "log.aggloPimpleFoam").read_text()
    lines = re.findall(r"Break-up: 0 events \([^)]*\), waiting for room 0,"
                       r" (\d+) agglomerates checked(?:, largest ratio"
                       r" (\S+))?,", log)
    steps = int(round(channel.preset("smoke")["agglomeration"] / 0.02))
    assert len(lines) == steps
    # checked in each step: the agglomerates the step's collisions left,
    # which (nothing breaking) stats.dat counts at the step's end
    checked = [int(n) for n, _ in lines]
    assert checked == st["nAgglomerates"].astype(int).tolist()
    assert sum(checked) > 0
    ratios = [float(r) for n, r in lines if int(n) > 0]
    assert 0 < max(ratios) < 1e-2
    assert (st["nPrimaries"] == st["nPrimaries"][0]).all()
    # The driver's break-up report (channel.post.breakup) from the same
    # files: nothing broke, the largest ratio the log's, and at every
    # write the agglomerates of agglomerateSizes.dat are the ones
    # stats.dat counts at that time
    rep = json.loads((case / "runs" / "smoke" / "report"
                      / "breakup.json").read_text())["C2 EAM"]
    assert all(v["stage"] == 0 for v in rep["mechanisms"].values())
    assert rep["largestRatio"] == max(ratios)
    assert rep["events"] == {"logged": 0, "replay": "nothing logged: "
                             "nothing to replay"}
    t0 = channel.end_time(channel.preset("smoke"), "dispersion")
    T = (st["Time"] - t0) / channel.preset("smoke")["tScale"]
    assert len(rep["sizes"]) >= 2
    for s in rep["sizes"]:
        i = int(np.argmin(abs(T - s["T"])))
        assert abs(T[i] - s["T"]) < 1e-9
        assert s["N_a"] == st["nAgglomerates"][i]
        assert sum(s["counts"].values()) == s["N_a"]
    # Nothing broke, so the stage is the one without break-up: every
    # column of the smoke run's C2 EAM statistics (break-up off) equal,
    # step for step (the model's draws are keyed, none is taken)
    off = read_stats(smoke_runs[1] / "runs" / "smoke" / "C2"
                     / "agglomeration-EAM", "EAM")
    assert len(off["Time"]) == len(st["Time"]) and off["nAgg"][-1] > 0
    for col in off:
        assert np.array_equal(off[col], st[col]), col


@pytest.mark.slow
def test_smoke_C2_with_strong_loads_breaks_and_replays(tmp_path, foam_env):
    """A break-up entry of the test's own (breakupModels' stressThreshold
    with every stress coefficient 10^4 times larger, rotationFactor
    625): agglomerates break in the smoke run, and the driver's report
    (channel.post.breakup) agrees with the files it reads: the logged
    break-ups are the counted ones, per mechanism; the kinetic energy of
    the records' splits is the sum of the solver log's per-step changes;
    breakupReplay -check reproduces each; the halved stresses keep the
    break-ups whose logged ratio exceeds 2 (the loads are linear in the
    coefficients), binary splits the same parents, and without the spin's
    mechanism no break-up is by rotation; primaries are kept."""
    case = copy(tmp_path, "strongLoads")
    models = case / "breakupModels"
    text = models.read_text()
    entry = "stressThreshold\n{" + text.split("\nstressThreshold\n{", 1)[1]
    entry = entry[:entry.index("\n}\n") + 3]
    strong = entry.replace("stressThreshold\n{", "strongLoads\n{", 1) \
        .replace("Cv 1; Ci 1; Cd 1; rotationFactor 0.0625;",
                 "Cv 1e4; Ci 1e4; Cd 1e4; rotationFactor 625;")
    assert strong.count("1e4") == 3
    models.write_text(text + "\n" + strong)
    res = subprocess.run(["./Allrun", "-preset", "smoke", "-configs", "C2",
                          "-np", "1", "-every", "600"], cwd=case,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    report = json.loads((case / "runs" / "smoke" / "report"
                         / "breakup.json").read_text())
    total = 0
    for m in ("EAM", "MAM"):
        rep = report[f"C2 {m}"]
        agg = case / "runs" / "smoke" / "C2" / f"agglomeration-{m}"
        st = read_stats(agg, m)
        assert (st["nPrimaries"] == st["nPrimaries"][0]).all()
        ev = breakuplog.read_breakup_events(agg, m)
        replay = rep["events"]["replay"]
        mechs = replay["mechanisms"]
        counted = [int(st["nBreakup" + k[0].upper() + k[1:]][-1])
                   for k in mechs]
        assert rep["events"]["logged"] == len(ev) == sum(counted)
        total += len(ev)
        e = rep["events"]["energyChange"]
        assert e["sum"] == pytest.approx(rep["energyChangeLog"], rel=1e-5)
        run, halved, binary, no_rot = replay["configurations"]
        assert [c["name"] for c in replay["configurations"]] == \
            ["run", "stressesHalved", "binary", "noRotation"]
        assert run["reproduced"] == len(ev) and run["byMechanism"] == counted
        assert halved["breaks"] == int(np.sum(ev["values"][:, 0] > 2))
        assert binary["breaks"] == len(ev)
        assert no_rot["byMechanism"][mechs.index("rotation")] == 0
    assert total > 0
