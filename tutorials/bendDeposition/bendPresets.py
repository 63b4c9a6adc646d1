"""The presets of bendDeposition (README.md): the pipe, its mesh, the
particles and the run of each. `default` and the study of the
resolution (README.md, "The resolution": coarseWall, mediumWall,
fineWall by the wall cells, fineSection and finerSection by the cells
across the section), `ci` (the tests' size) and `agglomeration` (the
dense variant).

Entries: stokes (the Stokes numbers, one run each) or sizes and model
(the agglomeration variant's diameters and model); n, n_ring, grading,
n_axial (aggloTools.bendmesh: core cells, ring cells and their grading,
cells along inlet, bend and outlet), curvature (R/a [rec]), straight
(the straight pipes' length over D), parcels, inject (s), dt (s),
flow_end (s, the flow's run), transits (a particle run's length after
the injection, in transits at the mean velocity; bendDeposition's
TRANSITS where absent)."""

#: The ci mesh and pipe (also the agglomeration variant's)
CI_PIPE = dict(n=6, n_ring=4, grading=0.3, n_axial=(6, 24, 6),
               curvature=5.6, straight=1.5, dt=1e-4, flow_end=0.03)

#: The wall-normal resolution (README.md, "The resolution"):
#: ring cells and their grading (last over first) by the wall cell's
#: thickness, about 4 um in `default`, converged against 1.5 um
WALL = {"coarseWall": (6, 0.3),      # about 100 um: the earlier default
        "mediumWall": (12, 0.05),    # about 15 um
        "default": (24, 0.02),       # about 4 um
        "fineWall": (36, 0.01)}      # about 1.5 um
#: The default pipe, its particles and its run, but the ring
PIPE = dict(n=8, n_axial=(10, 48, 10), curvature=5.6, straight=2.0,
            parcels=2000, dt=5e-5, flow_end=0.04, inject=0.01)
#: The Stokes numbers of default, and of the resolution study: where
#: the coarse wall and the measurements part
STOKES = [0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 1.0, 1.5]
STUDY = [0.1, 0.2, 0.3, 0.45]


def ring(name):
    """A preset's ring entries from WALL."""
    return dict(n_ring=WALL[name][0], grading=WALL[name][1])


PRESETS = {
    # about 8 minutes on 2 cores
    "default": dict(stokes=STOKES, **ring("default"), **PIPE),
    # the resolution study's other walls: the earlier default as it was,
    # the finer two at STUDY for 12 transits, as the particles next to
    # the wall move slower where it is resolved
    "coarseWall": dict(stokes=STOKES, **ring("coarseWall"), **PIPE),
    "mediumWall": dict(stokes=STUDY, transits=12, **ring("mediumWall"),
                       **PIPE),
    "fineWall": dict(stokes=STUDY, transits=12, **ring("fineWall"),
                     **PIPE),
    # and default's wall with 12 (fineSection) or 16 (finerSection) in
    # place of 8 cells across the core and along each quarter of the
    # wall
    **{name: dict(stokes=STUDY, transits=12, **ring("default"),
                  **dict(PIPE, n=n))
       for name, n in (("fineSection", 12), ("finerSection", 16))},
    # the tests' preset, the limits: about 1 minute
    "ci": dict(stokes=[0.02, 0.3, 5.0], parcels=300, inject=0.005,
               **CI_PIPE),
    # dense and polydisperse (3-12 um: St 0.07-1.2), collisions and EAM
    # agglomeration on: about 40 s
    "agglomeration": dict(sizes=(3e-6, 12e-6), model="EAM", parcels=100000,
                          inject=0.002, **CI_PIPE),
}
