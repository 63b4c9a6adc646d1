"""The tutorials' Allrun scripts refuse a bad option at once: an option
without its value (which looped forever), a count that is not a positive
number (-np 0 ran serially, -np abc gave a traceback, -j 0 busy-looped).
Each call must end within seconds with exit status 1 and a message
naming the option, before anything is run."""

import os
import subprocess

import pytest

from aggloTools.runner import project_dir

TUT = project_dir() / "tutorials"

CASES = [
    ("verticalChannel", ["-preset"], "-preset needs a value"),
    ("verticalChannel", ["-np"], "-np needs a value"),
    ("verticalChannel", ["-np", "-post"], "-np needs a value"),
    ("verticalChannel", ["-np", "0"], "not a positive number"),
    ("verticalChannel", ["-np", "-2"], "-np needs a value"),
    ("verticalChannel", ["-np", "abc"], "not a positive number"),
    ("shearFlowValidation", ["-preset"], "-preset needs a value"),
    ("shearFlowValidation", ["-j", "0"], "not a positive number"),
    ("shearFlowValidation", ["-every", "x"], "not a positive number"),
]


@pytest.mark.parametrize("tutorial, args, words", CASES,
                         ids=[f"{t}{''.join(a)}" for t, a, _ in CASES])
def test_bad_option_stops_at_once(tutorial, args, words, foam_env):
    res = subprocess.run(["./Allrun", *args], cwd=TUT / tutorial,
                         capture_output=True, text=True, timeout=60,
                         env=dict(os.environ, PWD=str(TUT / tutorial)))
    assert res.returncode == 1, res.stdout + res.stderr
    assert words in res.stderr
    assert not (TUT / tutorial / "runs" / "None").exists()
