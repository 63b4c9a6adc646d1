"""The vanDriestDamped LES delta (src/TurbulenceModels/LESdeltas/
vanDriestDamped) against a hand computation from the written fields: the
coarse channel of test_lesChannel, written at every step. The delta of
step 2 is computed from U of step 2 and nu_t of step 1 (the turbulence
model corrects its delta before nu_t), so

    y* = nu/sqrt((nu + nu_t,P) |U_P|/d_P)   at the wall face below (above)
                                           a column, P its wall cell at d_P
    Delta = V^(1/3) (1 - exp(-y/y*/25))    for y/y* < 500, else V^(1/3)

with y the cell centre's distance to the nearer wall. Serially and on 3
ranks split across the walls, so that the middle rank holds no wall face
and takes every cell's u_tau from the wall faces of the other ranks: at
the case's viscosity (y+ spans the cut-off 500, the middle rank's cells
lie beyond it) and at a 66 times larger one (every cell damped, so the
middle rank's widths depend on the other ranks' wall faces)."""

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.fields import read_internal
from aggloTools.runner import foam_bin, run
from aggloTools.foamfile import edit

from test_lesChannel import DT, L, N, channel_case

NU, APLUS = 1.5212e-5, 25


def expected_delta(case, t1, t2, nu=NU):
    C = read_internal(case / t2 / "C")
    V = read_internal(case / t2 / "V")
    U = read_internal(case / t2 / "U")
    nut = read_internal(case / t1 / "nut")
    y = np.minimum(C[:, 1], L[1] - C[:, 1])
    top = C[:, 1] > 0.5 * L[1]
    # the wall cell of each cell's column, on the side of its wall
    col = np.round(C[:, 0] * 1e9).astype(np.int64) * 10**12 \
        + np.round(C[:, 2] * 1e9).astype(np.int64)
    wall_cell = {}
    for i in np.argsort(y, kind="stable"):
        wall_cell.setdefault((col[i], bool(top[i])), i)
    P = np.array([wall_cell[(col[i], bool(top[i]))] for i in range(len(y))])
    ystar = nu / np.sqrt((nu + nut[P]) * np.linalg.norm(U[P], axis=1) / y[P])
    yplus = y / ystar
    geo = np.cbrt(V)
    return np.where(yplus < 500, geo * (1 - np.exp(-yplus / APLUS)), geo), \
        yplus


@pytest.mark.parametrize("ranks, nu, split", [
    (0, NU, "y"), (3, NU, "y"), (3, 1e-3, "y"), (2, NU, "z"), (2, NU, "x")])
def test_delta_matches_hand_computation(case_dir, foam_env, ranks, nu,
                                        split):
    channel_case(case_dir, n_particles=10)
    tp = case_dir / "constant/transportProperties"
    edit(tp, "nu 1.5212e-5;", f"nu {nu!r};")
    cd = case_dir / "system/controlDict"
    edit(cd, "writeInterval 30;",
         "writeInterval 1;")
    edit(cd, f"endTime {30 * DT!r};", f"endTime {2 * DT!r};")
    dp = case_dir / "system/decomposeParDict"
    edit(dp, "numberOfSubdomains 2;",
         f"numberOfSubdomains {max(ranks, 1)};")
    n = {"x": "(2 1 1)", "y": "(1 3 1)", "z": "(1 1 2)"}[split]
    edit(dp, "n (2 1 1);", f"n {n};")
    boxcase.run_case(case_dir, parallel=ranks)
    t1, t2 = (f"{k * DT:g}" for k in (1, 2))
    if ranks:
        run([foam_bin("reconstructPar"), "-fields", "(U nut delta)"],
            case_dir, "log.reconstructPar")
        log = (case_dir / "log.aggloPimpleFoam").read_text()
        assert "vanDriestDamped delta" in log
    run([foam_bin("postProcess"), "-func", "writeCellCentres", "-time", t2],
        case_dir, "log.writeCellCentres")
    run([foam_bin("postProcess"), "-func", "writeCellVolumes", "-time", t2],
        case_dir, "log.writeCellVolumes")
    want, yplus = expected_delta(case_dir, t1, t2, nu)
    got = read_internal(case_dir / t2 / "delta")
    assert len(got) == N[0] * N[1] * N[2]
    geo = np.cbrt(read_internal(case_dir / t2 / "V"))
    # the damping is felt at the walls; beyond y+ 500 (if any) none is
    assert (got / geo).min() < 0.99
    if nu == NU:
        assert yplus.min() < 500 < yplus.max()
    else:
        assert yplus.max() < 500 and (got / geo).max() < 0.999
    np.testing.assert_allclose(got, want, rtol=1e-9)
