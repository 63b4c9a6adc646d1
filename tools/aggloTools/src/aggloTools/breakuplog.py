"""The break-up event log of a run (stressThresholdCoeffs: eventLog true;
doc/eventLog.md): its records read into numpy, and replays through
variants of the break-up coefficients with the breakupReplay utility.

    ev = read_breakup_events(case)              # structured array
    res = replay_breakups(case, {"weaker": {"strength":
                                            {"rumpfPrefactor": 1.0}}})
"""

from pathlib import Path

import numpy as np

from .eventlog import HEADER_BYTES, body_records, run_replay
from .runner import foam_bin

_STATE = [("x", "<f8", 3), ("U", "<f8", 3), ("omega", "<f8", 3),
          ("d", "<f8"), ("rho", "<f8")]


def _state(k):
    return [(f"{n}_{k}",) + tuple(t) for n, *t in _STATE]


#: One record (breakupEvent.H), little-endian; the states are the
#: parent's (_p) and the fragments' (_a: the new parcel, _b: the parent's
#: parcel)
DTYPE = np.dtype(
    [("timeIndex", "<i4"), ("mechanism", "<i4"), ("proc", "<i4"),
     ("id", "<i4"), ("newProc", "<i4"), ("newId", "<i4"),
     ("nPrimary_p", "<i4"), ("nPrimary_a", "<i4"), ("nPrimary_b", "<i4"),
     ("pad", "<i4"), ("dt", "<f8")]
    + _state("p")
    + [("epsilon", "<f8"), ("nu", "<f8"), ("rhoF", "<f8"),
       ("dragForce", "<f8", 3), ("wallImpactSpeed", "<f8"),
       ("S", "<f8", 6), ("ratio", "<f8")]
    + _state("a") + _state("b"))


def folder(case, cloud="kinematicCloud"):
    return Path(case) / "postProcessing" / f"{cloud}BreakupEvents"


def read_file(path):
    """The records of one events<rank>.bin file of a break-up log and
    the mechanisms its header names (ValueError if it is not a log of
    this layout or ends in a partial record; breakupReplay checks every
    value of every record)."""
    data = Path(path).read_bytes()
    head = data[:HEADER_BYTES].decode(errors="replace")
    want = (f"aggloBreakupEvents 1 recordBytes {DTYPE.itemsize} arch LSB;"
            "label=32;scalar=64 mechanisms ")
    if not head.startswith(want) or not head[len(want):].split():
        raise ValueError(f"{path}: not a break-up event file of this"
                         f" layout (header {head.strip()!r})")
    mechanisms = tuple(head[len(want):].split()[0].split(","))
    records = body_records(path, data, DTYPE)
    bad = (records["mechanism"] < 0) | \
        (records["mechanism"] >= len(mechanisms))
    if bad.any():
        k = int(np.argmax(bad))
        raise ValueError(f"{path}: record {k}: mechanism "
                         f"{records['mechanism'][k]} (valid: 0-"
                         f"{len(mechanisms) - 1}); the file is corrupt")
    return records, mechanisms


def read_breakup_events(case, cloud="kinematicCloud"):
    """All break-ups of the case's log, in the order (time index, parent
    id) in which breakupReplay takes them."""
    files = sorted(folder(case, cloud).glob("events*.bin"))
    if not files:
        raise FileNotFoundError(f"no break-up event log in "
                                f"{folder(case, cloud)}")
    ev = np.concatenate([read_file(f)[0] for f in files])
    return ev[np.lexsort((ev["id"], ev["proc"], ev["timeIndex"]))]


def replay_breakups(case, variants=None, cloud="kinematicCloud",
                    check=False, out=None):
    """Run breakupReplay on the case: the run's own coefficients and the
    variants (name -> entries merged into stressThresholdCoeffs); returns
    its JSON as a dict. check: the run's kernel must reproduce every
    logged break-up (a failed check raises runner.CommandError)."""
    case = Path(case).resolve()
    out = Path(out or folder(case, cloud) / "breakupReplay.json")
    cmd = [foam_bin("breakupReplay"), "-case", str(case), "-cloud", cloud,
           "-json", str(out)]
    return run_replay(cmd, case, out, variants, check, "log.breakupReplay")
