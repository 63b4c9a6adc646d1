"""Volume fields: the internalField of a volScalarField or volVectorField
file, read (ASCII or binary) and replaced (ASCII), and the values of one
patch (ASCII)."""

import re
from pathlib import Path

import numpy as np

from .foamfile import ascii_list, binary_list, is_binary, vec


def read_internal(path):
    """internalField of a volume field (ASCII or binary) as an array ((n,)
    or (n, 3); a uniform value as one value)."""
    data = Path(path).read_bytes()
    head = data[:data.index(b"}") + 1]
    m = re.search(rb"internalField\s+nonuniform\s+List<(\w+)>\s*", data)
    if m and is_binary(head):
        return binary_list(data, m.end(), m.group(1).decode(), head)[0]
    text = data.decode()
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>", text)
    if not m:
        m2 = re.search(r"internalField\s+uniform\s+([^;]+);", text)
        return np.array([float(c) for c in m2.group(1).strip('()').split()])
    return ascii_list(text, m.end())


def read_patch(path, patch, n_faces):
    """The face values of one patch of a volume field's boundaryField
    (ASCII) as an array ((n_faces,) or (n_faces, 3); a uniform value
    repeated); a patch without a value entry is a ValueError."""
    text = Path(path).read_text()
    start = re.search(r"\bboundaryField\s*\{", text)
    m = start and re.compile(r"(?m)^\s*\"?" + re.escape(patch)
                             + r"\"?\s*\{").search(text, start.end())
    if not m:
        raise ValueError(f"{path}: no patch {patch} in boundaryField")
    end = text.index("}", m.end())
    v = re.compile(r"\bvalue\s+(uniform|nonuniform\s+List<\w+>)\s*")
    mv = v.search(text, m.end(), end)
    if not mv:
        raise ValueError(f"{path}: patch {patch} has no value")
    if mv.group(1) == "uniform":
        value = text[mv.end():text.index(";", mv.end())].strip()
        one = np.array([float(c) for c in value.strip("()").split()])
        return np.tile(one, (n_faces, 1)) if one.size > 1 \
            else np.full(n_faces, one[0])
    out = ascii_list(text, mv.end())
    if len(out) != n_faces:
        raise ValueError(f"{path}: patch {patch} has {len(out)} values, "
                         f"the mesh {n_faces} faces")
    return out


def set_internal_vector_field(path, values):
    """Replace the internalField of a volVectorField file by values (n, 3)."""
    path = Path(path)
    text = path.read_text()
    field = ("internalField   nonuniform List<vector>\n%d\n(\n%s\n);"
             % (len(values), "\n".join(vec(v) for v in values)))
    text, n = re.subn(r"internalField\s+uniform\s*\([^)]*\);",
                      lambda m: field, text)
    if n != 1:
        raise ValueError(f"{path}: no uniform internalField to replace")
    path.write_text(text)




def plane_means(y, q, per_cell=False):
    """Means of q (one value per cell) over the planes of equal y (cell
    centres' wall-normal coordinate, to 1e-12), by ascending y; per_cell:
    each cell's own plane mean instead."""
    _, inv = np.unique(np.round(y, 12), return_inverse=True)
    m = np.bincount(inv, q) / np.bincount(inv)
    return m[inv] if per_cell else m


def folded(y, q, odd=False):
    """plane_means of q with the two halves of a channel averaged, from the
    wall to the centre (odd: antisymmetric, as <u'v'>)."""
    m = plane_means(y, q)
    return 0.5 * (m + (-1 if odd else 1) * m[::-1])[:len(m) // 2]


def channel_profiles(y, um, r):
    """Mean and rms profiles across a channel (x streamwise, y wall-normal)
    from the time means um (n, 3) and <u_i'u_j'> r (n, 6: xx xy xz yy yz
    zz) of fieldAverage's UMean and UPrime2Mean, folded: U, urms, vrms,
    wrms and uv. The fluctuations are about the plane mean, so the spread
    of the cells' time means within a plane adds to <u_i'u_j'>."""
    dev = um - np.stack([plane_means(y, um[:, c], True) for c in range(3)],
                        axis=1)
    out = {"U": folded(y, um[:, 0])}
    for n, c, rc in (("u", 0, 0), ("v", 1, 3), ("w", 2, 5)):
        out[f"{n}rms"] = np.sqrt(folded(y, r[:, rc] + dev[:, c]**2))
    out["uv"] = folded(y, r[:, 1] + dev[:, 0] * dev[:, 1], odd=True)
    return out
