"""The hardSphereCollide utility end to end: dictionary in, JSON out,
against the reference collisions of doc/models.md 12.3 (quartz, 12 um,
Tab. 1, CSM); clear errors for particles not in contact or not
approaching."""

import json
import math
import subprocess

import pytest

from aggloTools.runner import foam_bin

MATERIAL = """
material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9; delta0 2e-10;
           rho0 2200; }
particleCollision { en 0.97; et 0.44; muSt 0.94; muKin 0.092; }
structureModel CSM;
"""


def pair(v, theta_deg, gap=0.0):
    th = math.radians(theta_deg)
    ur = (-v * math.cos(th), v * math.sin(th), 0.0)
    d = 12e-6
    u1 = tuple(-0.5 * c for c in ur)
    u2 = tuple(0.5 * c for c in ur)
    fmt = lambda t: "(" + " ".join(repr(c) for c in t) + ")"
    return (f"particle1 {{ position (0 0 0); U {fmt(u1)}; omega (0 0 0);"
            f" d {d}; rho 2200; nPrimary 1; }}\n"
            f"particle2 {{ position ({d + gap} 0 0); U {fmt(u2)};"
            f" omega (0 0 0); d {d}; rho 2200; nPrimary 1; }}\n")


def collide(tmp_path, model, body, check=True):
    f = tmp_path / "collideDict"
    f.write_text(MATERIAL + f"agglomerationModel {model};\n" + body)
    res = subprocess.run([foam_bin("hardSphereCollide"), str(f)],
                         capture_output=True, text=True)
    if check:
        assert res.returncode == 0, res.stderr + res.stdout
        return json.loads(res.stdout)
    return res


def test_eam_row11_agglomerates(tmp_path, foam_env):
    out = collide(tmp_path, "EAM", pair(3e-3, 60))
    assert out["branch"] == "eq21" and out["agglomerate"] is True
    ag = out["agglomerateState"]
    assert ag["nPrimary"] == 2
    assert ag["d"] == pytest.approx(23.4844e-6, rel=1e-4)
    assert ag["omega"][2] == pytest.approx(1.4132e2, rel=1e-4)
    im = out["intermediates"]
    assert im["EkinPlus"] == pytest.approx(2.2171e-18, rel=1e-4)
    assert im["ErotPlus"] == pytest.approx(1.4215e-18, rel=1e-4)
    assert im["ErotAg"] == pytest.approx(2.3993e-18, rel=1e-4)
    assert im["dEvdW"] == pytest.approx(1.6430e-18, rel=1e-4)
    bal = out["balance"]
    assert bal["massAfter"] == pytest.approx(bal["massBefore"], rel=1e-13)


def test_eam_row5_caseI_rebound(tmp_path, foam_env):
    out = collide(tmp_path, "EAM", pair(3e-3, 0))
    assert out["branch"] == "caseI" and out["collisionType"] == "sticking"
    p1, p2 = out["particles"]
    assert p2["U"][0] - p1["U"][0] == pytest.approx(1.3656e-3, rel=1e-4)
    assert out["intermediates"]["kn2"] == pytest.approx(0.2202, rel=2e-4)


def test_mam_row4_rebound_intermediates(tmp_path, foam_env):
    out = collide(tmp_path, "MAM", pair(2e-3, 0))
    assert out["branch"] == "rebound"
    p1, p2 = out["particles"]
    assert p2["U"][0] - p1["U"][0] == pytest.approx(1.2375e-3, rel=1e-4)
    im = out["intermediates"]
    assert im["fna"] == pytest.approx(1.97 * 2e-3, rel=1e-12)
    # t* = (mHat^2/(RHat EHat^2 v))^(1/5), section 12.4 at 1 mm/s scaled
    assert im["tStar"] == pytest.approx(4.74389e-8 * 2 ** -0.2, rel=1e-5)
    # the intermediates are those of every model, then the MAM's, and
    # nothing else; the flags of Eq. 75 as 0/1
    assert list(im) == ["fna", "dKEformation", "spinCapped", "fnc",
                        "fncStar", "tStar", "critI", "critII"]
    assert im["critI"] == 0 and im["spinCapped"] == 0


def test_not_in_contact_is_an_error(tmp_path, foam_env):
    res = collide(tmp_path, "EAM", pair(1e-3, 0, gap=1e-6), check=False)
    assert res.returncode != 0
    assert "not in contact" in res.stderr + res.stdout
    assert res.stdout.strip() == "" or not res.stdout.lstrip().startswith("{")


def test_not_approaching_is_an_error(tmp_path, foam_env):
    res = collide(tmp_path, "EAM", pair(-1e-3, 0), check=False)
    assert res.returncode != 0
    assert "not approaching" in res.stderr + res.stdout


def test_bad_model_name_lists_choices(tmp_path, foam_env):
    res = collide(tmp_path, "MAMM", pair(1e-3, 0), check=False)
    text = res.stderr + res.stdout
    assert res.returncode != 0
    for choice in ("EAM", "EAMAlletto2014", "MAM", "none"):
        assert choice in text
