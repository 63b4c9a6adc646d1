"""aggloTools.foamfile's dictionary writer: nested Python dicts written as
OpenFOAM dictionaries, checked against this package's own reader (an
exact round trip), against OpenFOAM's reader (foamDictionary -expand:
what the solver will see) and, for numbers, against float() over many
magnitudes; merged's rules; box_case's dictionaries read back as the
nested dicts it was given."""

import re

import numpy as np
import pytest

from aggloTools import boxcase, foamfile
from aggloTools.foamfile import (dict_text, entry_value, merged, number,
                                 parse_dict, read_dict, write_foamfile)
from aggloTools.runner import foam_bin, run

NESTED = {
    "solution": {"active": True, "coupled": False, "maxCo": 1,
                 "sourceTerms": {"schemes": {"U": "semiImplicit 1"}}},
    "material": {"H": 6.3e-20, "E": 7.2e10, "pMax": 1.612985e9,
                 "rho0": 2200},
    "particleForces": {"SchillerNaumannDrag": "", "gravity": ""},
    "injectionModels": {},
    "walls": {'".*"': {"wallModel": "smooth"}},
    "mechanisms": ("turbulence", "drag"),
    "n": (2, 1, 1),
    "Ubar": (0.5, 0, -1e-3),
    "left": None,
}


def tokens(text):
    """A dictionary's tokens (comments and the FoamFile header removed),
    numbers as floats: the same text for OpenFOAM whatever its layout."""
    text = re.sub(r"/\*.*?\*/|//[^\n]*", "", text, flags=re.S)
    text = re.sub(r"FoamFile\s*\{[^}]*\}", "", text)
    out = []
    for t in re.findall(r'"[^"]*"|[{}();]|[^\s{}();]+', text):
        try:
            out.append(float(t))
        except ValueError:
            out.append({"yes": "true", "on": "true"}.get(t, t))
    return out


def test_numbers_are_exact_and_read_as_written():
    """number(): float() gives back the same double for 10^4 values over
    the magnitudes of the project's inputs (1e-30 to 1e30), and large
    values keep the scientific form users write."""
    rng = np.random.default_rng(3)
    v = rng.uniform(-1, 1, 10000) * 10.0 ** rng.integers(-30, 31, 10000)
    assert all(float(number(x)) == x for x in v)
    assert number(7.2e10) == "7.2e10" and number(1.612985e9) == "1.612985e9"
    assert number(0.001) == "0.001" and number(99999.0) == "99999.0"
    assert number(-3e6) == "-3e6" and number(2e-10) == "2e-10"


def test_values():
    assert entry_value(True) == "true" and entry_value(False) == "false"
    assert entry_value(np.int64(3)) == "3"
    assert entry_value((1, 2.5, "x", (0, 1))) == "(1 2.5 x (0 1))"
    with pytest.raises(TypeError, match="set"):
        entry_value({1, 2})


def test_round_trip_through_the_reader():
    """parse_dict(dict_text(d)) gives d back (lists aside: the reader
    takes no lists), None entries left out, keywords alone as ''."""
    d = {k: v for k, v in NESTED.items()
         if not isinstance(v, tuple) and v is not None}
    back = parse_dict(dict_text(d))
    expect = {**d, "walls": {".*": {"wallModel": "smooth"}},
              "solution": {**d["solution"], "active": "true",
                                "coupled": "false",
                                "sourceTerms": {"schemes": {
                                    "U": ["semiImplicit", 1]}}},
              "particleForces": {"SchillerNaumannDrag": [],
                                 "gravity": []}}
    assert back == expect
    assert "left" not in dict_text(NESTED)


def test_openfoam_reads_what_was_written(tmp_path, foam_env):
    """foamDictionary -expand (OpenFOAM's reader and writer) prints the
    same tokens: keywords alone, empty and nested sub-dictionaries,
    quoted regular expressions, lists and numbers as meant (to the six
    digits it prints)."""
    f = tmp_path / "constant" / "d"
    write_foamfile(f, "dictionary", "constant", "d", dict_text(NESTED))
    run([foam_bin("foamDictionary"), "-expand", str(f)], tmp_path,
        "log.foamDictionary")
    read = (tmp_path / "log.foamDictionary").read_text()
    got, sent = tokens(read), tokens(dict_text(NESTED))
    assert len(got) == len(sent)
    for a, b in zip(got, sent):
        if isinstance(b, float):
            assert a == pytest.approx(b, rel=5e-6), (a, b)
        else:
            assert a == b


def test_merged():
    base = {"a": {"b": 1, "c": {"d": 2}}, "e": 3}
    out = merged(base, {"a": {"c": {"x": 4}, "b": None}, "e": {"f": 5},
                        "g": 6})
    assert out == {"a": {"c": {"d": 2, "x": 4}}, "e": {"f": 5}, "g": 6}
    assert base == {"a": {"b": 1, "c": {"d": 2}}, "e": 3}   # untouched
    copy = merged(base, None)
    assert copy == base
    copy["a"]["c"]["d"] = 7                 # a deep copy: base unchanged
    assert base["a"]["c"]["d"] == 2
    assert boxcase.kernel()["material"] is not boxcase.MATERIAL


def test_box_case_writes_the_dicts_it_is_given(tmp_path):
    """The cloud's dictionary reads back as cloud_properties() merged
    with the changes; the kernel's changes reach it; 'none' leaves the
    collision model out."""
    cloud = {"solution": {"coupled": True},
             "subModels": {"rotationModel": "fluidTorque",
                           "particleForces": boxcase.DRAG}}
    case = boxcase.box_case(tmp_path / "a", hard_sphere=boxcase.kernel(
        "EAM", structureModel="VSM", material={"H": 1e-21}), cloud=cloud)
    d = read_dict(case / "constant" / "kinematicCloudProperties")
    sub = d["subModels"]
    assert d["solution"]["coupled"] == "true"
    assert sub["rotationModel"] == "fluidTorque"
    assert sub["particleForces"] == {"SchillerNaumannDrag": []}
    hs = sub["hardSphereCoeffs"]
    assert hs["structureModel"] == "VSM" and hs["material"]["H"] == 1e-21
    assert hs["material"]["E"] == 7.2e10            # the rest kept
    assert hs["agglomerationModel"] == "EAM"
    assert hs["walls"] == {".*": {"wallModel": "smooth", "smoothCoeffs": {
        "en": 0.8, "et": 0.4, "muSt": 0.3, "muKin": 0.15}}}
    case = boxcase.box_case(tmp_path / "b", hard_sphere="none")
    sub = read_dict(case / "constant" / "kinematicCloudProperties")[
        "subModels"]
    assert sub["collisionModel"] == "none" and "hardSphereCoeffs" not in sub
    ctl = read_dict(case / "system" / "controlDict")
    assert ctl["endTime"] == 1e-3 and ctl["writeInterval"] == 10


def test_edit_replaces_and_refuses_a_text_not_there(tmp_path):
    f = tmp_path / "controlDict"
    f.write_text("endTime 1; writeInterval 1; endTime 1;\n")
    foamfile.edit(f, "endTime 1;", "endTime 2;", 1)
    assert f.read_text() == "endTime 2; writeInterval 1; endTime 1;\n"
    foamfile.edit(f, "1;", "3;")
    assert f.read_text() == "endTime 2; writeInterval 3; endTime 3;\n"
    with pytest.raises(ValueError, match="controlDict: 'endTime 1;' is "
                       "not in the file"):
        foamfile.edit(f, "endTime 1;", "endTime 4;")
    assert f.read_text() == "endTime 2; writeInterval 3; endTime 3;\n"
