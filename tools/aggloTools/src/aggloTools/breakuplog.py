"""The break-up event log of a run (<model>Coeffs: eventLog true;
doc/eventLog.md), for any model of the break-up family: its records read
into numpy (the model's values under the names its header gives), and
replays through variants of the model's coefficients with the
breakupReplay utility.

    ev = read_breakup_events(case)              # structured array
    res = replay_breakups(case, {"weaker": {"strength":
                                            {"rumpfPrefactor": 1.0}}})
"""

import hashlib
from pathlib import Path

import numpy as np

from .eventlog import body_records, run_replay
from .runner import foam_bin

_STATE = [("x", "<f8", 3), ("U", "<f8", 3), ("omega", "<f8", 3),
          ("d", "<f8"), ("rho", "<f8")]


def _state(k):
    return [(f"{n}_{k}",) + tuple(t) for n, *t in _STATE]


#: Bytes of a break-up log's header (breakupEvent.H)
HEADER_BYTES = 256

#: Slots of the model's values in a record
N_VALUES = 4

#: One record (breakupEvent.H), little-endian; the states are the
#: parent's (_p) and the fragments' (_a: the new parcel, _b: the parent's
#: parcel); "values" holds the model's values, named by the header;
#: "attempt" the try of the direction that placed the fragments (0: the
#: model's first; doc/breakup.md 3.2)
DTYPE = np.dtype(
    [("timeIndex", "<i4"), ("mechanism", "<i4"), ("proc", "<i4"),
     ("id", "<i4"), ("newProc", "<i4"), ("newId", "<i4"),
     ("nPrimary_p", "<i4"), ("nPrimary_a", "<i4"), ("nPrimary_b", "<i4"),
     ("check", "<u4"), ("dt", "<f8")]
    + _state("p")
    + [("epsilon", "<f8"), ("nu", "<f8"), ("rhoF", "<f8"),
       ("dragForce", "<f8", 3), ("wallImpactSpeed", "<f8"),
       ("S", "<f8", 6), ("values", "<f8", N_VALUES)]
    + _state("a") + _state("b")
    + [("attempt", "<i4"), ("padding", "<i4")])

#: The header's keys, in their order
KEYS = ("mechanisms", "model", "fields")

#: The offset of a record's checksum
_CHECK = DTYPE.fields["check"][1]


def checksum(record):
    """The checksum of one record's bytes (breakupEvent::checksum): the
    first 4 bytes of the SHA-1 of all its bytes but the checksum's."""
    b = bytes(record)
    return int(hashlib.sha1(b[:_CHECK] + b[_CHECK + 4:]).hexdigest()[:8],
               16)


def seal(records):
    """Set the checksum of each record (a structured array of DTYPE) to
    its bytes': an edited record that breakupReplay then reads as written
    by a run (for tests of what the replay makes of it)."""
    for r in records:
        r["check"] = checksum(r.tobytes())
    return records


def folder(case, cloud="kinematicCloud"):
    return Path(case) / "postProcessing" / f"{cloud}BreakupEvents"


def read_header(path):
    """The header of an events<rank>.bin file of a break-up log: a dict
    of its lists (mechanisms, model, fields; ValueError if it is not a
    log of this layout)."""
    head = Path(path).read_bytes()[:HEADER_BYTES].decode(errors="replace")
    layout = (f"aggloBreakupEvents 3 recordBytes {DTYPE.itemsize} arch LSB;"
              "label=32;scalar=64 ")
    words = head[len(layout):].split()
    if not head.startswith(layout) or tuple(words[0::2]) != KEYS \
            or len(words) != 2 * len(KEYS):
        raise ValueError(f"{path}: not a break-up event file of this"
                         f" layout (header {head.strip()!r})")
    lists = {k: tuple(v.split(",")) if v != "-" else ()
             for k, v in zip(words[0::2], words[1::2])}
    if len(lists["model"]) != 1 or not lists["mechanisms"] \
            or len(lists["fields"]) > N_VALUES:
        raise ValueError(f"{path}: header {head.strip()!r}: one model, at"
                         f" least one mechanism, at most {N_VALUES} fields")
    return lists


def read_file(path):
    """The records of one events<rank>.bin file of a break-up log and
    its header's lists (ValueError if it is not a log of this layout or
    ends in a partial record; breakupReplay checks every value of every
    record)."""
    header = read_header(path)
    records = body_records(path, Path(path).read_bytes(), DTYPE,
                           HEADER_BYTES)
    n = len(header["mechanisms"])
    bad = (records["mechanism"] < 0) | (records["mechanism"] >= n)
    if bad.any():
        k = int(np.argmax(bad))
        raise ValueError(f"{path}: record {k}: mechanism "
                         f"{records['mechanism'][k]} (valid: 0-"
                         f"{n - 1}); the file is corrupt")
    for k, r in enumerate(records):
        if r["check"] != checksum(r.tobytes()):
            raise ValueError(f"{path}: record {k}: checksum {r['check']}"
                             f" (the record's bytes give "
                             f"{checksum(r.tobytes())}: the record was"
                             " altered); the file is corrupt")
    return records, header


def values(ev, header):
    """The model's values of the records as a dict name -> array."""
    return {name: ev["values"][:, i]
            for i, name in enumerate(header["fields"])}


def header(case, cloud="kinematicCloud"):
    """The lists of the headers of the case's log (ValueError if its
    files name different models, mechanisms or fields)."""
    files = sorted(folder(case, cloud).glob("events*.bin"))
    if not files:
        raise FileNotFoundError(f"no break-up event log in "
                                f"{folder(case, cloud)}")
    heads = [read_header(f) for f in files]
    if any(h != heads[0] for h in heads):
        raise ValueError(f"{folder(case, cloud)}: the files' headers"
                         f" differ: {heads}")
    return heads[0]


def read_breakup_events(case, cloud="kinematicCloud"):
    """All break-ups of the case's log, in the order (time index, parent
    id) in which breakupReplay takes them."""
    header(case, cloud)
    files = sorted(folder(case, cloud).glob("events*.bin"))
    ev = np.concatenate([read_file(f)[0] for f in files])
    return ev[np.lexsort((ev["id"], ev["proc"], ev["timeIndex"]))]


def replay_breakups(case, variants=None, cloud="kinematicCloud",
                    check=False, out=None):
    """Run breakupReplay on the case: the run's own coefficients and the
    variants (name -> entries merged into <model>Coeffs); returns
    its JSON as a dict. check: the run's kernel must reproduce every
    logged break-up (a failed check raises runner.CommandError)."""
    case = Path(case).resolve()
    out = Path(out or folder(case, cloud) / "breakupReplay.json")
    cmd = [foam_bin("breakupReplay"), "-case", str(case), "-cloud", cloud,
           "-json", str(out)]
    return run_replay(cmd, case, out, variants, check, "log.breakupReplay")
