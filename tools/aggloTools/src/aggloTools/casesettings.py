"""The presets -> caseSettings mechanism of the tutorials, in one place.

A tutorial keeps its parameters in a `presets` dictionary: named presets,
a section of values common to all of them (`common`) and, where it has
them, groups of named entries (the channel's `configurations`). Every
entry is checked against the keys of its section when the file is read;
one preset's settings are the common values overridden by the preset's;
a choice (on/off, a run, a stage) is checked against its valid values.
Each run's values are then written into its `system/caseSettings`, which
the case's dictionaries #include, and which is read back, every entry
checked, by the tutorial's post-processing. Each tutorial keeps its own
keys, derived values and the text it writes; the errors stop with the
entry and the valid choices named.
"""

from pathlib import Path

from .foamfile import check_keys, read_dict


def read_presets(path, preset_keys, sections=None, groups=None):
    """The presets file at path, every entry checked: a section in
    sections (name -> keys) against its keys, each entry of a group in
    groups (name -> keys) against the group's keys, every other entry (a
    preset) against preset_keys."""
    sections = sections or {}
    groups = groups or {}
    try:
        d = read_dict(path)
    except ValueError as e:
        raise SystemExit(str(e)) from None
    for name, p in d.items():
        if name in groups:
            for entry, e in p.items():
                check_keys(e, groups[name], f"presets/{name}/{entry}")
        else:
            check_keys(p, sections.get(name, preset_keys),
                       f"presets/{name}")
    return d


def named(d, name, what, prog, exclude=()):
    """The entry name of d; an unknown name stops naming the valid ones
    (the keys of d but those in exclude)."""
    if name not in d or name in exclude:
        valid = [k for k in d if k not in exclude]
        raise SystemExit(f"{prog}: unknown {what} '{name}'; valid: "
                         + " ".join(valid))
    return d[name]


def merged(presets, name, prog, base="common", exclude=()):
    """The settings of the preset name: the section base overridden by
    the preset's own entries (sections and groups in exclude are not
    presets)."""
    p = dict(presets[base])
    p.update(named(presets, name, "preset", prog, (base,) + tuple(exclude)))
    return p


def choice(value, valid, where):
    """value if it is one of valid, else stop naming where and the
    choices."""
    if value not in valid:
        raise SystemExit(f"{where} '{value}' is not one of: "
                         + " ".join(str(v) for v in valid))
    return value


def read_settings(case, keys, more=None):
    """The system/caseSettings of a run, every entry checked: one of
    keys, or of more(settings) (the entries its own values make valid)."""
    f = Path(case) / "system" / "caseSettings"
    try:
        s = read_dict(f)
    except ValueError as e:
        raise SystemExit(str(e)) from None
    check_keys(s, set(keys) | set(more(s) if more else ()), str(f))
    return s


class Number:
    """How a numeric entry of a presets file is checked (checked()): a
    whole number (integer) or a real one, n of them (a list `(a b c)`
    where n > 1), each within [lo, hi] (None: unbounded; open_lo: lo
    excluded)."""

    def __init__(self, kind, lo=None, hi=None, open_lo=False, n=1):
        self.kind, self.lo, self.hi = kind, lo, hi
        self.open_lo, self.n = open_lo, n

    def range(self):
        lo = "-inf" if self.lo is None else f"{self.lo:g}"
        hi = "inf" if self.hi is None else f"{self.hi:g}"
        return f"{'(' if self.open_lo or self.lo is None else '['}{lo}, " \
               f"{hi}{']' if self.hi is not None else ')'}"

    def one(self, v, where):
        try:
            x = float(str(v))
        except ValueError:
            raise SystemExit(f"{where} '{v}' is not a number") from None
        if self.kind is int:
            if x != int(x):
                raise SystemExit(f"{where} '{v}' is not a whole number")
            x = int(x)
        elif isinstance(v, int):
            x = v                   # as written (60, not 60.0)
        if x != x or (self.lo is not None and (
                x < self.lo or (self.open_lo and x == self.lo))) or (
                self.hi is not None and x > self.hi):
            raise SystemExit(f"{where} '{v}' is out of range {self.range()}")
        return x

    def value(self, v, where):
        if self.n == 1:
            if isinstance(v, list):
                raise SystemExit(f"{where} '{' '.join(map(str, v))}' is not"
                                 " one number")
            return self.one(v, where)
        text = " ".join(map(str, v if isinstance(v, list) else [v]))
        words = text.replace("(", " ").replace(")", " ").split()
        if len(words) != self.n:
            raise SystemExit(f"{where} '{text}' needs {self.n} numbers: "
                             f"({' '.join(['x'] * self.n)})")
        return [self.one(w, where) for w in words]


def checked(p, spec, where):
    """p with each entry that spec (key -> Number) names converted and
    checked; the first bad one stops naming where/key, the value and
    what it must be (a number, a whole number, its range, its count)."""
    out = dict(p)
    for key, num in spec.items():
        if key in out:
            out[key] = num.value(out[key], f"{where}: {key}")
    return out
