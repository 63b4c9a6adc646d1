"""A pipe of circular cross-section with an optional 90-degree bend,
meshed without a Cartesian shortcut: an O-grid blockMesh (a square core
and four curved ring blocks) of a straight pipe along z, whose points are
then mapped onto the bend (each cross-section rotated about the bend's
axis, so every wall point lies exactly on the pipe's circle and the
torus). Patches: inlet, outlet and the walls inletPipe, bend and
outletPipe (one per segment, so that deposits are counted per segment).

    from aggloTools import bendmesh
    g = bendmesh.Geometry(a=2.5e-3, R=14e-3, L_in=10e-3, L_out=10e-3)
    bendmesh.write_block_mesh(case, g, n=8, n_ring=4, n_axial=(20, 30, 20))
    # blockMesh, then:
    bendmesh.bend_points(case, g)

The centreline runs along +z to z = L_in, turns by 90 degrees towards +x
on the radius R (centre of curvature at x = R, z = L_in) and runs along
+x for L_out; y is the bend's axis.
"""

from dataclasses import dataclass
import math
from pathlib import Path

import numpy as np

from .foamfile import list_body, read_list_file, vec, write_foamfile

#: The core square's corners lie at this fraction of the radius
CORE = 0.55


@dataclass(frozen=True)
class Geometry:
    """a: pipe radius; R: bend radius of the centreline (0: no bend);
    L_in, L_out: straight lengths before and after the bend [m]."""
    a: float
    R: float
    L_in: float
    L_out: float

    @property
    def bend_length(self):
        return 0.5 * math.pi * self.R

    @property
    def stations(self):
        """z of the straight pipe's segment ends."""
        z1 = self.L_in
        z2 = z1 + self.bend_length
        return (0.0, z1, z2, z2 + self.L_out) if self.R > 0 \
            else (0.0, z1, z1 + self.L_out)


def _section(a):
    """The 8 points of a cross-section: the core corners, then the wall
    points, at 45, 135, 225 and 315 degrees."""
    ang = np.radians([45, 135, 225, 315])
    core = [(CORE * a * math.cos(t), CORE * a * math.sin(t)) for t in ang]
    wall = [(a * math.cos(t), a * math.sin(t)) for t in ang]
    return core + wall


def write_block_mesh(case, g, n=8, n_ring=4, n_axial=(20, 30, 20),
                     ring_grading=1.0):
    """blockMeshDict of the straight pipe: n cells across the core (and
    along each quarter of the wall), n_ring from the core to the wall
    (ring_grading: last cell over first), n_axial per segment."""
    z = g.stations
    segments = len(z) - 1
    if len(n_axial) != segments:
        raise ValueError(f"{segments} segments need {segments} axial "
                         f"counts, got {n_axial}")
    sec = _section(g.a)
    verts = [(x, y, zz) for zz in z for (x, y) in sec]
    names = (["inletPipe", "bend", "outletPipe"] if segments == 3
             else ["inletPipe", "outletPipe"])
    blocks, edges = [], []
    walls = {w: [] for w in names}
    inlet, outlet = [], []

    def v(station, k):
        return 8 * station + k

    for j in range(segments + 1):
        for k in range(4):
            t = math.radians(90 + 90 * k)       # between k and k + 1
            edges.append(f"arc {v(j, 4 + k)} {v(j, 4 + (k + 1) % 4)} "
                         + vec((g.a * math.cos(t), g.a * math.sin(t), z[j])))
    for j in range(segments):
        core = [v(j, 2), v(j, 3), v(j, 0), v(j, 1)]
        top = [c + 8 for c in core]
        blocks.append(f"hex ({' '.join(map(str, core + top))}) "
                      f"({n} {n} {n_axial[j]}) simpleGrading (1 1 1)")
        faces = [core[::-1]]
        for k in range(4):
            k1 = (k + 1) % 4
            b = [v(j, k), v(j, 4 + k), v(j, 4 + k1), v(j, k1)]
            h = b + [c + 8 for c in b]
            blocks.append(f"hex ({' '.join(map(str, h))}) "
                          f"({n_ring} {n} {n_axial[j]}) "
                          f"simpleGrading ({ring_grading} 1 1)")
            walls[names[j]].append([h[1], h[2], h[6], h[5]])
            faces.append(b[::-1])
        if j == 0:
            inlet = faces
        if j == segments - 1:
            outlet = [[c + 8 for c in f[::-1]] for f in faces]

    def patch(name, kind, faces):
        body = " ".join("(" + " ".join(map(str, f)) + ")" for f in faces)
        return f"    {name} {{ type {kind}; faces ({body}); }}"

    bnd = [patch("inlet", "patch", inlet), patch("outlet", "patch", outlet)]
    bnd += [patch(w, "wall", walls[w]) for w in names]
    write_foamfile(
        Path(case) / "system/blockMeshDict", "dictionary", "system",
        "blockMeshDict",
        "scale 1;\nvertices\n(\n" + "\n".join("    " + vec(p) for p in verts)
        + "\n);\nblocks\n(\n" + "\n".join("    " + b for b in blocks)
        + "\n);\nedges\n(\n" + "\n".join("    " + e for e in edges)
        + "\n);\nboundary\n(\n" + "\n".join(bnd) + "\n);\n")


def map_to_bend(p, g):
    """Points (n, 3) of the straight pipe mapped onto the bend."""
    p = np.asarray(p, float)
    out = p.copy()
    if g.R <= 0:
        return out
    x, y, z = p[:, 0], p[:, 1], p[:, 2]
    z1, z2 = g.L_in, g.L_in + g.bend_length
    bend = (z > z1) & (z <= z2)
    phi = (z[bend] - z1) / g.R
    cx, cz = g.R * (1 - np.cos(phi)), z1 + g.R * np.sin(phi)
    out[bend, 0] = cx + x[bend] * np.cos(phi)
    out[bend, 2] = cz - x[bend] * np.sin(phi)
    after = z > z2
    u = z[after] - z2
    out[after, 0] = g.R + u
    out[after, 2] = z1 + g.R - x[after]
    out[:, 1] = y
    return out


def bend_points(case, g):
    """Map constant/polyMesh/points (written by blockMesh) onto the bend,
    in place (ASCII, exact)."""
    f = Path(case) / "constant/polyMesh/points"
    p = map_to_bend(read_list_file(f), g)
    write_foamfile(f, "vectorField", "constant/polyMesh", "points",
                   list_body(p, "%.17g"))


def pipe_case(case, g, n=8, n_ring=4, n_axial=(20, 30, 20),
              inlet_velocity=(0, 0, 0), ranks=(1, 1, 1), ring_grading=1.0,
              **box):
    """A complete case on the pipe (aggloTools.boxcase.box_case for the
    rest: box's keyword arguments, e.g. particles, hard_sphere, cloud,
    dt, end_time): the mesh, U and p with the inlet's
    velocity, a zero-gradient outlet and still walls, and a hierarchical
    decomposition into ranks (x, y, z) (ring_grading: the ring blocks'
    last cell over their first, below 1 finer at the wall): (1, 2, 1)
    cuts the whole pipe
    along its plane of symmetry y = 0, through every cross-section (scotch
    and metis are dummy libraries in Debian's OpenFOAM v1912)."""
    from .boxcase import box_case
    box_case(case, kinds=("patch", "patch", "patch"), **box)
    write_block_mesh(case, g, n, n_ring, n_axial, ring_grading)
    nx, ny, nz = ranks
    write_foamfile(Path(case) / "system/decomposeParDict", "dictionary",
                   "system", "decomposeParDict",
                   f"numberOfSubdomains {nx * ny * nz};\n"
                   "method hierarchical;\ncoeffs { n "
                   f"({nx} {ny} {nz}); order xyz; }}\n")
    walls = ["inletPipe", "bend", "outletPipe"] if g.R > 0 \
        else ["inletPipe", "outletPipe"]
    ub = [f"inlet {{ type fixedValue; value uniform {vec(inlet_velocity)};"
          " }", "outlet { type zeroGradient; }"]
    ub += [f"{w} {{ type noSlip; }}" for w in walls]
    pb = ["inlet { type zeroGradient; }",
          "outlet { type fixedValue; value uniform 0; }"]
    pb += [f"{w} {{ type zeroGradient; }}" for w in walls]
    for name, dims, bcs, value in (
            ("U", "[0 1 -1 0 0 0 0]", ub, "uniform (0 0 0)"),
            ("p", "[0 2 -2 0 0 0 0]", pb, "uniform 0")):
        cls = "volVectorField" if name == "U" else "volScalarField"
        write_foamfile(Path(case) / "0" / name, cls, "0", name,
                       f"dimensions {dims};\ninternalField {value};\n"
                       "boundaryField\n{\n    " + "\n    ".join(bcs)
                       + "\n}\n")
    return Path(case)


def run_pipe_case(case, g, parallel=0, check=True):
    """blockMesh, the bend's points, then the solver (serial, or
    decomposed on N ranks and reconstructed)."""
    from .boxcase import run_case
    return run_case(case, parallel, check,
                    after_mesh=lambda: bend_points(case, g))


def developed_inlet(case, g, U_mean):
    """The developed laminar inflow (Hagen-Poiseuille, (1 - r^2/a^2)
    along +z) at the inlet's face centres, scaled so that the flux is
    U_mean times the inlet's area exactly (the midpoint rule alone gives
    about 1 % more at 8 core cells), written into 0/U's inlet as a
    nonuniform fixedValue (after blockMesh; the inlet is not moved by the
    bend). Returns the volumetric flux through the inlet."""
    import re
    from .mesh import Mesh
    case = Path(case)
    text = (case / "constant/polyMesh/boundary").read_text()
    m = re.search(r"\binlet\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+"
                  r"(\d+);", text)
    n, start = int(m.group(1)), int(m.group(2))
    Cf, Sf = Mesh(case).face_centres_and_areas()
    r2 = (Cf[start:start + n, :2] ** 2).sum(axis=1)
    area = np.linalg.norm(Sf[start:start + n], axis=1)
    shape = np.clip(1 - r2 / g.a ** 2, 0, None)
    w = U_mean * area.sum() / (shape @ area) * shape
    U = np.zeros((n, 3))
    U[:, 2] = w
    f = case / "0" / "U"
    body = f.read_text()
    value = "nonuniform List<vector> " + list_body(U, "%.17g")
    new, k = re.subn(r"inlet \{ type fixedValue; value uniform \([^)]*\); \}",
                     lambda _: f"inlet {{ type fixedValue; value {value}; }}",
                     body)
    if k != 1:
        raise ValueError(f"{f}: no uniform fixedValue inlet to replace")
    f.write_text(new)
    return float(w @ area)
