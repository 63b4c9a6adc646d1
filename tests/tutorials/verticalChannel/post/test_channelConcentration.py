"""The particles' concentration across the channel over the release and
dispersion (channel.post.concentration): the profile between writes
undone from the running averages of profiles.dat, the near-wall over
centre ratio, the concentration the agglomeration starts from and the
rates per interval, on made-up writes with hand values
(channelTestRuns.write_dispersion)."""

import pytest

from channelTestRuns import script, write_dispersion


def test_concentration_between_writes(tmp_path):
    """concentration_history undoes the running average of profiles.dat
    (write_dispersion): near-wall over centre 1 and then 3 (hand values),
    over T* from the release to each write; with a span of 1 T* the
    first write is passed over and the one interval from the release
    holds all 30 steps: (10 + 20 x 3) / 30 = 7/3. The concentration the
    agglomeration starts from, over the last 100 T*, is that 7/3 too
    (from the release); over the last 1 T* the second interval's 3.
    dispersion_history
    adds the rates: 4 and 20 collisions over 0.5 and 1 T* are 8 and 20
    per T*, times s^2 = (6e6/N)^2; 1 and 10 wall impacts are 2 and 10 per
    T*, over N particles."""
    settings = script("channel.case.settings")
    conc = script("channel.post.concentration")
    p = settings.preset("smoke")
    t0 = write_dispersion(p, tmp_path)
    h = conc.concentration_history(p, tmp_path)
    T0 = t0 / p["tScale"]
    assert [x["T0"] - T0 for x in h] == pytest.approx([0.0, 0.5])
    assert [x["T1"] - T0 for x in h] == pytest.approx([0.5, 1.5])
    assert [x["nearWallOverCentre"] for x in h] == pytest.approx([1, 3])
    # over the last 100 T*, here from the release: the last write's
    # running average alone, (10 + 20 x 3) / 30 = 7/3
    c = conc.concentration(p, tmp_path)
    assert c["nearWallOverCentre"] == pytest.approx(7 / 3)
    assert (c["T0"] - T0, c["T1"] - T0) == pytest.approx((0.0, 1.5))
    # over the last 1 T*: from the write at 0.5, the second interval's 3
    c = conc.concentration(p, tmp_path, span=1.0)
    assert c["nearWallOverCentre"] == pytest.approx(3)
    assert (c["T0"] - T0, c["T1"] - T0) == pytest.approx((0.5, 1.5))
    coarse = conc.concentration_history(p, tmp_path, span=1.0)
    assert [v - T0 for x in coarse for v in (x["T0"], x["T1"])] == \
        pytest.approx([0.0, 1.5])
    assert coarse[0]["nearWallOverCentre"] == pytest.approx(7 / 3)
    N = p["nParticles"]
    s2 = (6e6 / N)**2
    r = conc.dispersion_history(p, tmp_path)
    assert [x["fColScaled"] for x in r] == pytest.approx([8 * s2, 20 * s2])
    assert [x["wallImpacts_per_particle_T"] for x in r] == \
        pytest.approx([2 / N, 10 / N])


def test_dispersion_history_without_readable_stats(tmp_path):
    """No stats.dat, or one whose last row is being written (a live run):
    the concentration history alone, no rates."""
    settings = script("channel.case.settings")
    conc = script("channel.post.concentration")
    p = settings.preset("smoke")
    write_dispersion(p, tmp_path, with_stats=False)
    h = conc.dispersion_history(p, tmp_path)
    assert len(h) == 2 and not any("fColScaled" in x for x in h)
    f = next((tmp_path / "postProcessing" / "particlesHardSphere").glob(
        "*/profiles.dat")).with_name("stats.dat")
    f.write_text("# Time nCol nWall\n0 0 0\n1e-3 4")
    assert not any("fColScaled" in x
                   for x in conc.dispersion_history(p, tmp_path))
