"""Deposition (the stick wall model), escape through an open patch and the
cloud's mass balance (clouds/cloudMassBalance): a particle deposits on
the face it touches, at one radius or with its centre, and leaves the
cloud; a parcel removed by the stock patch interaction is counted as
escaped; the record (per patch: parcels, primaries, mass), the per-face
field <cloud>:depositedMass and the audit against hand values, across a
restart and on three ranks; a restart whose record disagrees with its
particles is refused."""

import math
import re
import shutil

import numpy as np

from aggloTools.boxcase import WALL, box_case, kernel, run_case
from aggloTools.cloud import read_mass_balance, read_record
from aggloTools.fields import read_patch
from aggloTools.mesh import Mesh
from aggloTools.times import last_time
from aggloTools.stats import stats_rows as stats
from aggloTools.foamfile import edit
from cloudBoxCases import D, L, agglomerating_gas, cloud_state

#: The mass of one 12 um quartz primary [kg]
M1 = 2200 * math.pi / 6 * D ** 3

def hard_sphere(walls, agglomeration="none", **changes):
    """The collision model's body with the given walls entries."""
    return kernel(agglomeration, walls=walls, **changes)


def patch_faces(case, patch):
    """(startFace, nFaces) of a patch from constant/polyMesh/boundary."""
    text = (case / "constant" / "polyMesh" / "boundary").read_text()
    m = re.search(patch + r"\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+"
                  r"(\d+);", text)
    return int(m.group(2)), int(m.group(1))


def deposited_field(case, time, patch):
    start, n = patch_faces(case, patch)
    values = read_patch(case / str(time) / "kinematicCloud:depositedMass",
                        patch, n)
    return values, start


def the_face_under(case, patch, x):
    """The index in the patch of the face whose centre is nearest to x."""
    start, n = patch_faces(case, patch)
    Cf, _ = Mesh(case).face_centres_and_areas()
    return int(np.argmin(np.linalg.norm(Cf[start:start + n] - x, axis=1)))


def single_deposit(case_dir, extra):
    """One primary towards yMin (stick) at 10 mm/s, 3.3 um beyond contact;
    the other walls smooth. Returns the case, x0 and U0."""
    U0 = np.array([2e-3, -10e-3, 0.0])
    x0 = np.array([0.3 * L, 0.5 * D + 3.3e-6, 0.7 * L])
    box_case(case_dir, L=(L, L, L), particles=[dict(x=x0, U=U0)],
             dt=1e-4, end_time=1e-3,
             hard_sphere=hard_sphere({"yMin": {"wallModel": "stick"},
                                      '".*"': WALL}, **extra))
    run_case(case_dir)
    return case_dir, x0, U0


def check_single_deposit(case, x_contact):
    t = last_time(case)
    assert read_record(case, t, "kinematicCloud")["nParticlesTotal"] == 0
    bal = read_mass_balance(case, t)
    assert bal["escaped"] == {}
    assert set(bal["deposited"]) == {"yMin"}
    dep = bal["deposited"]["yMin"]
    assert dep["nParcels"] == 1 and dep["nPrimaries"] == 1
    np.testing.assert_allclose(dep["mass"], M1, rtol=1e-14)
    np.testing.assert_allclose(bal["massStart"], M1, rtol=1e-14)
    assert bal["nPrimariesStart"] == 1
    values, _ = deposited_field(case, t, "yMin")
    face = the_face_under(case, "yMin", x_contact)
    assert np.count_nonzero(values) == 1
    np.testing.assert_allclose(values[face], M1, rtol=1e-14)
    # a deposit is not a rebound
    assert stats(case)[-1]["nWall"] == 0


def test_deposit_at_one_radius(case_dir, foam_env):
    """Contact at one radius (the default): found at the end of step 4
    (the centre 5.3 um from the wall), deposited on the face below."""
    case, x0, U0 = single_deposit(case_dir, {})
    check_single_deposit(case, x0 + 4e-4 * U0 * np.array([1, 0, 1]))


def test_deposit_of_a_centre_on_the_wall(case_dir, foam_env):
    """wallContact centre: deposited during the tracking where the centre
    crosses the wall (t = 0.93 ms)."""
    case, x0, U0 = single_deposit(case_dir, {"wallContact": "centre"})
    check_single_deposit(case, x0 + 9.3e-4 * U0)


def test_escape_through_an_open_patch(case_dir, foam_env):
    """x open (patches), localInteraction escape there: a primary leaving
    through xMax is counted as escaped there; its neighbour at rest
    stays."""
    parts = [dict(x=(0.9 * L, 0.5 * L, 0.5 * L), U=(20e-3, 0, 0), id=0),
             dict(x=(0.5 * L, 0.5 * L, 0.5 * L), U=(0, 0, 0), id=1)]
    box_case(case_dir, L=(L, L, L), kinds=("patch", "wall", "wall"),
             particles=parts, dt=1e-4, end_time=1e-3,
             cloud={"subModels": {
                 "patchInteractionModel": "localInteraction",
                 "localInteractionCoeffs": {
                     "patches": '( "x.*" { type escape; } ".*" '
                                '{ type rebound; e 1; mu 0; } )'}}})
    run_case(case_dir)
    t = last_time(case_dir)
    bal = read_mass_balance(case_dir, t)
    assert bal["deposited"] == {}
    assert set(bal["escaped"]) == {"xMax"}
    esc = bal["escaped"]["xMax"]
    assert esc["nParcels"] == 1 and esc["nPrimaries"] == 1
    np.testing.assert_allclose(esc["mass"], 1 * M1, rtol=1e-14)
    np.testing.assert_allclose(bal["massStart"], 2 * M1, rtol=1e-14)
    state = cloud_state(case_dir, t)
    assert list(state["origId"]) == [1]


STICKY = hard_sphere({'"y.*"': {"wallModel": "stick"}}, "EAM")


def sticky_gas(case, end_time, write_interval, decompose=(1, 1, 1)):
    """The 300-primaries agglomerating gas of the event-log tests with
    sticking walls in y."""
    agglomerating_gas(case, end_time, write_interval, decompose,
                      hard_sphere=STICKY)


def balance_by_hand(case, t):
    """The record against the particles in flight: every primary is in
    flight or deposited, the mass is the primaries' (hand: M1 each)."""
    bal = read_mass_balance(case, t)
    state = cloud_state(case, t)
    dep = bal["deposited"]
    n_dep = sum(v["nPrimaries"] for v in dep.values())
    assert int(state["nPrimary"].sum()) + n_dep == 300
    assert bal["nPrimariesStart"] == 300
    np.testing.assert_allclose(bal["massStart"], 300 * M1, rtol=1e-13)
    for v in dep.values():
        np.testing.assert_allclose(v["mass"], v["nPrimaries"] * M1,
                                   rtol=1e-13)
    in_flight = (state["rho"] * math.pi / 6 * state["d"] ** 3).sum()
    np.testing.assert_allclose(in_flight, (300 - n_dep) * M1, rtol=1e-13)
    # the per-face field sums to the patch's total
    for patch, v in dep.items():
        values, _ = deposited_field(case, t, patch)
        assert values.min() >= 0
        np.testing.assert_allclose(values.sum(), v["mass"], rtol=1e-13)
    return bal


def test_agglomerates_deposit_whole_and_nothing_is_lost(case_dir, foam_env):
    """300 steps of the sticky gas: primaries and agglomerates deposit on
    both walls, each as one parcel with all its primaries."""
    sticky_gas(case_dir, 30e-3, 300)
    run_case(case_dir)
    bal = balance_by_hand(case_dir, last_time(case_dir))
    dep = bal["deposited"]
    assert set(dep) == {"yMin", "yMax"}, dep
    # an agglomerate deposited whole: more primaries than parcels
    assert sum(v["nPrimaries"] - v["nParcels"] for v in dep.values()) > 0


def test_restart_and_three_ranks_keep_the_balance(case_dir, foam_env):
    """The sticky gas to 8 ms: continuous, restarted at 4 ms, and on three
    ranks across the walls (the middle rank touches no wall and has more
    processor patches). The restart writes the same record and field byte
    for byte; three ranks count the same parcels and primaries, the same
    mass to round-off, on the same faces."""
    runs = {}
    for name, decompose in (("whole", (1, 1, 1)), ("split", (1, 1, 1)),
                            ("ranks", (1, 3, 1))):
        c = case_dir / name
        sticky_gas(c, 8e-3, 40, decompose)
        runs[name] = c
    run_case(runs["whole"])
    ctrl = runs["split"] / "system" / "controlDict"
    edit(ctrl, "endTime 0.008;",
         "endTime 0.004;")
    run_case(runs["split"])
    edit(ctrl, "endTime 0.004;",
         "endTime 0.008;")
    run_case(runs["split"])
    run_case(runs["ranks"], parallel=3)

    t = last_time(runs["whole"])
    assert t == last_time(runs["split"]) == "0.008"
    rec = "uniform/lagrangian/kinematicCloud/cloudMassBalance"
    for f in (rec, "kinematicCloud:depositedMass"):
        a = (runs["whole"] / t / f).read_bytes()
        assert a == (runs["split"] / t / f).read_bytes(), f
    whole = balance_by_hand(runs["whole"], t)
    ranks = balance_by_hand(runs["ranks"], t)
    assert whole["deposited"].keys() == ranks["deposited"].keys()
    for patch, v in whole["deposited"].items():
        w = ranks["deposited"][patch]
        assert (w["nParcels"], w["nPrimaries"]) == (v["nParcels"],
                                                    v["nPrimaries"])
        np.testing.assert_allclose(w["mass"], v["mass"], rtol=1e-13)
        a, _ = deposited_field(runs["whole"], t, patch)
        b, _ = deposited_field(runs["ranks"], t, patch)
        np.testing.assert_allclose(b, a, rtol=1e-13, atol=0)


def test_record_that_disagrees_is_refused(case_dir, foam_env):
    """A restart whose record misses one primary stops with the balance
    named; the same restart with the record intact runs."""
    sticky_gas(case_dir, 6e-3, 20)
    ctrl = case_dir / "system" / "controlDict"
    edit(ctrl, "endTime 0.006;",
         "endTime 0.004;")
    run_case(case_dir)
    edit(ctrl, "endTime 0.004;",
         "endTime 0.006;")
    intact = case_dir.parent / (case_dir.name + "_intact")
    if intact.exists():
        shutil.rmtree(intact)
    shutil.copytree(case_dir, intact)
    f = case_dir / "0.004/uniform/lagrangian/kinematicCloud/cloudMassBalance"
    text = f.read_text()
    assert "nPrimariesStart 300;" in text
    f.write_text(text.replace("nPrimariesStart 300;",
                              "nPrimariesStart 301;"))
    res = run_case(case_dir, check=False)
    assert res.returncode != 0
    assert "mass balance broken" in res.stdout
    assert "cloudMassBalance" in res.stdout
    assert run_case(intact).returncode == 0
    assert last_time(intact) == "0.006"
