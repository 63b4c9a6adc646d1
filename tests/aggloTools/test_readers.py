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


def test_positions_shorter_than_their_count(tmp_path):
    cloud.write_cloud(tmp_path, [(0, 0, 0), (1, 1, 1)], 1e-5, 1000)
    f = tmp_path / "0" / "lagrangian" / "kinematicCloud" / "positions"
    text = f.read_text()
    f.write_text(text.replace("(1 1 1) -1\n", ""))
    with pytest.raises(ValueError, match="1 positions for the 2"):
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
        "writer": "aggloTools", "nProcs": 1, "nParticles": 2,
        "nParticlesTotal": 2, "nPrimariesTotal": 4}
    cloud.append_particles(tmp_path, "0", "kinematicCloud",
                           np.array([(2.0, 2, 2)]),
                           {"nPrimary": np.array([2])})
    rec = cloud.read_record(tmp_path, "0", "kinematicCloud")
    x = cloud.read_positions(cloud.cloud_dir(tmp_path, "0") / "positions")
    n = cloud.read_lagrangian(cloud.cloud_dir(tmp_path, "0") / "nPrimary")
    assert rec["nParticlesTotal"] == len(x) == 3
    assert rec["nPrimariesTotal"] == n.sum() == 6
