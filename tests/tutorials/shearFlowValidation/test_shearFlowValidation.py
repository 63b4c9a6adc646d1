"""tutorials/shearFlowValidation: the theory of doc/cases.md B.2 as coded in
the post-processing (hand values of the spec), and the `ci` preset run end
to end in a copy of the tutorial (about 4-5 minutes on 2 cores).

The ci preset resolves: the detection-only first-contact count against
Saffman-Turner (100 expected contacts, 10 %), the conservation of mass and
primaries, N_p never increasing, and N_p(t)/N_p(0) against the B.8 curve
driven by the run's own kernel. Its alpha is statistically meaningless
(about one first-contact agglomeration), so only the wide band is gated."""

import json
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from aggloTools.runner import project_dir, tutorial_module

TUT = project_dir() / "tutorials" / "shearFlowValidation"
theory = tutorial_module("shearFlowValidation", "shear.theory")


def saturated_fraction(png):
    """The share of coloured (not black, grey or white) pixels of a PNG:
    plotted data lines, markers, legends and colour scales; 0 for a
    picture of empty axes."""
    import matplotlib.image
    img = matplotlib.image.imread(png)[..., :3]
    return float(((img.max(axis=-1) - img.min(axis=-1)) > 0.2).mean())


# ----------------------------------------------------------------- theory

def test_alpha_theory_matches_spec_table():
    """doc/cases.md B.2: f(1, 2, 4 um) = 0.95, 0.87, 0.79 (van de Ven & Mason),
    f(25 um) = 0.5785, the group 1.4538e-7 and alpha_th at the tabulated
    diameters."""
    assert theory.f_vdVM([1e-6, 2e-6, 4e-6]) == pytest.approx(
        [0.95, 0.87, 0.79], abs=1e-12)
    assert theory.f_vdVM(25e-6) == pytest.approx(0.5785, abs=1e-4)
    group = 8 * 2.28e-21 / (36 * math.pi * 1e-3 * 71 * (25e-6)**3)
    assert group == pytest.approx(1.4538e-7, rel=1e-4)
    table = {25: 3.401, 26: 3.303, 27: 3.212, 28: 3.126, 30: 2.970,
             31.50: 2.863}
    for d, a in table.items():
        assert 100 * theory.alpha_th(d * 1e-6) == pytest.approx(
            a, abs=6e-4)


def test_kernel_and_decay_match_spec():
    """K_ST = 1.4792e-12 m3/s, the initial rate 650/s, and the B.8
    recursion with K = K_ST and alpha = 0.034 over t*gammaDot = 1400:
    0.9942 (consistent) and 0.9885 (printed)."""
    K = theory.kernel_ST(25e-6)
    assert K == pytest.approx(1.4792e-12, rel=1e-4)
    V, N0, gamma = 6.4e-6, 75000, 71.0
    assert 0.5 * K * (N0 / V)**2 * V == pytest.approx(650.0, rel=1e-3)
    n, dt = 280000, 0.005 / gamma
    dn = np.full(n, 0.5 * K * N0**2 / V * dt)   # constant n (B.4)
    ns = np.full(n, N0)
    for form, end in (("consistent", 0.9942), ("printed", 0.9885)):
        th = theory.decay_theory(N0, dn, ns, 0.0340, form)
        assert th[-1] / N0 == pytest.approx(end, abs=1e-4)


def test_decay_removes_alpha_particles_per_collision():
    """The consistent form removes alpha particles per collision (to first
    order), the printed form 2 alpha."""
    N0, a = 1e6, 0.05
    dn = np.array([10.0])
    for form, c in (("consistent", 1), ("printed", 2)):
        th = theory.decay_theory(N0, dn, [N0], a, form)
        assert N0 - th[1] == pytest.approx(c * a * 10, rel=1e-5)


# -------------------------------------------------------------- ci preset

@pytest.fixture(scope="module")
def ci_results(tmp_path_factory, foam_env):
    tut = tmp_path_factory.mktemp("shearFlow") / "shearFlowValidation"
    shutil.copytree(TUT, tut, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    res = subprocess.run(["./Allrun", "-preset", "ci"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=1800)
    (tut / "log.Allrun").write_text(res.stdout)
    out = tut / "runs" / "ci" / "report"
    assert (out / "summary.json").exists(), res.stdout[-3000:]
    return res, json.loads((out / "summary.json").read_text()), tut


def test_ci_regression_table(ci_results):
    """The Allrun prints the regression table, saves it, exits 0 with no
    FAIL row, and writes the plots."""
    res, summary, tut = ci_results
    out = tut / "runs" / "ci" / "report"
    assert "shearFlowValidation regression, preset ci" in res.stdout
    # the report goes with the run; nothing is written into results/
    assert not (tut / "results").exists()
    assert f"Results: {tut}/runs/ci/report" in res.stdout
    assert (out / "regression.txt").read_text().strip().endswith("0 FAIL")
    assert res.returncode == 0, res.stdout[-3000:]
    # every plot shows data (coloured lines or markers)
    for png in ("alpha", "counts", "decay", "firstContacts"):
        assert saturated_fraction(out / f"{png}.png") > 1e-3, png
    # the particle pictures: agglomerates (coloured) where there are any
    for name in ("EAM", "MAM"):
        f = saturated_fraction(out / f"particles{name}.png")
        n_agg = summary["runs"][name]["N_agg"]
        assert (f > 0) == (n_agg > 0), (name, f, n_agg)


def test_ci_first_contacts_match_saffman_turner(ci_results):
    """Ghost contacts, first counting, t*gammaDot 1 -> 71: within 3 sqrt(N)
    of (1/2) K_ST n0^2 V (t - t0) (doc/cases.md B.6), and a constant slope in
    each half."""
    _, s, _ = ci_results
    det = s["detect"]
    assert det["N_expected"] == pytest.approx(1.430 * 70, rel=2e-3)
    assert abs(det["N_first"] - det["N_expected"]) \
        <= 3 * math.sqrt(det["N_expected"])
    for ns, ne in det["halves"]:
        assert abs(ns - ne) <= 3 * math.sqrt(ne)
    # ghost: nothing can repeat before the pair separates and is released
    assert det["N_repeat"] == 0


def test_ci_conservation_and_decay(ci_results):
    """Mass to 1e-12, primaries exactly, N_p = N_p(0) - N_agg and N_p(t)
    within 5 % of the consistent B.8 curve driven by its own kernel."""
    _, s, _ = ci_results
    for name in ("EAM", "MAM"):
        r = s["runs"][name]
        assert r["mass_rel_error"] <= 1e-12
        assert r["Np_final_over_Np0"] == pytest.approx(
            1 - r["N_agg"] / s["N0"], abs=1e-12)
        assert r["Np_max_deviation_consistent"] <= 0.05
        # paper counting: repeated contacts dominate (doc/cases.md B.4)
        assert r["N_col"] > 10 * r["N_col_first"]
    rows = {r["check"]: r for r in s["regression"]}
    assert all(r["status"] != "FAIL" for r in rows.values())


def test_ci_replay_of_the_event_logs(ci_results):
    """shear.post.replay (doc/eventLog.md): every run's log holds its first
    contacts; the EAM and MAM runs' own kernels (e_n 0.97) agglomerate on
    replay as often as the runs' first contacts did, and a lower e_n never
    agglomerates less often on the same collisions (EAM: less rebound
    energy; MAM: a larger cohesive share)."""
    _, s, tut = ci_results
    rep = json.loads((tut / "runs/ci/report/replay.json").read_text())
    assert sorted(rep["ensembles"]) == ["EAM", "MAM", "detect"]
    for name in ("EAM", "MAM"):
        res = rep["ensembles"][name]
        own = res["configurations"][0]
        assert own["events"] == s["runs"][name]["N_col_first"]
        assert own["compared"] == own["matches"] == own["events"]
        conf = {c["name"]: c for c in res["configurations"]}
        assert conf[f"{name}097"]["agglomerations"] == \
            s["runs"][name]["N_agg_first"]
    det = rep["ensembles"]["detect"]
    conf = {c["name"]: c for c in det["configurations"]}
    for m in ("EAM", "MAM"):
        a = [conf[f"{m}{e}"]["agglomerations"] for e in ("097", "080", "060")]
        assert a[0] <= a[1] <= a[2], (m, a)


def test_ci_first_contacts_spinless_and_by_partner(ci_results):
    """shear.post.contacts: the run's own kernel, replayed on its first
    contacts as logged, agglomerates as often as the run counted; the
    subsets of primary pairs and pairs with an agglomerate add up to all;
    a ghost particle never spins, so the detect run's spinless replay is
    its replay; and the MAM's test takes the normal relative speed only,
    which the spins do not change, so zero spins change none of its
    outcomes in any ensemble."""
    _, s, tut = ci_results
    fc = json.loads((tut / "runs/ci/report/firstContactsSpinless.json")
                    .read_text())
    assert sorted(fc["ensembles"]) == ["EAM", "MAM", "detect"]
    for name, e in fc["ensembles"].items():
        for k, by in e["kernels"].items():
            for key in ("events", "agg"):
                assert by["all"]["logged"][key] == \
                    by["primaries"]["logged"][key] \
                    + by["withAgglomerate"]["logged"][key], (name, k)
            if k == "MAM097" or name == "detect":
                assert by["all"]["onlyLogged"] == 0, (name, k)
                assert by["all"]["onlySpinless"] == 0, (name, k)
        if name == "detect":
            assert e["withAgglomerate"] == 0
            assert e["spinOverHalfGammaDot"]["values"] == [0, 0, 0]
        else:
            own = e["kernels"][f"{name}097"]["all"]["logged"]
            assert own["events"] == s["runs"][name]["N_col_first"]
            assert own["agg"] == s["runs"][name]["N_agg_first"]


def test_first_contacts_spin_reaches_the_eam_only(ci_results, tmp_path):
    """The EAM run's first contacts given spins of +-gammaDot (a
    constructed log): zeroing them changes EAM outcomes (its Eq. 21 holds
    the rotational energy), never the MAM's."""
    from aggloTools import eventlog
    fc = tutorial_module("shearFlowValidation", "shear.post.contacts")
    _, s, tut = ci_results
    case = tmp_path / "EAM"
    shutil.copytree(tut / "runs/ci/EAM", case, ignore=shutil.ignore_patterns(
        "firstSpinless", "processor*", "[0-9]*"))
    f = eventlog.folder(case) / "events0.bin"
    data = f.read_bytes()
    rec = eventlog.body_records(f, data, eventlog.DTYPE).copy()
    rec["omega1"][:, 2] = 71.0
    rec["omega2"][:, 2] = -71.0
    f.write_bytes(data[:eventlog.HEADER_BYTES] + rec.tobytes())
    e = fc.ensemble(case, 71.0)
    eam, mam = (e["kernels"][k]["all"] for k in ("EAM097", "MAM097"))
    assert eam["onlyLogged"] + eam["onlySpinless"] > 0
    assert mam["onlyLogged"] == mam["onlySpinless"] == 0
    assert e["spinOverHalfGammaDot"]["values"] == pytest.approx([2, 2, 2])



# ---------------------------------------------------- the readings study

STUDY_CI = """
matrix { impactVelocity (normal); fluidTorque (on off);
         dtGamma (0.005 0.02); }
"""


@pytest.fixture(scope="module")
def ci_study(tmp_path_factory, foam_env):
    """./Allrun -study -preset ci on a four-variant study (fluid torque
    on and off, dt*gammaDot 0.005 and 0.02: the study's baseline and the
    tutorial's default among them) in a copy of the tutorial."""
    tut = tmp_path_factory.mktemp("shearStudy") / "shearFlowValidation"
    shutil.copytree(TUT, tut, ignore=shutil.ignore_patterns(
        "runs", "__pycache__"))
    (tut / "study").write_text(STUDY_CI)
    res = subprocess.run(["./Allrun", "-study", "-preset", "ci"], cwd=tut,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=1800)
    (tut / "log.Allrun").write_text(res.stdout)
    out = tut / "runs" / "ci" / "study" / "report"
    assert res.returncode == 0, res.stdout[-3000:]
    # a plain run leaves the committed results as they are
    assert not (tut / "results" / "study-ci").exists()
    return json.loads((out / "study.json").read_text()), tut


@pytest.mark.slow
def test_ci_study_counts(ci_study):
    """Each variant's counts add up by category (the event log against the
    statistics' counters), and the tutorial's default variant is the
    tutorial's own ci run: the committed results/ci counts, exactly."""
    study, tut = ci_study
    names = [v["name"] for v in study["variants"]]
    assert names == ["normal-torque-dt0.005", "normal-torque-dt0.02",
                     "normal-noTorque-dt0.005", "normal-noTorque-dt0.02"]
    assert study["default"] == "normal-noTorque-dt0.02"
    ci = json.loads((tut / "results/ci/summary.json").read_text())
    ref = ci["runs"]
    for v in study["variants"]:
        assert set(v["statements"]) == {"S1", "S1d", "S1b", "S1c", "S2",
                                        "S3", "S4", "S4b", "S5", "S6",
                                        "S7", "S8"}
        assert set(v["statements"].values()) <= {"PASS", "FAIL", "n/r"}
        for m in ("EAM", "MAM"):
            r = v[m]
            cats = ("first", "repeat", "overlapStart")
            assert sum(r[f"N_col_{c}"] for c in cats) == r["N_col"]
            assert sum(r[f"N_agg_{c}"] for c in cats) == r["N_agg"]
            # every agglomeration removes one particle
            assert r["Np_final_over_Np0"] == pytest.approx(
                1 - r["N_agg"] / ci["N0"], abs=1e-12)
    d = study["variants"][3]
    for m in ("EAM", "MAM"):
        assert d[m]["N_col"] == ref[m]["N_col"]
        assert d[m]["N_agg"] == ref[m]["N_agg"]
        assert d[m]["N_col_first"] == ref[m]["N_col_first"]


@pytest.mark.slow
def test_ci_study_undisturbed_and_diagnosis(ci_study):
    """The undisturbed ensemble (without fluid torque) replayed through
    the default kernels is the committed ci replay of the tutorial's
    detect run (EAM097, MAM097: the same kernels on the same first
    contacts); the diagnosis of the baseline EAM run replays its own
    kernel, so its agglomerating fraction per category is the run's
    own."""
    study, tut = ci_study
    rep = json.loads((tut / "results/ci/replay.json").read_text())
    conf = {c["name"]: c for c in
            rep["ensembles"]["detect"]["configurations"]}
    d = study["variants"][3]
    for m in ("EAM", "MAM"):
        assert d["undisturbedAlphaFirst"][m] == pytest.approx(
            conf[f"{m}097"]["alpha"], rel=1e-9)
    d = study["variants"][0]
    diag = study["diagnosis"]["Baseline"]
    for cat in ("first", "repeat", "overlapStart"):
        n = d["EAM"][f"N_col_{cat}"]
        assert diag[cat]["events"] == n
        if n:
            assert diag[cat]["alpha_EAMnormal"] == pytest.approx(
                d["EAM"][f"N_agg_{cat}"] / n, rel=1e-12)


@pytest.mark.parametrize("entry, ok", [
    ("EAMCoeffs { impactVelocity full; }", True),
    ("agglomerationModel MAM;", False),
    ("MAMCoeffs { closure table4; }", False),
])
def test_kernel_coeffs_hold_only_the_runs_model(tmp_path, entry, ok):
    """A caseSettings' kernelCoeffs edited by hand to hold another entry
    than the run's own <model>Coeffs (agglomerationModel MAM would turn
    the EAM run into a MAM run unseen) is refused when the run is read."""
    entries = tutorial_module("shearFlowValidation", "shear.case.entries")
    text = subprocess.run(
        [str(project_dir() / ".venv/bin/python"), "-m", "shear.case",
         "settings", "ci", "EAM"], cwd=TUT, capture_output=True, text=True,
        check=True).stdout
    assert "kernelCoeffs        {  }" in text
    f = tmp_path / "system" / "caseSettings"
    f.parent.mkdir()
    f.write_text(text.replace("kernelCoeffs        {  }",
                              f"kernelCoeffs {{ {entry} }}"))
    if ok:
        assert entries.read_settings(tmp_path)["agglomerationModel"] \
            == "EAM"
    else:
        with pytest.raises(SystemExit, match="kernelCoeffs may hold only "
                           "EAMCoeffs"):
            entries.read_settings(tmp_path)
