"""Time folders of a case: listed in time order, and a last write that
was cut off (kill -9, a full disk) set aside before a restart."""

import gzip
import shutil
import zlib
from pathlib import Path


def time_dirs(case):
    """The time folders of a case (float-sortable names), ascending."""
    out = []
    for p in Path(case).iterdir():
        try:
            out.append((float(p.name), p))
        except ValueError:
            pass
    return [p for _, p in sorted(out)]


def _complete_file(path):
    """True if an OpenFOAM file ends with its end divider (a write that
    was killed leaves it truncated); a compressed file (writeCompression
    on) is read whole: a cut-off gzip stream is incomplete too."""
    if path.suffix == ".gz":
        try:
            with gzip.open(path, "rb") as f:
                tail = f.read()[-200:].rstrip()
        except (EOFError, OSError, zlib.error):
            return False
    else:
        with open(path, "rb") as f:
            f.seek(0, 2)
            f.seek(max(0, f.tell() - 200))
            tail = f.read().rstrip()
    return tail.endswith(b"//") and b"// ****" in tail


def _files(folder):
    return {p.relative_to(folder) for p in folder.rglob("*") if p.is_file()}


#: The record a hard-sphere cloud writes after its particles
#: (clouds/hardSphereCloudState) and the parcel fields it requires
CLOUD_RECORD = "hardSphereCloudState"
OWN_FIELDS = {"omega", "nPrimary", "lastPartnerProc", "lastPartnerId",
              "lastContactTime"}


def _record(path):
    """The entries of a cloud record that the checks read: nParticles
    (this rank's particles), complete, clouds (the clouds of the case)."""
    text = path.read_text()
    rec = {"nParticles": None, "complete": True, "clouds": []}
    for line in text.splitlines():
        words = line.replace(";", " ").split()
        if words[:1] == ["nParticles"]:
            rec["nParticles"] = int(words[1])
        elif words[:1] == ["complete"]:
            rec["complete"] = words[1] in ("true", "on", "yes", "1")
    start = text.find("clouds")
    if start >= 0 and "(" in text[start:]:
        inner = text[start:].split("(", 1)[1].split(")", 1)[0]
        rec["clouds"] = inner.split()
    return rec


def _clouds_incomplete(folder):
    """True if a cloud's files of a written time disagree with its record
    (clouds/hardSphereCloudState, the same rules as the solver's): the
    record says the write began only; the record missing beside the
    parcel's own fields, or where the record of another cloud names the
    cloud; present with a particle field missing."""
    lag, uni = folder / "lagrangian", folder / "uniform" / "lagrangian"
    names = {p.name for d in (lag, uni) if d.is_dir() for p in d.iterdir()
             if p.is_dir()}
    records = {n: _record(uni / n / CLOUD_RECORD) for n in names
               if (uni / n / CLOUD_RECORD).is_file()}
    named = {c for r in records.values() for c in r["clouds"]}
    for name in names | named:
        rec = records.get(name)
        have = ({f.name for f in (lag / name).iterdir()}
                if (lag / name).is_dir() else set())
        if rec is None:
            if have & OWN_FIELDS or name in named:
                return True
            continue
        if not rec["complete"]:
            return True
        n = rec["nParticles"]
        if n and not ({"coordinates", "positions"} & have
                      and OWN_FIELDS <= have):
            return True
    return False


def _empty_clouds(folder):
    """The clouds whose record at this time says this rank holds no
    particles (their particle files are not written)."""
    uni = folder / "uniform" / "lagrangian"
    if not uni.is_dir():
        return set()
    return {d.name for d in uni.iterdir()
            if (d / CLOUD_RECORD).is_file()
            and _record(d / CLOUD_RECORD)["nParticles"] == 0}


def _expected_files(previous, last):
    """The files of the previous write that the last one must have too:
    all but the particle files of a cloud that has none on this rank at
    the last write (a legitimate write of 0 particles writes none)."""
    empty = _empty_clouds(last)
    return {f for f in _files(previous)
            if not (len(f.parts) > 2 and f.parts[0] == "lagrangian"
                    and f.parts[1] in empty)}


#: Fields that utilities add to a start time and a solver never writes
#: (postProcess -func writeCellCentres, writeCellVolumes)
CELL_GEOMETRY = {"C", "Cx", "Cy", "Cz", "V"}


def _name(f):
    return f.name[:-3] if f.name.endswith(".gz") else f.name


def _start_fields(start):
    """The fields of a start time that the first write of a run must have
    too: its field files but the cell geometry and the fields of a cloud
    (`<cloud>:<field>`: the cloud of the next stage may have another
    name, and a cloud writes them only where it is coupled)."""
    return {_name(f) for f in start.iterdir() if f.is_file()
            and _name(f) not in CELL_GEOMETRY and ":" not in f.name}


def incomplete_time(case):
    """The latest time folder of a case (or of one processor folder) if
    its write was cut off, else None: a file without its end divider, no
    uniform/time, a cloud's files that disagree with its record, a file
    of the previous write missing or, at the first write of a run (the
    previous folder is the start), a field of the start missing. The
    first folder (the start) is never judged."""
    times = time_dirs(case)
    if len(times) < 2:
        return None
    last, previous = times[-1], times[-2]
    if not (last / "uniform" / "time").is_file():
        return last
    if any(not _complete_file(f) for f in last.rglob("*") if f.is_file()):
        return last
    if _clouds_incomplete(last):
        return last
    if len(times) > 2 and not _expected_files(previous, last) \
            <= _files(last):
        return last
    if len(times) == 2 and not _start_fields(previous) <= {
            _name(f) for f in last.iterdir() if f.is_file()}:
        return last
    return None


def set_aside_incomplete_times(case):
    """Before a restart from the latest time: move a time folder whose
    write was cut off (kill -9, a full disk) to incomplete.<time>, in the
    case and in every processor folder, and say so; OpenFOAM would stop
    reading it. Returns the folders set aside."""
    case = Path(case)
    roots = [case] + sorted(case.glob("processor*"))
    # a time cut off on one processor is set aside on all of them
    bad = {t.name for t in map(incomplete_time, roots) if t is not None}
    moved = []
    for name in sorted(bad):
        for root in roots:
            folder = root / name
            if folder.is_dir():
                target = root / f"incomplete.{name}"
                if target.exists():
                    shutil.rmtree(target)
                folder.rename(target)
                moved.append(target)
        print(f"{case}: the write of time {name} was cut off; set aside as "
              f"incomplete.{name}, continuing from the previous write")
    return moved



def last_time(case):
    """The name of the latest time folder of a case."""
    return time_dirs(case)[-1].name
