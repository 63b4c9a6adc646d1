"""bench/channelCostsVs.py's projection of a configuration's wall time
from the measured step costs, against hand values from the presets."""

import pytest

from aggloTools.runner import bench_module


@pytest.fixture(scope="module")
def costs_vs():
    return bench_module("channelCostsVs")


def test_projection_from_step_costs(costs_vs):
    """small: phases 60/10/30/60 T* at dt* = 0.02 are 3000/500/1500/3000
    steps; at 1, 2 and 3 s per unladen, one-cloud and two-cloud step that
    is 3000 + 1000 + 3000 + 9000 s = 16000 s; medium (240/100/520/200 T*,
    dt* = 0.01) at 0.5 s per step throughout is 106000 x 0.5 s."""
    steps = {"unladen": {"step_s": 1.0}, "laden1": {"step_s": 2.0},
             "laden2": {"step_s": 3.0}}
    h = costs_vs.projection_h("small", steps)
    assert h["unladen"] == pytest.approx(3000 / 3600)
    assert h["release"] == pytest.approx(1000 / 3600)
    assert h["dispersion"] == pytest.approx(3000 / 3600)
    assert h["agglomeration"] == pytest.approx(9000 / 3600)
    assert h["total"] == pytest.approx(16000 / 3600)
    flat = {k: {"step_s": 0.5} for k in steps}
    assert costs_vs.projection_h("medium", flat)["total"] == \
        pytest.approx(106000 * 0.5 / 3600)
