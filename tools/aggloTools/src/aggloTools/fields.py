"""Volume fields: the internalField of a volScalarField or volVectorField
file, read (ASCII or binary) and replaced (ASCII)."""

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


