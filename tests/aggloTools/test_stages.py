"""aggloTools.stages: a driver's options refused in the Allrun words with
exit status 1; the pool runs every item, up to jobs at a time, and
returns the failed ones; a decomposition takes the latest folder and one
cut off is done again."""

import shutil

import pytest

from aggloTools import stages
from aggloTools.cloud import read_cloud
from aggloTools.runner import foam_bin, run
from aggloTools.times import time_dirs
from aggloTools.runner import CommandError


def parse(argv):
    p = stages.Parser("t", "doc")
    p.add_argument("-preset", default="small")
    p.add_argument("-j", type=stages.positive("-j"), default=1)
    return p.parse_args(argv)


@pytest.mark.parametrize("argv, words", [
    (["-preset"], "Allrun: -preset needs a value"),
    (["-j", "0"], "-j '0' is not a positive number"),
    (["-j", "x"], "-j 'x' is not a positive number"),
    (["-bogus"], "unknown option -bogus"),
])
def test_refused_options(argv, words, capsys):
    with pytest.raises(SystemExit) as e:
        parse(argv)
    assert e.value.code == 1
    assert words in capsys.readouterr().err


def test_accepted_options():
    a = parse(["-preset", "ci", "-j", "3"])
    assert (a.preset, a.j) == ("ci", 3)


def test_pool_collects_the_failures():
    done = []

    def work(i):
        if i % 3 == 0:
            raise CommandError("no")
        done.append(i)
    assert sorted(stages.pool(range(7), work, 2)) == [0, 3, 6]
    assert sorted(done) == [1, 2, 4, 5]


def test_decompose_takes_the_latest_folder_by_name(raised_digits, case_dir):
    """A case branched at a folder OpenFOAM v1912 does not find by itself
    (16.333317, timePrecision 2) decomposes onto 2 ranks with its fields
    and every particle; plain decomposePar writes none of them and
    succeeds."""
    case = case_dir / "branch"
    shutil.copytree(raised_digits, case)
    for t in time_dirs(case):
        if t.name != "16.333317":
            shutil.rmtree(t)
    for entry, value in (("numberOfSubdomains", "2"), ("coeffs/n", "(2 1 1)")):
        run([foam_bin("foamDictionary"), "-entry", entry, "-set", value,
             "system/decomposeParDict"], case, "log.foamDictionary")
    run([foam_bin("decomposePar"), "-force"], case, "log.plain")
    assert not (case / "processor0" / "16.333317").exists()
    stages.decompose(case)
    ids = []
    for proc in ("processor0", "processor1"):
        assert (case / proc / "16.333317" / "U").is_file(), proc
        if (case / proc / "16.333317" / "lagrangian").is_dir():
            ids += list(read_cloud(case / proc, "16.333317",
                                   names=["origId"])["origId"])
    assert sorted(ids) == [0, 1, 2]


def test_decomposition_cut_off_is_done_again(raised_digits, case_dir):
    """A decomposePar killed half-way leaves processor0 behind: the
    driver took the folders for complete and never decomposed again
    ('1077 particles read, but 2100 were written'). A case counts as
    decomposed only by the marker written after decomposePar succeeded;
    a failed decomposition removes it."""
    case = case_dir / "cut"
    shutil.copytree(raised_digits, case)
    for entry, value in (("numberOfSubdomains", "2"), ("coeffs/n", "(2 1 1)")):
        run([foam_bin("foamDictionary"), "-entry", entry, "-set", value,
             "system/decomposeParDict"], case, "log.foamDictionary")
    (case / "processor0").mkdir()            # what the kill left
    assert not stages.decomposed(case)
    stages.decompose(case)
    assert stages.decomposed(case)
    assert (case / stages.DECOMPOSED).read_text() == "2\n"
    run([foam_bin("foamDictionary"), "-entry", "numberOfSubdomains", "-set",
         "3", "system/decomposeParDict"], case, "log.foamDictionary")
    with pytest.raises(CommandError):
        stages.decompose(case)                # 3 subdomains, (2 1 1)
    assert not stages.decomposed(case)
