"""The polyMesh of a case (points, faces, owner, neighbour; ASCII or
binary) and its cell centres computed as OpenFOAM computes them
(primitiveMesh: face centres from the triangle fan about the face's
point average, cell centres from the face pyramids about the average of
the face centres), for locating barycentric particle coordinates.

    m = Mesh(case)          # or Mesh(case / "processor0")
    C = m.cell_centres()
"""

import re
from pathlib import Path

import numpy as np

from .foamfile import binary_list, is_binary, read_list_file


def _read_labels(path):
    return read_list_file(path).astype(np.int64)


def read_faces(path):
    """The faces of a polyMesh: (offsets, labels) with face i the labels
    offsets[i]:offsets[i+1]; ASCII faceList `N(n(a b ...) ...)` or binary
    faceCompactList (the offsets list, then the labels list)."""
    data = Path(path).read_bytes()
    head = data[:data.index(b"}") + 1]
    body = data.index(b"}") + 1
    if is_binary(head):
        m = re.compile(rb"(\s|//[^\n]*)*").match(data, body)
        offsets, end = binary_list(data, m.end(), "label", head)
        labels, _ = binary_list(data, end, "label", head)
        return offsets, labels
    text = data.decode()
    m = re.compile(r"\s*(?://[^\n]*\s*)*(\d+)\s*\(").match(text, body)
    n = int(m.group(1))
    inner = text[m.end():text.rindex(")")]
    tokens = np.array(inner.replace("(", " ").replace(")", " ").split(),
                      np.int64)
    sizes, labels, pos = np.empty(n, np.int64), [], 0
    for i in range(n):              # n(a b c ...): the size, then n labels
        k = tokens[pos]
        sizes[i] = k
        labels.append(tokens[pos + 1:pos + 1 + k])
        pos += 1 + k
    return (np.concatenate(([0], np.cumsum(sizes))),
            np.concatenate(labels) if labels else np.zeros(0, np.int64))


class Mesh:
    """The polyMesh under <case>/constant/polyMesh."""

    def __init__(self, case):
        d = Path(case) / "constant" / "polyMesh"
        self.points = read_list_file(d / "points")
        self.offsets, self.labels = read_faces(d / "faces")
        self.owner = _read_labels(d / "owner")
        self.neighbour = _read_labels(d / "neighbour")
        self.n_cells = int(max(self.owner.max(initial=-1),
                               self.neighbour.max(initial=-1))) + 1
        self._centres = None

    def face(self, i):
        return self.labels[self.offsets[i]:self.offsets[i + 1]]

    def face_centres_and_areas(self):
        """Face centres and area vectors (primitiveMeshFaceCentresAndAreas),
        vectorised over the faces of one size at a time."""
        nf = len(self.offsets) - 1
        sizes = np.diff(self.offsets)
        Cf, Sf = np.zeros((nf, 3)), np.zeros((nf, 3))
        for k in np.unique(sizes):
            idx = np.nonzero(sizes == k)[0]
            pts = self.points[self.labels[self.offsets[idx][:, None]
                                          + np.arange(k)]]   # (m, k, 3)
            if k == 3:
                Cf[idx] = pts.mean(axis=1)
                Sf[idx] = 0.5 * np.cross(pts[:, 1] - pts[:, 0],
                                         pts[:, 2] - pts[:, 0])
                continue
            fc = pts.mean(axis=1)
            nxt = np.roll(pts, -1, axis=1)
            c = pts + nxt + fc[:, None, :]
            n = np.cross(nxt - pts, fc[:, None, :] - pts)
            a = np.linalg.norm(n, axis=2)
            sumA = a.sum(axis=1)
            Cf[idx] = (1 / 3) * (a[:, :, None] * c).sum(axis=1) \
                / np.where(sumA > 1e-300, sumA, 1.0)[:, None]
            small = sumA <= 1e-300
            Cf[idx[small]] = fc[small]
            Sf[idx] = 0.5 * n.sum(axis=1)
        return Cf, Sf

    def cell_centres(self):
        """Cell centres (primitiveMeshCellCentresAndVols)."""
        if self._centres is not None:
            return self._centres
        Cf, Sf = self.face_centres_and_areas()
        nc, ni = self.n_cells, len(self.neighbour)
        cells = np.concatenate((self.owner, self.neighbour))
        faces = np.concatenate((np.arange(len(self.owner)), np.arange(ni)))
        nfaces = np.bincount(cells, minlength=nc)
        cEst = np.stack([np.bincount(cells, Cf[faces, a], nc)
                         for a in range(3)], axis=1) / nfaces[:, None]
        sign = np.concatenate((np.ones(len(self.owner)), -np.ones(ni)))
        vol = np.maximum(sign * np.einsum("ij,ij->i", Sf[faces],
                                          Cf[faces] - cEst[cells]), 1e-300)
        pc = 0.75 * Cf[faces] + 0.25 * cEst[cells]
        V = np.bincount(cells, vol, nc)
        C = np.stack([np.bincount(cells, vol * pc[:, a], nc)
                      for a in range(3)], axis=1) / V[:, None]
        self._centres = C
        return C

    def positions(self, coords, celli, tetFacei, tetPti):
        """Cartesian positions of barycentric particle coordinates in the
        tets (cell centre, face base point, two face points) of
        tetIndices::faceTriIs, with the face base point 0 (OpenFOAM's
        choice on faces whose every tet is valid, as on blockMesh boxes)."""
        C = self.cell_centres()
        start = self.offsets[tetFacei]
        size = self.offsets[tetFacei + 1] - start
        base = self.labels[start]
        a = (tetPti % size)
        b = (a + 1) % size
        pa, pb = self.labels[start + a], self.labels[start + b]
        swap = self.owner[tetFacei] != celli
        pa, pb = np.where(swap, pb, pa), np.where(swap, pa, pb)
        P = self.points
        return (coords[:, :1] * C[celli] + coords[:, 1:2] * P[base]
                + coords[:, 2:3] * P[pa] + coords[:, 3:4] * P[pb])
