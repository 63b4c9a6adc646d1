"""aggloTools.eventlog names the codes of the collision-event log as the C++
sources do: the categories in the order of encounterMemory::categoryType,
the branches in the order and spelling of collisionOutcome::branchTypeNames
(read from the sources, so that a renamed or added branch fails here), and
doc/eventLog.md documents the same codes."""

import re
from pathlib import Path

import numpy as np
import pytest

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


def _record():
    """One valid record: two 12 um quartz primaries approaching."""
    r = np.zeros(1, eventlog.DTYPE)
    r["d1"] = r["d2"] = 12e-6
    r["rho1"] = r["rho2"] = 2200.0
    r["nPrimary1"] = r["nPrimary2"] = 1
    r["U1"] = (1e-3, 0, 0)
    r["x2"] = (12e-6, 0, 0)
    return r


def _log(path, records):
    head = (f"aggloCollisionEvents 1 recordBytes {eventlog.DTYPE.itemsize}"
            " arch LSB").encode().ljust(eventlog.HEADER_BYTES, b" ")
    path.write_bytes(head + records.tobytes())


@pytest.mark.parametrize("field, value, words", [
    ("agglomerates", 7, "agglomerates 7"),
    ("category", 3, "category 3"),
    ("branch", 7, "branch 7"),
    ("type", 2, "collision type 2"),
    ("timeIndex", -1, "time index -1"),
    ("time", np.inf, "contact time inf"),
    ("d1", np.nan, "partner 1: d nan"),
    ("d2", 1e300, "partner 2: d 1e+300"),
    ("rho1", 1e-300, "partner 1: rho 1e-300"),
    ("nPrimary2", 0, "partner 2: nPrimary 0"),
    ("U1", (1e308, 0, 0), "partner 1: velocity"),
    ("omega2", (0, 0, 2e12), "partner 2: spin"),
    ("x1", (np.nan, 0, 0), "partner 1: position"),
])
def test_corrupt_records_refused(tmp_path, field, value, words):
    """Each value the C++ reader refuses (collisionEventFile.C; the same
    words: tests/unit/cloud/test_eventLog.py replays them) is refused by
    read_file too, naming the file and the record; the valid record and
    the bounds themselves are read."""
    f = tmp_path / "events0.bin"
    ok = np.concatenate([_record()] * 3)
    _log(f, ok)
    assert len(eventlog.read_file(f)) == 3
    edge = _record()
    edge["d1"], edge["rho2"] = eventlog.D_RANGE[1], eventlog.RHO_RANGE[0]
    edge["U2"] = (-eventlog.U_MAX, 0, eventlog.U_MAX)
    edge["branch"] = eventlog.GHOST
    _log(f, edge)
    assert len(eventlog.read_file(f)) == 1
    bad = ok.copy()
    bad[field][2] = value
    _log(f, bad)
    with pytest.raises(ValueError, match=re.escape(words)) as e:
        eventlog.read_file(f)
    assert str(f) in str(e.value) and "record 2" in str(e.value)
