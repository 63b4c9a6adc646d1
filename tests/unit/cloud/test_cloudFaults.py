"""Faults found in the cloud, each kept as a test on a scripted box
(cloudBoxCases): a positions file without its uniform properties, the
serial -> 2 ranks -> serial round trip, a displacement beyond half a
period, vtkCloud's parcel fields, a wall that nothing handles, a fast pair
across the processor plane, a restart after a cut-off write and an
agglomerate at a wall across the processor plane."""

import shutil
import subprocess

import numpy as np
import pytest

from aggloTools import placement, times
from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.cloud import cloud_dir, read_cloud, read_positions
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows as stats
from aggloTools.foamfile import edit
from cloudBoxCases import PAIR, L, assert_fatal_naming


def cloud_totals(case_dir, t):
    st = read_cloud(case_dir, t, names=("d", "rho", "nPrimary"))
    d = [float(x) for x in st["d"]]
    rho = [float(x) for x in st["rho"]]
    mass = sum(r * 3.141592653589793 / 6 * x**3 for x, r in zip(d, rho))
    return len(d), sum(int(n) for n in st["nPrimary"]), mass, stats(case_dir)


def gas(case_dir):
    rng = np.random.default_rng(5)
    Lb = 2e-4
    xs = placement.place(300, 14.4e-6, (8e-6,) * 3, (Lb - 8e-6,) * 3,
                         (None,) * 3, rng)
    U = rng.normal(0, 1.5e-3, (len(xs), 3))
    parts = [dict(x=tuple(x), U=tuple(u), id=i) for i, (x, u)
             in enumerate(zip(xs, U))]
    box_case(case_dir, L=(Lb,) * 3, n=(6, 6, 6), particles=parts,
             kinds=("cyclic", "wall", "cyclic"), dt=1e-4, end_time=4e-3,
             hard_sphere=kernel("EAM"), decompose=(2, 1, 1))
    return len(parts)


def test_positions_file_without_uniform_properties(case_dir, foam_env):
    """A hand-written positions file without the uniform cloudProperties
    (which says 'geometry positions') used to give 0 particles."""
    n = gas(case_dir)
    shutil.rmtree(case_dir / "0/uniform")
    run_case(case_dir)
    assert cloud_totals(case_dir, "0.004")[1] == n


def test_parallel_round_trip_loses_nothing(case_dir, foam_env):
    """serial -> decomposePar -> 2 ranks -> reconstructPar -> serial with a
    hand-written cloud in the positions form: particles, primaries, mass
    and counters as in the serial run (decomposePar writes coordinates but
    keeps 'geometry positions': 0 particles on both ranks before)."""
    serial, mpi = case_dir / "serial", case_dir / "mpi"
    n = gas(serial)
    gas(mpi)
    run_case(serial)
    run_case(mpi, parallel=2)
    assert times.last_time(mpi) == times.last_time(serial) == "0.004"
    ns, ps, ms, rows_s = cloud_totals(serial, "0.004")
    nm, pm, mm, rows_m = cloud_totals(mpi, "0.004")
    assert ps == pm == n
    assert rows_s[-1]["nAgg"] > 0 and rows_s[-1]["nCol"] > 5
    assert nm == ns == n - int(rows_s[-1]["nAgg"])
    assert mm == pytest.approx(ms, rel=1e-12)
    keys = ("nParticles", "nPrimaries", "nCol", "nAgg", "nWall")
    assert [[r[k] for k in keys] for r in rows_m] == \
        [[r[k] for k in keys] for r in rows_s]
    # and back: the reconstructed cloud restarts serially with everything
    run([foam_bin("foamDictionary"), "-entry", "endTime", "-set", "0.008",
         "system/controlDict"], mpi, "log.foamDictionary")
    run([foam_bin("aggloPimpleFoam")], mpi, "log.aggloPimpleFoam.serial")
    assert cloud_totals(mpi, "0.008")[1] == n


def test_displacement_beyond_half_a_period(case_dir, foam_env):
    """A particle moving more than the periodic length in one step collided
    with the wrong image and the pair ended overlapping, without a warning:
    now the reach of the search along each axis is checked against half
    the period along it."""
    parts = [dict(x=(0.2 * L, 0.5 * L, 0.5 * L), U=(2.0, 0, 0), id=0),
             dict(x=(0.6 * L, 0.5 * L, 0.5 * L), U=(0, 0, 0), id=1)]
    box_case(case_dir, L=(L, L, L), particles=parts, dt=1e-4, end_time=2e-4,
             kinds=("cyclic", "wall", "wall"))
    res = run_case(case_dir, check=False)
    assert_fatal_naming(res, "more than half the periodic length along x")


def test_vtkcloud_writes_every_parcel_field(case_dir, foam_env):
    """The vtkCloud function object writes lastPartnerProc, lastPartnerId
    and lastContactTime (the README promises it; only omega and nPrimary
    were registered): after the head-on rebound the partners name each
    other."""
    import re
    parts = [dict(x=(0.4 * L, 0.5 * L, 0.5 * L), U=(0.1, 0, 0), id=0),
             dict(x=(0.6 * L, 0.5 * L, 0.5 * L), U=(-0.1, 0, 0), id=1)]
    box_case(case_dir, L=(L, L, L), particles=parts, dt=1e-5, end_time=1e-4)
    # keep the last partner after the pair has separated
    f = case_dir / "constant" / "kinematicCloudProperties"
    edit(f,
         "agglomerationModel none;",
         "agglomerationModel none; encounterRelease none;", 1)
    cd = case_dir / "system" / "controlDict"
    cd.write_text(cd.read_text() + """
functions
{
    cloudVtk
    {
        type            vtkCloud;
        libs            ("liblagrangianFunctionObjects.so");
        cloud           kinematicCloud;
        fields          (nPrimary lastPartnerProc lastPartnerId
                         lastContactTime origId);
        format          ascii;
        writeControl    writeTime;
    }
}
""")
    run_case(case_dir)
    vtps = sorted((case_dir / "postProcessing" / "cloudVtk").rglob("*.vtp"))
    assert vtps
    text = vtps[-1].read_text()
    for name in ("nPrimary", "lastPartnerProc", "lastPartnerId",
                 "lastContactTime"):
        assert f"Name='{name}'" in text, name
    def values(name):
        return [int(float(x)) for x in re.search(
            rf"Name='{name}'[^>]*>([^<]*)<", text).group(1).split()]

    # in whatever order the cloud holds them (cell order)
    assert dict(zip(values("origId"), values("lastPartnerId"))) == \
        {0: 1, 1: 0}


def test_unhandled_wall_is_fatal(case_dir, foam_env):
    """collisionModel none with patchInteractionModel none: a particle that
    reached a wall looped forever in tracking; now the set-up is refused,
    naming both entries."""
    box_case(case_dir, L=(L, L, L), particles=PAIR, dt=1e-5, end_time=2e-5,
             hard_sphere="none")
    res = run_case(case_dir, check=False)
    assert_fatal_naming(res, "patchInteractionModel")
    assert "collisionModel" in res.stdout.split("FOAM FATAL", 1)[1]


def test_fast_pair_on_two_ranks_one_contact_time(case_dir, foam_env):
    """A head-on pair crossing the processor plane within the step (six
    cells per step each): both partners store the same contact time, the
    one of the serial run; the rebound velocities are the serial ones."""
    Lx = 1e-3
    parts = [dict(x=(0.2 * Lx, 0.5e-4, 0.5e-4), U=(6.0, 0, 0), id=0),
             dict(x=(0.8 * Lx, 0.5e-4, 0.5e-4), U=(-6.0, 0, 0), id=1)]
    out = {}
    for ranks in (0, 2):
        c = case_dir / f"np{ranks}"
        box_case(c, L=(Lx, 1e-4, 1e-4), n=(10, 1, 1), particles=parts,
                 dt=1e-4, end_time=1e-4, decompose=(2, 1, 1),
                 kinds=("wall", "wall", "wall"))
        run_case(c, parallel=ranks)
        assert stats(c)[-1]["nCol"] == 1
        out[ranks] = read_cloud(c, "0.0001",
                                names=("origId", "U", "lastContactTime"))
    serial, mpi = out[0], out[2]
    tc = mpi["lastContactTime"]
    assert tc[0] == tc[1]
    assert tc[0] == pytest.approx(serial["lastContactTime"][0], rel=1e-12)
    order = lambda st: [u for _, u in sorted(zip(st["origId"], st["U"]))]
    for us, um in zip(order(serial), order(mpi)):
        assert um == pytest.approx(us, rel=1e-12)


def test_restart_after_a_cut_off_write(case_dir, foam_env):
    """A kill -9 during a write leaves a half-written last time folder that
    stops OpenFOAM's restart (it reads the latest time). The tutorials'
    resume (aggloTools.times.set_aside_incomplete_times, called by both
    Allruns before continuing) sets it aside and says so; the run then
    continues from the previous write and ends where an uninterrupted run
    ends."""
    import re
    n = gas(case_dir)
    run([foam_bin("foamDictionary"), "-entry", "writeInterval", "-set",
         "10", "system/controlDict"], case_dir, "log.foamDictionary")
    run_case(case_dir)
    full = stats(case_dir)[-1]
    # cut off the last write: truncate one particle field, then restart
    last = case_dir / "0.004"
    assert (last / "uniform" / "time").is_file()
    f = last / "lagrangian" / "kinematicCloud" / "U"
    f.write_text(f.read_text()[: len(f.read_text()) // 2])
    assert times.incomplete_time(case_dir) == last
    plain = subprocess.run([foam_bin("aggloPimpleFoam")], cwd=case_dir,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True)
    assert plain.returncode != 0           # OpenFOAM's own behaviour
    moved = times.set_aside_incomplete_times(case_dir)
    assert [m.name for m in moved] == ["incomplete.0.004"]
    assert times.incomplete_time(case_dir) is None
    run([foam_bin("aggloPimpleFoam")], case_dir, "log.aggloPimpleFoam.2")
    log = (case_dir / "log.aggloPimpleFoam.2").read_text()
    assert re.search(r"Starting time loop", log)
    assert cloud_totals(case_dir, "0.004")[1] == n
    again = stats(case_dir)[-1]
    assert again.pop("Time") == pytest.approx(full.pop("Time"), rel=1e-12)
    assert again == full


def test_agglomerate_at_wall_across_processor_plane(case_dir, foam_env):
    """An agglomerate formed next to a wall, whose centre of mass lies on
    the other processor than its lower-id partner, overlaps the wall and is
    moved out to one radius: at the same place on 2 ranks as in serial (it
    ended 20 nm off on 2 ranks: the wall faces were looked up around the
    partner, on the partner's processor)."""
    Lx = 4e-4
    D2 = 24e-6
    y1, y2 = 6.5e-6, 12.5e-6
    # particle 1 (the heavier, higher id) is across the plane x = Lx/2
    R = 0.5 * (12e-6 + D2)
    dx = ((R + 2e-9) ** 2 - (y2 - y1) ** 2) ** 0.5
    parts = [dict(x=(0.5 * Lx - 15e-6, y1, 5e-5), U=(1.5e-4, 0, 0), id=0),
             dict(x=(0.5 * Lx - 15e-6 + dx, y2, 5e-5), U=(-1.5e-4, 0, 0),
                  d=D2, nPrimary=8, id=1)]
    out = {}
    for ranks in (0, 2):
        c = case_dir / f"np{ranks}"
        box_case(c, L=(Lx, 1e-4, 1e-4), n=(8, 2, 2), particles=parts,
                 dt=1e-5, end_time=1e-5, decompose=(2, 1, 1),
                 hard_sphere=kernel("MAM"), kinds=("wall", "wall", "wall"))
        run_case(c, parallel=ranks)
        assert stats(c)[-1]["nAgg"] == 1
        out[ranks] = read_positions(cloud_dir(c, "1e-05") / "positions")
    assert len(out[0]) == len(out[2]) == 1
    assert out[2][0] == pytest.approx(out[0][0], rel=0, abs=1e-12)
