"""The grid robustness of the judged comparisons (channel.post.gridCheck):
a ratio whose direction holds beyond 3 sigma at 64^3 and 48^3 passes, one
that flips between the grids is grid-dependent (FAIL, not agreement), one
within 3 sigma of 1 at a grid is undecided (n/r); only the pairs both
grids ran are compared. The report of regime64 (no runs: C1 from the
regime study at both grids) carries the rows, with the ratios of the
committed record computed here by hand."""

import json
import math
import shutil
import subprocess
import sys

import pytest

from channelTestRuns import TUTORIAL, script

S2 = 3600.0


def run(col, agg, rel=0.02):
    f_col, f_agg = col / S2, agg / S2
    return {"f_col": f_col, "f_agg": f_agg, "sigma_col": rel * f_col,
            "sigma_agg": rel * f_agg, "alpha_f": f_agg / f_col,
            "scale": S2}


@pytest.fixture(scope="module")
def mods():
    return script("channel.post.gridCheck"), script("channel.post.regression")


def by_name(rows):
    return {r["quantity"]: r for r in rows}


def test_holds_flips_undecided(mods):
    grid, reg = mods
    fine = {("C1", "EAM"): run(8e4, 700), ("C2", "EAM"): run(6e4, 170),
            ("C1", "MAM"): run(8e4, 500), ("C2", "MAM"): run(6e4, 130)}
    coarse = {("C1", "EAM"): run(3e4, 1000), ("C2", "EAM"): run(2e4, 250),
              ("C1", "MAM"): run(3e4, 900), ("C2", "MAM"): run(9e4, 880)}
    rows = by_name(grid.grid_rows(reg.R, fine, coarse))
    r = rows["grid EAM f_col C2/C1 (64^3/48^3)"]
    assert r["status"] == "PASS" and r["note"].startswith("holds at both")
    assert r["sim"] == pytest.approx((6 / 8) / (2 / 3), rel=1e-12)
    # MAM: C2 below C1 at 64^3, above at 48^3 (3.0 +- 0.08)
    r = rows["grid MAM f_col C2/C1 (64^3/48^3)"]
    assert r["status"] == "FAIL" and "grid-dependent" in r["note"]
    assert "64^3 below 1, 48^3 above 1" in r["note"]
    # MAM f_agg: 130/500 at 64^3, 880/900 (within 3 sigma of 1) at 48^3
    r = rows["grid MAM f_agg C2/C1 (64^3/48^3)"]
    assert r["status"] == "n/r" and "48^3 within 3 sigma" in r["note"]
    assert rows["grid C1 f_col EAM/MAM (64^3/48^3)"]["status"] == "n/r"
    # only what both grids ran
    del coarse[("C2", "MAM")]
    rows = by_name(grid.grid_rows(reg.R, fine, coarse))
    assert not any("MAM" in k and "C2/C1" in k for k in rows)
    assert "grid EAM alpha_f C2/C1 (64^3/48^3)" in rows
    # nothing at the coarser grid: said in one row
    rows = grid.grid_rows(reg.R, fine, {})
    assert len(rows) == 1 and rows[0]["status"] == "n/r"
    assert "no finished runs at 48^3" in rows[0]["note"]


def test_report_of_regime64_from_the_study(tmp_path):
    case = tmp_path / "verticalChannel"
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
        "runs", "__pycache__"))
    res = subprocess.run([sys.executable, "-m", "channel.post", "regime64"],
                         cwd=case, capture_output=True, text=True)
    assert res.returncode in (0, 1), res.stderr[-2000:]
    text = (case / "runs/regime64/report/regression.txt").read_text()
    line = next(x for x in text.splitlines()
                if x.startswith("grid C1 f_col EAM/MAM (64^3/48^3)"))
    study = {v["name"]: v["result"]["models"] for v in json.loads(
        (TUTORIAL / "results/regime/regime.json").read_text())["variants"]
        if v["result"]}

    def ratio(name):
        return study[name]["EAM"]["f_col_scaled"] / \
            study[name]["MAM"]["f_col_scaled"]
    assert float(line.split()[5]) == pytest.approx(
        ratio("regime64") / ratio("regime48"), rel=1e-3)
    assert math.isclose(ratio("regime64"), 50004 / 48492, rel_tol=1e-4)
