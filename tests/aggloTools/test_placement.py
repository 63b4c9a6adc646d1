"""aggloTools.placement against a brute-force oracle: the grid search finds
exactly the overlapping pairs of the O(N^2) search, across periodic planes
(minimum image) and bounded walls, at one to many particles per cell and
for a query subset; place() leaves no overlap, keeps to its bounds and is
reproducible for a seed."""

import math

import numpy as np
import pytest

from aggloTools.placement import overlaps, place


def brute(x, dmin, periods, query=None):
    """Oracle: every pair (with a queried particle), minimum image along
    the periodic axes; sorted unique max(i, j) of the close pairs."""
    q = np.arange(len(x)) if query is None else np.asarray(query)
    r = x[:, None, :] - x[None, q, :]
    for a, L in enumerate(periods):
        if L:
            r[..., a] -= L * np.round(r[..., a] / L)
    i, k = np.nonzero(np.einsum("ijk,ijk->ij", r, r) < dmin**2)
    ok = i != q[k]
    return np.unique(np.maximum(i[ok], q[k][ok]))


CHANNEL = (2 * math.pi * 0.02, 0.04, math.pi * 0.02)


def channel_sample(dmin, rng):
    """2500 particles in the channel box with pairs 0.4 dmin apart across
    the periodic planes x = 0 and z = 0 and a dense cluster."""
    Lx, Ly, Lz = CHANNEL
    x = rng.uniform((0, 0, 0), CHANNEL, (2500, 3))
    x[20:40] = x[:20]
    x[:20, 0], x[20:40, 0] = 0.2 * dmin, Lx - 0.2 * dmin
    x[60:80] = x[40:60]
    x[40:60, 2], x[60:80, 2] = 0.2 * dmin, Lz - 0.2 * dmin
    x[100:300] = [Lx / 2, Ly / 2, Lz / 2] + rng.uniform(-2, 2, (200, 3)) \
        * dmin
    return x


@pytest.mark.parametrize("dmin", [2e-4, 1e-3, 3e-3])
def test_overlaps_channel_matches_brute_force(dmin):
    periods = (CHANNEL[0], None, CHANNEL[2])
    x = channel_sample(dmin, np.random.default_rng(7))
    ref = brute(x, dmin, periods)
    # the oracle sees the pairs across the periodic planes
    assert set(range(20, 40)) | set(range(60, 80)) <= set(ref)
    assert len(ref) > 100
    assert np.array_equal(overlaps(x, dmin, periods), ref)
    q = np.arange(0, 2500, 3)
    assert np.array_equal(overlaps(x, dmin, periods, q),
                          brute(x, dmin, periods, q))


@pytest.mark.parametrize("periods", [(1.0, 1.0, 1.0), (None, None, None),
                                     (None, 1.0, None)])
def test_overlaps_other_boxes_match_brute_force(periods):
    """Fully periodic, fully bounded and mixed unit boxes, particles
    also on the faces of the box."""
    rng = np.random.default_rng(11)
    x = rng.uniform(0, 1, (1500, 3))
    x[:30, 0], x[30:60, 1], x[60:90, 2] = 0.0, 0.999, 0.0005
    dmin = 0.04
    ref = brute(x, dmin, periods)
    assert len(ref) > 50
    assert np.array_equal(overlaps(x, dmin, periods), ref)


def test_place_no_overlap_bounds_and_seed():
    L = CHANNEL
    dp = 1e-3              # dense: about 30 % of the first draws overlap
    lo, hi = (0, dp / 2, 0), (L[0], L[1] - dp / 2, L[2])
    periods = (L[0], None, L[2])
    a = place(3000, dp, lo, hi, periods, np.random.default_rng(3))
    b = place(3000, dp, lo, hi, periods, np.random.default_rng(3))
    assert np.array_equal(a, b)
    assert len(brute(a, dp, periods)) == 0
    # the first draws do overlap: the redraws did the work
    first = np.random.default_rng(3).uniform(lo, hi, (3000, 3))
    assert len(brute(first, dp, periods)) > 50
    assert np.all(a >= lo) and np.all(a <= hi)


def test_place_reports_a_full_box():
    with pytest.raises(RuntimeError, match="too full"):
        place(2000, 0.2, (0, 0, 0), (1, 1, 1), (1, 1, 1),
              np.random.default_rng(1), rounds=20)
