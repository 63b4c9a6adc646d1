"""A restart continues at the exact time that was written, not at the
time folder's name (rounded to timePrecision digits, which OpenFOAM v1912
takes when the stored name matches; aggloPimpleFoam's restoreStartTime.H):
with dt = 1/30000 s and timePrecision 4 the folder name of step 3 differs
from the stored value, and a run restarted there ends with the same time
value and the same particles, byte for byte, as the uninterrupted run."""

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
