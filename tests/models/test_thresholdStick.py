"""An agglomeration model that lives only in the test tree
(tests/models/agglomerationModels/thresholdStick: its folder plus one line
in tests/models/Make/files) is selected by name in a case, counted in
stats.dat and the statistics' restart state under the names it declares,
logged with its branch names and replayed by hardSphereReplay; no file of
the library, the utilities or aggloTools names it. The expectations come
from the log's own pre-collision states: the model sticks every impact
with |u_n| <= vStick, so the counts follow from u_n computed here."""

import re
import subprocess
from pathlib import Path

import numpy as np

from aggloTools import eventlog, placement
from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.stats import stats_rows
from aggloTools.times import time_dirs

ROOT = Path(__file__).resolve().parents[2]
D, LB, N, V_STICK = 12e-6, 1.6e-4, 300, 1.5e-3


def stick_gas(case):
    """300 quartz primaries at about 2 mm/s in a periodic box with walls
    in y, the test model selected with its coefficient and the event log
    on; the library of the test models loaded by controlDict."""
    rng = np.random.default_rng(5)
    xs = placement.place(N, 1.2 * D, (0, 0.6 * D, 0),
                         (LB, LB - 0.6 * D, LB), (LB, None, LB), rng)
    U = rng.normal(0, 1.5e-3, (N, 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i)
             for i, (x, u) in enumerate(zip(xs, U))]
    model = (f"thresholdStick; thresholdStickCoeffs {{ vStick {V_STICK!r}; "
             "} eventLog true")
    box_case(case, L=(LB,) * 3, n=(5, 5, 5),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=8e-3, write_interval=40, hard_sphere=kernel(model))
    cd = case / "system/controlDict"
    cd.write_text(cd.read_text() + 'libs ("libaggloTestModels.so");\n')
    return case


def normal_speed(ev):
    """|u_n| of each logged pair from its pre-collision states."""
    n = ev["x2"] - ev["x1"]
    n /= np.linalg.norm(n, axis=1)[:, None]
    return -np.einsum("ij,ij->i", ev["U2"] - ev["U1"], n)


def test_model_of_the_test_tree_is_selected_counted_logged_replayed(
        case_dir, foam_env):
    c = stick_gas(case_dir / "stick")
    run_case(c)

    # logged with the model's branch names; every event applied
    assert eventlog.branches(c) == ("rebound", "stick")
    ev = eventlog.read_events(c)
    assert len(ev) > 50 and np.all(ev["branch"] <= 1)
    un = normal_speed(ev)
    sticks = un <= V_STICK
    assert 0.1 < sticks.mean() < 0.9, sticks.mean()
    assert np.array_equal(ev["agglomerates"] == 1, sticks)
    assert np.array_equal(ev["branch"] == 1, sticks)

    # counted under its own names, after the common counters
    last = stats_rows(c)[-1]
    assert last["nCol"] == len(ev)
    assert last["nAgg"] == sticks.sum()
    assert last["nFastRebounds"] == np.sum(un > 2 * V_STICK)
    assert "nCaseII" not in last and "nMAMslidingCritII" not in last
    stats = sorted((c / "postProcessing/kinematicCloudHardSphere")
                   .glob("*/stats.dat"))
    head = next(ln for ln in stats[0].read_text().splitlines()
                if ln.startswith("# Time"))
    assert head.split()[-5:] == ["nFastRebounds", "aggRate", "D10", "Dmax",
                                 "mass"]

    # its sum in the restart state of the statistics at the last write
    t = time_dirs(c)[-1]
    state = (c / t / "uniform/lagrangian/kinematicCloud"
             / "kinematicCloudHardSphereStatistics").read_text()
    s = float(re.search(r"\bsumStickSpeed\s+([^;]+);", state).group(1))
    assert np.isclose(s, un[sticks].sum(), rtol=1e-12, atol=0)
    assert int(re.search(r"\bnFastRebounds\s+(\d+);", state).group(1)) \
        == last["nFastRebounds"]

    # replayed: the run's kernel (the test model) reproduces every outcome
    res = eventlog.replay(c, check=True)
    run_ = res["configurations"][0]
    assert res["loggedBranches"] == ["rebound", "stick"]
    assert run_["branches"] == {"rebound": int((~sticks).sum()),
                                "stick": int(sticks.sum())}
    assert run_["compared"] == run_["matches"] == len(ev)


def test_nothing_outside_the_test_tree_names_the_model():
    """The model's folder and its Make/files line are all it takes."""
    hits = subprocess.run(
        ["git", "grep", "-l", "thresholdStick", "--", "src", "applications",
         "tools", "tutorials", "bench", "etc", "bin"],
        cwd=ROOT, capture_output=True, text=True)
    assert hits.returncode == 1 and hits.stdout == "", hits.stdout
    files = (ROOT / "tests/models/Make/files").read_text()
    assert sum("thresholdStick" in ln for ln in files.splitlines()) == 1
