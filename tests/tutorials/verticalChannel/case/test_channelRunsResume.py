"""The channel driver's outputs after a kill: foamToVTK cut off or
failing left a VTK/ folder that later calls took for written (rc 0,
VTK/lagrangian/MAM missing); it is now written once, behind a marker,
and a failure fails the call and leaves no VTK/."""

import shutil

import pytest

from aggloTools.runner import CommandError
from channelTestRuns import script


def test_vtk_written_again_after_a_cut(raised_digits, case_dir):
    runs = script("channel.case.runs")
    case = case_dir / "vtk"
    shutil.copytree(raised_digits, case)
    (case / "VTK").mkdir()
    (case / "VTK" / "left.vtk").write_text("cut off")      # a kill's rest
    runs.Channel.vtk(case)
    assert (case / "VTK" / "done.foamToVTK").is_file()
    assert not (case / "VTK" / "left.vtk").exists()
    written = sorted((case / "VTK").rglob("*.vt*"))
    assert written and all(f.stat().st_size > 100 for f in written)
    runs.Channel.vtk(case)                       # done: not written again
    assert sorted((case / "VTK").rglob("*.vt*")) == written

    shutil.rmtree(case / "VTK")
    (case / "constant" / "polyMesh" / "faces").unlink()
    with pytest.raises(CommandError, match="foamToVTK failed"):
        runs.Channel.vtk(case)
    assert not (case / "VTK").exists()
