"""keyedPatchInjection (submodels/InjectionModels): single particles
through a patch at a steady rate, their random numbers keyed by the
parcel's number. Against hand values: the count floor(rate t), the ids
(origProc -3, origId 0, 1, ...), the size, a uniform spread over the
patch (chi-square over its faces), the mass balance of an outlet that
lets them all escape; a restart continues byte for byte; two ranks that
split the inlet inject the same particles at the same places; bad input
stops naming the entry."""

import math

import numpy as np
import pytest
from scipy import stats as sps

from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.cloud import read_cloud, read_mass_balance, read_positions, \
    cloud_dir
from aggloTools.times import last_time
from aggloTools.foamfile import edit

D = 12e-6
M1 = 2200 * math.pi / 6 * D ** 3
L = 1e-4
ESCAPE = {"patchInteractionModel": "localInteraction",
          "localInteractionCoeffs": {
              "patches": '( ".*" { type escape; } )'}}


def injector(pps, duration, U0=(0.05, 0, 0), placement="area"):
    """keyedPatchInjection at xMin: fixed-size primaries at pps parcels
    per second for the duration, at U0 (placement area) or with the
    fluid's face flux (placement flux)."""
    inlet = {"type": "keyedPatchInjection", "patch": "xMin", "SOI": 0,
             "duration": float(duration), "parcelsPerSecond": float(pps),
             "placement": placement,
             "U0": tuple(U0) if placement == "area" else None,
             "massTotal": 0, "parcelBasisType": "fixed", "nParticle": 1,
             "sizeDistribution": {"type": "fixedValue",
                                  "fixedValueDistribution": {"value": D}}}
    return {"injectionModels": {"inlet": inlet}}


def injection_case(case, pps=2e4, duration=1e-3, end_time=4e-3,
                   write_interval=10, U0=(0.05, 0, 0), n=(4, 4, 4),
                   decompose=(1, 1, 1), placement="area"):
    """An open box (every side a patch; escape everywhere), inlet xMin."""
    return box_case(case, L=(L, L, L), n=n,
                    kinds=("patch", "patch", "patch"), dt=1e-4,
                    end_time=end_time, write_interval=write_interval,
                    hard_sphere=kernel(walls={}), decompose=decompose,
                    cloud={"subModels": {
                        **ESCAPE, **injector(pps, duration, U0,
                                             placement)}})


def test_count_ids_size_and_balance(case_dir, foam_env):
    """2e4 parcels/s for 1 ms: 20 parcels, ids 0-19, d 12 um, nPrimary 1,
    all in the box at 1 ms; at 4 ms all have escaped through xMax (0.05
    m/s over 0.1 mm) and the balance is 20 primaries."""
    injection_case(case_dir)
    run_case(case_dir)
    c = read_cloud(case_dir, "0.001", names=("origProcId", "origId", "d",
                                             "nPrimary", "U"))
    assert sorted(c["origId"]) == list(range(20))
    assert set(c["origProcId"]) == {-3}
    np.testing.assert_array_equal(c["d"], D)
    np.testing.assert_array_equal(c["nPrimary"], 1)
    np.testing.assert_array_equal(c["U"], [[0.05, 0, 0]] * 20)
    x = read_positions(cloud_dir(case_dir, "0.001") / "positions")
    assert x[:, 0].max() < L
    bal = read_mass_balance(case_dir, last_time(case_dir))
    assert last_time(case_dir) == "0.004"
    assert bal["massStart"] == 0 and bal["nPrimariesStart"] == 0
    assert set(bal["escaped"]) == {"xMax"}
    esc = bal["escaped"]["xMax"]
    assert esc["nParcels"] == esc["nPrimaries"] == 20
    np.testing.assert_allclose(esc["mass"], 20 * M1, rtol=1e-13)


def test_spread_over_the_patch_is_uniform(case_dir, foam_env):
    """1600 parcels at rest on the inlet (one step): the counts over the
    16 inlet faces fit a uniform spread (chi-square, p > 0.001); all lie
    on the inlet plane."""
    injection_case(case_dir, pps=1.6e7, duration=1e-4, end_time=1e-4,
                   write_interval=1, U0=(0, 0, 0))
    run_case(case_dir)
    x = read_positions(cloud_dir(case_dir, "0.0001") / "positions")
    assert len(x) == 1600
    assert x[:, 0].max() < 1e-9 * L * 1e3
    iy = np.minimum((x[:, 1] / (L / 4)).astype(int), 3)
    iz = np.minimum((x[:, 2] / (L / 4)).astype(int), 3)
    counts = np.bincount(4 * iz + iy, minlength=16)
    p = sps.chisquare(counts).pvalue
    assert p > 1e-3, (counts, p)
    # and within each face: the quarters of the face centre fit too
    fy = (x[:, 1] / (L / 4)) % 1 < 0.5
    fz = (x[:, 2] / (L / 4)) % 1 < 0.5
    q = np.bincount(2 * fz + fy, minlength=4)
    assert sps.chisquare(q).pvalue > 1e-3, q


def test_flux_placement_follows_the_inflow(case_dir, foam_env):
    """placement flux: the carrier enters through xMin at u = 0.1 m/s
    times (j + 0.5)/4 in the j-th row of faces (y): 1600 parcels at rest
    in a frozen flow spread over the rows as 1:3:5:7 (chi-square, p >
    0.001), each at the velocity of its face."""
    injection_case(case_dir, pps=1.6e7, duration=1e-4, end_time=1e-4,
                   write_interval=1, placement="flux")
    from aggloTools.boxcase import write_internal_U
    write_internal_U(case_dir, (L, L, L), (4, 4, 4),
                     lambda x, y, z: (0.1 * (int(y / (L / 4)) + 0.5) / 4,
                                      0, 0))
    run_case(case_dir)
    c = read_cloud(case_dir, "0.0001", names=("U", "lastPartnerId"))
    x = read_positions(cloud_dir(case_dir, "0.0001") / "positions")
    row = np.minimum((x[:, 1] / (L / 4)).astype(int), 3)
    counts = np.bincount(row, minlength=4)
    assert counts.sum() == 1600
    expected = 1600 * np.array([1, 3, 5, 7]) / 16
    assert sps.chisquare(counts, expected).pvalue > 1e-3, counts
    # U0 absent: each parcel at its face's velocity (no forces; those
    # that collided with another, packed on the inlet plane, aside)
    free = c["lastPartnerId"] == -1
    assert free.sum() > 500
    np.testing.assert_allclose(c["U"][free, 0],
                               0.1 * (row[free] + 0.5) / 4, rtol=1e-12)
    np.testing.assert_array_equal(c["U"][free, 1:], 0)


def test_restart_continues_exactly(case_dir, foam_env):
    """Injecting for 2 ms, restarted at 1 ms: the particles at 3 ms are
    those of the uninterrupted run, byte for byte."""
    runs = {}
    for name in ("whole", "split"):
        runs[name] = injection_case(case_dir / name, duration=2e-3,
                                    end_time=3e-3)
    run_case(runs["whole"])
    ctrl = runs["split"] / "system" / "controlDict"
    edit(ctrl, "endTime 0.003;",
         "endTime 0.001;")
    run_case(runs["split"])
    edit(ctrl, "endTime 0.001;",
         "endTime 0.003;")
    run_case(runs["split"])
    for t in ("0.002", "0.003"):
        whole = sorted(p.relative_to(runs["whole"] / t)
                       for p in (runs["whole"] / t).rglob("*")
                       if p.is_file())
        assert whole
        for f in whole:
            a = (runs["whole"] / t / f).read_bytes()
            assert a == (runs["split"] / t / f).read_bytes(), f


def test_two_ranks_inject_the_same_particles(case_dir, foam_env):
    """The inlet split between two ranks (y): the same ids, places and
    sizes as the serial run."""
    runs = {}
    for name, dec in (("serial", (1, 1, 1)), ("ranks", (1, 2, 1))):
        runs[name] = injection_case(case_dir / name, pps=2e5,
                                    end_time=1e-3, decompose=dec)
    run_case(runs["serial"])
    run_case(runs["ranks"], parallel=2)
    out = {}
    for name, c in runs.items():
        cl = read_cloud(c, "0.001", names=("origId", "d"))
        x = read_positions(cloud_dir(c, "0.001") / "positions")
        order = np.argsort(cl["origId"])
        out[name] = (cl["origId"][order], x[order], cl["d"][order])
    assert len(out["serial"][0]) == 200
    np.testing.assert_array_equal(out["ranks"][0], out["serial"][0])
    np.testing.assert_allclose(out["ranks"][1], out["serial"][1], rtol=0,
                               atol=1e-15)
    np.testing.assert_array_equal(out["ranks"][2], out["serial"][2])


@pytest.mark.parametrize("old,new,word", [
    ("parcelBasisType fixed;", "parcelBasisType mass;", "nParticle 1"),
    ("nParticle 1;", "nParticle 3;", "nParticle 1"),
    ("patch xMin;", "patch inlet;", "inlet"),
    ("parcelsPerSecond", "flowRateProfile constant 1; parcelsPerSecond",
     "flowRateProfile"),
    ("duration 0.001;", "duration 0;", "duration"),
    ("placement area;", "", "placement"),
    ("placement area;", "placement flux;", "U0"),
    ("placement area;", "placement even;", "even"),
], ids=["basisMass", "nParticle3", "patchName", "flowRateProfile",
        "durationZero", "placementMissing", "fluxWithU0", "placementName"])
def test_bad_injector_input(case_dir, foam_env, old, new, word):
    injection_case(case_dir, end_time=2e-4)
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    assert old in text, old
    f.write_text(text.replace(old, new, 1))
    res = run_case(case_dir, check=False)
    assert res.returncode != 0
    assert "FOAM FATAL" in res.stdout and word in res.stdout, \
        res.stdout[-1500:]
