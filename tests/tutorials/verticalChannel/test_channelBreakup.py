"""Break-up in the main case: a preset names a model of breakupModels
(`breakup stressThreshold;`), the agglomeration stage runs it and the
stages before it do not; a name that is not there is refused naming the
valid ones. The smoke preset's C2 with break-up (serial, about 40 s):
the break-up counters in stats.dat of the agglomeration stage only, every
agglomerate of every step checked (the log's count against stats.dat's
nAgglomerates of the step), and the largest ratio of load to
strength far below 1 (about 4e-4: the quartz doublets' van der Waals
bond against this flow's stresses), so nothing breaks and the primaries
are kept."""

import re
import shutil
import subprocess
import sys

import pytest

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
def test_smoke_C2_with_breakup(tmp_path, foam_env):
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
