"""verticalChannel: the break-up a preset names (`breakup NAME;`), an
entry of the tutorial's breakupModels file, as the caseSettings text of
a stage."""

import sys

from aggloTools.foamfile import entry_text, read_dict

from channel import TUTORIAL

#: The break-up models a preset may name (`breakup NAME;`)
BREAKUP_MODELS = TUTORIAL / "breakupModels"


def breakup_models():
    """The names of the entries of breakupModels."""
    try:
        d = read_dict(BREAKUP_MODELS)
    except ValueError as e:
        sys.exit(f"channel.case: {e}")
    return tuple(d)


def breakup_entry(p, stage):
    """The caseSettings text of the stage's break-up: the preset's model
    (breakupModels) in the agglomeration stage, none before it."""
    name = p["breakup"] if stage == "agglomeration" else "none"
    body = entry_text(BREAKUP_MODELS.read_text(), name)
    # the entry's lines as breakupModels indents them (its first one's
    # indentation stripped)
    return "breakup\n{\n    " + body + "\n}"
