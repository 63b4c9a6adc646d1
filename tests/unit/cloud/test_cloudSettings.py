"""The cloud's settings on scripted boxes (cloudBoxCases): bad entries of
hardSphereCoeffs are fatal and name the entry; ghost contacts pass
through and are counted; the encounter release makes a new first
contact; two clouds of one flow each give the statistics of the cloud
run alone."""

import math
import shutil

import pytest

from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.stats import stats_rows as stats
from aggloTools.times import last_time
from aggloTools.foamfile import edit
from cloudBoxCases import (D, L, add_hard_sphere_entries, agglomerating_gas,
                           assert_fatal_naming, cloud_state, pair_particles)


BAD = {
    "unknownModel": ("agglomerationModel EAM;", "agglomerationModel EAMX;",
                     "EAMX"),
    "missingCoefficient": ("en 0.97;", "", "en"),
    "restitution": ("en 0.97;", "en 1.2;", "en"),
    "unknownWallModel": ("wallModel smooth;", "wallModel rough;", "rough"),
    "ghostAgglomerating": ("agglomerationModel EAM;",
                           "agglomerationModel EAM; collisionResponse ghost;",
                           "ghost"),
    "unknownResponse": ("agglomerationModel EAM;",
                        "agglomerationModel EAM; collisionResponse gost;",
                        "gost"),
    "negativeRelease": ("agglomerationModel EAM;",
                        "agglomerationModel EAM; encounterRelease -1;",
                        "encounterRelease"),
    "negativeCellOrderInterval": ("solution\n{\n",
                                  "solution\n{\n    cellOrderInterval -1;\n",
                                  "cellOrderInterval"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_is_fatal(case_dir, foam_env, name):
    old, new, word = BAD[name]
    box_case(case_dir, L=(L, L, L), particles=pair_particles(3e-3, 0),
             hard_sphere=kernel("EAM"), dt=1e-4, end_time=2e-4)
    f = case_dir / "constant" / "kinematicCloudProperties"
    text = f.read_text()
    assert old in text
    f.write_text(text.replace(old, new, 1))
    assert_fatal_naming(run_case(case_dir, check=False), word)


@pytest.mark.parametrize("release", ["0.1", "none"])
def test_ghost_pair_passes_through(case_dir, foam_env, release):
    """collisionResponse ghost: an oblique pair (30 deg) passes through;
    counted once as a first contact, then as overlapStart at every step
    start that finds it overlapping and approaching; velocities unchanged.
    The last partner is forgotten beyond 1.1 (r1 + r2) (release 0.1) or
    kept (none)."""
    v, dt, gap = 3e-3, 1e-4, 1e-6
    parts = pair_particles(v, 30, gap=gap)
    box_case(case_dir, L=(L, L, L), particles=parts, dt=dt, end_time=2e-2)
    add_hard_sphere_entries(
        case_dir, f"collisionResponse ghost; encounterRelease {release};")
    run_case(case_dir)
    rows = stats(case_dir)
    last = rows[-1]
    # contact at gap/v, closest approach at X/v (X: initial x distance)
    X = D * math.cos(math.radians(30)) + gap
    n_overlap = math.floor(X / v / dt) - math.floor(gap / v / dt)
    assert (last["nCol"], last["nColFirst"], last["nColRepeat"],
            last["nAgg"]) == (1 + n_overlap, 1, 0, 0)
    assert last["nColOverlapStart"] == n_overlap
    st = cloud_state(case_dir, last_time(case_dir))
    for k, p in enumerate(parts):
        assert st["U"][k] == pytest.approx(p["U"], abs=1e-15)
    expect = [-1, -1] if release == "0.1" else [1, 0]
    assert [int(i) for i in st["lastPartnerId"]] == expect


@pytest.mark.parametrize("release", ["0.1", "none"])
def test_encounter_release_makes_a_new_first_contact(case_dir, foam_env,
                                                      release):
    """A head-on pair rebounds, both hit the walls and meet again. After
    separating beyond 1.1 (r1 + r2) the second meeting is a first contact
    (doc/cases.md B.4); without release it is a repeat of the last partner
    (doc/models.md 6.7, unlimited memory)."""
    parts = pair_particles(3e-3, 0)
    box_case(case_dir, L=(L, L, L), particles=parts, dt=1e-4, end_time=0.1)
    add_hard_sphere_entries(case_dir, f"encounterRelease {release};")
    run_case(case_dir)
    rows = stats(case_dir)
    last = rows[-1]
    assert last["nCol"] >= 2 and last["nWall"] >= 2
    if release == "0.1":
        assert (last["nColFirst"], last["nColRepeat"]) == (last["nCol"], 0)
    else:
        assert (last["nColFirst"], last["nColRepeat"]) == \
            (1, last["nCol"] - 1)


def test_two_clouds_share_one_flow(case_dir, foam_env):
    """constant/cloudProperties clouds (EAMCloud MAMCloud): two one-way
    clouds with different agglomeration models in one run give, each, the
    statistics of the same cloud run alone (bit-identical rows)."""
    single = {}
    for model in ("EAM", "MAM"):
        d = case_dir / model
        agglomerating_gas(d, 4e-3, 40)
        f = d / "constant" / "kinematicCloudProperties"
        edit(f, "agglomerationModel EAM;",
             f"agglomerationModel {model};")
        run_case(d)
        single[model] = stats(d)
        assert single[model][-1]["nAgg"] > 0

    both = case_dir / "both"
    agglomerating_gas(both, 4e-3, 40)
    props = (both / "constant" / "kinematicCloudProperties").read_text()
    for model in ("EAM", "MAM"):
        name = f"{model}Cloud"
        (both / "constant" / f"{name}Properties").write_text(
            props.replace("agglomerationModel EAM;",
                          f"agglomerationModel {model};")
            .replace("kinematicCloudProperties", f"{name}Properties"))
        for sub in ("0/lagrangian", "0/uniform/lagrangian"):
            shutil.copytree(both / sub / "kinematicCloud", both / sub / name)
    (both / "constant" / "kinematicCloudProperties").unlink()
    shutil.rmtree(both / "0" / "lagrangian" / "kinematicCloud")
    (both / "constant" / "cloudProperties").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object cloudProperties; }\nclouds (EAMCloud MAMCloud);\n")
    res = run_case(both)
    assert "Constructing cloud EAMCloud" in res.stdout
    assert "Constructing cloud MAMCloud" in res.stdout
    for model in ("EAM", "MAM"):
        rows = stats(both, cloud=f"{model}Cloud")
        assert rows == single[model]
    assert single["EAM"][-1]["nCol"] != single["MAM"][-1]["nCol"] or \
        single["EAM"][-1]["nAgg"] != single["MAM"][-1]["nAgg"]
