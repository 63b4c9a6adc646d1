"""The cases of bench/hardSphereCloud.py: the periodic box of quartz
particles at the paper's number density (or a multiple of it) and its
variants (another pair search, the event log on, the cell order off, the
stock cloud with the same particles, mesh, fluid and forces)."""

import math
import re
import shutil

import numpy as np

from aggloTools import boxcase

N_DENSITY = 6e6 / (2 * math.pi * 2 * math.pi * 0.02**3)
PER_CELL = 6e6 / 128**3
D, DT = 12e-6, 1.1e-5


def n_steps(N):
    """21 steps, more for small clouds (at least 3e6 particle-steps)"""
    return max(21, math.ceil(3e6 / N))

STOCK_PROPERTIES = """
solution
{
    active true; coupled false; transient yes;
    cellValueSourceCorrection off; maxCo 1;
    sourceTerms { schemes { U semiImplicit 1; } }
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties { rho0 2200; }
subModels
{
    particleForces { sphereDrag; gravity; }
    injectionModels {}
    dispersionModel none;
    patchInteractionModel none;
    surfaceFilmModel none;
    stochasticCollisionModel none;
}
cloudFunctions {}
"""


def make_case(case, N, density, search="particleGrid", particles=True,
              cell_order=False):
    """The periodic box; returns the number of cells. Without particles
    (the memory baseline) it runs 300 steps, so that the memory while
    stepping can be sampled as in the runs with particles. With
    cell_order the particles are written (and so read and allocated) in
    the order of their cells: the stock cloud sorted once, since they
    move about 1 % of a cell in the run."""
    steps = n_steps(N) if particles else 300
    shutil.rmtree(case, ignore_errors=True)
    Lb = (N / (density * N_DENSITY)) ** (1 / 3)
    nc = max(2, round((N / PER_CELL) ** (1 / 3)))
    parts = []
    if particles:
        rng = np.random.default_rng(1)
        X = rng.uniform(0, Lb, (N, 3))
        U = rng.normal(0, 0.5, (N, 3))
        order = np.arange(N)
        if cell_order:
            # blockMesh numbers the cells x fastest, then y, then z
            ijk = np.minimum((X / Lb * nc).astype(int), nc - 1)
            cell = ijk[:, 0] + nc * (ijk[:, 1] + nc * ijk[:, 2])
            order = np.argsort(cell, kind="stable")
        parts = [dict(x=tuple(X[i]), U=tuple(U[i]), id=int(i))
                 for i in order]
    boxcase.box_case(case, L=(Lb,) * 3, n=(nc,) * 3, kinds=("cyclic",) * 3,
                     particles=parts, dt=DT, end_time=steps * DT,
                     write_interval=10 * steps, gravity=(0, -9.81, 0),
                     hard_sphere=boxcase.kernel("EAM", walls={},
                                                pairSearch=search),
                     cloud={"subModels": {"particleForces": {
                         "sphereDrag": "", "gravity": ""}}})
    return nc**3


def as_variant(src, dst, search=None, stock=False, log=False,
               unsorted=False):
    """A copy of a written case with another search, with the collision
    event log on, with our cloud's cell order off, or for the stock cloud
    (same particles, mesh, fluid and forces)."""
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(src, dst)
    props = dst / "constant" / "kinematicCloudProperties"
    text = props.read_text()
    if search:
        text = re.sub(r"pairSearch \w+;", f"pairSearch {search};", text)
    if log:
        text = re.sub(r"(pairSearch \w+;)", r"\1 eventLog true;", text)
    if unsorted:
        text = re.sub(r"(\nsolution\s*\{)", r"\1\n    cellOrderInterval 0;",
                      text, count=1)
    if stock:
        text = text[:text.index("solution")] + STOCK_PROPERTIES
    props.write_text(text)
