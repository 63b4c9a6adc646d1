"""verticalChannel: the presets file read and checked (README.md,
"Presets"): each preset's entries (common values first), the
configurations, a preset's own particle number for a configuration
(perConfiguration) and the stages a preset shares with another
(stagesFrom). channel.case.settings writes a run's caseSettings from
them (and offers preset and configuration to the other modules).

    p = preset("regime64", "C4")    # regime64's settings of C4's runs
    c = configuration("C4")
"""

import math
import sys

from aggloTools import casesettings
from aggloTools.foamfile import check_keys
from channel import TUTORIAL
from channel.case.breakup import breakup_models

MODELS = ("EAM", "MAM")
PI = math.pi

COMMON_KEYS = {"delta", "Ubar", "nu", "rhoInf", "rhoParticle", "perturb",
               "ddtScheme", "seed", "writeFormat", "writePositions",
               "purgeWrite", "eventLog", "UTolerance", "breakup"}
PRESET_KEYS = {"n", "yGrading", "dtStar", "nParticles", "couplingScale",
               "unladen", "release", "dispersion", "agglomeration", "window",
               "writeStar", "profileBins", "seededPairs", "models",
               "stagesFrom", "perConfiguration"} | COMMON_KEYS
CONFIGURATION_KEYS = {"subModels", "wall", "d", "en"}
#: What a configuration's `subModels` may switch on, one by one (`on`:
#: all, the paper's three sub-models with its lift taken as both forces;
#: `off`: none): the two-way coupling, the Pozorski-Apte SGS velocity
#: seen by the particles, the Saffman-Mei shear lift, the rotation lift
SUB_MODELS = ("twoWayCoupling", "sgsDispersion", "shearLift",
              "rotationLift")
#: What a preset's perConfiguration entry sets for one configuration: the
#: particle number and, with it, the two-way coupling's scale (both given:
#: couplingScale 6e6/nParticles keeps the paper's mass loading)
PER_CONFIGURATION_KEYS = ("nParticles", "couplingScale")
N = casesettings.Number
#: What each numeric entry must be (the window is checked against the
#: agglomeration phase in preset())
PRESET_NUMBERS = {
    "n": N(int, 1, n=3), "yGrading": N(float, 0, open_lo=True),
    "dtStar": N(float, 0, 1, open_lo=True), "nParticles": N(int, 1),
    "couplingScale": N(float, 0, open_lo=True),
    "unladen": N(float, 0), "release": N(float, 0),
    "dispersion": N(float, 0), "agglomeration": N(float, 0),
    "window": N(float, 0, n=2), "writeStar": N(float, 0, open_lo=True),
    "profileBins": N(int, 1, 100000), "seededPairs": N(int, 0),
    "delta": N(float, 0, open_lo=True), "Ubar": N(float, 0, open_lo=True),
    "nu": N(float, 0, open_lo=True), "rhoInf": N(float, 0, open_lo=True),
    "rhoParticle": N(float, 0, open_lo=True), "perturb": N(float, 0),
    "seed": N(int, 0), "purgeWrite": N(int, 0),
    "UTolerance": N(float, 0, 1e-3, open_lo=True)}
CONFIGURATION_NUMBERS = {"d": N(float, 0, open_lo=True),
                         "en": N(float, 0, 1)}


def read_presets():
    """The presets file, every entry checked."""
    return casesettings.read_presets(
        TUTORIAL / "presets", PRESET_KEYS, {"common": COMMON_KEYS},
        {"configurations": CONFIGURATION_KEYS})


def preset(name, config=None):
    """The merged settings of a preset (common values first); with
    config, those of that configuration's runs (the preset's
    perConfiguration entry for it applied, the entry itself left out)."""
    p = casesettings.checked(
        casesettings.merged(read_presets(), name, "channel.case",
                            exclude=("configurations",)),
        PRESET_NUMBERS, f"channel.case: presets/{name}")
    p["name"] = name
    p.setdefault("seededPairs", 0)
    lo, hi = p["window"]
    agg = p["agglomeration"]
    if not lo < hi <= agg:
        sys.exit(f"channel.case: presets/{name}: window ({lo:g} {hi:g}) must"
                 f" lie inside the agglomeration phase (0 {agg:g}) and end"
                 " after it starts")
    p["tScale"] = p["delta"] / p["Ubar"]            # delta/U_B [s]
    p["deltaT"] = p["dtStar"] * p["tScale"]
    p["L"] = (2 * PI * p["delta"], 2 * p["delta"], PI * p["delta"])
    choices = {"writeFormat": ("ascii", "binary"),
               "writePositions": ("on", "off"), "eventLog": ("on", "off"),
               "breakup": breakup_models()}
    for key, valid in choices.items():
        casesettings.choice(p[key], valid,
                            f"channel.case: presets/{name}: {key}")
    # The agglomeration models run, (EAM MAM) unless the preset says
    m = p.get("models", MODELS)
    m = " ".join(map(str, m if isinstance(m, (list, tuple)) else [m]))
    p["models"] = tuple(m.replace("(", " ").replace(")", " ").split())
    for m in p["models"] or ("()",):
        casesettings.choice(m, MODELS, f"channel.case: presets/{name}: "
                            "models: each of them")
    if len(set(p["models"])) < len(p["models"]):
        sys.exit(f"channel.case: presets/{name}: models names a model twice")
    p["perConfiguration"] = per_configuration(p)
    p["stagesFrom"] = shared_stages(p)
    if config is not None:
        configuration(config)
        p.update(p.pop("perConfiguration").get(config, {}))
    return p


def per_configuration(p):
    """The preset p's perConfiguration entry checked: configuration name
    -> {nParticles, couplingScale}, both given (the particle number of
    that configuration's runs and the coupling's scale that goes with
    it); {} without the entry."""
    where = f"channel.case: presets/{p['name']}: perConfiguration"
    entry = p.get("perConfiguration", {})
    if not isinstance(entry, dict):
        sys.exit(f"{where} must be a dictionary: configuration name ->"
                 " { nParticles N; couplingScale S; }")
    out = {}
    for cname, values in entry.items():
        casesettings.named(read_presets()["configurations"], cname,
                           "configuration", where)
        if not isinstance(values, dict):
            sys.exit(f"{where}: {cname} must be a dictionary"
                     " { nParticles N; couplingScale S; }")
        check_keys(values, PER_CONFIGURATION_KEYS, f"{where}/{cname}")
        missing = [k for k in PER_CONFIGURATION_KEYS if k not in values]
        if missing:
            sys.exit(f"{where}/{cname}: {' and '.join(missing)} missing:"
                     " give nParticles and couplingScale together (the"
                     " coupling's scale 6e6/nParticles keeps the paper's"
                     " mass loading)")
        out[cname] = casesettings.checked(
            values, {k: PRESET_NUMBERS[k] for k in PER_CONFIGURATION_KEYS},
            f"{where}/{cname}")
    return out


#: What a preset whose earlier stages are another's (stagesFrom) may
#: change: the entries that act in the agglomeration stage alone
AGGLOMERATION_ONLY = {"breakup", "eventLog", "models", "stagesFrom",
                      "name"}


def shared_stages(p):
    """The preset whose unladen, release and dispersion runs (runs/NAME)
    the preset p branches its agglomeration stages from: None where p runs
    its own, else its `stagesFrom`, which must be a preset of its own
    stages that equals p in every entry but AGGLOMERATION_ONLY (so these
    stages are exactly the ones p would run)."""
    name, base = p["name"], p.get("stagesFrom")
    if base is None or base == name:
        return None
    b = preset(str(base))
    where = f"channel.case: presets/{name}: stagesFrom {base}"
    if b["stagesFrom"] is not None:
        sys.exit(f"{where}: that preset takes its stages from "
                 f"{b['stagesFrom']}: name that one")
    differ = sorted(k for k in set(p) | set(b) if k not in
                    AGGLOMERATION_ONLY and p.get(k) != b.get(k))
    if differ:
        sys.exit(f"{where}: its stages before agglomeration would differ "
                 f"from this preset's in {' '.join(differ)} (only "
                 f"{' '.join(sorted(AGGLOMERATION_ONLY - {'name'}))} may)")
    return str(base)


def configuration(name):
    c = casesettings.checked(
        casesettings.named(read_presets()["configurations"], name,
                           "configuration", "channel.case"),
        CONFIGURATION_NUMBERS, f"channel.case: presets/configurations/{name}")
    where = f"channel.case: presets/configurations/{name}"
    casesettings.choice(c["wall"], ("smooth", "rough"), f"{where}: wall")
    c["name"] = name
    c["switched"] = sub_models(c["subModels"], f"{where}: subModels")
    if c["subModels"] not in ("on", "off"):
        c["subModels"] = f"({' '.join(c['switched'])})"
    c["twoWay"] = "twoWayCoupling" in c["switched"]
    return c


def sub_models(value, where):
    """The sub-models a configuration's `subModels` switches on: `on`
    (all of SUB_MODELS: the paper's C2-C4), `off` (none: C1), or a list
    of SUB_MODELS' names, each at most once (the paper's three split:
    README.md, "Which sub-model drives C2's particles to the walls")."""
    text = " ".join(map(str, value if isinstance(value, list) else [value]))
    if text in ("on", "off"):
        return SUB_MODELS if text == "on" else ()
    names = text.replace("(", " ").replace(")", " ").split()
    if not text.startswith("(") or not text.endswith(")") or not names:
        sys.exit(f"{where} '{text}' is not one of: on off, or a list of "
                 f"({' '.join(SUB_MODELS)})")
    for v in names:
        casesettings.choice(v, SUB_MODELS, f"{where} {text}: sub-model")
    twice = sorted({v for v in names if names.count(v) > 1})
    if twice:
        sys.exit(f"{where} {text}: {' '.join(twice)} named twice")
    return tuple(v for v in SUB_MODELS if v in names)
