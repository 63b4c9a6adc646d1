"""aggloTools.runner's script modules: a tutorial's or benchmark's script
imported as a module brings the scripts of its folder that it imports
(found in its source, at any depth: no list of siblings to keep, no
search-path edit), each once; a script whose import is not a sibling
(the package, the standard library) brings nothing else."""

import subprocess
import sys

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


def test_a_tutorial_script_without_its_siblings_loaded_first():
    """channelReport imports channel, channelContacts, ...: loaded on its
    own, in a fresh interpreter, it finds them (the tests kept a
    hand-ordered list of 17 modules before)."""
    code = ("from aggloTools import runner; import sys; "
            "runner.tutorial_module('verticalChannel', 'channelReport'); "
            "print(sys.modules['channel'].__file__)")
    res = subprocess.run([sys.executable, "-c", code], capture_output=True,
                         text=True)
    assert res.returncode == 0, res.stderr
    assert res.stdout.strip() == str(
        runner.project_dir() / "tutorials" / "verticalChannel" / "channel.py")
