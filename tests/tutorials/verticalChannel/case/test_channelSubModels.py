"""A configuration's sub-models one by one (presets: `subModels` as a list
of twoWayCoupling, sgsDispersion, shearLift, rotationLift): each switch
sets its own caseSettings entries and nothing else, the full list is the
paper's `on` (C2) line for line, and the one-way variants of the presets
file share an LES with C1 at every preset."""

import itertools
import json
import subprocess
import sys

from channelTestRuns import TUTORIAL
from test_channelStagesFrom import with_presets

SWITCHES = ("twoWayCoupling", "sgsDispersion", "shearLift", "rotationLift")

CODE = """
import json, re, sys
from channel.case import settings
out = {}
for c in sys.argv[1:]:
    # the configuration's name (in comments) as one word
    text = re.sub(rf"\\b{c}\\b", "CONFIG",
                  settings.settings("small", c, "dispersion"))
    out[c] = [ln for ln in text.splitlines()
              if not ln.startswith(("configuration ", "subModels "))]
print(json.dumps(out))
"""


def key(line):
    return (line.split() or [""])[0]


def entry(lines, name):
    line = next(ln for ln in lines if key(ln) == name)
    return line.split(None, 1)[1].split("//")[0].strip().rstrip(";")


def test_each_switch_sets_its_own_entries(tmp_path):
    subsets = [s for n in range(1, 5)
               for s in itertools.combinations(SWITCHES, n)]
    names = [f"V{i}" for i in range(len(subsets))]
    case = with_presets(tmp_path)
    p = case / "presets"
    p.write_text(p.read_text().replace(
        "    C1  { subModels off;", "".join(
            f"    {n} {{ subModels ({' '.join(reversed(s))}); wall "
            "smooth; d 12e-6; en 0.97; }\n" for n, s in zip(names, subsets))
        + "    C1  { subModels off;", 1))
    res = subprocess.run([sys.executable, "-c", CODE, "C1", "C2", *names],
                         cwd=case, capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    out = json.loads(res.stdout)
    assert len(subsets) == 15
    for n, s in zip(names, subsets):
        lines = out[n]
        forces = entry(lines, "cloudForces")
        # the spec's switches (doc/models.md 8.2, 8.3, 9, 10), each its
        # own entry, and drag and gravity always
        assert (entry(lines, "coupled") == "true") == \
            ("twoWayCoupling" in s), n
        assert entry(lines, "couplingScale") == (
            "60" if "twoWayCoupling" in s else "1"), n
        assert (entry(lines, "dispersionModel") == "PozorskiApte") == \
            ("sgsDispersion" in s), n
        assert ("SaffmanMeiLiftForce" in forces) == ("shearLift" in s), n
        assert ("rotationLift" in forces) == ("rotationLift" in s), n
        assert forces.startswith("{ SchillerNaumannDrag;") and \
            forces.endswith("gravity; }"), n
        # apart from these lines, every variant is C1's, line for line
        own = ("coupled", "couplingScale", "cloudForces", "dispersionModel")
        assert [ln for ln in lines if key(ln) not in own] == \
            [ln for ln in out["C1"] if key(ln) not in own], n
    # all four switched on, in any order, is the paper's `on` (C2)
    assert out[names[-1]] == out["C2"]
    assert out[names[-1]] != out["C1"]


def test_the_one_way_variants_share_c1s_les_at_every_preset():
    """The presets file's one-way variants and C1 form a group (the
    presets' comment gives it) at every preset, and the two-way ones are
    refused there."""
    code = """
import json
from channel.case import groups, presets
cs = presets.read_presets()["configurations"]
variants = [c for c in cs
            if presets.configuration(c)["subModels"] not in ("on", "off")]
one_way = [c for c in variants if not presets.configuration(c)["twoWay"]]
ps = [p for p in presets.read_presets()
      if p not in ("FoamFile", "common", "configurations")]
for p in ps:
    groups.check(p, "+".join(["C1"] + one_way))
print(json.dumps({"variants": variants, "oneWay": one_way}))
"""
    res = subprocess.run([sys.executable, "-c", code], cwd=TUTORIAL,
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    r = json.loads(res.stdout)
    assert sorted(r["oneWay"]) == sorted(
        ["C1sgs", "C1lift", "C1shearLift", "C1rotationLift", "C2oneWay"])
    assert sorted(set(r["variants"]) - set(r["oneWay"])) == \
        ["C2noLift", "C2noSgs"]
    text = (TUTORIAL / "presets").read_text()
    assert "-configs " + "+".join(["C1"] + r["oneWay"]) in text
