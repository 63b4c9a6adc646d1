"""The readers of aggloTools refuse damaged files with an error that names
the file and what is wrong (a cut-off stats.dat row, a truncated or
miscounted list, a positions file shorter than its count, unbalanced
braces), instead of numpy's shape errors, AttributeErrors or silently
short arrays; the cloud record the writers keep stays consistent when
particles are appended."""

import numpy as np
import pytest

from aggloTools import cloud, foamfile, stats

HEAD = foamfile.HEADER.format(cls="scalarField", loc="0", obj="d")


def stats_file(case, t, body):
    d = case / "postProcessing" / "kinematicCloudHardSphere" / t
    d.mkdir(parents=True)
    (d / "stats.dat").write_text("# Time nParticles nCol\n" + body)


def test_stats_with_a_cut_off_row(tmp_path):
    stats_file(tmp_path, "0", "0.1 10 0\n0.2 10 3\n0.3 9")
    with pytest.raises(ValueError, match=r"stats.dat, line 4: 2 values "
                       r"for 3 columns"):
        stats.read_stats(tmp_path)


def test_cut_off_row_replaced_by_a_restart(tmp_path):
    """The row a kill cut off is followed by the restart's file, whose
    rows replace the earlier file's rows after its start time."""
    stats_file(tmp_path, "0", "0.1 10 0\n0.2 10 3\n0.3 9")
    stats_file(tmp_path, "0.2", "0.3 9 4\n")
    st = stats.read_stats(tmp_path)
    assert st["Time"].tolist() == [0.1, 0.2, 0.3]
    assert st["nCol"].tolist() == [0, 3, 4]


@pytest.mark.parametrize("body, words", [
    ("3\n(\n1\n2\n", r"closing '\)'"),
    ("3\n(\n1\n2\n)\n", "announces 3 values but holds 2"),
    ("2\n(\n(1 2 3)\n", r"closing '\)'"),
])
def test_truncated_or_miscounted_list(tmp_path, body, words):
    f = tmp_path / "d"
    f.write_text(HEAD + body)
    with pytest.raises(ValueError, match=words) as e:
        cloud.read_lagrangian(f)
    assert str(f) in str(e.value)


def test_symmetric_tensor_list(tmp_path):
    """A volSymmTensorField's list (UPrime2Mean) is read as rows of six."""
    f = tmp_path / "d"
    f.write_text(HEAD + "2\n(\n(1 2 3 4 5 6)\n(7 8 9 10 11 12)\n)\n")
    a = cloud.read_lagrangian(f)
    assert a.shape == (2, 6) and a[1, 5] == 12 and a[0, 3] == 4


@pytest.mark.parametrize("body", ["2\n(\n(1 2 3 4)\n(5 6)\n)\n",
                                  "2\n(\n(1 2)\n(3 4 5 6)\n)\n"])
def test_tuples_of_mixed_sizes(tmp_path, body):
    """Tuples of other sizes than the first are refused, also where their
    numbers would fill whole rows of the first's size."""
    f = tmp_path / "d"
    f.write_text(HEAD + body)
    with pytest.raises(ValueError, match="numbers in 2 tuples of"):
        cloud.read_lagrangian(f)


def test_positions_shorter_than_their_count(tmp_path):
    cloud.write_cloud(tmp_path, [(0, 0, 0), (1, 1, 1)], 1e-5, 1000)
    f = tmp_path / "0" / "lagrangian" / "kinematicCloud" / "positions"
    text = f.read_text()
    f.write_text(text.replace("(1 1 1) -1\n", ""))
    with pytest.raises(ValueError, match="1 rows for the 2"):
        cloud.read_positions(f)


@pytest.mark.parametrize("text, words", [
    ("a { b 1; ", "without its closing"),
    ("a 1; }", "without its '{'"),
    ("a 1", "does not end with ';'"),
])
def test_unbalanced_dictionary(tmp_path, text, words):
    f = tmp_path / "dict"
    f.write_text(text)
    with pytest.raises(ValueError, match=words) as e:
        foamfile.read_dict(f)
    assert str(f) in str(e.value)


def test_record_follows_appended_particles(tmp_path):
    """write_cloud writes the record the cloud checks on reading;
    append_particles keeps it equal to the particles on file."""
    cloud.write_cloud(tmp_path, [(0, 0, 0), (1, 1, 1)], 1e-5, 1000,
                      n_primary=[1, 3])
    assert cloud.read_record(tmp_path, "0", "kinematicCloud") == {
        "writer": "aggloTools", "complete": True,
        "clouds": ["kinematicCloud"], "nProcs": 1, "nParticles": 2,
        "nParticlesTotal": 2, "nPrimariesTotal": 4}
    cloud.append_particles(tmp_path, "0", "kinematicCloud",
                           np.array([(2.0, 2, 2)]),
                           {"nPrimary": np.array([2])})
    rec = cloud.read_record(tmp_path, "0", "kinematicCloud")
    x = cloud.read_positions(cloud.cloud_dir(tmp_path, "0") / "positions")
    n = cloud.read_lagrangian(cloud.cloud_dir(tmp_path, "0") / "nPrimary")
    assert rec["nParticlesTotal"] == len(x) == 3
    assert rec["nPrimariesTotal"] == n.sum() == 6


COORD_HEAD = ("FoamFile { version 2.0; format ascii; class Cloud<x>; "
              "location \"0\"; object coordinates; }\n")


def _coordinates(n):
    rows = "".join(f"(0.25 0.25 0.25 0.25) {k} {k + 1} 1\n"
                   for k in range(n))
    return COORD_HEAD + f"{n}\n(\n{rows})\n"


def test_coordinates_round_trip(tmp_path):
    f = tmp_path / "coordinates"
    f.write_text(_coordinates(5))
    b, cell, face, pt = cloud.read_coordinates(f)
    assert b.shape == (5, 4) and list(cell) == list(range(5))
    assert list(face) == list(range(1, 6)) and (pt == 1).all()


@pytest.mark.parametrize("edit, words", [
    (lambda t: t[:int(0.6 * len(t))], "rows for the 291"),
    (lambda t: t.replace("291\n(", "290\n(", 1), "291 rows for the 290"),
    (lambda t: t.replace("(0.25 0.25 0.25 0.25) 7 8 1",
                         "(0.25 0.25) 7 8 1", 1), "row 7 has 2 components"),
], ids=["cutAt60percent", "wrongCount", "twoComponents"])
def test_coordinates_cut_or_miscounted(tmp_path, edit, words):
    """A coordinates file cut at 60 %, one whose count disagrees with its
    rows, or a row with another number of components stops instead of
    returning what it could read."""
    f = tmp_path / "coordinates"
    f.write_text(edit(_coordinates(291)))
    with pytest.raises(ValueError, match=words) as e:
        cloud.read_coordinates(f)
    assert str(f) in str(e.value)


def test_positions_with_mixed_vector_sizes(tmp_path):
    """4- and 2-component vectors together hold 6 numbers: they were read
    as two positions of 3."""
    cloud.write_cloud(tmp_path, [(0, 0, 0), (1, 1, 1)], 1e-5, 1000)
    f = tmp_path / "0" / "lagrangian" / "kinematicCloud" / "positions"
    text = f.read_text()
    f.write_text(text.replace("(0 0 0) -1", "(0 0 0 0) -1")
                 .replace("(1 1 1) -1", "(1 1) -1"))
    with pytest.raises(ValueError, match="row 0 has 4 components"):
        cloud.read_positions(f)


def test_binary_positions_cut_off(tmp_path):
    """Binary records (the position and the cell in parentheses, then a
    newline) read back; cut off before the list closes, they stop."""
    import struct
    head = ('FoamFile { version 2.0; format binary; '
            'arch "LSB;label=32;scalar=64"; class Cloud<x>; '
            'location "0"; object positions; }\n')
    recs = b"".join(b"(" + struct.pack("<3di", k, k, k, -1) + b")\n"
                    for k in range(3))
    f = tmp_path / "positions"
    f.write_bytes(head.encode() + b"3\n(" + recs + b")\n")
    assert cloud.read_positions(f).tolist() == [[k] * 3 for k in range(3)]
    f.write_bytes(head.encode() + b"3\n(" + recs[:-20])
    with pytest.raises(ValueError, match="cut off") as e:
        cloud.read_positions(f)
    assert str(f) in str(e.value)


@pytest.mark.parametrize("body, words", [
    ("# k count\n1 20\n2", "line 3: 1 values for 2 columns"),
    ("# k count\n1 20\n2 1e", "line 3: 2 values for 2 columns"),
    ("1 20\n", "line 1: a row before the header"),
    ("", "no header"),
])
def test_table_with_a_cut_off_row(tmp_path, body, words):
    """A cut agglomerateSizes.dat is refused naming the file and the line
    (numpy's shape error named neither)."""
    f = tmp_path / "agglomerateSizes.dat"
    f.write_text(body)
    with pytest.raises(ValueError, match=words) as e:
        stats.read_table(f)
    assert str(f) in str(e.value)


ALTERNATIVES = """FoamFile { version 2.0; }
// off { commented out }
none { breakupModel none; }
stressThreshold
{
    nested { none { q 1; } }   // a nested entry of the same name
    word "}";
}
cut { x {
"""


@pytest.mark.parametrize("name, body", [
    ("none", "breakupModel none;"),
    ("stressThreshold", 'nested { none { q 1; } }   \n    word "}";'),
])
def test_entry_text(name, body):
    """The top-level entry's text as written (a nested entry of the same
    name, a brace in quotes and comments do not confuse it), parsed back
    to what the whole file's parse holds."""
    text = foamfile.entry_text(ALTERNATIVES, name)
    assert text == body
    whole = foamfile.parse_dict(ALTERNATIVES.replace("cut { x {", ""))
    assert foamfile.parse_dict(text) == whole[name]


@pytest.mark.parametrize("name, words", [
    ("q", "no entry 'q"), ("nested", "no entry 'nested"),
    ("off", "no entry 'off"), ("cut", "'cut': its '{' does not close")])
def test_entry_text_refused(name, words):
    with pytest.raises(ValueError, match=words):
        foamfile.entry_text(ALTERNATIVES, name)


@pytest.mark.parametrize("name, kept", [
    # the name rounded to 10 digits (timePrecision): the row at the
    # restart time, 4e-11 above the name, is the earlier run's
    ("0.1767760468", [0.17673185282828599, 0.17677604683999598]),
    # an exact name (trailing zeros dropped): nothing after it kept
    ("1", [0.5, 1.0]),
])
def test_restart_keeps_the_row_at_its_time(tmp_path, name, kept):
    """The earlier run's rows up to the restart's time are kept, the
    row at that time too where the folder's name is the time rounded;
    the restart's rows follow, later rows of the earlier run are
    replaced."""
    t0 = kept[-1]
    dt = kept[-1] - kept[-2]
    stats_file(tmp_path, "0", "".join(
        f"{t!r} 10 {i}\n" for i, t in enumerate(kept + [t0 + dt])))
    stats_file(tmp_path, name, f"{t0 + dt!r} 10 7\n{t0 + 2 * dt!r} 10 8\n")
    st = stats.read_stats(tmp_path)
    assert st["Time"].tolist() == kept + [t0 + dt, t0 + 2 * dt]
    assert st["nCol"].tolist() == [0, 1, 7, 8]
