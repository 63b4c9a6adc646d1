"""OpenFOAM files: the FoamFile header, dictionaries (flat `key value;`
entries and sub-dictionaries: read, and written from nested Python dicts),
the binary header's arch, and list bodies (ASCII written, ASCII or binary
read)."""

import re
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


def strip_comments(text):
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
    sub-dictionaries (no lists; macros `$x` kept as text; a directive
    such as `#include "file"` skipped) into a dict; a
    missing ';', '{' or '}', or an entry given twice in one dictionary,
    is a ValueError."""
    tokens = re.findall(r'"[^"]*"|[{};]|[^\s{};]+', strip_comments(text))
    pos = 0

    def block(inner):
        nonlocal pos
        out = {}
        while pos < len(tokens):
            tok = tokens[pos]
            pos += 1
            if tok == "}":
                if not inner:
                    raise ValueError("unbalanced braces: a '}' without "
                                     "its '{'")
                return out
            if tok.startswith("#include"):
                pos += 1                # the directive's file
                continue
            if tok.startswith("#"):     # e.g. #default key value;
                while pos < len(tokens) and tokens[pos] != ";":
                    pos += 1
                pos += 1
                continue
            key = tok.strip('"')
            if key in out:
                # OpenFOAM lets the later entry replace the earlier one;
                # in the files these tools read a repeated entry is a
                # slip whose first value would be lost silently
                raise ValueError(f"entry '{key}' given twice")
            if pos < len(tokens) and tokens[pos] == "{":
                pos += 1
                out[key] = block(True)
                continue
            vals = []
            while pos < len(tokens) and tokens[pos] not in (";", "{", "}"):
                vals.append(_value(tokens[pos]))
                pos += 1
            if pos == len(tokens) or tokens[pos] != ";":
                raise ValueError(f"entry '{key}' does not end with ';'")
            pos += 1
            out[key] = vals[0] if len(vals) == 1 else vals
        if inner:
            raise ValueError("a sub-dictionary without its closing '}'")
        return out

    d = block(False)
    d.pop("FoamFile", None)
    return d


def entry_text(text, name):
    """The text inside the braces of the top-level sub-dictionary `name`
    of a dictionary's text (comments removed), as written: for copying
    one entry of a file of named alternatives into another dictionary.
    ValueError if there is none or its braces do not close."""
    body = strip_comments(text)
    tokens = list(re.finditer(r'"[^"]*"|[{};]|[^\s{};"]+', body))
    depth, first = 0, None
    for k, m in enumerate(tokens):
        tok = m.group()
        if tok == "{":
            depth += 1
            if depth == 1 and k and tokens[k - 1].group() == name \
                    and first is None:
                first = m.end()
        elif tok == "}":
            depth -= 1
            if depth == 0 and first is not None:
                return body[first:m.start()].strip()
    if first is not None:
        raise ValueError(f"entry '{name}': its '{{' does not close")
    raise ValueError(f"no entry '{name} {{ ... }}'")


def read_dict(path):
    """parse_dict of a file; an error names the file."""
    try:
        return parse_dict(Path(path).read_text())
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


def check_keys(d, valid, where):
    """Stop with a message naming the entry, the dictionary and the valid
    entries if the parsed dictionary d holds an entry not in valid."""
    for key in d:
        if key not in valid:
            raise SystemExit(f"unknown entry '{key}' in {where}; valid "
                             "entries: " + " ".join(sorted(valid)))


def edit(path, old, new, count=-1):
    """Replace old by new in the file path (the first count occurrences;
    all by default), as a test or a script edits a written case file; a
    ValueError naming the file if old is not in it, so that an edit whose
    text has moved does not pass unnoticed as an unchanged case."""
    path = Path(path)
    text = path.read_text()
    if old not in text:
        raise ValueError(f"{path}: {old!r} is not in the file: nothing to "
                         "replace")
    path.write_text(text.replace(old, new, count))


def write_foamfile(path, cls, loc, obj, body):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls=cls, loc=loc, obj=obj) + body
                    + "\n\n// " + "*" * 73 + " //\n")


def entry_value(v):
    """One value of a dictionary entry as written: a bool as true/false, a
    number exactly (number()), a tuple or list as `(a b c)` (nested alike), a
    string as it is (a word, or a value OpenFOAM reads as several
    tokens)."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return number(v)
    if isinstance(v, (list, tuple)):
        return "(" + " ".join(entry_value(c) for c in v) + ")"
    if isinstance(v, str):
        return v
    raise TypeError(f"no dictionary value for {type(v).__name__} {v!r}")


def number(v):
    """A float as its shortest exact text (repr), large ones in scientific
    notation as a user writes them (7.2e10, not 72000000000.0)."""
    v = float(v)
    if np.isfinite(v) and abs(v) >= 1e5:
        return np.format_float_scientific(v, unique=True, trim="-",
                                          exp_digits=1).replace("+", "")
    return repr(v)


def dict_text(d, indent=0):
    """A nested dict as the entries of an OpenFOAM dictionary, one per
    line and 4 spaces a level: a dict value is a sub-dictionary
    `key { ... }` (`key {}` when empty), "" a keyword alone
    (`SchillerNaumannDrag;`), None leaves the entry out, anything else
    `key value;` (entry_value)."""
    pad = " " * indent
    out = []
    for key, v in d.items():
        if v is None:
            continue
        if isinstance(v, dict) and not v:
            out.append(f"{pad}{key} {{}}\n")
        elif isinstance(v, dict):
            out.append(f"{pad}{key}\n{pad}{{\n{dict_text(v, indent + 4)}"
                       f"{pad}}}\n")
        elif isinstance(v, str) and not v:
            out.append(f"{pad}{key};\n")
        else:
            out.append(f"{pad}{key} {entry_value(v)};\n")
    return "".join(out)


def merged(base, changes=None):
    """A copy of the nested dict base (every sub-dictionary copied: the
    result can be changed without changing base) with changes applied: a
    dict merges into a sub-dictionary entry by entry, None removes the
    entry, any other value replaces it (or is added, at the end)."""
    out = {k: merged(v) if isinstance(v, dict) else v
           for k, v in base.items()}
    for key, v in (changes or {}).items():
        if v is None:
            out.pop(key, None)
        elif isinstance(v, dict) and isinstance(out.get(key), dict):
            out[key] = merged(out[key], v)
        elif isinstance(v, dict):
            out[key] = merged(v)
        else:
            out[key] = v
    return out


def vec(v):
    """An OpenFOAM vector `(x y z)` written exactly (repr of floats)."""
    return "(" + " ".join(repr(float(c)) for c in v) + ")"


def field_class(path):
    """The class entry of a file's FoamFile header ('' if none)."""
    m = re.search(rb"class\s+(\S+);", Path(path).read_bytes()[:2000])
    return m.group(1).decode() if m else ""


def binary_arch(head):
    """(label dtype, scalar dtype) of a binary file's FoamFile header."""
    m = re.search(rb"arch\s+\"([^\"]*)\"", head)
    arch = m.group(1).decode() if m else "LSB;label=32;scalar=64"
    order = ">" if arch.startswith("MSB") else "<"
    bits = dict(re.findall(r"(label|scalar)=(\d+)", arch))
    return (np.dtype(f"{order}i{int(bits.get('label', 32)) // 8}"),
            np.dtype(f"{order}f{int(bits.get('scalar', 64)) // 8}"))


def is_binary(head):
    return re.search(rb"format\s+binary\s*;", head) is not None


def binary_list(data, pos, kind, head):
    """The binary list whose count starts at data[pos:] (`N\n(` raw bytes
    `)`): a numpy array ((n,) or (n, 3)) and the offset after it."""
    m = re.compile(rb"\s*(\d+)\s*\(").match(data, pos)
    n = int(m.group(1))
    label, scalar = binary_arch(head)
    dt, ncomp = {"label": (label, 1), "scalar": (scalar, 1),
                 "vector": (scalar, 3)}[kind]
    a = np.frombuffer(data, dt, n * ncomp, m.end())
    end = m.end() + a.nbytes
    if data[end:end + 1] != b")":
        raise ValueError("malformed binary list")
    a = a.astype(np.int64 if kind == "label" else float)
    return (a.reshape(n, 3) if ncomp == 3 else a), end + 1


def list_body(a, fmt):
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


def _skip_comments(text, pos):
    """The offset of the first token at or after pos (white space, // and
    /* */ comments skipped)."""
    n = len(text)
    while pos < n:
        if text[pos].isspace():
            pos += 1
        elif text.startswith("//", pos):
            end = text.find("\n", pos)
            pos = n if end < 0 else end + 1
        elif text.startswith("/*", pos):
            pos = text.index("*/", pos) + 2
        else:
            break
    return pos


def ascii_list(text, pos=0):
    """The ASCII list that starts at text[pos:] (after white space and
    comments) as a numpy array: `N{value}` (uniform), `N(...)` or `(...)`
    of numbers or of tuples (`(x y z)` vectors, `(xx xy xz yy yz zz)`
    symmetric tensors), on one line or many; comments only outside the
    list (as OpenFOAM writes them). The numbers are split
    once (no per-entry parsing in Python)."""
    pos = _skip_comments(text, pos)
    m = re.compile(r"(?:(\d+)\s*)?([({])").match(text, pos)
    if not m or (m.group(1) is None and m.group(2) == "{"):
        raise ValueError(f"no list at offset {pos}")
    n = None if m.group(1) is None else int(m.group(1))   # `(...)`: counted
    if m.group(2) == "{":                   # uniform list N{value}
        v = text[m.end():text.index("}", m.end())].strip()
        if v.startswith("("):
            return np.tile([float(c) for c in v.strip("()").split()],
                           (n, 1))
        return np.full(n, float(v))
    if n == 0:
        return np.zeros(0)
    start = m.end()
    first = _skip_comments(text, start)
    if text.startswith("(", first):         # a list of (x y z), (xx ..)
        close = re.compile(r"\)\s*\)").search(text, first)
        if close is None:
            raise ValueError("a list of vectors without its closing ')'"
                             " (a file cut off?)")
        width = len(text[first + 1:text.index(")", first)].split())
        flat = np.array(text[start:close.end() - 1].replace("(", " ")
                        .replace(")", " ").split(), float)
        tuples = text.count("(", first, close.end() - 1)
        if flat.size != tuples * width:
            raise ValueError(f"{flat.size} numbers in {tuples} tuples of "
                             f"{width} (the first tuple's size)")
        out = flat.reshape(-1, width)
    else:
        end = text.find(")", start)
        if end < 0:
            raise ValueError("a list without its closing ')' (a file cut"
                             " off?)")
        out = np.array(text[start:end].split(), float)
    if n is not None and len(out) != n:
        raise ValueError(f"the list announces {n} values but holds "
                         f"{len(out)}")
    return out


def read_list_file(path):
    """A lagrangian IOField or a plain list file (labelList, vectorField:
    cellProcAddressing, points), ASCII or binary, as a numpy array ((n,)
    or (n, 3)); a file that is not a whole list is a ValueError naming
    it."""
    try:
        return _read_list_file(path)
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


def _read_list_file(path):
    data = Path(path).read_bytes()
    hend = data.index(b"}") + 1
    head = data[:hend]
    if is_binary(head):
        cls = re.search(rb"class\s+(\S+);", head).group(1).decode()
        kind = ("vector" if "vector" in cls.lower() else
                "label" if "label" in cls.lower() else "scalar")
        body = re.compile(rb"(\s|//[^\n]*)*").match(data, hend).end()
        m = re.compile(rb"(\d+)\s*\{").match(data, body)
        if m:  # uniform list N{raw value}
            label, scalar = binary_arch(head)
            dt = label if kind == "label" else scalar
            v = np.frombuffer(data, dt, 3 if kind == "vector" else 1,
                              m.end()).astype(float)
            n = int(m.group(1))
            if kind == "vector":
                return np.tile(v, (n, 1))
            return np.full(n, v[0])
        return binary_list(data, body, kind, head)[0]
    return ascii_list(data.decode(), hend)
