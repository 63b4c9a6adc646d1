"""bench/channelProfile.py: perf samples sorted into the parts of the
channel step, and the table that bench/results/channelProfile.md holds."""

import pytest

from aggloTools.runner import bench_module


@pytest.fixture(scope="module")
def prof():
    return bench_module("channelProfile")


@pytest.mark.parametrize("dso, sym, part", [
    ("libOpenFOAM.so", "Foam::DICSmoother::smooth", "fluid"),
    ("aggloPimpleFoam", "Foam::fvc::surfaceIntegrate<double>", "fluid"),
    # the solver binary's cloud templates are the cloud's, not the fluid's
    ("aggloPimpleFoam", "Foam::KinematicCloud<Foam::Cloud<X> >::info",
     "cloud"),
    ("libagglomerationHardSphere.so", "Foam::sweptBoxGrid::build", "cloud"),
    # locating particles at start-up is not the cloud's step
    ("libOpenFOAM.so", "Foam::polyMeshTetDecomposition::findTet",
     "start-up and writes"),
    ("libincompressibleTurbulenceModels.so",
     "Foam::LESModels::Smagorinsky<X>::correctNut", "LES model"),
    ("libOpenFOAM.so", "Foam::FaceCellWave<Foam::wallPointYPlus>::iterate",
     "LES model"),
    ("libc.so.6", "__memmove_avx_unaligned_erms", "other"),
])
def test_part_of(prof, dso, sym, part):
    assert prof.part_of(dso, sym) == part


def test_profile_table(prof):
    """One stage of one preset: parts by falling share, one decimal, the
    function cut at 60 characters and given its part."""
    fn = "Foam::" + "x" * 80
    res = [{"preset": "small", "cells": 32768, "particles": 100000,
            "np1": {"unladen": {
                "step_s": 0.03421,
                "profile": [{"cloud": 0.25, "fluid": 76.66},
                            [[15.84, "libOpenFOAM.so", fn]]]}}}]
    lines = prof.profile_table(res).splitlines()
    i = lines.index("## small (32,768 cells, 100,000 particles), unladen:"
                    " 0.0342 s/step under perf")
    assert lines[i + 4:i + 6] == ["| fluid | 76.7 |", "| cloud | 0.2 |"]
    assert lines[i + 9] == f"| 15.8 | fluid | libOpenFOAM.so | `{fn[:60]}` |"
    assert not any("laden1" in ln for ln in lines)
