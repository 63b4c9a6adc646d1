"""aggloTools.runner's script modules: a tutorial's or benchmark's script
imported as a module brings the scripts of its folder that it imports
(found in its source, at any depth: no list of siblings to keep, no
search-path edit), each once; a script whose import is not a sibling
(the package, the standard library) brings nothing else; a module of a
tutorial's package is imported by its dotted name, its package found in
the tutorial's folder."""

import os
import subprocess
import sys

import pytest

from aggloTools import runner


def write(folder, name, text):
    f = folder / f"{name}.py"
    f.write_text(text)
    return f


def test_siblings_loaded_in_their_order(tmp_path):
    write(tmp_path, "zzTop", "import zzMiddle\nVALUE = zzMiddle.VALUE + 1\n")
    write(tmp_path, "zzMiddle", "from zzBottom import VALUE as V\n"
          "VALUE = V + 1\n\ndef later():\n    import zzLazy\n"
          "    return zzLazy.VALUE\n")
    write(tmp_path, "zzBottom", "import math\nVALUE = 1\n")
    write(tmp_path, "zzLazy", "VALUE = 7\n")
    write(tmp_path, "zzUnused", "raise RuntimeError('not imported')\n")
    try:
        top = runner._script_module(tmp_path / "zzTop.py", "zzTop")
        assert top.VALUE == 3
        assert sys.modules["zzMiddle"].later() == 7
        assert sys.modules["zzLazy"].__file__ == str(tmp_path / "zzLazy.py")
        assert "zzUnused" not in sys.modules
        again = runner._script_module(tmp_path / "zzTop.py", "zzTop")
        assert again is top
        assert [p.name for p in runner._siblings(tmp_path / "zzMiddle.py")] \
            == ["zzBottom.py", "zzLazy.py"]
        assert runner._siblings(tmp_path / "zzBottom.py") == []
    finally:
        for n in ("zzTop", "zzMiddle", "zzBottom", "zzLazy"):
            sys.modules.pop(n, None)


def test_a_tutorial_package_module_without_a_module_list():
    """channel.post.report imports channel.case.settings,
    channel.post.contacts, ...: loaded on its own, in a fresh interpreter,
    it finds them in the tutorial's package (the tests kept a hand-ordered
    list of 17 modules before); the package is the tutorial's folder's."""
    code = ("from aggloTools import runner; import sys; "
            "m = runner.tutorial_module('verticalChannel', "
            "'channel.post.report'); "
            "print(m.__name__, m.settings.__name__, "
            "sys.modules['channel'].__file__)")
    res = subprocess.run([sys.executable, "-c", code], capture_output=True,
                         text=True)
    assert res.returncode == 0, res.stderr
    init = runner.project_dir() / "tutorials" / "verticalChannel" / \
        "channel" / "__init__.py"
    assert res.stdout.split() == ["channel.post.report",
                                  "channel.case.settings", str(init)]


def test_a_folder_without_init_is_not_a_package(tmp_path):
    """A dotted name whose first part is no package folder is refused by
    name (not imported from elsewhere on the search path)."""
    (tmp_path / "zzPlain").mkdir()
    with pytest.raises(ImportError, match=r"zzPlain: not a package \(no "
                       r"__init__\.py\)"):
        runner._package(tmp_path / "zzPlain")
    assert "zzPlain" not in sys.modules


def test_package_command_runs_a_package_module_from_any_folder(tmp_path,
                                                               monkeypatch):
    """runner.package_command: python -m of a tutorial's package module
    run in another folder (a case) finds the package: its folder goes
    first on PYTHONPATH, once, before what was there."""
    tut = tmp_path / "tut"
    (tut / "zzPkg").mkdir(parents=True)
    (tut / "zzPkg" / "__init__.py").write_text("")
    (tut / "zzPkg" / "hello.py").write_text(
        "import sys\nprint('hello', *sys.argv[1:])\n")
    case = tmp_path / "case"
    case.mkdir()
    monkeypatch.setenv("PYTHONPATH", "/elsewhere")
    cmd = runner.package_command(tut, "zzPkg.hello", "a", 1)
    runner.package_command(tut, "zzPkg.hello")
    assert os.environ["PYTHONPATH"].split(os.pathsep) == [str(tut),
                                                          "/elsewhere"]
    assert cmd[1:] == ["-m", "zzPkg.hello", "a", "1"]
    res = subprocess.run(cmd, cwd=case, capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    assert res.stdout.split() == ["hello", "a", "1"]
    monkeypatch.delenv("PYTHONPATH")
    res = subprocess.run(cmd, cwd=case, capture_output=True, text=True)
    assert res.returncode != 0 and "No module named 'zzPkg'" in res.stderr
