"""A break-up model that lives only in the test tree
(tests/models/breakupKernels/sizeLimit: its folder plus one line in
tests/models/Make/files) is selected by name in a case, counted in
stats.dat under the mechanism it declares, logged with its model, mechanism
and value names in the header, and replayed by breakupReplay; no file of
the library, the utilities or aggloTools names it. The expectations are
hand counts: an agglomerate of N > nMax primaries at rest in still fluid
loses one primary per step until nMax are left."""

import subprocess
from pathlib import Path

import numpy as np

from aggloTools import boxcase, breakuplog
from aggloTools.boxcase import box_case, run_case
from aggloTools.stats import stats_rows

ROOT = Path(__file__).resolve().parents[2]
DP, RHO_P = 12e-6, 2200.0
N_MAX, STEPS = 4, 8
SIZES = (10, 7, 3)      # break-ups: 6 (in steps 1-6), 3, none


def size_limit_case(case):
    """Three VSM agglomerates at rest, far apart, in still fluid without
    forces; the test model with the event log on; the library of the test
    models loaded by controlDict."""
    parts = [dict(x=(x, 5e-4, 5e-4), U=(0, 0, 0), d=DP * n ** (1 / 3),
                  rho=RHO_P, nPrimary=n, id=i)
             for i, (x, n) in enumerate(zip((2e-4, 5e-4, 8e-4), SIZES))]
    hs = boxcase.kernel("EAM", structureModel="VSM")
    brk = {"subModels": {"breakupModel": "sizeLimit", "sizeLimitCoeffs": {
        "nMax": N_MAX, "gap": 0.5, "eventLog": True}}}
    box_case(case, L=(1e-3, 1e-3, 1e-3), n=(4, 4, 4), particles=parts,
             dt=1e-6, end_time=STEPS * 1e-6, write_interval=4,
             hard_sphere=hs, cloud=brk)
    cd = case / "system/controlDict"
    cd.write_text(cd.read_text() + 'libs ("libaggloTestModels.so");\n')
    return case


def test_break_up_model_of_the_test_tree(case_dir, foam_env):
    c = size_limit_case(case_dir / "sizeLimit")
    run_case(c)

    # counted under its own mechanism: one primary per step off each
    # agglomerate above nMax, none below
    expected = sum(min(STEPS, n - N_MAX) for n in SIZES if n > N_MAX)
    assert expected == 9
    rows = stats_rows(c)
    assert rows[-1]["nBreakupSize"] == expected
    assert "nBreakupTurbulence" not in rows[-1]
    assert rows[-1]["nCol"] == 0

    # logged with the model's names; the value is the excess N - nMax
    head = breakuplog.header(c)
    assert head == {"mechanisms": ("size",), "model": ("sizeLimit",),
                    "fields": ("excess",)}
    ev = breakuplog.read_breakup_events(c)
    assert len(ev) == expected
    assert np.array_equal(breakuplog.values(ev, head)["excess"],
                          ev["nPrimary_p"] - N_MAX)
    assert sorted(ev["nPrimary_p"]) == sorted(
        [n for n in range(5, 11)] + [5, 6, 7])
    assert np.all(ev["nPrimary_a"] == 1)

    # replayed: the run's model reproduces every break-up; a variant with
    # nMax 6 breaks the logged parents above 6 (10, 9, 8, 7 and 7)
    res = breakuplog.replay_breakups(c, {"larger": {"nMax": 6}},
                                     check=True)
    assert res["model"] == "sizeLimit"
    run_, larger = res["configurations"]
    assert run_["reproduced"] == run_["breaks"] == expected
    assert larger["breaks"] == 5 == int(np.sum(ev["nPrimary_p"] > 6))


def test_nothing_outside_the_test_tree_names_the_break_up_model():
    """The model's folder and its Make/files line are all it takes."""
    hits = subprocess.run(
        ["git", "grep", "-l", "sizeLimit", "--", "src", "applications",
         "tools", "tutorials", "bench", "etc", "bin"],
        cwd=ROOT, capture_output=True, text=True)
    assert hits.returncode == 1 and hits.stdout == "", hits.stdout
    files = (ROOT / "tests/models/Make/files").read_text()
    assert sum("sizeLimit" in ln for ln in files.splitlines()) == 1
