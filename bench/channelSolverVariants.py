"""The variants of the channel's solver settings that
bench/channelSolverSettings.py runs: the tutorial's system/fvSolution
or system/fvSchemes with one setting changed (or GAMG's other knobs, only
timed), written into a case and recorded."""

import re
import sys

from aggloTools import foamfile
from aggloTools.runner import project_dir

TUTORIAL = project_dir() / "tutorials" / "verticalChannel"

#: One setting of the tutorial's system/fvSolution changed per variant
#: ("block/key": value; "fvSchemes:block/key" for system/fvSchemes;
#: null: the start flow rounded instead)
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
    # The mesh is orthogonal: the explicit non-orthogonal corrections of
    # the Laplacians and surface-normal gradients are round-off, but each
    # costs a gradient, its interpolation to the faces and a divergence
    "uncorrected": {
        "fvSchemes:laplacianSchemes/default": "Gauss linear uncorrected",
        "fvSchemes:snGradSchemes/default": "uncorrected"},
}

#: Variants only timed (--cost-only): GAMG's other knobs and PCG
COST_ONLY = {
    "coarsest100": {"p/+nCellsInCoarsestLevel": "100"},
    "DICGaussSeidel": {"p/smoother": "DICGaussSeidel"},
    "finestSweeps1": {"p/+nFinestSweeps": "1"},
    "PCG": {"p/solver": "PCG", "p/smoother": None,
            "p/+preconditioner": "DIC"},
}

def system_file(name, fname="fvSolution"):
    """The tutorial's system/<fname> with the variant's entries of that
    file set in the first block of their name (pFinal takes p's by $p):
    "block/key" sets an entry the block has, "block/+key" adds one, a
    value None removes one; an entry "fvSchemes:block/key" belongs to
    fvSchemes, any other to fvSolution."""
    path = TUTORIAL / "system" / fname
    text = path.read_text()
    for entry, value in (VARIANTS | COST_ONLY)[name].items():
        efile, _, entry = entry.rpartition(":")
        if (efile or "fvSolution") != fname:
            continue
        block, key = entry.rsplit("/", 1)
        # A block on lines of its own or on one line ("name { ... }")
        m = re.search(r'\n\s*"?' + re.escape(block) + r'"?\s*\{', text)
        end = text.index("}", m.end()) if m else 0
        body, n = text[m.end():end] if m else "", 0
        if m and key.startswith("+"):
            # Indented as the block's entries, before its closing brace
            indent = re.search(r"\n([ \t]*)\S", body).group(1)
            body, n = (body.rstrip(" ") + f"{indent}{key[1:]} {value};\n"
                       + indent[:-4]), 1
        elif m:
            body, n = re.subn(rf"(\s*(?<!\S){re.escape(key)}\s+)[^;]+;",
                              r"" if value is None else rf"\g<1>{value};",
                              body, count=1)
        if n != 1:
            sys.exit(f"channelSolverSettings: no entry {entry} in {path}")
        text = text[:m.end()] + body + text[end:]
    return text


def fv_solution(name):
    return system_file(name, "fvSolution")


def settings_of(name):
    """The variant's solvers and PIMPLE dictionaries, as parsed, and its
    entries of fvSchemes as set (where it has any)."""
    d = foamfile.parse_dict(fv_solution(name))
    schemes = {k.split(":", 1)[1]: v for k, v in
               (VARIANTS | COST_ONLY)[name].items()
               if k.startswith("fvSchemes:")}
    return {k: d[k] for k in ("solvers", "PIMPLE")} | (
        {"fvSchemes": schemes} if schemes else {})


def write_settings(case, name):
    """The variant's system/fvSolution and system/fvSchemes in case."""
    for fname in ("fvSolution", "fvSchemes"):
        (case / "system" / fname).write_text(system_file(name, fname))
