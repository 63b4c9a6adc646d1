"""A restart continues at the exact time that was written, not at the
time folder's name (rounded to timePrecision digits, which OpenFOAM v1912
takes when the stored name matches; aggloPimpleFoam's restoreStartTime.H):
with dt = 1/30000 s and timePrecision 4 the folder name of step 3 differs
from the stored value, and a run restarted there ends with the same time
value and the same particles, byte for byte, as the uninterrupted run.
A run raises the digits of its time names where its times need them
(past t = 1 s with dt = 1/3 s and timePrecision 2: 1.33, 1.667, ...); a
restart from such a folder continues with those digits, as the
uninterrupted run did: from a folder v1912 finds at 17 digits (at which
the stored value names another folder) and from one it does not find at
all (it gives up where 18 and 17 digits write the same name)."""

import re
import shutil

import pytest

from aggloTools import boxcase
from aggloTools.runner import foam_bin, run
from aggloTools.times import time_dirs

DT = 1 / 30000


def stored_value(case, t):
    text = (case / t / "uniform" / "time").read_text()
    return re.search(r"^value\s+(\S+);", text, re.M).group(1)


def test_restart_keeps_the_stored_time(case_dir, foam_env):
    parts = [dict(x=(2e-4 + 1e-4 * i, 5e-4, 5e-4), U=(1e-2, 2e-3 * i, 0),
                  id=i) for i in range(6)]
    whole = case_dir / "whole"
    boxcase.box_case(whole, particles=parts, dt=DT, end_time=6 * DT,
                     write_interval=3, hard_sphere=boxcase.kernel("EAM"))
    run([foam_bin("foamDictionary"), "-entry", "timePrecision", "-set", "4",
         "system/controlDict"], whole, "log.foamDictionary")
    boxcase.run_case(whole)
    names = [t.name for t in time_dirs(whole)]
    assert len(names) == 3, names
    mid, end = names[1], names[2]
    # the name is rounded: OpenFOAM alone would restart 1e-9 s off
    assert float(stored_value(whole, mid)) != float(mid)

    part = case_dir / "restarted"
    shutil.copytree(whole, part)
    shutil.rmtree(part / end)
    run([foam_bin("aggloPimpleFoam")], part, "log.restart")
    assert stored_value(part, end) == stored_value(whole, end)
    for f in sorted((whole / end / "lagrangian" / "kinematicCloud")
                    .iterdir()):
        assert f.read_bytes() == (part / end / "lagrangian" / "kinematicCloud"
                                  / f.name).read_bytes(), f.name


def v1912_found_at(name, precision, most=18):
    """The digits at which OpenFOAM v1912 (Time::setControls) finds the
    start folder of this name, None where it does not: its name at
    timePrecision, else ever fewer digits from the most, giving up at
    the first that writes the same name as the one before."""
    value = float(name)
    old = f"{value:.{precision}g}"
    if old == name:
        return precision
    found = None
    for digits in range(most, precision, -1):
        new = f"{value:.{digits}g}"
        if new == old:
            break
        old = new
        if new == name:
            found = digits
    return found


def test_v1912_search_restated():
    # the names v1912 finds and does not find in the channel study
    assert v1912_found_at("1.900342503529", 10) == 17
    assert v1912_found_at("1.63517843327", 10) is None
    assert v1912_found_at("0.5303281405", 10) == 10


@pytest.mark.parametrize("found", [17, None], ids=["at17", "notFound"])
def test_restart_where_the_run_raised_the_digits(raised_digits, case_dir,
                                                 found):
    whole = raised_digits
    names = [t.name for t in time_dirs(whole)]
    # two digits until the names need more (OpenFOAM's own rule raises
    # them at every write from 1.33 on)
    assert names[:5] == ["0", "0.33", "0.67", "1", "1.33"], names
    assert len(names) == 52, names
    # the first folder with more digits than timePrecision that v1912
    # finds at 17 digits (1.667), or does not find (16.333317)
    mid = next(i for i, t in enumerate(names[:-1])
               if len(t.replace(".", "")) > 2
               and v1912_found_at(t, 2) == found)
    part = case_dir / "restarted"
    shutil.copytree(whole, part)
    for t in names[mid + 1:]:
        shutil.rmtree(part / t)
    run([foam_bin("aggloPimpleFoam")], part, "log.restart")
    assert [t.name for t in time_dirs(part)] == names
    for t in names[mid + 1:]:
        assert stored_value(part, t) == stored_value(whole, t), t
        for f in sorted((whole / t / "lagrangian" / "kinematicCloud")
                        .iterdir()):
            assert f.read_bytes() == (part / t / "lagrangian"
                                      / "kinematicCloud" / f.name
                                      ).read_bytes(), (t, f.name)
