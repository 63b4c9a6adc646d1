"""tutorials/bendDeposition: the Stokes number's diameter against the hand
formula, the gates' verdicts on made-up rows (each limit fails when it
should: the theory's limits, the serial comparison, the agglomeration
variant's checks), Pui et al.'s expression at its hand values and the
comparison's verdicts, the `ci` preset run end to end in a copy of the
tutorial, serial then on 2 ranks (about 45 s): exit status 0, every row
PASS, the counts from the mass balance adding up to the injected
particles, the 2-rank counts equal to the serial ones, the pictures
written; and the `agglomeration` preset end to end (about 35 s)."""

import json
import math
import shutil
import subprocess

import pytest

from aggloTools.runner import project_dir, tutorial_module

TUT = project_dir() / "tutorials" / "bendDeposition"
efficiency = tutorial_module("bendDeposition", "bendEfficiency")
agglomeration = tutorial_module("bendDeposition", "bendAgglomeration")
driver = tutorial_module("bendDeposition", "bendDeposition")
measured = tutorial_module("bendDeposition", "bendMeasured")


def test_stokes_number_diameter():
    """St = rho_p d^2 U / (9 mu D): at St = 1 in air (mu = 1.8e-5 Pa s)
    at 3 m/s in a 5 mm pipe, rho_p = 2200: d = sqrt(9 mu D / (rho_p U))
    = 11.08 um."""
    assert driver.U_MEAN == pytest.approx(3.0)
    assert driver.diameter(1.0) == pytest.approx(
        math.sqrt(9 * 1.8e-5 * 5e-3 / (2200 * 3.0)), rel=1e-12)
    assert driver.diameter(1.0) == pytest.approx(11.08e-6, rel=1e-3)


def row(st, eta, n=1000, flight=0, injected=1000):
    return dict(St=st, eta=eta, sigma=math.sqrt(eta * (1 - eta) / n),
                entered=n, inFlight=flight, undecided=flight,
                injected=injected, expected=1000)


def test_gate_verdicts():
    """Each limit of the gate fails a row that breaks it, and only it."""
    good = [row(0.05, 0.03), row(0.5, 0.5), row(5.0, 0.97)]
    assert [r["verdict"] for r in efficiency.judge(good)] == ["PASS"] * 3
    # tracers that deposit
    bad = efficiency.judge([row(0.05, 0.2), row(0.5, 0.5), row(5.0, 0.97)])
    assert [r["verdict"] for r in bad] == ["FAIL", "PASS", "PASS"]
    # ballistic particles that do not
    bad = efficiency.judge([row(0.05, 0.03), row(0.5, 0.5), row(5.0, 0.8)])
    assert [r["verdict"] for r in bad] == ["PASS", "PASS", "FAIL"]
    # a fall beyond 2 sigma with St, but not within it
    bad = efficiency.judge([row(0.05, 0.03), row(0.5, 0.6), row(1.0, 0.5),
                        row(5.0, 0.97)])
    assert [r["verdict"] for r in bad] == ["PASS", "PASS", "FAIL", "PASS"]
    ok = efficiency.judge([row(0.05, 0.03), row(0.5, 0.6), row(1.0, 0.59),
                       row(5.0, 0.97)])
    assert all(r["verdict"] == "PASS" for r in ok)
    # particles lost or left in flight
    bad = efficiency.judge([row(0.05, 0.03, flight=30), row(0.5, 0.5,
                        injected=999), row(5.0, 0.97, flight=20)])
    assert [r["verdict"] for r in bad] == ["FAIL", "FAIL", "PASS"]


def test_serial_comparison_gate():
    """A row on N ranks FAILs when one count differs from the serial
    row's, names the count, and says n/r without a serial run."""
    serial = [dict(row(0.3, 0.5), deposited={"bend": 500},
                   escaped={"outlet": 500})]
    same = [dict(r) for r in serial]
    r = efficiency.compare(efficiency.judge(same), serial)[0]
    assert (r["verdict"], r["serial"]) == ("PASS", "same counts")
    moved = [dict(serial[0], deposited={"bend": 499, "outletPipe": 1})]
    r = efficiency.compare(efficiency.judge(moved), serial)[0]
    assert (r["verdict"], r["serial"]) == ("FAIL", "differs: deposited")
    alone = efficiency.compare(efficiency.judge([dict(serial[0])]), None)[0]
    assert alone["verdict"] == "PASS" and alone["serial"].startswith("n/r")


def test_pui_expression_hand_values():
    """Pui et al.'s laminar expression (doc/bendDeposition.md, 2) at the
    hand values: x = St/0.171 = 1 gives P = 1/2 for 90 degrees and 2^-2
    for 180 degrees, whatever the exponent; x = 2 checks the exponent's
    coefficients (2^3.146 = 8.852); St = 0 deposits nothing; a negative
    St is refused."""
    assert measured.eta_pui(0.171) == pytest.approx(0.5, rel=1e-14)
    assert measured.eta_pui(0.171, angle=math.pi) == pytest.approx(
        0.75, rel=1e-14)
    # x = 2: the exponent 0.452 * 2 + 2.242 = 3.146 by hand
    assert measured.eta_pui(0.342) == pytest.approx(
        1 - 1 / (1 + 2 ** 3.146), rel=1e-12)
    assert measured.eta_pui(0.342) == pytest.approx(8.852 / 9.852,
                                                    abs=1e-4)
    assert measured.eta_pui(0.0) == 0.0
    assert measured.eta_pui(0.05) == pytest.approx(0.051, abs=5e-4)
    assert measured.eta_pui(1.0) == pytest.approx(1.0, abs=5e-4)
    with pytest.raises(ValueError, match="St -0.1"):
        measured.eta_pui(-0.1)


def test_measured_verdicts():
    """A row within 0.1 + 3 sigma of the expression PASSes, one beyond
    FAILs, on either side; a bend other than Pui et al.'s (Re, R/a)
    prints n/r with the reason; the summary counts and names the rows
    outside; the gate's verdict is left as it was."""
    # St 0.171: eta_Pui = 0.5; n = 1000: sigma(0.62) = 0.01535
    near = dict(row(0.171, 0.62), verdict="PASS")
    far = dict(row(0.171, 0.66), verdict="PASS")
    low = dict(row(0.171, 0.34), verdict="PASS")
    rows = measured.compare([near, far, low], 1000, 5.6)
    assert [r["measured"] for r in rows] == ["PASS", "FAIL", "FAIL"]
    assert all(r["verdict"] == "PASS" for r in rows)
    assert rows[0]["etaPui"] == pytest.approx(0.5)
    line = measured.summary(rows)
    assert "1 of 3 within" in line and "outside: St 0.171, 0.171" in line
    for re_, curv, why in ((6000, 5.6, "Re 6000"), (1000, 10, "R/a 10")):
        r = measured.compare([row(0.171, 0.5)], re_, curv)[0]
        assert r["measured"].startswith("n/r") and why in r["measured"]
        assert "etaPui" not in r
    assert measured.summary([r]) is None
    text = efficiency.table([dict(near, d=5e-6, deposited={},
                                  escaped={})], measured.summary([near]))
    assert "Pui87" in text and "0.500  PASS" in text


def agg_row(**kw):
    r = dict(injected=100, accounted=100, nAgg=3, deposited={"bend": 40},
             depositedPrimaries={"bend": 43})
    r.update(kw)
    return r


def test_agglomeration_gate():
    """Each check of the agglomeration variant fails alone: a primary
    missing, no agglomeration, agglomerates not deposited whole."""
    assert agglomeration.judge(agg_row())["verdict"] == "PASS"
    for bad, check in ((dict(accounted=99), "every primary accounted for"),
                       (dict(nAgg=0), "agglomerates formed"),
                       (dict(depositedPrimaries={"bend": 40}),
                        "agglomerates deposited whole")):
        r = agglomeration.judge(agg_row(**bad))
        assert r["verdict"] == "FAIL"
        assert [k for k, ok in r["checks"].items() if not ok] == [check]


def copy_tutorial(tmp_path):
    tut = tmp_path / "bendDeposition"
    shutil.copytree(TUT, tut, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    return tut


def test_ci_preset_end_to_end(tmp_path, foam_env):
    tut = copy_tutorial(tmp_path)
    res = subprocess.run(["./Allrun", "-preset", "ci", "-every", "1"],
                         cwd=tut, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    out = tut / "runs/ci/report"
    summary = json.loads((out / "summary.json").read_text())
    rows = summary["rows"]
    assert [r["St"] for r in rows] == [0.02, 0.3, 5.0]
    for r in rows:
        assert r["verdict"] == "PASS", r
        counted = (r["inFlight"] + sum(r["deposited"].values())
                   + sum(r["escaped"].values()))
        assert counted == r["injected"] == 300
        assert r["entered"] == (300 - r["deposited"].get("inletPipe", 0)
                                - r["undecided"])
        assert 0 <= r["undecided"] <= r["inFlight"]
        assert r["eta"] == pytest.approx(
            r["deposited"].get("bend", 0) / r["entered"], rel=1e-12)
        # compared with Pui et al.'s expression (R/a 5.6, Re 1000)
        assert r["etaPui"] == measured.eta_pui(r["St"])
        assert r["measured"] == ("PASS" if abs(r["eta"] - r["etaPui"])
                                 <= 0.1 + 3 * r["sigma"] else "FAIL")
    for png in ("efficiency.png", "deposits.png"):
        assert (out / png).stat().st_size > 10000
    # a second call keeps the finished runs and writes the same report
    res = subprocess.run(["./Allrun", "-preset", "ci"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=300)
    assert res.returncode == 0 and "finished earlier, kept" in res.stdout
    assert json.loads((out / "summary.json").read_text())["rows"] == rows
    # on 2 ranks (scattered decomposition): the serial run's counts
    res = subprocess.run(["./Allrun", "-preset", "ci", "-np", "2"],
                         cwd=tut, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=600)
    assert res.returncode == 0, res.stdout[-3000:]
    two = json.loads((tut / "runs/ci-np2/report/summary.json").read_text())
    assert two["ranks"] == 2
    for r, s in zip(two["rows"], rows):
        assert r["serial"] == "same counts"
        assert {k: r[k] for k in efficiency.SAME} == \
            {k: s[k] for k in efficiency.SAME}
    assert len(list((tut / "runs/ci-np2/St0.3").glob("processor*"))) == 2


def test_agglomeration_preset_end_to_end(tmp_path, foam_env):
    """The dense variant: collisions and agglomerates, every primary
    accounted for, agglomerates deposited whole (more primaries than
    parcels on the walls), the primaries injected equal to the preset's."""
    tut = copy_tutorial(tmp_path)
    res = subprocess.run(["./Allrun", "-preset", "agglomeration"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    r = json.loads((tut / "runs/agglomeration/report/summary.json")
                   .read_text())["rows"][0]
    assert r["verdict"] == "PASS", r
    assert r["nCol"] > r["nAgg"] > 0
    total = (r["inFlightPrimaries"] + sum(r["depositedPrimaries"].values())
             + sum(r["escapedPrimaries"].values()))
    assert total == r["injected"] == driver.PRESETS["agglomeration"][
        "parcels"]
    walls = ("inletPipe", "bend", "outletPipe")
    assert sum(r["depositedPrimaries"].get(w, 0) for w in walls) > \
        sum(r["deposited"].get(w, 0) for w in walls)
    assert (tut / "runs/agglomeration/report/deposits.png").stat() \
        .st_size > 10000
