"""A preset whose stages before agglomeration are another preset's
(`stagesFrom NAME`) and one that runs some agglomeration models only
(`models (EAM)`): the entries read and refused as documented (presets),
and the shared stages exact: the smoke preset's C2 branched from the
smoke run's own dispersion, with only EAM, gives that run's EAM
agglomeration statistics byte for byte, writes no unladen, release or
dispersion of its own and no MAM run; with break-up (nothing breaks at
smoke) the break-up report finds the base's run without it equal."""

import shutil
import subprocess
import sys

import pytest

from aggloTools.foamfile import entry_text
from channelTestRuns import TUTORIAL


def with_presets(tmp_path, *entries):
    """A copy of the tutorial (no runs) whose presets file has the named
    entries added: (name, base preset, extra text)."""
    case = tmp_path / "verticalChannel"
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
        "runs", "results", "__pycache__"))
    presets = case / "presets"
    text = presets.read_text()
    for name, base, extra in entries:
        text += f"\n{name}\n{{\n{entry_text(text, base)}\n{extra}\n}}\n"
    presets.write_text(text)
    return case


def settings(case, preset, config="C2", stage="agglomeration"):
    return subprocess.run([sys.executable, "-m", "channel.case", "settings",
                           preset, config, stage], cwd=case,
                          capture_output=True, text=True)


def clouds(stdout):
    line = next(x for x in stdout.splitlines() if x.startswith("clouds"))
    return line.split(None, 1)[1]


def test_models_choose_the_agglomeration_clouds(tmp_path):
    case = with_presets(tmp_path, ("onlyMAM", "smoke", "models (MAM);"),
                        ("both", "smoke", "models (EAM MAM);"))
    # two-way (C2): the first of the preset's models unless one is named;
    # one-way (C1): all of them in one run
    assert clouds(settings(case, "onlyMAM").stdout) == "(MAM);"
    assert clouds(settings(case, "onlyMAM", "C1").stdout) == "(MAM);"
    assert clouds(settings(case, "both", "C1").stdout) == "(EAM MAM);"
    assert clouds(settings(case, "smoke", "C1").stdout) == "(EAM MAM);"


@pytest.mark.parametrize("extra, message", [
    ("models (EAM EAM);", "models names a model twice"),
    ("models (EAM MAN);", "models: each of them 'MAN' is not one of: EAM "
     "MAM"),
    ("models ();", "models: each of them '()' is not one of: EAM MAM"),
    ("stagesFrom smok;", "preset 'smok'"),
    ("stagesFrom small;", "stagesFrom small: its stages before "
     "agglomeration would differ from this preset's in"),
    ("stagesFrom shared;", "stagesFrom shared: that preset takes its "
     "stages from smoke: name that one"),
    ("perConfiguration C4;", "perConfiguration must be a dictionary"),
    ("perConfiguration { C9 { nParticles 3000; couplingScale 2; } }",
     "unknown configuration 'C9'; valid: C1 C2 C3 C4 R80 R60"),
    ("perConfiguration { C4 { nParticles 3000; } }",
     "perConfiguration/C4: couplingScale missing"),
    ("perConfiguration { C4 { nParticles 3000; couplingScale 2; seed 3; } }",
     "unknown entry 'seed' in channel.case: presets/bad: "
     "perConfiguration/C4; valid "
     "entries: couplingScale nParticles"),
    ("perConfiguration { C4 { nParticles 30.5; couplingScale 2; } }",
     "perConfiguration/C4: nParticles '30.5' is not a whole number"),
    ("perConfiguration { C4 { nParticles 3000; couplingScale 0; } }",
     "perConfiguration/C4: couplingScale '0' is out of range (0, inf)"),
])
def test_bad_entries_refused(tmp_path, extra, message):
    case = with_presets(tmp_path, ("shared", "smoke", "stagesFrom smoke;"),
                        ("bad", "smoke", extra))
    assert settings(case, "shared").returncode == 0
    res = settings(case, "bad")
    assert res.returncode == 1
    assert message in res.stderr, res.stderr


def test_a_configuration_of_its_own_particle_number(tmp_path):
    """perConfiguration gives C4 (two-way) and R80 (one-way: no coupling
    to scale) their own particle number; the other configurations keep
    the preset's, and a preset whose stages are shared must say the
    same."""
    extra = ("perConfiguration { C4 { nParticles 6000; couplingScale 3; }"
             " R80 { nParticles 4000; couplingScale 5; } }")
    case = with_presets(tmp_path, ("own", "smoke", extra),
                        ("sharedOwn", "smoke", extra + " stagesFrom own;"),
                        ("sharedNot", "smoke", "stagesFrom own;"))

    def entries(config, preset="own"):
        res = settings(case, preset, config, "release")
        assert res.returncode == 0, res.stderr
        return {k: v for k, v in (line.rstrip(";").split(None, 1)
                                  for line in res.stdout.splitlines()
                                  if line.startswith(("nParticles",
                                                      "couplingScale")))}
    assert entries("C4") == {"nParticles": "6000", "couplingScale": "3"}
    assert entries("C2") == {"nParticles": "2000", "couplingScale": "1"}
    assert entries("R80") == {"nParticles": "4000", "couplingScale": "1"}
    assert entries("C4", "sharedOwn")["nParticles"] == "6000"
    res = settings(case, "sharedNot", "C4", "release")
    assert res.returncode == 1
    assert "would differ from this preset's in perConfiguration" \
        in res.stderr, res.stderr


def test_a_stage_entry_that_differs_is_named(tmp_path):
    """Everything before agglomeration must be the base preset's: a time
    step or a seed that differs is named (breakup, eventLog, models may
    differ)."""
    case = with_presets(
        tmp_path,
        ("ok", "smoke", "stagesFrom smoke; breakup stressThreshold; "
         "eventLog off; models (EAM);"))
    text = (case / "presets").read_text()
    ok = entry_text(text, "ok")
    text += ("\ndt\n{\n" + ok.replace("dtStar          0.02;",
                                      "dtStar 0.01;") + "\n}\n")
    text += "\nseeded\n{\n" + ok + "\nseed 2;\n}\n"
    (case / "presets").write_text(text)
    assert settings(case, "ok").returncode == 0
    for name, key in (("dt", "deltaT dtStar"), ("seeded", "seed")):
        res = settings(case, name)
        assert res.returncode == 1
        assert f"would differ from this preset's in {key} (only " \
            "breakup eventLog models stagesFrom may)" in res.stderr, \
            res.stderr


@pytest.mark.slow
def test_shared_stages_give_the_own_run(tmp_path, smoke_runs):
    """smokeShared = smoke with stagesFrom smoke and models (EAM), run
    beside the smoke run's folders: its C2 EAM agglomeration stage equals
    the smoke run's byte for byte (statistics of every step), and it ran
    nothing else."""
    case = with_presets(tmp_path, ("smokeShared", "smoke",
                                   "stagesFrom smoke; models (EAM);"))
    own = smoke_runs[1] / "runs" / "smoke"
    shutil.copytree(own / "C2" / "dispersion",
                    case / "runs" / "smoke" / "C2" / "dispersion")
    shutil.copytree(own / "unladen", case / "runs" / "smoke" / "unladen")
    res = subprocess.run(["./Allrun", "-preset", "smokeShared", "-configs",
                          "C2", "-np", "1", "-every", "600"], cwd=case,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    assert "C2: release and dispersion: preset smoke's" in res.stdout
    mine = case / "runs" / "smokeShared"
    assert sorted(p.name for p in mine.iterdir()) == ["C2", "report"]
    assert sorted(p.name for p in (mine / "C2").iterdir()) == \
        ["agglomeration-EAM"]
    stats = sorted((mine / "C2" / "agglomeration-EAM" / "postProcessing"
                    / "EAMHardSphere").glob("*/stats.dat"))
    theirs = sorted((own / "C2" / "agglomeration-EAM" / "postProcessing"
                     / "EAMHardSphere").glob("*/stats.dat"))
    assert [f.parent.name for f in stats] == \
        [f.parent.name for f in theirs] and stats
    for a, b in zip(stats, theirs):
        assert a.read_bytes() == b.read_bytes(), a
    # the unladen LES of the report is the base preset's
    text = (mine / "report" / "regression.txt").read_text()
    assert "fluid unladen: u_tau/U_B" in text

    # The same with break-up (nothing breaks at smoke): the break-up
    # report finds the base preset's run without it and says they agree
    # (the columns both have, at every step); the counters of the run
    # without it are the reference, not this run's own stages
    text = (case / "presets").read_text()
    text += ("\nsmokeBreakup\n{\n" + entry_text(text, "smokeShared")
             + "\nbreakup stressThreshold;\n}\n")
    (case / "presets").write_text(text)
    shutil.copytree(own / "C2" / "agglomeration-EAM",
                    case / "runs" / "smoke" / "C2" / "agglomeration-EAM")
    res = subprocess.run(["./Allrun", "-preset", "smokeBreakup", "-configs",
                          "C2", "-np", "1", "-every", "600"], cwd=case,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:]
    rep = (case / "runs" / "smokeBreakup" / "report"
           / "breakup.txt").read_text()
    assert "  the same stage without break-up (runs/smoke/C2/agglomeration-"\
        "EAM): every statistics column equal at every step" in rep, rep
    # and a base run that differs is said to: its nAgg one higher from
    # the tenth step on
    st = sorted((case / "runs" / "smoke" / "C2" / "agglomeration-EAM"
                 / "postProcessing" / "EAMHardSphere").glob("*/stats.dat"))
    lines = st[0].read_text().splitlines()
    head = next(x for x in lines if x.startswith("# Time")).split()[1:]
    k, rows = head.index("nAgg"), [x for x in lines if x[:1] != "#"]
    for i in range(9, len(rows)):
        v = rows[i].split()
        v[k] = str(int(v[k]) + 1)
        rows[i] = " ".join(v)
    st[0].write_text("\n".join([x for x in lines if x[:1] == "#"] + rows)
                     + "\n")
    res = subprocess.run([sys.executable, "-m", "channel.post.breakup",
                          "smokeBreakup"], cwd=case, capture_output=True,
                         text=True)
    assert res.returncode == 0, res.stderr
    # the tenth step ends at T*agg = 10 x 0.02
    assert "EAM): differs from T*agg 0.2\n" in res.stdout, res.stdout


def test_the_driver_refuses_an_unfinished_base(tmp_path, foam_env):
    """Without the base preset's finished dispersion the driver stops,
    naming the command that makes it, and writes nothing."""
    case = with_presets(tmp_path, ("smokeShared", "smoke",
                                   "stagesFrom smoke; models (EAM);"))
    res = subprocess.run(["./Allrun", "-preset", "smokeShared", "-configs",
                          "C2", "-np", "1"], cwd=case,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=300)
    assert res.returncode == 1
    assert "runs/smoke/C2/dispersion has not finished its dispersion " \
        "stage, which this preset branches from (stagesFrom smoke): " \
        "./Allrun -preset smoke -configs C2 first" in res.stdout, res.stdout
    assert not (case / "runs" / "smoke").exists()
