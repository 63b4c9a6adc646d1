"""Decompositions that follow neither the mesh's blocks nor the axes, for
showing that a case gives the same answer on N ranks as in serial where
a user would decompose with scotch (a dummy library in Debian's OpenFOAM
v1912, as metis is).

    scattered(case, 2)      # then decomposePar

`scattered` writes decomposePar's `manual` method: every cell goes to the
rank of the nearest of a few seed points (cell centres drawn with a
seeded generator, dealt to the ranks in turn), so each rank holds several
separate pieces and the processor boundaries are planes at arbitrary
angles that cut cells' rows, curved walls and the inlet and outlet
obliquely, more often than a graph partitioner's would.
"""

from pathlib import Path

import numpy as np

from .foamfile import list_body, write_foamfile
from .mesh import Mesh

#: The file manual decomposition reads, in constant/
DATA = "cellDecomposition"


def scattered_ranks(centres, ranks, pieces=4, seed=0):
    """The rank of each cell (centres (n, 3)): the nearest of
    pieces x ranks seed cells drawn without repetition by
    numpy's generator from seed, seed k belonging to rank k mod ranks.
    Every rank holds at least its seeds' cells."""
    centres = np.asarray(centres, float)
    n = len(centres)
    k = min(n, pieces * ranks)
    if ranks < 1 or k < ranks:
        raise ValueError(f"cannot deal {n} cells to {ranks} ranks")
    seeds = np.random.default_rng(seed).choice(n, size=k, replace=False)
    d2 = ((centres[:, None, :] - centres[seeds][None, :, :]) ** 2).sum(-1)
    owner = np.argmin(d2, axis=1)
    return (owner % ranks).astype(np.int64)


def scattered(case, ranks, pieces=4, seed=0):
    """Write system/decomposeParDict (method manual) and
    constant/cellDecomposition for scattered_ranks of the case's cell
    centres. Returns the number of cells per rank."""
    case = Path(case)
    proc = scattered_ranks(Mesh(case).cell_centres(), ranks, pieces, seed)
    write_foamfile(case / "constant" / DATA, "labelList", "constant", DATA,
                   list_body(proc, "%d"))
    write_foamfile(case / "system" / "decomposeParDict", "dictionary",
                   "system", "decomposeParDict",
                   f"numberOfSubdomains {ranks};\nmethod manual;\n"
                   f"coeffs {{ dataFile \"{DATA}\"; }}\n")
    return np.bincount(proc, minlength=ranks)
