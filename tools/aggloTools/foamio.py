"""Minimal OpenFOAM file input/output for the tutorials: flat
dictionaries, volume-field internal values and lagrangian fields (read in
ASCII or binary, written in ASCII), and the stats.dat of a hard-sphere
cloud."""

import re
import shutil
from pathlib import Path

import numpy as np

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
| agglomerationHardSphere                                                     |
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "{loc}";
    object      {obj};
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""


def _strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def _value(tok):
    try:
        v = float(tok)
        return int(v) if re.fullmatch(r"[-+]?\d+", tok) else v
    except ValueError:
        return tok


def parse_dict(text):
    """Parse a dictionary of `key value;` entries and `name { ... }`
    sub-dictionaries (no lists, macros or directives) into a dict."""
    tokens = re.findall(r'"[^"]*"|[{};]|[^\s{};]+', _strip_comments(text))
    pos = 0

    def block():
        nonlocal pos
        out = {}
        while pos < len(tokens):
            tok = tokens[pos]
            if tok == "}":
                pos += 1
                return out
            key = tok.strip('"')
            pos += 1
            if tokens[pos] == "{":
                pos += 1
                out[key] = block()
                continue
            vals = []
            while tokens[pos] != ";":
                vals.append(_value(tokens[pos]))
                pos += 1
            pos += 1
            out[key] = vals[0] if len(vals) == 1 else vals
        return out

    d = block()
    d.pop("FoamFile", None)
    return d


def read_dict(path):
    return parse_dict(Path(path).read_text())


def check_keys(d, valid, where):
    """Stop with a message naming the entry, the dictionary and the valid
    entries if the parsed dictionary d holds an entry not in valid."""
    for key in d:
        if key not in valid:
            raise SystemExit(f"unknown entry '{key}' in {where}; valid "
                             "entries: " + " ".join(sorted(valid)))


def write_foamfile(path, cls, loc, obj, body):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls=cls, loc=loc, obj=obj) + body
                    + "\n\n// " + "*" * 73 + " //\n")


def _vec(v):
    return "(" + " ".join(repr(float(c)) for c in v) + ")"


def _binary_arch(head):
    """(label dtype, scalar dtype) of a binary file's FoamFile header."""
    m = re.search(rb"arch\s+\"([^\"]*)\"", head)
    arch = m.group(1).decode() if m else "LSB;label=32;scalar=64"
    order = ">" if arch.startswith("MSB") else "<"
    bits = dict(re.findall(r"(label|scalar)=(\d+)", arch))
    return (np.dtype(f"{order}i{int(bits.get('label', 32)) // 8}"),
            np.dtype(f"{order}f{int(bits.get('scalar', 64)) // 8}"))


def _is_binary(head):
    return re.search(rb"format\s+binary\s*;", head) is not None


def _binary_list(data, pos, kind, head):
    """The binary list whose count starts at data[pos:] (`N\n(` raw bytes
    `)`): a numpy array ((n,) or (n, 3)) and the offset after it."""
    m = re.compile(rb"\s*(\d+)\s*\(").match(data, pos)
    n = int(m.group(1))
    label, scalar = _binary_arch(head)
    dt, ncomp = {"label": (label, 1), "scalar": (scalar, 1),
                 "vector": (scalar, 3)}[kind]
    a = np.frombuffer(data, dt, n * ncomp, m.end())
    end = m.end() + a.nbytes
    if data[end:end + 1] != b")":
        raise ValueError("malformed binary list")
    a = a.astype(np.int64 if kind == "label" else float)
    return (a.reshape(n, 3) if ncomp == 3 else a), end + 1


def read_internal(path):
    """internalField of a volume field (ASCII or binary) as an array ((n,)
    or (n, 3); a uniform value as one value)."""
    data = Path(path).read_bytes()
    head = data[:data.index(b"}") + 1]
    m = re.search(rb"internalField\s+nonuniform\s+List<(\w+)>\s*", data)
    if m and _is_binary(head):
        return _binary_list(data, m.end(), m.group(1).decode(), head)[0]
    text = data.decode()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(",
                  text)
    if not m:
        m2 = re.search(r"internalField\s+uniform\s+([^;]+);", text)
        return np.array([float(c) for c in m2.group(1).strip('()').split()])
    n = int(m.group(2))
    body = text[m.end():]
    if m.group(1) == "vector":
        inner = body[:body.index("\n)")]
        flat = np.array(inner.replace("(", " ").replace(")", " ").split(),
                        float)
        return flat.reshape(n, 3)
    return np.array(body[:body.index("\n)")].split(), float)


def set_internal_vector_field(path, values):
    """Replace the internalField of a volVectorField file by values (n, 3)."""
    path = Path(path)
    text = path.read_text()
    field = ("internalField   nonuniform List<vector>\n%d\n(\n%s\n);"
             % (len(values), "\n".join(_vec(v) for v in values)))
    text, n = re.subn(r"internalField\s+uniform\s*\([^)]*\);",
                      lambda m: field, text)
    if n != 1:
        raise ValueError(f"{path}: no uniform internalField to replace")
    path.write_text(text)


def _list_body(a, fmt):
    """ASCII list body of a (n,) or (n, 3) array: `N{value}` when every
    entry is the same (OpenFOAM reads it as a uniform list), else `N(...)`
    with one entry per line formatted by fmt (%.17g: exact)."""
    a = np.asarray(a)
    n = len(a)
    row = fmt if a.ndim == 1 else "(" + " ".join([fmt] * a.shape[1]) + ")"
    if n > 1 and (a == a[0]).all():
        return f"{n}{{{row % tuple(np.atleast_1d(a[0]).tolist())}}}"
    body = (row + "\n") * n % tuple(a.ravel().tolist())
    return f"{n}\n(\n{body})"


def write_cloud(case, positions, d, rho, U=None, omega=None, n_primary=None,
                cloud="kinematicCloud", time="0", ids=None, count=None):
    """Write a complete initial cloud (one particle per parcel) for the
    basicAgglomerateParcel: the legacy positions file (cell -1: located on
    reading) plus every field, with origProcId 0 and origId 0..N-1 or ids
    (decomposition-independent ids); count (default: the largest id + 1)
    is the particleCount from which new particles are numbered."""
    loc = f"{time}/lagrangian/{cloud}"
    out = Path(case) / loc
    x = np.asarray(positions, float)
    N = len(x)
    zeros = np.zeros((N, 3))
    U = zeros if U is None else np.asarray(U, float)
    omega = zeros if omega is None else np.asarray(omega, float)
    d = np.broadcast_to(np.asarray(d, float), (N,))
    rho = np.broadcast_to(np.asarray(rho, float), (N,))
    n_primary = (np.ones(N, int) if n_primary is None
                 else np.asarray(n_primary, int))
    ids = np.arange(N) if ids is None else np.asarray(ids, int)
    if count is None:
        count = int(ids.max()) + 1 if N else 0

    def field(name, cls, a, fmt="%.17g"):
        write_foamfile(out / name, cls, loc, name, _list_body(a, fmt))

    write_foamfile(out / "positions", "Cloud<basicAgglomerateParcel>", loc,
                   "positions",
                   f"{N}\n(\n" + "(%.17g %.17g %.17g) -1\n" * N
                   % tuple(x.ravel().tolist()) + ")")
    field("origProcId", "labelField", np.zeros(N, int), "%d")
    field("origId", "labelField", ids, "%d")
    field("active", "labelField", np.ones(N, int), "%d")
    field("typeId", "labelField", np.zeros(N, int), "%d")
    field("nParticle", "scalarField", np.ones(N))
    field("d", "scalarField", d)
    field("dTarget", "scalarField", d)
    field("rho", "scalarField", rho)
    field("age", "scalarField", np.zeros(N))
    field("tTurb", "scalarField", np.zeros(N))
    field("U", "vectorField", U)
    field("UTurb", "vectorField", zeros)
    field("omega", "vectorField", omega)
    field("nPrimary", "labelField", n_primary, "%d")
    write_foamfile(Path(case) / time / "uniform" / "lagrangian" / cloud
                   / "cloudProperties", "dictionary",
                   f"{time}/uniform/lagrangian/{cloud}", "cloudProperties",
                   f"geometry positions;\nprocessor0 {{ particleCount "
                   f"{count}; }}")


def read_lagrangian(path):
    """A lagrangian IOField or a plain list file (labelList, vectorField:
    cellProcAddressing, points), ASCII or binary, as a numpy array ((n,)
    or (n, 3))."""
    data = Path(path).read_bytes()
    hend = data.index(b"}") + 1
    head = data[:hend]
    if _is_binary(head):
        cls = re.search(rb"class\s+(\S+);", head).group(1).decode()
        kind = ("vector" if "vector" in cls.lower() else
                "label" if "label" in cls.lower() else "scalar")
        body = re.compile(rb"(\s|//[^\n]*)*").match(data, hend).end()
        m = re.compile(rb"(\d+)\s*\{").match(data, body)
        if m:  # uniform list N{raw value}
            label, scalar = _binary_arch(head)
            dt = label if kind == "label" else scalar
            v = np.frombuffer(data, dt, 3 if kind == "vector" else 1,
                              m.end()).astype(float)
            n = int(m.group(1))
            if kind == "vector":
                return np.tile(v, (n, 1))
            return np.full(n, v[0])
        return _binary_list(data, body, kind, head)[0]
    return _read_lagrangian_text(data.decode())


def _read_lagrangian_text(text):
    body = _strip_comments(text[text.index("}") + 1:])
    m = re.search(r"(\d+)\s*\{([^}]*)\}", body)
    if m:  # uniform list N{value}
        n, v = int(m.group(1)), m.group(2).strip()
        if v.startswith("("):
            return np.tile([float(c) for c in v.strip("()").split()],
                           (n, 1))
        return np.full(n, float(v))
    m = re.search(r"(\d+)\s*\((.*)\)", body, re.S)
    if not m or int(m.group(1)) == 0:
        return np.zeros(0)
    inner = m.group(2)
    if "(" in inner:
        flat = np.array(inner.replace("(", " ").replace(")", " ").split(),
                        float)
        return flat.reshape(-1, 3)
    return np.array(inner.split(), float)


def read_positions(path):
    """Cartesian positions from the legacy `positions` file."""
    text = Path(path).read_text()
    rows = re.findall(r"\(([-+0-9.eE ]+)\)\s+-?\d+", text)
    return np.array([[float(c) for c in r.split()] for r in rows])


def time_dirs(case):
    """The time folders of a case (float-sortable names), ascending."""
    out = []
    for p in Path(case).iterdir():
        try:
            out.append((float(p.name), p))
        except ValueError:
            pass
    return [p for _, p in sorted(out)]


def read_stats(case, cloud="kinematicCloud"):
    """The rows of postProcessing/<cloud>HardSphere/<t>/stats.dat as a dict
    of numpy arrays. Restarted runs write a new start-time folder; the rows
    are joined in time order (later folders win at equal times)."""
    base = Path(case) / "postProcessing" / f"{cloud}HardSphere"
    cols, rows = None, []
    for sub in sorted(base.iterdir(), key=lambda p: float(p.name)):
        f = sub / "stats.dat"
        if not f.exists():
            continue
        t0 = float(sub.name)
        rows = [r for r in rows if r[0] <= t0 + 1e-12 * max(1, abs(t0))]
        for line in f.read_text().splitlines():
            if line.startswith("# Time"):
                cols = line[2:].split()
            elif line and not line.startswith("#"):
                rows.append([float(c) for c in line.split()])
    if cols is None:
        raise FileNotFoundError(f"no stats.dat under {base}")
    arr = np.array(rows)
    return {c: arr[:, i] for i, c in enumerate(cols)}


def _complete_file(path):
    """True if an OpenFOAM file ends with its end divider (a write that
    was killed leaves it truncated); compressed files are not checked."""
    if path.suffix == ".gz":
        return True
    with open(path, "rb") as f:
        f.seek(0, 2)
        f.seek(max(0, f.tell() - 200))
        tail = f.read().rstrip()
    return tail.endswith(b"//") and b"// ****" in tail


def _files(folder):
    return {p.relative_to(folder) for p in folder.rglob("*") if p.is_file()}


def incomplete_time(case):
    """The latest time folder of a case (or of one processor folder) if
    its write was cut off, else None: a file without its end divider, no
    uniform/time, or a file of the previous write missing. The first
    folder (the start) is never judged."""
    times = time_dirs(case)
    if len(times) < 2:
        return None
    last, previous = times[-1], times[-2]
    if not (last / "uniform" / "time").is_file():
        return last
    if any(not _complete_file(f) for f in last.rglob("*") if f.is_file()):
        return last
    if len(times) > 2 and not _files(previous) <= _files(last):
        return last
    return None


def set_aside_incomplete_times(case):
    """Before a restart from the latest time: move a time folder whose
    write was cut off (kill -9, a full disk) to incomplete.<time>, in the
    case and in every processor folder, and say so; OpenFOAM would stop
    reading it. Returns the folders set aside."""
    case = Path(case)
    roots = [case] + sorted(case.glob("processor*"))
    # a time cut off on one processor is set aside on all of them
    bad = {t.name for t in map(incomplete_time, roots) if t is not None}
    moved = []
    for name in sorted(bad):
        for root in roots:
            folder = root / name
            if folder.is_dir():
                target = root / f"incomplete.{name}"
                if target.exists():
                    shutil.rmtree(target)
                folder.rename(target)
                moved.append(target)
        print(f"{case}: the write of time {name} was cut off; set aside as "
              f"incomplete.{name}, continuing from the previous write")
    return moved

