"""aggloTools.times judges a written time as the solver's restart record
check does (clouds/hardSphereCloudState): a legitimate write is kept, a
cut-off one is set aside. The folders are written here file by file, as a
processor folder of a 2-rank run leaves them."""

from aggloTools import times
from aggloTools.foamfile import HEADER, edit

END = "\n\n// " + "*" * 73 + " //\n"


def _file(path, obj, body=""):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls="dictionary", loc="x", obj=obj)
                    + body + END)


def _write(root, t, clouds, n, complete=True, files=True):
    """A written time of root: the fluid, uniform/time and, per cloud of
    clouds, its record (n particles on this rank) and, if n and files,
    its particle files."""
    d = root / t
    _file(d / "U", "U")
    _file(d / "uniform" / "time", "time")
    for c in clouds:
        body = (f"complete {'true' if complete else 'false'};\n"
                f"clouds {len(clouds)} ( {' '.join(clouds)} );\n")
        if complete:
            body += f"nParticles {n};\n"
        _file(d / "uniform" / "lagrangian" / c / times.CLOUD_RECORD,
              times.CLOUD_RECORD, body)
        if n and files:
            for f in sorted(times.OWN_FIELDS) + ["coordinates", "d"]:
                _file(d / "lagrangian" / c / f, f)


def test_processor_left_without_particles_is_complete(tmp_path):
    """processor1 held particles at 0.002 and none at 0.004 (they moved
    to processor0): its 0.004 has no particle files, legitimately."""
    p1 = tmp_path / "processor1"
    _write(p1, "0", ["EAM"], 3)
    _write(p1, "0.002", ["EAM"], 3)
    _write(p1, "0.004", ["EAM"], 0)
    assert times.incomplete_time(p1) is None
    assert times.set_aside_incomplete_times(tmp_path) == []


def test_particle_files_missing_where_the_record_counts_some(tmp_path):
    _write(tmp_path, "0", ["EAM"], 3)
    _write(tmp_path, "0.002", ["EAM"], 3)
    _write(tmp_path, "0.004", ["EAM"], 3, files=False)
    assert times.incomplete_time(tmp_path) == tmp_path / "0.004"


def test_write_that_began_only(tmp_path):
    """The record that a cloud writes when the step that writes begins
    (complete false): the write was cut off."""
    _write(tmp_path, "0", ["EAM", "MAM"], 3)
    _write(tmp_path, "0.002", ["EAM", "MAM"], 3)
    _write(tmp_path, "0.004", ["EAM", "MAM"], 3)
    assert times.incomplete_time(tmp_path) is None
    rec = tmp_path / "0.004/uniform/lagrangian/MAM" / times.CLOUD_RECORD
    edit(rec, "complete true", "complete false")
    assert times.incomplete_time(tmp_path) == tmp_path / "0.004"


def test_cloud_named_by_another_record_missing(tmp_path):
    """The second cloud's record and files missing: the first cloud's
    record names it."""
    import shutil
    _write(tmp_path, "0", ["EAM", "MAM"], 3)
    _write(tmp_path, "0.002", ["EAM", "MAM"], 3)
    _write(tmp_path, "0.004", ["EAM", "MAM"], 3)
    for d in ("lagrangian/MAM", "uniform/lagrangian/MAM"):
        shutil.rmtree(tmp_path / "0.004" / d)
    # the previous write's files are required too: drop that rule's say
    for d in ("lagrangian/MAM", "uniform/lagrangian/MAM"):
        shutil.rmtree(tmp_path / "0.002" / d)
    assert times.incomplete_time(tmp_path) == tmp_path / "0.004"


def test_first_write_without_the_fluid_is_cut_off(tmp_path):
    """A kill at the first write of a run: uniform/time and the cloud's
    record written, U and p not. The start has U, p, nut, the cell
    centres of postProcess and a cloud's source field; the first write
    must have U, p and nut (not the others) to be complete."""
    _write(tmp_path, "0", ["EAM"], 3)
    for f in ("p", "nut", "C", "Cx", "particles:UTrans"):
        _file(tmp_path / "0" / f, f)
    _write(tmp_path, "0.002", ["EAM"], 3)
    (tmp_path / "0.002" / "U").unlink()
    assert times.incomplete_time(tmp_path) == tmp_path / "0.002"
    for f in ("U", "p"):
        _file(tmp_path / "0.002" / f, f)
    assert times.incomplete_time(tmp_path) == tmp_path / "0.002"   # nut
    _file(tmp_path / "0.002" / "nut", "nut")
    assert times.incomplete_time(tmp_path) is None
    moved = times.set_aside_incomplete_times(tmp_path)
    assert moved == []


def test_cut_off_compressed_write(tmp_path):
    """writeCompression on: a gzip stream cut off by a kill is an
    incomplete write (compressed files were not checked)."""
    import gzip
    _write(tmp_path, "0", ["EAM"], 3)
    _write(tmp_path, "0.002", ["EAM"], 3)
    _write(tmp_path, "0.004", ["EAM"], 3)
    for t in ("0.002", "0.004"):
        u = tmp_path / t / "U"
        (tmp_path / t / "U.gz").write_bytes(gzip.compress(u.read_bytes()))
        u.unlink()
    assert times.incomplete_time(tmp_path) is None
    gz = tmp_path / "0.004" / "U.gz"
    gz.write_bytes(gz.read_bytes()[:-12])
    assert times.incomplete_time(tmp_path) == tmp_path / "0.004"
