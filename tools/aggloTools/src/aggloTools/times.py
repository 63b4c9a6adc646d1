"""Time folders of a case: listed in time order, and a last write that
was cut off (kill -9, a full disk) set aside before a restart."""

import shutil
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
    was killed leaves it truncated); compressed files are not checked."""
    if path.suffix == ".gz":
        return True
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


def _record_count(path):
    """nParticles of a cloud record (this rank's particles)."""
    for line in path.read_text().splitlines():
        words = line.replace(";", " ").split()
        if words[:1] == ["nParticles"]:
            return int(words[1])
    return None


def _clouds_incomplete(folder):
    """True if a cloud's files of a written time disagree with its record:
    the record missing beside the parcel's own fields, or present with a
    particle field missing."""
    lag, uni = folder / "lagrangian", folder / "uniform" / "lagrangian"
    names = {p.name for d in (lag, uni) if d.is_dir() for p in d.iterdir()
             if p.is_dir()}
    for name in names:
        rec = uni / name / CLOUD_RECORD
        have = ({f.name for f in (lag / name).iterdir()}
                if (lag / name).is_dir() else set())
        if not rec.is_file():
            # the parcel's fields without the cloud's uniform folder: lost
            # (a version without the record keeps the folder)
            if have & OWN_FIELDS and not (uni / name).is_dir():
                return True
            continue
        n = _record_count(rec)
        if n and not ({"coordinates", "positions"} & have
                      and OWN_FIELDS <= have):
            return True
    return False


def incomplete_time(case):
    """The latest time folder of a case (or of one processor folder) if
    its write was cut off, else None: a file without its end divider, no
    uniform/time, a cloud's files that disagree with its record, or a
    file of the previous write missing. The first folder (the start) is
    never judged."""
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
    if len(times) > 2 and not _files(previous) <= _files(last):
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
