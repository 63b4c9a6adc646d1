"""tutorials/verticalChannel, what the smoke runs' post-processing makes of
them (the runs: channelTestRuns, once per session): the particle picture
without legacy positions, the regime study's post-processing (contacts
from the event log against the counters, the concentration of a uniform
release, variants not run) and the report's head, sim/paper factors and
comparison between the serial and 2-rank runs."""

import json
import math
import shutil

import numpy as np
import pytest

from aggloTools import cloud, times
from aggloTools.stats import read_stats
from channelTestRuns import N_RELEASED, agg_runs, script


def test_picture_without_legacy_positions(smoke_runs, tmp_path, capsys):
    """A run that writes no legacy positions (the paper preset) still gets
    its particle picture, drawn from the barycentric coordinates and the
    mesh at the same places; a run with neither file is named."""
    post = script("channel.post.postprocess")
    src = agg_runs(smoke_runs[1])[("C1", "EAM")]
    adir = tmp_path / "agglomeration"
    shutil.copytree(src, adir, ignore=shutil.ignore_patterns(
        "processor*", "VTK", "postProcessing"))
    t = times.time_dirs(adir)[-1]
    pos = t / "lagrangian" / "EAM" / "positions"
    x_legacy = cloud.read_positions(pos)
    pos.unlink()
    x = cloud.cloud_positions(adir, t.name, "EAM")
    assert np.abs(x - x_legacy).max() < 1e-12
    p = post.settings.preset("smoke")
    png = post.picture(tmp_path, p, {("C1", "EAM"): (adir, "EAM")})
    assert png is not None and png.stat().st_size > 10000
    (t / "lagrangian" / "EAM" / "coordinates").unlink()
    assert post.picture(tmp_path, p, {("C1", "EAM"): (adir, "EAM")}) is None
    assert "neither positions nor coordinates" in capsys.readouterr().out


def test_regime_study_post(smoke_runs, tmp_path):
    """The regime study's post-processing (channel.regime) on the smoke
    runs: the contacts it reads from the event log add up to the
    statistics' counters (first, repeat and agglomerating contacts of the
    window), the particle concentration at the start of agglomeration is
    that of the uniform release (near-wall over centre within 3 sigma of
    1, Poisson), and a variant not run is reported as such, not guessed."""
    regime = script("channel.regime.study")
    runs = smoke_runs[2] / "runs"
    res = regime.run_post(runs, tmp_path, ["smoke", "regime32"])
    smoke, missing = res["variants"]
    assert missing["result"] is None and missing["progress"] is None
    assert f"regime32       not run in {runs / 'regime32'}" in \
        (tmp_path / "regime.txt").read_text()
    # no grid variant finished: the trend to 128^3 is n/r, not guessed
    assert res["gridTrend"]["variants"] == []
    assert res["gridTrend"]["EAM"]["f_col_scaled"] is None
    assert "EAM f_col_scaled: n/r" in (tmp_path / "regime.txt").read_text()
    r = smoke["result"]
    adir = agg_runs(smoke_runs[2])[("C1", "EAM")]
    for m in ("EAM", "MAM"):
        x = r["models"][m]
        st = read_stats(adir, m)
        ct = x["contacts"]
        assert ct["nFirst"] == x["nColFirst_end"] == st["nColFirst"][-1]
        assert ct["nRepeat"] == x["nColRepeat_end"] == st["nColRepeat"][-1]
        assert ct["nAgg"] == st["nAggFirst"][-1] + st["nAggRepeat"][-1]
        assert ct["nAgg"] >= 25     # the slow seeded pairs
        wb = ct["byWallDistance"]
        assert (sum(wb["n"]), sum(wb["nAgg"])) == (ct["n"], ct["nAgg"])
        # the slow seeded pairs approach at 0.3 mm/s, the fast at 20
        assert 0.25 < np.median(ct["un_mm_s_agg"]) < 0.35
    c = r["concentration"]
    nb = len(c["alpha"])
    per_slab = N_RELEASED / nb
    sigma = math.sqrt(1 / (2 * per_slab) + 1 / (nb / 4 * per_slab))
    assert abs(c["nearWallOverCentre"] - 1) < 3 * sigma, c
    assert (tmp_path / "regime.png").stat().st_size > 10000
    assert json.loads((tmp_path / "regime.json").read_text())[
        "variants"][0]["result"]["models"]["EAM"]["f_col_scaled"] > 0


def test_report_head_factors_and_comparison(smoke_runs):
    """The report says first what its preset resolves and which preset
    to compare with the paper, with the command that runs it; every row
    with a published value carries sim/paper;
    the comparison with another report weighs each value against both
    sigmas: the serial and 2-rank C1 runs (no random numbers) agree
    exactly (z = 0), and nothing differs beyond 3 sigma."""
    post = script("channel.post.postprocess")
    rep = {n: smoke_runs[n] / "runs" / "smoke" / "report" for n in (1, 2)}
    lines = (rep[2] / "regression.txt").read_text().splitlines()
    assert lines[0].startswith("What preset smoke resolves: nothing of")
    assert "preset regime64" in lines[1] and "results/regime" in lines[1]
    assert "./Allrun -preset regime64 -configs C2" in lines[1]
    rows = json.loads((rep[2] / "summary.json").read_text())["regression"]
    with_paper = [r for r in rows if r["sim"] is not None and r["paper"]]
    assert len(with_paper) >= 12
    for r in with_paper:
        assert r["factor"] == pytest.approx(r["sim"] / r["paper"],
                                            rel=1e-12)
    assert any(r["quantity"] == "C1 EAM alpha_f = f_agg/f_col"
               and r["paper"] == pytest.approx(6.67e2 / 8.14e4)
               for r in rows)
    runs2 = json.loads((rep[2] / "summary.json").read_text())["runs"]
    text = post.compare(rows, rep[1] / "summary.json", runs2)
    assert "This run: 2 ranks; the reference: serial." in \
        text.splitlines()[1]
    # the head's near-wall share is the event log's: every run has one
    assert all(0 <= r["nearWallShare"] <= 1 for r in runs2.values())
    c1 = [line for line in text.splitlines()
          if line.startswith("C1 ") and " f_col x s^2" in line]
    assert len(c1) == 2 and all(" 0 " in line and "agree" in line
                                for line in c1), c1
    assert " 0 differ" in text.splitlines()[-1], text.splitlines()[-1]


def test_regime_post_keeps_earlier_results(smoke_runs, tmp_path):
    """post --earlier: a variant whose runs are not under --runs keeps its
    finished result from the earlier regime.json, marked so (the study's
    runs were lost with a machine; its committed numbers stand), and is
    compared with the variants run since; without --earlier it is 'not
    run'."""
    regime = script("channel.regime.study")
    runs = smoke_runs[2] / "runs"
    committed = regime.TUTORIAL / "results" / "regime" / "regime.json"
    before = json.loads(committed.read_text())
    old64 = [v for v in before["variants"] if v["name"] == "regime64"][0]
    res = regime.run_post(runs, tmp_path, ["smoke", "regime64", "printed"],
                          earlier=committed)
    v64 = [v for v in res["variants"] if v["name"] == "regime64"][0]
    assert v64["result"] == old64["result"]
    assert v64["from"] == str(committed)
    assert "Kept from" in (tmp_path / "regime.txt").read_text()
    # the pair printed over regime64: only printed is missing now
    assert res["wallNormal"] == [{"variant": "printed", "base": "regime64",
                                  "missing": ["printed"]}]
    res = regime.run_post(runs, tmp_path, ["smoke", "regime64"])
    v64 = [v for v in res["variants"] if v["name"] == "regime64"][0]
    assert v64["result"] is None and "from" not in v64
    assert json.loads(committed.read_text()) == before


def test_matrix_figure(smoke_runs, tmp_path):
    """matrix.png: each run's f_col x s^2, f_agg x s^2 and alpha_f with
    its sigma beside Table D.6's values, as the report's summary has
    them (C1 and C2 of the 2-rank smoke runs)."""
    mp = script("channel.plots.matrix")
    channel = script("channel.case.settings")
    summary = json.loads((smoke_runs[2] / "runs" / "smoke" / "report"
                          / "summary.json").read_text())
    assert (smoke_runs[2] / "runs" / "smoke" / "report"
            / "matrix.png").stat().st_size > 10000
    res = {tuple(k.split()): v for k, v in summary["runs"].items()}
    pts = mp.matrix_figure(tmp_path, channel.preset("smoke"), res)
    assert (tmp_path / "matrix.png").stat().st_size > 10000
    for m in ("EAM", "MAM"):
        c, v, s, paper = pts["col"][m][0]
        r = res[("C1", m)]
        assert c == "C1" and v == r["f_col_scaled"]
        assert s == pytest.approx(r["sigma_col"] * r["scale"])
        assert paper == channel.TABLE_D6["C1"]["fcol"][m]
        assert [q[0] for q in pts["agg"][m]] == ["C1", "C2"]


def test_allrun_reports_the_dispersion(smoke_runs):
    """./Allrun writes channel.post.dispersion's report beside the
    regression: each configuration run, from its own dispersion case, one
    interval from the release to the end of the dispersion stage (smoke's
    presets entry: unladen 0.2 T*, no release phase, dispersion 0.2 T*:
    T* 0.2 to 0.4), the near-wall concentration of the just released
    uniform cloud within 3 sigma of the centre's (Poisson, 16 bins), and
    the serial and 2-rank runs alike."""
    reports = {}
    for n in (1, 2):
        rep = smoke_runs[n] / "runs" / "smoke" / "report"
        r = json.loads((rep / "dispersion.json").read_text())["runs"]
        assert sorted(r) == ["C1", "C2"]
        text = (rep / "dispersion.txt").read_text()
        for c in ("C1", "C2"):
            assert r[c]["folder"] == f"runs/smoke/{c}/dispersion"
            (x,) = r[c]["intervals"]
            assert (x["T0"], x["T1"]) == pytest.approx((0.2, 0.4),
                                                       rel=1e-9)
            assert any(ln.startswith(f"{c} ") for ln in text.splitlines())
        reports[n] = r
    nb = 16
    per_slab = N_RELEASED / nb
    sigma = math.sqrt(1 / (2 * per_slab) + 1 / (nb / 4 * per_slab))
    for c in ("C1", "C2"):
        cw = [reports[n][c]["intervals"][0]["nearWallOverCentre"]
              for n in (1, 2)]
        assert abs(cw[0] - 1) < 3 * sigma
        assert cw[1] == pytest.approx(cw[0], rel=1e-12)
