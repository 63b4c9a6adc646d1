"""A two-way coupled agglomeration stage on 2 ranks repeats bit for bit:
the smoke C2 EAM stage (two-way coupling, collisions across the processor
plane) restarted from its first write, run to its second and compared
file by file with the stored run, REPEATS times from identical files
(tutorials/verticalChannel/README.md, 'Reproducibility': once seen to
part in the 14th digit, about one restart in a hundred; 999 restarts of
this test's kind since agreed). AGGLO_DETERMINISM_REPEATS sets the
number (e.g. 1000, about 50 min on 2 idle cores)."""
import os
import shutil
import subprocess

import numpy as np
import pytest

from aggloTools import times
from channelTestRuns import agg_runs

REPEATS = int(os.environ.get("AGGLO_DETERMINISM_REPEATS", "20"))


def files(folder):
    return {p.relative_to(folder): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.mark.slow
def test_two_rank_two_way_restart_repeats(smoke_runs, tmp_path):
    src = agg_runs(smoke_runs[2])[("C2", "EAM")]
    t = [d.name for d in times.time_dirs(src / "processor0")]
    start, end = t[1], t[2]            # the first and second writes
    stored = {r: files(src / f"processor{r}" / end) for r in (0, 1)}
    assert stored[0] and stored[1]

    def restart(perturb=False):
        """The stage from `start` to `end` in a fresh copy; perturb: the
        first cell's velocity changed in its last bit (the control)."""
        case = tmp_path / "case"
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(src, case, ignore=shutil.ignore_patterns(
            "VTK", "log.*"))
        for p in (case, case / "processor0", case / "processor1"):
            for d in times.time_dirs(p):
                if p == case or d.name != start:
                    shutil.rmtree(d)
        if perturb:
            u = case / "processor0" / start / "U"
            text = u.read_text()
            # the first cell's u_x: after "(" of the list and of its vector
            first = text.index("\n(", text.index("internalField")) + 4
            end_ = text.index(" ", first)
            u_x = float(text[first:end_])
            # the next double: a change that reading cannot round away
            # (a changed 17th digit may name the same double)
            u.write_text(text[:first]
                         + repr(float(np.nextafter(u_x, np.inf)))
                         + text[end_:])
        settings = case / "system" / "caseSettings"
        settings.write_text("".join(
            f"endTime         {end};\n" if ln.startswith("endTime")
            else ln for ln in settings.read_text().splitlines(True)))
        res = subprocess.run(["mpirun", "-np", "2", "aggloPimpleFoam",
                              "-parallel"], cwd=case, capture_output=True,
                             text=True, timeout=600)
        assert res.returncode == 0, res.stdout[-2000:] + res.stderr
        return [sorted(str(f) for f, b in files(case / f"processor{r}"
                                                / end).items()
                       if b != stored[r].get(f)) for r in (0, 1)]

    # the control: a change in the last bit of one cell's velocity
    # shows in the written state
    assert any(restart(perturb=True))
    differ = [(k, d) for k in range(REPEATS) for d in [restart()]
              if any(d)]
    assert not differ, differ
