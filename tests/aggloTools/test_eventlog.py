"""aggloTools.eventlog reads the collision-event log as the C++ writes it:
the categories in the order of encounterMemory::categoryType (read from
the sources, so that a renamed or added category fails here), the branch
names from each file's header (the run's agglomeration model names them),
and every value the C++ reader refuses is refused here too."""

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


def _record():
    """One valid record: two 12 um quartz primaries approaching."""
    r = np.zeros(1, eventlog.DTYPE)
    r["d1"] = r["d2"] = 12e-6
    r["rho1"] = r["rho2"] = 2200.0
    r["nPrimary1"] = r["nPrimary2"] = 1
    r["U1"] = (1e-3, 0, 0)
    r["x2"] = (12e-6, 0, 0)
    return r


EAM = ("eq21", "eq65", "caseI", "caseII")


def _log(path, records, branches=EAM):
    head = (f"aggloCollisionEvents 2 recordBytes {eventlog.DTYPE.itemsize}"
            " arch LSB;label=32;scalar=64 branches " + ",".join(branches))
    head = head.encode().ljust(eventlog.HEADER_BYTES - 1, b" ") + b"\n"
    path.write_bytes(head + records.tobytes())


def test_header_names_the_branches(tmp_path):
    """The branch codes of a file index the names of its header: a code
    of the header's range is read, the next one is refused in the C++
    reader's words; a case whose files name different branches (two
    models in one folder) is refused; an older layout is refused."""
    f = tmp_path / "postProcessing/kinematicCloudCollisionEvents"
    f.mkdir(parents=True)
    r = _record()
    r["branch"] = 3
    _log(f / "events0.bin", r)
    assert eventlog.read_header(f / "events0.bin") == EAM
    assert len(eventlog.read_file(f / "events0.bin")) == 1
    assert eventlog.branches(tmp_path) == EAM
    r["branch"] = 4
    _log(f / "events0.bin", r)
    with pytest.raises(ValueError, match=re.escape(
            "record 0: branch 4 (valid: 0-3, 255 ghost)")):
        eventlog.read_file(f / "events0.bin")
    r["branch"] = 1
    _log(f / "events0.bin", r)
    _log(f / "events1.bin", r, ("rebound", "agglomerate"))
    assert len(eventlog.read_file(f / "events1.bin")) == 1
    with pytest.raises(ValueError, match="different branches"):
        eventlog.branches(tmp_path)
    with pytest.raises(ValueError, match="different branches"):
        eventlog.read_events(tmp_path)
    old = ("aggloCollisionEvents 1 recordBytes 220 arch LSB;label=32;"
           "scalar=64").encode().ljust(eventlog.HEADER_BYTES, b" ")
    (f / "events1.bin").write_bytes(old + r.tobytes())
    with pytest.raises(ValueError, match="not a collision event file"):
        eventlog.read_file(f / "events1.bin")


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


def test_alpha_plot_takes_intervals_as_written(tmp_path):
    """hardSphereReplay writes alpha and its interval with 10 digits: an
    interval end may pass alpha by a round-off (alpha 0, low 1e-17); the
    plot draws it (it stopped the channel's replay once) and refuses
    nothing else."""
    ens = (0.97, 0.8)
    confs = [{"name": f"{m}{round(100 * e):03d}", "alpha": a,
              "alphaLow": lo, "alphaHigh": hi}
             for m, (a, lo, hi) in (("EAM", (0.0, 1e-17, 0.05)),
                                    ("MAM", (0.1, 0.05, 0.2)))
             for e in ens]
    png = tmp_path / "alpha.png"
    eventlog.plot_alpha_en({"configurations": confs}, png, "t", ens)
    assert png.stat().st_size > 1000

