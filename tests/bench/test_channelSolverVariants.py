"""The variants of the channel's solver settings
(bench/channelSolverVariants.py): base is the tutorial's fvSolution and
fvSchemes as they are, a variant changes its own entries only, and an
entry that is not there is refused."""

import pytest

from aggloTools import foamfile
from aggloTools.runner import bench_module


@pytest.fixture(scope="module")
def variants():
    return bench_module("channelSolverVariants")


def test_base_is_the_tutorial_fvSolution(variants, tmp_path):
    """base writes the tutorial's fvSolution as it is; a variant changes
    its own entry only (pFinal follows p's tolerance through $p)."""
    (tmp_path / "system").mkdir()
    variants.write_settings(tmp_path, "base")
    for fname in ("fvSolution", "fvSchemes"):
        assert (tmp_path / "system" / fname).read_bytes() == \
            (variants.TUTORIAL / "system" / fname).read_bytes()
    tutorial = variants.TUTORIAL / "system" / "fvSolution"
    theirs = foamfile.read_dict(tutorial)
    for name, entry, value in (("pTol1e-6", ("p", "tolerance"), 1e-6),
                               ("UTol1e-6", ("(U|UFinal)", "tolerance"),
                                1e-6),
                               ("GaussSeidel", ("p", "smoother"),
                                "GaussSeidel")):
        variants.write_settings(tmp_path, name)
        ours = foamfile.read_dict(tmp_path / "system" / "fvSolution")
        assert ours["solvers"][entry[0]][entry[1]] == value
        ours["solvers"][entry[0]][entry[1]] = \
            theirs["solvers"][entry[0]][entry[1]]
        assert ours == theirs
        assert variants.settings_of(name)["solvers"][entry[0]][entry[1]] \
            == value


def test_unknown_entry_is_refused(variants, monkeypatch):
    monkeypatch.setitem(variants.VARIANTS, "bad", {"p/tolerence": "1e-6"})
    with pytest.raises(SystemExit, match="no entry p/tolerence"):
        variants.fv_solution("bad")


def test_added_and_removed_entries(variants, tmp_path):
    """PCG: the solver set, the smoother removed, a preconditioner added;
    nothing else changes."""
    theirs = foamfile.read_dict(variants.TUTORIAL / "system" / "fvSolution")
    ours = variants.settings_of("PCG")
    p = dict(theirs["solvers"]["p"], solver="PCG", preconditioner="DIC")
    del p["smoother"]
    assert ours["solvers"]["p"] == p
    assert ours["PIMPLE"] == theirs["PIMPLE"]
    assert variants.settings_of("coarsest100")["solvers"]["p"][
        "nCellsInCoarsestLevel"] == 100


def test_entry_added_to_a_top_level_block(variants):
    """momentumPredictorOff adds its entry to PIMPLE, indented as PIMPLE's
    entries, and changes nothing else."""
    theirs = foamfile.read_dict(variants.TUTORIAL / "system" / "fvSolution")
    ours = variants.settings_of("momentumPredictorOff")
    assert ours["PIMPLE"] == dict(theirs["PIMPLE"], momentumPredictor="off")
    assert ours["solvers"] == theirs["solvers"]
    assert "\n    momentumPredictor off;\n}" in \
        variants.fv_solution("momentumPredictorOff")


def test_fvSchemes_entries(variants, tmp_path, monkeypatch):
    """A variant of fvSchemes sets its entries in one-line blocks, leaves
    fvSolution and every other line of fvSchemes as they are, and records
    the entries in its settings; uncorrected names the tutorial's
    entries."""
    entries = {"fvSchemes:laplacianSchemes/default":
               "Gauss linear limited corrected 0.5",
               "fvSchemes:snGradSchemes/default": "limited corrected 0.5"}
    monkeypatch.setitem(variants.VARIANTS, "limited", entries)
    (tmp_path / "system").mkdir()
    variants.write_settings(tmp_path, "limited")
    system = variants.TUTORIAL / "system"
    assert (tmp_path / "system" / "fvSolution").read_bytes() == \
        (system / "fvSolution").read_bytes()
    ours = (tmp_path / "system" / "fvSchemes").read_text().splitlines()
    theirs = (system / "fvSchemes").read_text().splitlines()
    changed = [(a, b) for a, b in zip(theirs, ours) if a != b]
    assert len(ours) == len(theirs)
    assert [b.split() for _, b in changed] == [
        ["laplacianSchemes", "{", "default", "Gauss", "linear", "limited",
         "corrected", "0.5;", "}"],
        ["snGradSchemes", "{", "default", "limited", "corrected", "0.5;",
         "}"]]
    assert variants.settings_of("limited")["fvSchemes"] == {
        "laplacianSchemes/default": "Gauss linear limited corrected 0.5",
        "snGradSchemes/default": "limited corrected 0.5"}
    assert "fvSchemes" not in variants.settings_of("base")
    # uncorrected's entries are found in the tutorial's fvSchemes
    assert variants.settings_of("uncorrected")["fvSchemes"] == {
        "laplacianSchemes/default": "Gauss linear uncorrected",
        "snGradSchemes/default": "uncorrected"}
    variants.system_file("uncorrected", "fvSchemes")


def test_unknown_fvSchemes_entry_is_refused(variants, monkeypatch):
    monkeypatch.setitem(variants.VARIANTS, "bad",
                        {"fvSchemes:laplacianSchemes/defualt": "x"})
    with pytest.raises(SystemExit, match="no entry laplacianSchemes/defualt"):
        variants.system_file("bad", "fvSchemes")
