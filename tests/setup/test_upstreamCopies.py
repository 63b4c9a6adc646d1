"""Code copied from OpenFOAM's own source, with changes: the copy names
the upstream function and the SHA-256 of its text, and this test fails
when the installed OpenFOAM source (Debian's v1912 source package, which
bin/aggloSetup unpacks; $AGGLO_FOAM_SRC or $WM_PROJECT_DIR) holds another
text, so that an upgrade cannot change the function the copy follows
silently."""
import hashlib
import os
import re
from pathlib import Path

import pytest

from aggloTools.runner import project_dir

ROOT = project_dir()

#: (our copy, the upstream file under src/, the upstream function)
COPIES = [
    ("src/lagrangian/agglomerationHardSphere/parcels/Templates/"
     "AgglomerateParcel/AgglomerateParcelTracking.C",
     "lagrangian/intermediate/parcels/Templates/KinematicParcel/"
     "KinematicParcel.C",
     "bool Foam::KinematicParcel<ParcelType>::move"),
]


def function_text(text, signature):
    """A function's text from the last template line before its
    signature to its closing brace (braces counted)."""
    i = text.index(signature)
    start = text.rfind("template<", 0, i)
    depth, k = 0, text.index("{", i)
    for k in range(k, len(text)):
        depth += {"{": 1, "}": -1}.get(text[k], 0)
        if depth == 0:
            break
    return text[start:k + 1]


def test_function_text_counts_braces():
    text = ("x\ntemplate<class T>\nbool A<T>::f(int a)\n{\n  if (a) { b(); }"
            "\n  return {};\n}\ntemplate<class T> void g() {}\n")
    assert function_text(text, "bool A<T>::f").endswith(
        "return {};\n}")
    assert function_text(text, "bool A<T>::f").startswith("template<class T>")


@pytest.mark.parametrize("ours, upstream, signature", COPIES,
                         ids=[c[2] for c in COPIES])
def test_upstream_function_unchanged(ours, upstream, signature):
    src = os.environ.get("AGGLO_FOAM_SRC") or os.environ.get(
        "WM_PROJECT_DIR")
    if not src:
        pytest.fail("neither AGGLO_FOAM_SRC nor WM_PROJECT_DIR is set:"
                    " run the tests through ./Alltest")
    path = Path(src) / "src" / upstream
    assert path.is_file(), f"no upstream source {path}"
    digest = hashlib.sha256(function_text(path.read_text(), signature)
                            .encode()).hexdigest()
    recorded = re.findall(r"\b[0-9a-f]{64}\b",
                          (ROOT / ours).read_text())
    assert recorded, f"{ours} names no SHA-256 of {signature}"
    assert digest in recorded, (
        f"{signature} in {path} has changed (SHA-256 {digest}, {ours}"
        f" follows {recorded}): compare the copy with it, then record the"
        " new digest")
