"""One-way configurations run as clouds of one LES (channel.case.groups,
`-configs R80+R60`): the group's caseSettings (a cloud per configuration
and stage, each configuration's collision coefficients in its own entry),
the groups refused (a two-way member, a member named twice, members
whose particles differ), and the run exact: the smoke preset's R80 and
R60 run as one group give, cloud by cloud, what each gives run alone
(statistics, profiles, size distributions, collision-event logs and
particles of every write, byte for byte but the cloud's name), with the
fluid solved once."""

import re
import shutil
import subprocess

import pytest

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
    # configurations: 0.80 and 0.60); none of the group's own
    for name, en in (("R80", "0.8"), ("R60", "0.6")):
        assert f"enParticle {en};" in a[name]
        assert f"smoothCoeffs {{ en {en}; et 0.44;" in a[name]
    assert not {"enParticle", "wallType", "wallCoeffs"} & set(a)
    # the rest is the first configuration's, alone
    alone = entries(settings(case, "smoke", "R80", "agglomeration").stdout)
    for k in set(alone) - {"configuration", "clouds", "enParticle",
                           "wallType", "wallCoeffs"}:
        assert a[k] == alone[k], k


@pytest.mark.parametrize("group, message", [
    ("C1+C2", "C2 is two-way coupled (subModels on)"),
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
    res = allrun(alone, "R80 R60")
    assert res.returncode == 0, res.stdout[-3000:]
    res = allrun(group, "R80+R60")
    assert res.returncode == 0, res.stdout[-3000:]
    ra, rg = alone / "runs" / "smoke", group / "runs" / "smoke"
    # one fluid for both: one dispersion and one agglomeration run
    assert sorted(p.name for p in rg.iterdir()) == \
        ["R80+R60", "report", "unladen"]
    agg = rg / "R80+R60" / "agglomeration"
    n = 0
    for c in ("R80", "R60"):
        for stage, clouds in (("dispersion", {"particles": c}),
                              ("agglomeration", {m: c + m for m in
                                                 ("EAM", "MAM")})):
            a_dir, g_dir = ra / c / stage, rg / "R80+R60" / stage
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
    assert n > 100
    # the fluid is the same at the end (one-way: the particles' own)
    last = sorted(agg.glob("0.*"))[-1].name
    assert (agg / last / "U").read_bytes() == \
        (ra / "R80" / "agglomeration" / last / "U").read_bytes()
    # and the comparison can fail: R80 and R60 differ alone (e_n,p)
    st = "postProcessing/EAMHardSphere/*/stats.dat"
    r80 = next((ra / "R80" / "agglomeration").glob(st)).read_bytes()
    r60 = next((ra / "R60" / "agglomeration").glob(st)).read_bytes()
    assert r80 != r60
    # the reports agree row by row (R80 and R60, both models)
    rows = [[ln for ln in (r / "report" / "regression.txt").read_text()
             .splitlines() if ln.startswith(("R80 ", "R60 "))]
            for r in (ra, rg)]
    assert rows[0] == rows[1] and len(rows[0]) >= 16
    # one fluid, reported once by its folder's name
    text = (rg / "report" / "regression.txt").read_text()
    assert text.count("fluid R80+R60 agglomeration: u_tau/U_B") == 1
    assert "fluid R80 agglomeration" not in text
    # a configuration run both alone and in a group is refused by the
    # post, naming both
    shutil.copytree(rg / "R80+R60", ra / "R80+R60")
    res = allrun(alone, "R80", "-post")
    assert res.returncode == 1
    assert "channel.post: R80 EAM ran twice, in" in res.stdout
    assert "R80+R60/agglomeration" in res.stdout
