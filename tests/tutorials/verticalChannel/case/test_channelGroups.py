"""One-way configurations run as clouds of one LES (channel.case.groups,
`-configs R80+R60`): the group's caseSettings (a cloud per configuration
and stage, each configuration's collision coefficients in its own entry),
the groups refused (a two-way member, a member named twice, members
whose particles differ), and the run exact: the smoke preset's R80, R60
and C2oneWay (a sub-model variant: lift forces and SGS velocity, one-way)
run as one group give, cloud by cloud, what each gives run alone
(statistics, profiles, size distributions, collision-event logs and
particles of every write, byte for byte but the cloud's name), with the
fluid solved once."""

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from channelTestRuns import TUTORIAL
from test_channelStagesFrom import settings, with_presets


def entries(stdout):
    return {k: v.rstrip(";") for k, v in (
        line.split(None, 1) for line in stdout.splitlines()
        if line and line[0].isalpha() and " " in line)}


def test_the_group_case_settings(tmp_path):
    case = with_presets(tmp_path)
    res = {st: settings(case, "smoke", "R80+R60", st)
           for st in ("unladen", "release", "dispersion", "agglomeration")}
    for r in res.values():
        assert r.returncode == 0, r.stderr
    e = {st: entries(r.stdout) for st, r in res.items()}
    assert e["unladen"]["clouds"] == "()"
    assert e["release"]["clouds"] == "(R80 R60)"
    assert e["dispersion"]["clouds"] == "(R80 R60)"
    assert e["agglomeration"]["clouds"] == "(R80EAM R80MAM R60EAM R60MAM)"
    a = e["agglomeration"]
    assert a["members"] == "(R80 R60)"
    # each configuration's own e_n,p and wall (the presets'
    # configurations: 0.80 and 0.60) and sub-models; none of the group's
    own = {"subModels", "cloudForces", "dispersionModel", "enParticle",
           "wallType", "wallCoeffs"}
    for name, en in (("R80", "0.8"), ("R60", "0.6")):
        assert f"enParticle {en};" in a[name]
        assert f"smoothCoeffs {{ en {en}; et 0.44;" in a[name]
        assert "dispersionModel none;" in a[name]
    assert not own & set(a)
    # the rest is the first configuration's, alone
    alone = entries(settings(case, "smoke", "R80", "agglomeration").stdout)
    for k in set(alone) - {"configuration", "clouds"} - own:
        assert a[k] == alone[k], k
    # and a member's own entries are its lines alone (a sub-model
    # variant beside C1: its forces and SGS velocity its own)
    g = entries(settings(case, "smoke", "C1+C2oneWay", "release").stdout)
    for m in ("C1", "C2oneWay"):
        solo = entries(settings(case, "smoke", m, "release").stdout)
        for k in own:
            v = solo[k].split(";")[0]      # subModels: its comment dropped
            assert f"{k} {v}" in g[m], (m, k)
    assert "SaffmanMeiLiftForce" in g["C2oneWay"] \
        and "SaffmanMeiLiftForce" not in g["C1"]


@pytest.mark.parametrize("group, message", [
    ("C1+C2", "C2 is two-way coupled (its subModels switch "
              "twoWayCoupling on)"),
    ("C1+C2noLift", "C2noLift is two-way coupled"),
    ("R80+R80", "R80 named twice"),
    ("R80+", "name two configurations or more"),
    ("R80+C9", "unknown configuration 'C9'"),
    ("R80+S4", "R80 and S4 differ in d;"),
    ("R80+R60", "R80 and R60 differ in nParticles couplingScale;"),
])
def test_groups_refused(tmp_path, group, message):
    """Members must be one-way, distinct, and agree in all but e_n,p and
    the wall (S4: a one-way configuration of 4 um particles; the preset
    `own` gives R80 a particle number of its own)."""
    case = with_presets(tmp_path, (
        "own", "smoke",
        "perConfiguration { R80 { nParticles 4000; couplingScale 3; } }"))
    p = case / "presets"
    p.write_text(p.read_text().replace(
        "    R60 { subModels off;",
        "    S4  { subModels off; wall smooth; d 4e-6;  en 0.97; }\n"
        "    R60 { subModels off;"))
    assert settings(case, "smoke", "R80+R60", "release").returncode == 0
    res = settings(case, "own" if group == "R80+R60" else "smoke", group,
                   "release")
    assert res.returncode == 1
    assert message in res.stderr, res.stderr


@pytest.mark.parametrize("configs, before, said", [
    ("C1 C1", (), ["C1 is named 2 times in -configs (C1, C1)"]),
    ("C1 C1+R80+R60", (), ["C1 is named 2 times in -configs (C1, "
                           "C1+R80+R60)"]),
    ("R80+R60 R60+C1", (), ["R60 is named 2 times in -configs (R80+R60, "
                            "R60+C1)"]),
    ("C1+R80+R60 C2", ("C1", "C2", "unladen", "report"),
     ["C1 (C1+R80+R60) has run before as C1 in {base}/C1"]),
    ("R80 C1", ("R80+R60",), ["R80 (R80) has run before as R80+R60 in "
                             "{base}/R80+R60"]),
    ("C1+R80+R60 C2", ("C1+R80+R60", "C2", "C3"), []),
    ("C1 C2 R80 R60", (), []),
])
def test_a_configuration_runs_once(tmp_path, configs, before, said):
    """A configuration named twice, or run before under another name
    (alone where a group names it, in a group where it is named alone),
    is refused: the report would find two runs of it; a folder of the
    same name is that run, continued, and folders that are not
    configurations (unladen, report) do not count."""
    case = with_presets(tmp_path)
    base = case / "runs" / "smoke"
    for d in before:
        (base / d / "dispersion").mkdir(parents=True)
    code = ("import sys; from pathlib import Path; "
            "from channel.case import groups; "
            "print('\\n'.join(groups.twice(sys.argv[1].split(), "
            "groups.runs_before(Path('runs/smoke')))))")
    res = subprocess.run([sys.executable, "-c", code, configs], cwd=case,
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    lines = [x for x in res.stdout.splitlines() if x]
    assert len(lines) == len(said), lines
    for line, want in zip(lines, said):
        assert line.startswith(want.format(base=Path("runs/smoke"))), line


def test_the_driver_refuses_a_second_run_before_it_starts(tmp_path,
                                                         foam_env):
    """C1 run alone before and now named in a group: the driver stops
    with exit status 1, naming the folder, and starts nothing."""
    case = with_presets(tmp_path)
    alone = case / "runs" / "smoke" / "C1" / "dispersion"
    alone.mkdir(parents=True)
    res = allrun(case, "C1+R80+R60")
    assert res.returncode == 1, res.stdout[-2000:]
    assert "Allrun: C1 (C1+R80+R60) has run before as C1 in runs/smoke/C1:" \
        " the report takes each configuration from one run; remove " \
        "runs/smoke/C1, or name C1 as it ran there (C1)" in res.stdout, \
        res.stdout
    assert sorted(p.name for p in (case / "runs" / "smoke").iterdir()) \
        == ["C1"]
    assert not any(alone.iterdir())


def test_the_matrix_runs_each_configuration_once_and_shares_the_fluid():
    """-matrix names every paper configuration of the presets file once
    (subModels on or off; not the sub-model variants, which list
    theirs), the one-way ones (sub-models off) in one group, accepted at
    every preset (the members agree there in all but e_n,p and the
    wall)."""
    code = """
import json
from channel.case import groups, presets, runs
configs = runs.options(["-matrix"]).configs.split()
ps = [p for p in presets.read_presets()
      if p not in ("FoamFile", "common", "configurations")]
for p in ps:
    for c in configs:
        groups.check(p, c)
paper = [c for c in presets.read_presets()["configurations"]
         if presets.configuration(c)["subModels"] in ("on", "off")]
one_way = [c for c in paper if not presets.configuration(c)["twoWay"]]
print(json.dumps({
    "members": [groups.members(c) for c in configs],
    "all": paper,
    "oneWay": one_way, "presets": len(ps),
    "twice": groups.twice(configs)}))
"""
    res = subprocess.run([sys.executable, "-c", code], cwd=TUTORIAL,
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    r = json.loads(res.stdout)
    named = [m for ms in r["members"] for m in ms]
    assert sorted(named) == sorted(r["all"]) and len(r["all"]) == 6
    assert r["twice"] == []
    assert r["presets"] > 10
    # the one-way configurations (C1, R80, R60) in one LES
    assert sorted(r["oneWay"]) == ["C1", "R60", "R80"]
    assert [sorted(ms) for ms in r["members"] if len(ms) > 1] == \
        [sorted(r["oneWay"])]


def allrun(case, configs, *extra):
    return subprocess.run(["./Allrun", "-preset", "smoke", "-configs",
                           configs, "-np", "1", "-every", "600", *extra],
                          cwd=case, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=900)


def files(d):
    """The solver's files below d (not the post's replay outputs, which
    name the case)."""
    return sorted(str(f.relative_to(d)) for f in d.rglob("*")
                  if f.is_file() and not f.name.startswith("replay"))


def same_but_name(a, b, name, group_name):
    """The file b of the group's cloud group_name equals a of the cloud
    name run alone, but for the cloud's name (headers, FoamFile)."""
    pat = re.compile(rb"\b" + group_name.encode() + rb"\b")
    return pat.sub(name.encode(), b.read_bytes()) == a.read_bytes()


@pytest.mark.slow
def test_a_group_gives_each_configuration_run_alone(tmp_path):
    alone = with_presets(tmp_path / "alone")
    group = with_presets(tmp_path / "group")
    # R80 and R60 differ in e_n,p, C2oneWay from both in its sub-models
    # too (the lift forces and the SGS velocity, one-way)
    members = ("R80", "R60", "C2oneWay")
    name = "+".join(members)
    res = allrun(alone, " ".join(members))
    assert res.returncode == 0, res.stdout[-3000:]
    res = allrun(group, name)
    assert res.returncode == 0, res.stdout[-3000:]
    ra, rg = alone / "runs" / "smoke", group / "runs" / "smoke"
    # one fluid for both: one dispersion and one agglomeration run
    assert sorted(p.name for p in rg.iterdir()) == \
        [name, "report", "unladen"]
    agg = rg / name / "agglomeration"
    n = 0
    for c in members:
        for stage, clouds in (("dispersion", {"particles": c}),
                              ("agglomeration", {m: c + m for m in
                                                 ("EAM", "MAM")})):
            a_dir, g_dir = ra / c / stage, rg / name / stage
            for mine, theirs in clouds.items():
                pp = [(a_dir / "postProcessing" / f"{mine}{k}",
                       g_dir / "postProcessing" / f"{theirs}{k}")
                      for k in ("HardSphere", "CollisionEvents")]
                times = [t.name for t in sorted(a_dir.glob("0.*"))]
                pp += [(a_dir / t / "lagrangian" / mine,
                        g_dir / t / "lagrangian" / theirs) for t in times]
                for a, g in pp:
                    if not a.exists():          # no event log: dispersion
                        assert not g.exists(), g
                        continue
                    names = files(a)
                    assert names == files(g) and names, a
                    for f in names:
                        assert same_but_name(a / f, g / f, mine, theirs), \
                            (a / f, g / f)
                        n += 1
    assert n > 150
    # the fluid is the same at the end (one-way: the particles' own)
    last = sorted(agg.glob("0.*"))[-1].name
    assert (agg / last / "U").read_bytes() == \
        (ra / "R80" / "agglomeration" / last / "U").read_bytes()
    # and the comparison can fail: the members differ alone (e_n,p; the
    # sub-models)
    st = "postProcessing/EAMHardSphere/*/stats.dat"
    stats = [next((ra / c / "agglomeration").glob(st)).read_bytes()
             for c in members]
    assert len(set(stats)) == 3
    # the reports agree row by row (each member, both models)
    rows = [[ln for ln in (r / "report" / "regression.txt").read_text()
             .splitlines() if ln.startswith(tuple(c + " " for c in
                                                  members))]
            for r in (ra, rg)]
    assert rows[0] == rows[1] and len(rows[0]) >= 24
    # one fluid, reported once by its folder's name
    text = (rg / "report" / "regression.txt").read_text()
    assert text.count(f"fluid {name} agglomeration: u_tau/U_B") == 1
    assert "fluid R80 agglomeration" not in text
    # a configuration run both alone and in a group is refused by the
    # post, naming both
    shutil.copytree(rg / name, ra / name)
    res = allrun(alone, "R80", "-post")
    assert res.returncode == 1
    assert "channel.post: R80 EAM ran twice, in" in res.stdout
    assert f"{name}/agglomeration" in res.stdout
