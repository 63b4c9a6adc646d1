"""verticalChannel: one-way coupled configurations run as clouds of one
LES, a group named by its configurations joined with '+' (R80+R60).

Where the particles do not act on the fluid (one-way coupling: the
configurations whose sub-models are off), the fluid of every such
configuration is the same LES: the unladen LES continued with the same
step, whatever its particles do. So a group's configurations run in one
case, each with clouds of its own that see that LES and nothing of the
others' particles: the release and dispersion stages one cloud per
configuration (named after it), the agglomeration stage one per
configuration and model (R80EAM R80MAM R60EAM R60MAM). The fluid is
solved once instead of once per configuration.

A group's configurations must agree in everything their runs' caseSettings
hold but their one-way sub-models (the forces, the SGS velocity) and
collision coefficients (e_n,p and the wall): the particles' diameter and
number, the coupling's scale. Each cloud takes its configuration's own
from caseSettings, where a group writes one entry per configuration,

    R80 { subModels off; cloudForces { ... } dispersionModel none;
          enParticle 0.8; wallType smooth; wallCoeffs { ... } }

expanded by the cloud's constant/<cloud>Properties (written by the
driver, properties()) before the common cloud set-up:

    #include "$FOAM_CASE/system/caseSettings"
    $R80;
    cloudAgglomerationModel EAM;
    #include "cloudCommon"

(the group's caseSettings has none of these entries of its own, so
cloudCommon's #include of it leaves each cloud's).

    members("R80+R60")                          -> ["R80", "R60"]
    clouds("R80+R60", "agglomeration", ("EAM", "MAM"))
        -> ["R80EAM", "R80MAM", "R60EAM", "R60MAM"]
    check("regime64", "R80+R60")    # stops naming what differs
    twice(["C1+R80+R60"], runs_before(Path("runs/regime64")))
        -> what would run a configuration twice (none: [])
"""

import sys
from pathlib import Path

from aggloTools.foamfile import write_foamfile

from channel.case.presets import (MODELS, PER_CONFIGURATION_KEYS,
                                  configuration, preset, read_presets)

SEP = "+"
#: The entries of a configuration that a group's members must share (the
#: sub-models, the wall and e_n,p are each cloud's own)
SHARED = ("d",)
#: The caseSettings entries that are each member's own (its entry): its
#: one-way sub-models (the forces, the SGS velocity) and its collision
#: coefficients
OWN = ("subModels", "cloudForces", "dispersionModel", "enParticle",
       "wallType", "wallCoeffs")


def is_group(name):
    return SEP in name


def members(name):
    """The configurations of a group (a configuration alone: [name]),
    each a configuration of the presets file, one-way coupled, at least
    two, none twice."""
    if not is_group(name):
        return [name]
    ms = name.split(SEP)
    where = f"channel.case: configuration group '{name}'"
    if len(ms) < 2 or "" in ms:
        sys.exit(f"{where}: name two configurations or more, joined with "
                 f"'{SEP}' (e.g. R80{SEP}R60)")
    twice = sorted({m for m in ms if ms.count(m) > 1})
    if twice:
        sys.exit(f"{where}: {' '.join(twice)} named twice")
    for m in ms:
        if configuration(m)["twoWay"]:
            sys.exit(f"{where}: {m} is two-way coupled (its subModels "
                     "switch twoWayCoupling on): its particles move the "
                     "fluid, so it cannot share an LES; a group's "
                     "configurations must be one-way")
    return ms


def lead(name):
    """The configuration whose shared settings stand for the group's."""
    return members(name)[0]


def check(pname, name):
    """Stop unless the group's configurations agree, in the preset pname,
    in everything but their one-way sub-models and collision coefficients
    (SHARED, and the preset's perConfiguration entries)."""
    ms = members(name)
    c0, p0 = configuration(ms[0]), preset(pname, ms[0])
    for m in ms[1:]:
        c, p = configuration(m), preset(pname, m)
        differ = ([k for k in SHARED if c[k] != c0[k]]
                  + [k for k in PER_CONFIGURATION_KEYS if p[k] != p0[k]])
        if differ:
            sys.exit(f"channel.case: configuration group '{name}' in preset "
                     f"{pname}: {ms[0]} and {m} differ in "
                     f"{' '.join(differ)}; a group's configurations may "
                     "differ only in their one-way sub-models and their "
                     "collision coefficients (subModels, en, wall)")


def runs_before(base):
    """The configurations and groups run (or begun) before under base:
    its folders named after configurations of the presets file."""
    known = set(read_presets()["configurations"])
    if not Path(base).is_dir():
        return []
    return [p for p in sorted(Path(base).iterdir()) if p.is_dir()
            and all(m in known for m in p.name.split(SEP))]


def dispersion_clouds(base):
    """{configuration: (dispersion folder, its cloud)} of every
    configuration run (or begun) under base, a group's members each with
    its own cloud."""
    out = {}
    for d in runs_before(base):
        ddir = d / "dispersion"
        if ddir.is_dir():
            for cloud, m in zip(clouds(d.name, "release", ()),
                                members(d.name)):
                out[m] = (ddir, cloud)
    return out


def twice(names, before=()):
    """Where a call's configurations and groups (names) would run a
    configuration twice, one line each: a configuration in two of names,
    or in one of names and in another name among the folders run before
    (before: runs_before); the report takes each configuration from one
    run, so this stops a call before it spends hours on a second one. A
    name run before under its own name is that run, continued."""
    out = []
    where = {}
    for n in names:
        for m in members(n):
            where.setdefault(m, []).append(n)
    for m, ns in where.items():
        if len(ns) > 1:
            out.append(f"{m} is named {len(ns)} times in -configs "
                       f"({', '.join(ns)}): each configuration runs once, "
                       "alone or in one group")
    for d in before:
        if d.name in names:
            continue
        for m in members(d.name):
            if m in where:
                out.append(f"{m} ({where[m][0]}) has run before as "
                           f"{d.name} in {d}: the report takes each "
                           f"configuration from one run; remove {d}, or "
                           f"name {m} as it ran there ({d.name})")
    return out


def _made(name, stage, models):
    """(cloud, configuration, model) of each cloud of a stage: the one
    place of the clouds' names. None (unladen); `particles` (release,
    dispersion) and one per model (agglomeration) for a configuration
    alone; one per configuration (named after it), then one per
    configuration and model (R80EAM), for a group."""
    if stage == "unladen":
        return []
    group = is_group(name)
    if stage != "agglomeration":
        return [(m if group else "particles", m, "none")
                for m in members(name)]
    return [(m + model if group else model, m, model)
            for m in members(name) for model in models]


def clouds(name, stage, models):
    """The clouds of a stage (_made)."""
    return [c for c, _, _ in _made(name, stage, models)]


def branches(name, models):
    """Each agglomeration cloud -> the dispersion cloud it starts from."""
    start = {m: c for c, m, _ in _made(name, "release", ())}
    return {c: start[m] for c, m, _ in _made(name, "agglomeration", models)}


def cloud_key(name, cloud):
    """(configuration, model) of an agglomeration cloud of the run of
    name (a configuration or a group)."""
    for c, m, model in _made(name, "agglomeration", MODELS):
        if c == cloud:
            return (m, model)
    if not is_group(name):
        return (name, cloud)
    raise KeyError(f"{cloud}: not an agglomeration cloud of the "
                   f"configuration group {name}")


def entries(name, own):
    """The group's caseSettings lines: its members and each member's
    entry of its own values (own(configuration): OWN -> text)."""
    ms = members(name)
    lines = [f"members         ({' '.join(ms)});"]
    for m in ms:
        v = own(m)
        lines.append(f"{m:<15} {{ " + " ".join(
            f"{k} {v[k]}" + ("" if v[k].startswith("{") else ";")
            for k in OWN) + " }")
    return "\n".join(lines)


def own_entries(name):
    """The caseSettings entries a group adds (none for a configuration
    alone): its members and one entry per member."""
    return ["members"] + members(name) if is_group(name) else []


def properties(case, name, stage, models):
    """constant/<cloud>Properties of each cloud of a group's stage (none
    for a configuration alone: the tutorial's own files serve)."""
    if not is_group(name):
        return
    for cloud, m, model in _made(name, stage, models):
        write_foamfile(
            Path(case) / "constant" / f"{cloud}Properties", "dictionary",
            "constant", f"{cloud}Properties", f"""\
// Cloud "{cloud}" of the configuration group {name}
// (channel.case.groups, written by ./Allrun): configuration {m}'s
// sub-models and collision coefficients (its entry of caseSettings),
// agglomeration model {model}

#include "$FOAM_CASE/system/caseSettings"

${m};

cloudAgglomerationModel {model};

#include "cloudCommon\"""")
