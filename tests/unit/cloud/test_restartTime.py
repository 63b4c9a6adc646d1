"""A restart continues at the exact time that was written, not at the
time folder's name (rounded to timePrecision digits, which OpenFOAM v1912
takes when the stored name matches; aggloPimpleFoam's restoreStartTime.H):
with dt = 1/30000 s and timePrecision 4 the folder name of step 3 differs
from the stored value, and a run restarted there ends with the same time
value and the same particles, byte for byte, as the uninterrupted run.
A run raises the digits of its time names where its times need them
(past t = 1 s with dt = 1/3 s and timePrecision 2: 1.33, 1.667); a restart
from such a folder continues with those digits, as the uninterrupted run
did, instead of stopping because the stored value names another folder
at the 17 digits v1912 found the folder with."""

import re
import shutil

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
                     write_interval=3, agglomeration="EAM")
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


def test_restart_where_the_run_raised_the_digits(case_dir, foam_env):
    parts = [dict(x=(2e-4 + 1e-4 * i, 5e-4, 5e-4), U=(0, 0, 0), id=i)
             for i in range(3)]
    whole = case_dir / "whole"
    boxcase.box_case(whole, particles=parts, dt=1 / 3, end_time=3.0,
                     write_interval=1, agglomeration="EAM")
    run([foam_bin("foamDictionary"), "-entry", "timePrecision", "-set", "2",
         "system/controlDict"], whole, "log.foamDictionary")
    boxcase.run_case(whole)
    names = [t.name for t in time_dirs(whole)]
    # two digits until the names need more (OpenFOAM's own rule raises
    # them at every write from 1.33 on)
    assert names[:5] == ["0", "0.33", "0.67", "1", "1.33"], names
    assert len(names) == 10, names
    mid = 5
    assert len(names[mid].replace(".", "")) > 3, names
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
