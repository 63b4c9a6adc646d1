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


def test_a_stage_continued_is_told_from_one_begun(tmp_path):
    """A stage counts as continued (its run time not compared with
    README.md's) only where its folder holds a write after the stage's
    start: the dispersion stage shares its folder with the release's
    writes and starts at the release's end. Before, any second time
    folder counted, so no run with a release was ever compared."""
    runs = script("channel.case.runs")
    settings = script("channel.case.settings")
    p = settings.preset("small")
    dt = p["deltaT"]
    d = tmp_path / "dispersion"
    t_unladen = settings.end_time(p, "unladen")
    t_release = settings.end_time(p, "release")
    # the release from the unladen end, written every writeStar
    for t in np_range(t_unladen, t_release, p["writeStar"] / p["dtStar"]
                      * dt):
        (d / f"{t:.10g}").mkdir(parents=True)
    assert runs.continued(d, p, "release")           # its own writes
    assert not runs.continued(d, p, "dispersion")    # the release's only
    (d / f"{t_release + 100 * dt:.10g}").mkdir()
    assert runs.continued(d, p, "dispersion")
    u = tmp_path / "unladen"
    (u / "0").mkdir(parents=True)
    assert not runs.continued(u, p, "unladen")
    (u / f"{dt:.10g}").mkdir()
    assert runs.continued(u, p, "unladen")
    a = tmp_path / "agglomeration"
    (a / f"{settings.end_time(p, 'dispersion'):.10g}").mkdir(parents=True)
    assert not runs.continued(a, p, "agglomeration")


def np_range(t0, t1, step):
    n = int(round((t1 - t0) / step))
    return [t0 + k * step for k in range(n + 1)]
