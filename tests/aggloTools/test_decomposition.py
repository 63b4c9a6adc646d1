"""aggloTools.decomposition: the scattered manual decomposition. Every
cell on the rank of its nearest seed (a brute-force loop as the oracle),
every rank holding cells, the same seed the same ranks and another seed
others; the files decomposePar reads (constant/cellDecomposition, the
manual method) hold exactly those ranks; decomposePar of the bent pipe
on 2 ranks gives the counts written."""

import re

import numpy as np
import pytest

from aggloTools import bendmesh, decomposition
from aggloTools.foamfile import read_list_file
from aggloTools.runner import foam_bin, run


def test_nearest_seed_against_a_loop():
    rng = np.random.default_rng(7)
    c = rng.uniform(size=(500, 3))
    ranks = decomposition.scattered_ranks(c, 3, pieces=4, seed=11)
    seeds = np.random.default_rng(11).choice(500, size=12, replace=False)
    for i, x in enumerate(c):
        best = min(range(12), key=lambda k: np.sum((x - c[seeds[k]]) ** 2))
        assert ranks[i] == best % 3
    assert sorted(set(ranks.tolist())) == [0, 1, 2]
    again = decomposition.scattered_ranks(c, 3, pieces=4, seed=11)
    assert (again == ranks).all()
    other = decomposition.scattered_ranks(c, 3, pieces=4, seed=12)
    assert (other != ranks).any()


def test_too_few_cells_refused():
    with pytest.raises(ValueError, match="cannot deal 1 cells to 2"):
        decomposition.scattered_ranks(np.zeros((1, 3)), 2)


def test_files_and_decomposePar(tmp_path, foam_env):
    g = bendmesh.Geometry(a=1e-3, R=5e-3, L_in=2e-3, L_out=2e-3)
    case = bendmesh.pipe_case(tmp_path / "pipe", g, n=4, n_ring=2,
                              n_axial=(3, 8, 3), particles=[])
    run([foam_bin("blockMesh")], case, "log.blockMesh")
    bendmesh.bend_points(case, g)
    per_rank = decomposition.scattered(case, 2)
    labels = read_list_file(case / "constant/cellDecomposition")
    assert np.bincount(labels.astype(int)).tolist() == per_rank.tolist()
    assert per_rank.min() > 0
    assert "method manual;" in \
        (case / "system/decomposeParDict").read_text()
    run([foam_bin("decomposePar"), "-force"], case, "log.decomposePar")
    cells = [int(n) for n in re.findall(
        r"Number of cells = (\d+)",
        (case / "log.decomposePar").read_text())]
    assert cells == per_rank.tolist()
