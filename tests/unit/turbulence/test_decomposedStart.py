"""A run started on 2 ranks from a serial write continues as the serial
run does (applications/solvers/aggloPimpleFoam/correctProcessorPatches.H).

decomposePar of OpenFOAM v1912 gives the processor faces that were faces
of a cyclic patch (processorCyclic) the value of their own cell instead of
the neighbour's; the solver used those values in its first steps. The
channel decomposes across its spanwise period, and every stage of a run on
2 ranks starts from a serial or reconstructed write.

The case: test_lesChannel's channel without particles, started from a
velocity that varies along both periods (so that the own and neighbour
cells of a periodic face differ by up to 0.4 U_B), two serial steps
written (U, U_0, p, phi, phi_0, nut, delta). From that write one more step
serially, and one on 2 ranks split across the spanwise (z) or the
streamwise (x) period, every solve of that step to 1e-12. Expected: the
same velocity up to the solvers' tolerances, and no global continuity
error (the fluxes through a processor face cancel). Measured
before the correction: the first step's global continuity error 5e-7 and
velocities up to 1.5 m/s apart at 48^3 (README.md, "Running in
parallel")."""

import math
import re
import shutil

import numpy as np
import pytest

from aggloTools import boxcase
from aggloTools.fields import read_internal
from aggloTools.foamfile import edit
from aggloTools.runner import foam_bin, run

from test_lesChannel import DT, L, N, UB, channel_case


def velocity(x, y, z):
    sx, sz = (2 * math.pi * x / L[0]), (2 * math.pi * z / L[2])
    return (UB * (1 + 0.4 * math.sin(sz) + 0.2 * math.cos(sx)),
            0.05 * UB * math.sin(sx) * math.sin(sz),
            0.1 * UB * math.cos(sx))


def start_case(case):
    """Two serial steps from the varying velocity, the second written."""
    channel_case(case, n_particles=1)
    boxcase.foamfile(case / "constant/cloudProperties", "dictionary",
                     "constant", "cloudProperties", "clouds ();\n")
    boxcase.write_internal_U(case, L, N, velocity)
    cd = case / "system/controlDict"
    edit(cd, "writeInterval 30;", "writeInterval 2;")
    edit(cd, f"endTime {30 * DT!r};", f"endTime {2 * DT!r};")
    boxcase.run_case(case)
    t = f"{2 * DT:g}"
    assert (case / t / "U_0").is_file() and (case / t / "delta").is_file()
    edit(cd, f"endTime {2 * DT!r};", f"endTime {3 * DT!r};")
    edit(cd, "writeInterval 2;", "writeInterval 1;")
    # every solve to 1e-12 (the case's first pressure corrector stops at
    # 1e-2 of its initial residual, where serial and 2-rank iterations,
    # whose preconditioners differ at the rank boundary, part by 3.5e-5
    # m/s)
    fs = case / "system/fvSolution"
    edit(fs, "relTol 0.01;", "relTol 0;")
    edit(fs, "tolerance 1e-8;", "tolerance 1e-12;")
    return t


def global_continuity(log):
    return [float(x) for x in re.findall(
        r"continuity errors : sum local = \S+, global = (\S+),", log)]


@pytest.mark.parametrize("split", ["z", "x"])
def test_two_ranks_from_a_serial_write(case_dir, foam_env, split):
    t = start_case(case_dir / "start")
    serial, par = case_dir / "serial", case_dir / "parallel"
    for c in (serial, par):
        shutil.copytree(case_dir / "start", c, ignore=shutil.ignore_patterns(
            "log.*", "processor*"))
    n = {"x": "(2 1 1)", "z": "(1 1 2)"}[split]
    edit(par / "system/decomposeParDict", "n (2 1 1);", f"n {n};")
    run([foam_bin("aggloPimpleFoam")], serial, "log.aggloPimpleFoam")
    run([foam_bin("decomposePar"), "-force", "-latestTime"], par,
        "log.decomposePar")
    shutil.rmtree(par / t)     # the step must come from the ranks' fields
    (par / t).mkdir()
    shutil.copytree(case_dir / "start" / t / "uniform", par / t / "uniform")
    run(["mpirun", "-np", "2", "--oversubscribe", foam_bin("aggloPimpleFoam"),
         "-parallel"], par, "log.aggloPimpleFoam")
    t3 = f"{3 * DT:g}"
    run([foam_bin("reconstructPar"), "-time", t3], par, "log.reconstructPar")

    log = (par / "log.aggloPimpleFoam").read_text()
    assert "processorCyclic" not in log     # a run, not an error message
    errors = global_continuity(log)
    assert len(errors) == 2 and max(map(abs, errors)) < 1e-15, errors

    Us = read_internal(serial / t3 / "U")
    Up = read_internal(par / t3 / "U")
    assert Us.shape == Up.shape == (N[0] * N[1] * N[2], 3)
    # the step changed the velocity (the check can see a difference)
    U0 = read_internal(case_dir / "start" / t / "U")
    assert np.abs(Us - U0).max() > 1e-3 * UB
    assert np.abs(Up - Us).max() < 1e-8 * UB, np.abs(Up - Us).max()
