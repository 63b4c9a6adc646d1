"""The solver-settings study of the channel (bench/channelSolverSettings.py):
a batch's values (rms with the plane variance of the time means,
u_tau from the mean driving gradient, iterations, step time) follow hand
values."""

import math

import numpy as np
import pytest

from aggloTools.runner import bench_module


@pytest.fixture(scope="module")
def study():
    return bench_module("channelSolverSettings")


def test_rms_holds_the_plane_variance_of_the_means(study, tmp_path):
    """u' from <u'u'> of each cell plus the spread of the cells' time
    means about their plane mean; U_tau from the mean driving gradient."""
    y = np.array([0.25, 0.25, 0.75, 0.75, 1.25, 1.25, 1.75, 1.75])
    um = np.zeros((8, 3))
    um[:, 0] = [1, 3, 2, 2, 2, 2, 1, 3]
    r = np.zeros((8, 6))
    r[:, 0] = 0.5
    r[:, 3] = [0.1, 0.3, 0.2, 0.2, 0.2, 0.2, 0.1, 0.3]
    t = tmp_path / "1"
    t.mkdir()
    for name, cls, a in (("UMean", "vector", um),
                         ("UPrime2Mean", "symmTensor", r)):
        body = "\n".join("(" + " ".join(str(x) for x in row) + ")"
                         for row in a)
        (t / name).write_text(
            "FoamFile { class vol; object x; }\n"
            f"internalField nonuniform List<{cls}> {len(a)}\n(\n{body}\n);\n")
    (tmp_path / "log").write_text(
        "".join(f"\nTime = {i}\nsmoothSolver:  Solving for Ux, Initial "
                "residual = 1, Final residual = 1, No Iterations 3\n"
                f"pressure gradient = {g}\nGAMG:  Solving for p, Initial "
                "residual = 1, Final residual = 1, No Iterations 2\n"
                f"pressure gradient = {g}\nGAMG:  Solving for p, Initial "
                "residual = 1, Final residual = 1, No Iterations 5\n"
                f"ExecutionTime = {0.5 * i} s  ClockTime = 1 s\n"
                for i, g in enumerate((2.0, 4.0, 6.0), 1)))
    b = study.batch_values(tmp_path, "1", "log", y,
                           {"Ubar": 2.0, "delta": 0.5})
    # plane variance of Ux means: 1 at y 0.25 and 1.75, 0 between
    assert b["profiles"]["urms"] == pytest.approx(
        [math.sqrt(0.5 + 1) / 2, math.sqrt(0.5) / 2], abs=1e-15)
    assert b["profiles"]["vrms"] == pytest.approx(
        [math.sqrt(0.2) / 2, math.sqrt(0.2) / 2], abs=1e-15)
    assert b["profiles"]["U"] == [1.0, 1.0]
    assert b["uTauByUb"] == pytest.approx(math.sqrt(4.0 * 0.5) / 2)
    assert (b["itP"], b["itPFinal"], b["itU"]) == (2, 5, 3)
    assert b["step_s"] == pytest.approx(0.5)
