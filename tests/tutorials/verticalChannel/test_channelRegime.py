"""channelRegime.py's runner (the regime study's variants, one Allrun
each) and channelRegimeAnalysis's concentration between writes; the
study's post-processing is tested on the smoke runs in
test_verticalChannel.py."""

import threading

import numpy as np
import pytest

from aggloTools.runner import tutorial_module


def channel_regime():
    """channelRegime as a module, after the siblings it imports."""
    for sibling in ("channel", "channelPlots", "channelRegression",
                    "channelPost", "channelRegimeTrend",
                    "channelRegimeAnalysis", "channelRegimeReport",
                    "channelRegime"):
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


def test_concentration_between_writes(tmp_path):
    """concentration_history undoes the running average of profiles.dat:
    a release uniform for its first 10 steps (alpha 1 everywhere), then 20
    steps with the slabs next to the walls at 3 and the rest at 1, written
    as the averages over 10 and 30 steps, give near-wall over centre 1 and
    then 3 (hand values), over T* from the release to each write."""
    import channel
    channel_regime()
    regime = tutorial_module("verticalChannel", "channelRegimeAnalysis")
    p = channel.preset("smoke")
    nb = 16
    later = np.ones(nb)
    later[[0, -1]] = 3.0
    t0 = channel.end_time(p, "unladen")
    writes = ((10, np.ones(nb), t0 + 0.5 * p["tScale"]),
              (30, (10 * np.ones(nb) + 20 * later) / 30,
               t0 + 1.5 * p["tScale"]))
    base = tmp_path / "postProcessing" / "particlesHardSphere"
    for n, alpha, t in writes:
        d = base / f"{t:.12g}"
        d.mkdir(parents=True)
        rows = "\n".join(f"{(i + 0.5) / nb:.6g} {float(a):.17g}"
                         for i, a in enumerate(alpha))
        (d / "profiles.dat").write_text(
            f"# Profiles of cloud particles along (0 1 0), {n} steps "
            f"sampled\n# x alpha\n{rows}\n")
    h = regime.concentration_history(p, tmp_path)
    T0 = t0 / p["tScale"]
    assert [x["T0"] - T0 for x in h] == pytest.approx([0.0, 0.5])
    assert [x["T1"] - T0 for x in h] == pytest.approx([0.5, 1.5])
    assert [x["nearWallOverCentre"] for x in h] == pytest.approx([1, 3])
    # the last write's running average alone: (10 + 20 x 3) / 30 = 7/3
    assert regime.concentration(p, tmp_path)["nearWallOverCentre"] == \
        pytest.approx(7 / 3)
