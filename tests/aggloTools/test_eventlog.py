"""aggloTools.eventlog names the codes of the collision-event log as the C++
sources do: the categories in the order of encounterMemory::categoryType,
the branches in the order and spelling of collisionOutcome::branchTypeNames
(read from the sources, so that a renamed or added branch fails here), and
doc/eventLog.md documents the same codes."""

import re
from pathlib import Path

from aggloTools import eventlog

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "src/lagrangian/agglomerationHardSphere"


def _enum(header, name):
    """The enumerators of enum `name` in a C++ header, in order."""
    text = header.read_text()
    body = re.search(r"enum " + name + r"\s*\{(.*?)\}", text, re.S).group(1)
    body = re.sub(r"//[^\n]*", "", body)
    return [e.split("=")[0].strip() for e in body.split(",") if e.strip()]


def test_categories_follow_encounter_memory():
    enum = _enum(SRC / "submodels/HardSphereCollision/encounterMemory"
                 / "encounterMemory.H", "categoryType")
    assert enum == ["FIRST", "REPEAT", "OVERLAP_START"]
    assert len(eventlog.CATEGORIES) == len(enum)
    spelled = [c.replace("_", "").lower() for c in enum]
    assert [c.lower() for c in eventlog.CATEGORIES] == spelled


def test_branches_follow_collision_outcome():
    kernels = SRC / "collisionKernels/collisionOutcome"
    enum = _enum(kernels / "collisionOutcome.H", "branchType")
    names = dict(re.findall(r"\{\s*branchType::(\w+),\s*\"(\w+)\"\s*\}",
                            (kernels / "collisionOutcome.C").read_text()))
    assert list(eventlog.BRANCHES) == [names[e] for e in enum]
    # one name per branch: the C++ counts the branches by the names
    assert len(names) == len(enum)


def test_event_log_doc_lists_the_codes():
    doc = (ROOT / "doc/eventLog.md").read_text()
    row = next(ln for ln in doc.splitlines() if "branch of the run" in ln)
    codes = [int(c) for c in
             re.findall(r"(\d+) [a-zA-Z]", row.split(":", 1)[1])]
    n = len(eventlog.BRANCHES)
    assert codes[:n] == list(range(n))
    assert str(eventlog.GHOST) in row
