"""aggloTools.casesettings, the presets -> caseSettings mechanism both
tutorials use: every entry of a presets file checked against its
section's keys (presets, common, a group's entries), a preset merged over
the common values, unknown names and choices stopped with the valid ones
named, a run's caseSettings read back with its keys checked. Each case is
a hand-written file whose expected result is stated here."""

import pytest

from aggloTools import casesettings

PRESETS = """
common { a 1; b 2; }
small { b 3; c 4; }
large { c 5; }
configurations { C1 { x 1; } C2 { x 2; } }
"""


def write(tmp_path, text, name="presets"):
    f = tmp_path / name
    f.write_text(text)
    return f


def read(path, **kw):
    return casesettings.read_presets(
        path, {"a", "b", "c"}, {"common": {"a", "b"}},
        {"configurations": {"x"}}, **kw)


def test_preset_overrides_the_common_values(tmp_path):
    ps = read(write(tmp_path, PRESETS))
    p = casesettings.merged(ps, "small", "prog",
                            exclude=("configurations",))
    assert p == {"a": 1, "b": 3, "c": 4}
    assert casesettings.merged(ps, "large", "prog",
                               exclude=("configurations",)) == \
        {"a": 1, "b": 2, "c": 5}
    assert casesettings.named(ps["configurations"], "C2", "configuration",
                              "prog") == {"x": 2}


@pytest.mark.parametrize("text, where, key", [
    ("common { a 1; z 2; }", "presets/common", "z"),
    ("common { a 1; } small { d 4; }", "presets/small", "d"),
    ("common { a 1; } configurations { C1 { y 1; } }",
     "presets/configurations/C1", "y"),
    # c is a preset key, not a common one
    ("common { c 1; }", "presets/common", "c"),
])
def test_an_unknown_entry_names_itself_and_its_section(tmp_path, text,
                                                        where, key):
    with pytest.raises(SystemExit) as e:
        read(write(tmp_path, text))
    msg = str(e.value)
    assert f"'{key}'" in msg and where in msg, msg


def test_unknown_preset_names_the_valid_ones_only(tmp_path):
    ps = read(write(tmp_path, PRESETS))
    for bad in ("medium", "common", "configurations"):
        with pytest.raises(SystemExit) as e:
            casesettings.merged(ps, bad, "prog", exclude=("configurations",))
        msg = str(e.value)
        assert msg == f"prog: unknown preset '{bad}'; valid: small large"


def test_choice(tmp_path):
    assert casesettings.choice("on", ("on", "off"), "w") == "on"
    with pytest.raises(SystemExit) as e:
        casesettings.choice("yes", ("on", "off"), "presets/x: eventLog")
    assert str(e.value) == ("presets/x: eventLog 'yes' is not one of: "
                            "on off")


def test_read_settings_checks_every_entry(tmp_path):
    (tmp_path / "system").mkdir()
    write(tmp_path / "system", "deltaT 0.5; clouds (a b);", "caseSettings")
    s = casesettings.read_settings(tmp_path, {"deltaT", "clouds"})
    assert s["deltaT"] == 0.5
    with pytest.raises(SystemExit) as e:
        casesettings.read_settings(tmp_path, {"deltaT"})
    assert "'clouds'" in str(e.value) and "caseSettings" in str(e.value)
