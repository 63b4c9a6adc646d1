"""channelRegime.py's runner (the regime study's variants, one Allrun
each); its post-processing is tested on the smoke runs in
test_verticalChannel.py."""

import threading

import pytest

from aggloTools.runner import tutorial_module


def channel_regime():
    """channelRegime as a module, after the siblings it imports."""
    for sibling in ("channel", "channelPlots", "channelRegression",
                    "channelPost", "channelRegime"):
        module = tutorial_module("verticalChannel", sibling)
    return module


def test_regime_study_runs_side_by_side(monkeypatch, tmp_path):
    """channelRegime.py run -j 2: two variants' Allruns at once (each waits
    for the other at a barrier: run one after the other, the barrier
    breaks), each with the ranks asked for and its output in its own
    log; the exit status is the first failed variant's, in the order
    given, and 0 when all finish."""
    regime = channel_regime()
    monkeypatch.setattr(regime, "HERE", tmp_path)
    meet = threading.Barrier(2, timeout=10)
    calls = []

    def fake_call(cmd, cwd, stdout=None, stderr=None):
        calls.append(cmd)
        meet.wait()
        stdout.write(f"ran {cmd[2]}\n")
        return {"regime32": 0, "regime48": 3, "regime64": 5}[cmd[2]]

    monkeypatch.setattr(regime.subprocess, "call", fake_call)
    assert regime.main(["channelRegime.py", "run", "-np", "1", "-j", "2",
                        "regime32", "regime48"]) == 3
    assert sorted(c[2] for c in calls) == ["regime32", "regime48"]
    assert all(c[3:] == ["-np", "1"] for c in calls)
    for n in ("regime32", "regime48"):
        assert (tmp_path / "runs" / f"{n}.log").read_text() == f"ran {n}\n"
    assert regime.main(["channelRegime.py", "run", "-j", "2", "regime64",
                        "regime48"]) == 5
    meet.reset()
    assert regime.main(["channelRegime.py", "run", "-j", "2", "regime32",
                        "regime32"]) == 0
    with pytest.raises(SystemExit):
        regime.main(["channelRegime.py", "run", "-j", "0", "regime32"])
