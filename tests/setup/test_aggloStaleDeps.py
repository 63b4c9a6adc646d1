"""bin/aggloStaleDeps: a dependency file that names a header no longer
there (renamed by an update of the sources) is removed, so that an
incremental build does not stop with "No rule to make target"; one whose
files all exist, and OpenFOAM's own $(...) paths, are left alone."""

import os
import subprocess

from aggloTools.runner import project_dir

ROOT = project_dir()


def dep(path, files):
    path.parent.mkdir(parents=True, exist_ok=True)
    lines = ["$(OBJECTS_DIR)/a.C.dep: \\"] + [f"{f} \\" for f in files]
    path.write_text("\n".join(lines) + "\n\n")


def test_stale_dependency_files_removed(tmp_path, foam_env):
    lib = tmp_path / "lib"
    (lib / "lnInclude").mkdir(parents=True)
    for f in ("a.C", "b.C", "lnInclude/kept.H"):
        (lib / f).write_text("")
    objs = lib / "Make" / os.environ["WM_OPTIONS"]
    stale, fresh = objs / "sub/a.C.dep", objs / "b.C.dep"
    dep(stale, ["a.C", "lnInclude/kept.H", "lnInclude/renamed.H",
                "$(WM_PROJECT_DIR)/src/OpenFOAM/lnInclude/none.H"])
    dep(fresh, ["b.C", "lnInclude/kept.H",
                "$(WM_PROJECT_DIR)/src/OpenFOAM/lnInclude/none.H"])
    res = subprocess.run([str(ROOT / "bin/aggloStaleDeps"), str(lib)],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    assert not stale.exists() and fresh.exists()
    assert "removed 1 dependency file(s)" in res.stdout
    # nothing left to remove: silent
    res = subprocess.run([str(ROOT / "bin/aggloStaleDeps"), str(lib)],
                         capture_output=True, text=True)
    assert res.returncode == 0 and res.stdout == "" and fresh.exists()
