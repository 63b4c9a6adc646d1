"""The variants of the channel's linear-solver settings that
bench/channelSolverSettings.py runs: the tutorial's
system/fvSolution with one entry changed (or GAMG's other knobs, only
timed), written into a case and recorded as parsed."""

import re
import sys

from aggloTools import foamfile
from aggloTools.runner import project_dir

TUTORIAL = project_dir() / "tutorials" / "verticalChannel"

#: One setting of the tutorial's system/fvSolution changed per variant
#: ("block/key": value; null: the start flow rounded instead)
VARIANTS = {
    "base": {},
    "null": {},
    "UTol1e-6": {"(U|UFinal)/tolerance": "1e-6"},
    "pTol1e-6": {"p/tolerance": "1e-6"},
    "pTol1e-5": {"p/tolerance": "1e-5"},
    "pRelTol0.05": {"p/relTol": "0.05"},
    "GaussSeidel": {"p/smoother": "GaussSeidel"},
    "mergeLevels2": {"p/+mergeLevels": "2"},
    "momentumPredictorOff": {"PIMPLE/+momentumPredictor": "off"},
}

#: Variants only timed (--cost-only): GAMG's other knobs and PCG
COST_ONLY = {
    "coarsest100": {"p/+nCellsInCoarsestLevel": "100"},
    "DICGaussSeidel": {"p/smoother": "DICGaussSeidel"},
    "finestSweeps1": {"p/+nFinestSweeps": "1"},
    "PCG": {"p/solver": "PCG", "p/smoother": None,
            "p/+preconditioner": "DIC"},
}

def fv_solution(name):
    """The tutorial's fvSolution with the variant's entries set in the
    first block of their name (pFinal takes p's by $p): "block/key" sets
    an entry the block has, "block/+key" adds one, a value None removes
    one."""
    text = (TUTORIAL / "system" / "fvSolution").read_text()
    for entry, value in (VARIANTS | COST_ONLY)[name].items():
        block, key = entry.rsplit("/", 1)
        m = re.search(r'\n\s*"?' + re.escape(block) + r'"?\s*\n\s*\{', text)
        end = text.index("}", m.end()) if m else 0
        body, n = text[m.end():end] if m else "", 0
        if m and key.startswith("+"):
            # Indented as the block's entries, before its closing brace
            indent = re.search(r"\n([ \t]*)\S", body).group(1)
            body, n = (body.rstrip(" ") + f"{indent}{key[1:]} {value};\n"
                       + indent[:-4]), 1
        elif m:
            body, n = re.subn(rf"(\n\s*{key}\s+)[^;]+;",
                              r"" if value is None else rf"\g<1>{value};",
                              body, count=1)
        if n != 1:
            sys.exit(f"channelSolverSettings: no entry {entry} in "
                     f"{TUTORIAL / 'system' / 'fvSolution'}")
        text = text[:m.end()] + body + text[end:]
    return text


def settings_of(name):
    """The variant's solvers and PIMPLE dictionaries, as parsed."""
    d = foamfile.parse_dict(fv_solution(name))
    return {k: d[k] for k in ("solvers", "PIMPLE")}


def write_fv_solution(case, name):
    (case / "system" / "fvSolution").write_text(fv_solution(name))
