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
    d = read_dict(path)
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


def read_settings(case, keys):
    """The system/caseSettings of a run, every entry checked."""
    f = Path(case) / "system" / "caseSettings"
    s = read_dict(f)
    check_keys(s, keys, str(f))
    return s
