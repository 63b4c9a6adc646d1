"""hardSphereCollide, the kernel utility: it insists on its one argument
(the dictionary) and its dictionary rejects unknown entries, naming
them."""

import subprocess

import pytest

from aggloTools.runner import foam_bin
from cloudBoxCases import assert_fatal_naming


COLLIDE = """FoamFile { version 2.0; format ascii; class dictionary;
object collide; }
material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9; delta0 2e-10;
           rho0 2200; }
particleCollision { en 0.97; et 0.44; muSt 0.94; muKin 0.092; }
agglomerationModel EAM;
structureModel CSM;
particle1 { position (0 0 0); U (5e-4 0 0); d 12e-6; rho 2200; }
particle2 { position (12e-6 0 0); U (-5e-4 0 0); d 12e-6; rho 2200; }
"""


def collide(tmp_path, args, text=COLLIDE):
    f = tmp_path / "collide"
    f.write_text(text)
    return subprocess.run([foam_bin("hardSphereCollide")] + args,
                          cwd=tmp_path, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=60)


def test_collide_valid(tmp_path, foam_env):
    res = collide(tmp_path, ["collide"])
    assert res.returncode == 0, res.stdout
    assert '"agglomerate": true' in res.stdout


@pytest.mark.parametrize("args", [[], ["collide", "extra"]])
def test_collide_needs_one_argument(tmp_path, foam_env, args):
    """No argument used to abort with 'new cannot satisfy memory request'
    (exit 134); extra arguments were ignored."""
    res = collide(tmp_path, args)
    assert res.returncode not in (0, 134)
    assert "dictFile" in res.stdout
    assert "memory" not in res.stdout


@pytest.mark.parametrize("old,new,word", [
    ("particle1 {", "partcle1 {", "partcle1"),
    ("d 12e-6; rho 2200; }\nparticle2",
     "d 12e-6; rho 2200; diameter 1; }\nparticle2", "diameter"),
    ("structureModel CSM;", "structureModel CSM; contactTolerence 1;",
     "contactTolerence"),
])
def test_collide_unknown_entries(tmp_path, foam_env, old, new, word):
    assert old in COLLIDE
    res = collide(tmp_path, ["collide"], COLLIDE.replace(old, new, 1))
    assert_fatal_naming(res, word)
