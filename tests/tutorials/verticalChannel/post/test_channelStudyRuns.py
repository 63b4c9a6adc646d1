"""The regime study's C1 in a preset's report (channel.post.studyRuns):
where the preset has no C1 run of its own, C1's rows are the study's
committed numbers (results/regime/regime.json) for that preset; a record
made with other settings than the preset's is refused naming them; the
preset's own C1 run comes first; the committed record of regime64 gives
the study's published C1 (README.md, 'The study's result'); an own C1 run
is compared with the record (identical, within 2 sigma, or a FAIL)."""

import copy
import json
import math

import pytest

from channelTestRuns import script


@pytest.fixture(scope="module")
def mods():
    return (script("channel.post.studyRuns"),
            script("channel.post.regression"),
            script("channel.case.settings"))


def record(study, name="regime64"):
    return copy.deepcopy(study.study_record(name))


def rows(reg, p, res):
    return {r["quantity"]: r for r in reg.regression(p, res)}


def test_committed_record_gives_the_study_c1(mods):
    """regime64's C1 from the committed record: the rows carry the
    study's f_col x s^2 (50,004 / 48,492 with sigma 1,342 / 1,675), f_agg
    x s^2 (864 / 504) and alpha_f, the events in the window; the
    conservation rows say where it was checked."""
    study, reg, channel = mods
    p = channel.preset("regime64")
    res = study.study_runs(p, {})
    assert sorted(res) == [("C1", "EAM"), ("C1", "MAM")]
    v = record(study)["result"]["models"]
    r = rows(reg, p, res)
    for m in ("EAM", "MAM"):
        col = r[f"C1 {m} f_col x s^2"]
        assert col["sim"] == pytest.approx(v[m]["f_col_scaled"], rel=1e-12)
        assert col["sigma"] == pytest.approx(v[m]["sigma_col_scaled"],
                                             rel=1e-12)
        assert f"{v[m]['events_col']:.0f} events" in col["note"]
        agg = r[f"C1 {m} f_agg x s^2"]
        assert agg["sim"] == pytest.approx(v[m]["f_agg_scaled"], rel=1e-12)
        assert r[f"C1 {m} alpha_f = f_agg/f_col"]["sim"] == \
            pytest.approx(v[m]["alpha_f"], rel=1e-12)
        cons = r[f"C1 {m} conservation"]
        assert cons["status"] == "n/r" and "regime study" in cons["note"]
    assert round(r["C1 EAM f_col x s^2"]["sim"]) == 50004
    assert round(r["C1 MAM f_col x s^2"]["sim"]) == 48492


def test_own_run_first(mods):
    study, _, channel = mods
    p = channel.preset("regime64")
    assert study.study_runs(p, {("C1", "EAM"): {}, ("C1", "MAM"): {}}) == {}
    # only the model without its own run comes from the study
    assert list(study.study_runs(p, {("C1", "EAM"): {}})) == [("C1", "MAM")]


def test_no_record_of_the_preset(mods):
    study, _, channel = mods
    assert study.study_runs(channel.preset("smoke"), {}) == {}


@pytest.mark.parametrize("key, value, named", [
    ("window", [50.0, 200.0], "window"),
    ("dtStar", 0.02, "dtStar"),
    ("nParticles", 300000, "nParticles"),
    ("phases", [240, 100, 400, 200], "phases"),
    ("grid", [64, 128, 64], "grid"),
    ("UTolerance", 1e-6, "UTolerance")])
def test_record_of_other_settings_refused(mods, tmp_path, key, value,
                                          named):
    """A record whose settings are not the preset's (changed here in a
    copy of the record) would pass its numbers for the preset's: refused,
    naming the entry."""
    study, _, channel = mods
    v = record(study)
    v["result"][key] = value
    path = tmp_path / "regime.json"
    path.write_text(json.dumps({"variants": [v]}))
    with pytest.raises(SystemExit) as e:
        study.study_runs(channel.preset("regime64"), {}, path)
    assert f"made with other {named} than presets/regime64" in str(e.value)
    # the unchanged record is taken
    path.write_text(json.dumps({"variants": [record(study)]}))
    assert len(study.study_runs(channel.preset("regime64"), {}, path)) == 2


def own_runs(study, channel, shift_sigmas=0.0):
    """C1's own runs made from the record (as a rerun of the study would
    give them), f_col x s^2 of EAM moved by shift_sigmas of the combined
    sigma."""
    p = channel.preset("regime64")
    res = {k: dict(r) for k, r in study.study_runs(p, {}).items()}
    for r in res.values():
        del r["fromStudy"]
    r = res[("C1", "EAM")]
    s = math.hypot(r["sigma_col"] * r["scale"],
                   record(study)["result"]["models"]["EAM"]
                   ["sigma_col_scaled"])
    r["f_col_scaled"] += shift_sigmas * s
    return p, res


@pytest.mark.parametrize("shift, status, said", [
    (0.0, "PASS", "identical: the record repeated"),
    (1.5, "PASS", "z +1.50 (within 2 sigma: the same statistics"),
    (-2.5, "FAIL", "z -2.50: the physics or the settings changed"),
])
def test_own_run_against_the_record(mods, shift, status, said):
    """A preset's own C1 run is compared with the study's record of it:
    identical, within 2 sigma, or beyond (a FAIL); f_agg and MAM, left as
    the record, are identical."""
    study, reg, channel = mods
    p, res = own_runs(study, channel, shift)
    rows = {r["quantity"]: r for r in
            study.record_rows(reg.R, p, res)}
    assert len(rows) == 4
    col = rows["C1 EAM f_col x s^2: own run / the study's record"]
    assert col["status"] == status and said in col["note"], col
    v = record(study)["result"]["models"]["EAM"]
    assert col["sim"] == pytest.approx(
        (v["f_col_scaled"] + shift * math.hypot(
            v["sigma_col_scaled"], v["sigma_col_scaled"]))
        / v["f_col_scaled"], rel=1e-12)
    for m, q in (("EAM", "agg"), ("MAM", "col"), ("MAM", "agg")):
        r = rows[f"C1 {m} f_{q} x s^2: own run / the study's record"]
        assert r["status"] == "PASS" and r["sim"] == 1.0


def test_no_comparison_without_both(mods, tmp_path):
    """No own C1 run, or no record of the preset: no rows; a record made
    with other settings: n/r, naming them."""
    study, reg, channel = mods
    p, res = own_runs(study, channel)
    assert study.record_rows(reg.R, p, study.study_runs(p, {})) == []
    assert study.record_rows(reg.R, channel.preset("smoke"), res) == []
    v = record(study)
    v["result"]["dtStar"] = 0.02
    path = tmp_path / "regime.json"
    path.write_text(json.dumps({"variants": [v]}))
    rows = study.record_rows(reg.R, p, res, path)
    assert len(rows) == 4
    assert all(r["status"] == "n/r" and "other dtStar: not comparable"
               in r["note"] for r in rows)


def test_record_without_tolerance_is_the_studys(mods):
    """The committed records predate the UTolerance entry; every run of
    the study solved U to 1e-8. So `small`'s record (the study's small,
    U to 1e-8) is not the preset `small` of today (U to 1e-6): its C1 is
    refused naming the tolerance, and the preset's own C1 run is not
    compared with it (n/r) where a FAIL would say the physics changed;
    regime64's record (1e-8, as its preset) is still taken."""
    study, reg, channel = mods
    p = channel.preset("small")
    assert p["UTolerance"] == 1e-6
    assert "UTolerance" not in record(study, "small")["result"]
    with pytest.raises(SystemExit) as e:
        study.study_runs(p, {})
    assert "made with other UTolerance than presets/small" in str(e.value)
    _, res = own_runs(study, channel)
    rows = study.record_rows(reg.R, p, res)
    assert len(rows) == 4
    assert all(r["status"] == "n/r" and "other UTolerance: not comparable"
               in r["note"] for r in rows)
    assert len(study.study_runs(channel.preset("regime64"), {})) == 2
