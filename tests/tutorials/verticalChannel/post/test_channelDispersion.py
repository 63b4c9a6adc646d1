"""channel.post.dispersion: the release and dispersion of each
configuration of a preset's runs, a group's members each from its own
cloud, on made-up stage files with hand values
(channelTestRuns.write_dispersion)."""

import json

import pytest

from channelTestRuns import script, write_dispersion


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    """runs/smoke with C2 alone (cloud particles) and the group C1+R80
    (clouds C1, R80; R80 with twice the counts): the same concentration
    profiles, 1 then 3 near the walls over the centre."""
    disp = script("channel.post.dispersion")
    settings = script("channel.case.settings")
    p = settings.preset("smoke")
    base = tmp_path / "runs" / "smoke"
    write_dispersion(p, base / "C2" / "dispersion")
    write_dispersion(p, base / "C1+R80" / "dispersion", cloud="C1")
    write_dispersion(p, base / "C1+R80" / "dispersion", cloud="R80",
                     counts=2)
    (base / "unladen").mkdir()          # not a configuration
    monkeypatch.setattr(disp, "TUTORIAL", tmp_path)
    monkeypatch.setattr(disp.settings, "report_dir",
                        lambda pname, reference=False: tmp_path / "report")
    return disp, p


def test_each_configuration_from_its_own_cloud(made_up, tmp_path):
    """The hand values: near-wall over centre 1 and 3 over T* 0-0.5 and
    0.5-1.5 after the release; 4 and 20 collisions (8 and 20 per T*,
    times s^2) and 1 and 10 wall impacts (2 and 10 per T* over N); R80's
    counts twice C1's, C2 (alone) C1's; with a span of 1 T* one interval
    from the release: 7/3, 24 collisions over 1.5 T*."""
    disp, p = made_up
    assert disp.main(["smoke", "--span", "0"]) == 0
    r = json.loads((tmp_path / "report" / "dispersion.json").read_text())
    runs = r["runs"]
    assert sorted(runs) == ["C1", "C2", "R80"]
    assert (runs["C1"]["cloud"], runs["R80"]["cloud"],
            runs["C2"]["cloud"]) == ("C1", "R80", "particles")
    assert runs["C2"]["subModels"] == "on" and \
        runs["C1"]["subModels"] == "off"
    N, s2 = p["nParticles"], (6e6 / p["nParticles"])**2
    for c, k in (("C1", 1), ("R80", 2), ("C2", 1)):
        x = runs[c]["intervals"]
        assert [y["nearWallOverCentre"] for y in x] == pytest.approx([1, 3])
        assert [y["fColScaled"] for y in x] == \
            pytest.approx([8 * k * s2, 20 * k * s2])
        assert [y["wallImpacts_per_particle_T"] for y in x] == \
            pytest.approx([2 * k / N, 10 * k / N])
    text = (tmp_path / "report" / "dispersion.txt").read_text()
    assert len([ln for ln in text.splitlines()
                if ln.startswith(("C1 ", "C2 ", "R80 "))]) == 6
    assert disp.main(["smoke", "--span", "1"]) == 0
    r = json.loads((tmp_path / "report" / "dispersion.json").read_text())
    x = r["runs"]["R80"]["intervals"]
    assert len(x) == 1 and r["span"] == 1
    assert x[0]["nearWallOverCentre"] == pytest.approx(7 / 3)
    assert x[0]["fColScaled"] == pytest.approx(2 * 24 / 1.5 * s2)


@pytest.mark.parametrize("argv, words", [
    (["smoke", "--span", "abc"], "'abc' is not a number"),
    (["smoke", "--span", "-1"], "-1 must be >= 0"),
])
def test_bad_span_refused(made_up, capsys, argv, words):
    disp, _ = made_up
    with pytest.raises(SystemExit) as e:
        disp.main(argv)
    assert e.value.code == 2
    assert words in capsys.readouterr().err


def test_unknown_preset_and_no_runs(made_up, tmp_path, capsys):
    disp, _ = made_up
    assert disp.main(["smok"]) == 1
    assert "unknown preset 'smok'" in capsys.readouterr().err
    assert disp.main(["small"]) == 0
    assert "no release under runs/small: nothing written" in \
        capsys.readouterr().out
