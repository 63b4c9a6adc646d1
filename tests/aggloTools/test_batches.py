"""aggloTools.batches: a variant's bias over paired batches against the
base's own standard error, by hand values."""

import math

import numpy as np
import pytest

from aggloTools import batches

BASE = np.array([[1.0], [2.0], [3.0], [4.0]])
SIGMA_RUN = math.sqrt(5 / 3) / 2        # std of 1..4 over sqrt(4)


@pytest.mark.parametrize("shift, visible", [(0.5, False), (1.0, True)])
def test_constant_shift(shift, visible):
    """A constant shift is the bias with standard error 0: significant,
    and visible where it exceeds sigma_run."""
    j = batches.paired_bias(BASE, BASE + shift)
    assert j["bias"] == pytest.approx(shift)
    assert j["biasSE"] == pytest.approx(0, abs=1e-15)
    assert j["sigmaRun"] == pytest.approx(SIGMA_RUN)
    assert j["biasBySigmaRun"] == pytest.approx(shift / SIGMA_RUN)
    assert j["significant"] and j["visible"] is visible


def test_noisy_difference_is_not_visible():
    """Differences +-3 around a bias 1 (SE sqrt(12)/2, t975(3) 3.18): above
    sigma_run but not significant, so not visible."""
    var = BASE + np.array([[4.0], [-2.0], [4.0], [-2.0]])
    j = batches.paired_bias(BASE, var)
    assert j["bias"] == pytest.approx(1.0)
    assert j["biasSE"] == pytest.approx(math.sqrt(12) / 2)
    assert j["biasBySigmaRun"] > 1
    assert not j["significant"] and not j["visible"]


def test_bin_choice_and_constant_bins():
    """The reported bin is the significant one of the largest ratio; a bin
    that never varies is visible by any bias and not by none."""
    base = np.column_stack([BASE[:, 0], np.zeros(4), BASE[:, 0]])
    var = base + np.array([0.5, 0.0, 2.0])
    j = batches.paired_bias(base, var)
    assert j["bin"] == 2 and j["visible"]
    var = base + np.array([0.5, 1e-9, 0.0])
    j = batches.paired_bias(base, var)
    assert j["bin"] == 1 and j["biasBySigmaRun"] == math.inf and j["visible"]


def test_t975():
    assert batches.t975(9) == 2.262
    assert batches.t975(27) == 2.060        # the next smaller tabulated
    with pytest.raises(ValueError):
        batches.t975(0)
