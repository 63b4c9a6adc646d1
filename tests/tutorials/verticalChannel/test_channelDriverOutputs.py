"""The Python driver of the channel tutorial (channel.case.runs, behind a
thin Allrun) writes the same files as the shell Allrun it replaced (its
last version, commit 6c04c7b): the `smoke` preset with configurations C1
and C2, serially and on 2 ranks, every file of runs/smoke byte for byte
apart from the logs (time stamps, paths), the stage times and the case
paths that the replays and the comparison record; `-post` gives the same
report. Both drivers run in copies of today's tutorial; the old copy
takes its Allrun and channel.py from 6c04c7b (the shell called
subcommands of channel.py that the Python driver replaced by function
calls; its functions are unchanged since), so only the driver differs
(about 2 min). The old copy's presets drop the UTolerance entries its
channel.py does not know (smoke's value is fvSolution's default); its
Allrun's channelPost.py and channelReplay.py are two-line scripts that
run today's channel.post and channel.post.replay."""

import os
import re
import shutil
import subprocess

import pytest

from aggloTools.foamfile import entry_text

from aggloTools.runner import project_dir

TUT = project_dir() / "tutorials" / "verticalChannel"
OLD = "6c04c7b"


def old_file(name):
    """A file of the tutorial at commit OLD (None if the clone lacks
    it)."""
    res = subprocess.run(["git", "show",
                          f"{OLD}:tutorials/verticalChannel/{name}"],
                         cwd=project_dir(), capture_output=True, text=True)
    return res.stdout if res.returncode == 0 else None


def allrun(tut, *args):
    return subprocess.run(["./Allrun", "-preset", "smoke", "-configs",
                           "C1 C2", *args], cwd=tut, capture_output=True,
                          text=True, timeout=1200,
                          env=dict(os.environ, PWD=str(tut)))


def files(root):
    """Those that must be equal: all but logs and stage times."""
    return sorted(p.relative_to(root) for p in root.rglob("*")
                  if p.is_file() and not p.name.startswith("log.")
                  and not p.name.startswith("done."))


#: What the old driver's cases lack: the break-up entry of caseSettings
#: and its merge into the clouds' subModels
BREAKUP_SETTINGS = re.compile(rb"\n// Break-up \(the preset.*?\n\}\n", re.S)


def text_without(path, tut):
    """The file with the tutorial's path replaced, and a caseSettings
    without the UTolerance line and the break-up entry the old channel.py
    did not write (cloudCommon without the entry's merge)."""
    data = path.read_bytes().replace(str(tut).encode(), b"TUT")
    if path.name == "caseSettings":
        data = b"".join(ln for ln in data.splitlines(keepends=True)
                        if not ln.startswith(b"UTolerance"))
        # the command named in its head: channel.py then, the package now
        data = data.replace(b"//     channel.py settings",
                            b"//     python -m channel.case settings")
        data = BREAKUP_SETTINGS.sub(b"", data)
    if path.name == "cloudCommon":
        data = b"".join(ln for ln in data.splitlines(keepends=True)
                        if b"$breakup;" not in ln)
    return data


@pytest.mark.legacy
@pytest.mark.parametrize("np_", ["1", "2"])
def test_python_driver_writes_what_the_shell_driver_wrote(tmp_path,
                                                          foam_env, np_):
    old = {n: old_file(n) for n in ("Allrun", "channel.py")}
    if None in old.values():
        pytest.skip(f"n/r: commit {OLD} is not in this clone (shallow)")
    tuts = {}
    for name in ("old", "new"):
        t = tmp_path / name / "verticalChannel"
        shutil.copytree(TUT, t, ignore=shutil.ignore_patterns(
            "runs", "__pycache__"))
        tuts[name] = t
    for n, text in old.items():
        (tuts["old"] / n).write_text(text)
    # The old Allrun's post-processing calls scripts that are now the
    # package's modules: the same code, reached by their old names, with
    # today's presets while they run (the package reads them; the old
    # channel.py reads the shortened ones below)
    shutil.copy(tuts["old"] / "presets", tuts["old"] / "presets.today")
    for n, module in (("channelPost.py", "channel.post"),
                      ("channelReplay.py", "channel.post.replay")):
        (tuts["old"] / n).write_text(
            "import runpy, shutil\n"
            "shutil.copy('presets', 'presets.old')\n"
            "shutil.copy('presets.today', 'presets')\n"
            "try:\n"
            f"    runpy.run_module({module!r}, run_name='__main__', "
            "alter_sys=True)\n"
            "finally:\n"
            "    shutil.copy('presets.old', 'presets')\n")
    # nor the break-up entry that cloudCommon merges
    common = tuts["old"] / "constant" / "cloudCommon"
    common.write_bytes(text_without(common, tuts["old"]))
    # The old channel.py checks every preset of the file and knows none
    # of the entries added since (UTolerance, breakup, models,
    # stagesFrom, perConfiguration): its presets file holds the sections
    # it runs (common, smoke, configurations) without the UTolerance and
    # breakup lines (smoke's UTolerance is the common 1e-6, fvSolution's
    # default for a caseSettings without it; its break-up none)
    presets = tuts["old"] / "presets"
    text = presets.read_text()
    kept = text[:text.index("FoamFile")]
    for name in ("FoamFile", "common", "smoke", "configurations"):
        lines = [ln for ln in entry_text(text, name).splitlines()
                 if not ln.strip().startswith(("UTolerance", "breakup"))]
        kept += name + "\n{\n" + "\n".join(lines) + "\n}\n\n"
    presets.write_text(kept)
    for t in tuts.values():
        res = allrun(t, "-np", np_)
        assert res.returncode == 0, res.stdout[-2000:] + res.stderr
    roots = {k: t / "runs" / "smoke" for k, t in tuts.items()}
    names = files(roots["old"])
    assert names == files(roots["new"])
    assert len(names) > 500
    for r in roots.values():                    # every stage ran
        assert (r / "C2" / "agglomeration-MAM" / "done.agglomeration") \
            .is_file()
    for n in names:
        assert text_without(roots["old"] / n, tuts["old"]) == \
            text_without(roots["new"] / n, tuts["new"]), n

    for t in tuts.values():
        res = allrun(t, "-post")
        assert res.returncode == 0, res.stdout[-2000:] + res.stderr
    for f in ("regression.txt", "summary.json", "replay.txt"):
        assert text_without(roots["old"] / "report" / f, tuts["old"]) == \
            text_without(roots["new"] / "report" / f, tuts["new"]), f
