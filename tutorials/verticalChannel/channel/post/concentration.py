"""verticalChannel: the particles' concentration across the channel over
the release and dispersion stages, from the profiles.dat of each write
(each the average over all steps since the release) and the cloud's
stats.dat: the profile between two writes, the near-wall over centre
volume fraction c_w/c_0, its growth per interval with the collision and
wall-impact rates (the regime study, channel.post.dispersion, the
near-wall statements of channel.post.nearWall), and the concentration the
agglomeration stage starts from."""

import re
from pathlib import Path

import numpy as np

from aggloTools.stats import read_stats, read_table

from channel.case import settings


def near_wall_over_centre(alpha):
    """The particle volume fraction of the slabs next to either wall over
    that of the middle quarter (None where the centre is empty)."""
    nb = len(alpha)
    wall = 0.5 * (alpha[0] + alpha[-1])
    mid = alpha[3 * nb // 8: nb - 3 * nb // 8].mean()
    return float(wall / mid) if mid > 0 else None


#: The concentration the agglomeration phase starts from: the profile
#: over the dispersion's last START_SPAN T* (from the release where the
#: release and dispersion are shorter)
START_SPAN = 100.0


def _running_profiles(p, ddir, cloud="particles"):
    """Each write's profiles.dat of the release and dispersion stages
    (of the cloud: a group's are named after its configurations): T*
    (absolute), the steps sampled since the release and the profile
    averaged over them (y, alpha)."""
    base = Path(ddir) / "postProcessing" / f"{cloud}HardSphere"
    out = []
    for f in sorted(base.glob("*/profiles.dat"),
                    key=lambda f: float(f.parent.name)):
        m = re.search(r"(\d+) steps sampled", f.read_text().split("\n")[0])
        t = read_table(f)
        out.append({"T": float(f.parent.name) / p["tScale"],
                    "n": int(m.group(1)) if m else 0,
                    "y": np.asarray(t["x"], float),
                    "alpha": np.asarray(t["alpha"], float), "file": f})
    return out


def _release(p):
    """The release as a write of no steps (T* absolute), where the first
    interval of _between starts."""
    return {"T": settings.end_time(p, "unladen") / p["tScale"], "n": 0,
            "alpha": 0.0}


def _between(w0, w1):
    """The profile of the steps between two writes: each write averages
    over all steps since the release, so (N1 a1 - N0 a0) / (N1 - N0)."""
    return (w1["n"] * w1["alpha"] - w0["n"] * w0["alpha"]) \
        / (w1["n"] - w0["n"])


def concentration(p, ddir, span=START_SPAN):
    """The particle volume fraction across the channel at the start of
    the agglomeration phase: the profile over the dispersion's last span
    T* (between its last write and the latest write at least span T*
    before it, or from the release), the near-wall peak of it
    (near_wall_over_centre) and T0, T1 (T*, absolute) of that span."""
    w = _running_profiles(p, ddir)
    if not w or w[-1]["n"] <= 0:
        return None
    last = w[-1]
    early = [x for x in w[:-1] if x["T"] <= last["T"] - span + 1e-9
             and 0 < x["n"] < last["n"]]
    w0 = early[-1] if early else _release(p)
    a = _between(w0, last)
    return {"nearWallOverCentre": near_wall_over_centre(a),
            "y": last["y"].tolist(), "alpha": a.tolist(),
            "T0": w0["T"], "T1": last["T"], "file": str(last["file"])}


def concentration_history(p, ddir, span=0.0, cloud="particles"):
    """How the near-wall peak grows over the release and dispersion
    stages: per interval between writes (the first from the release, T*
    absolute; writes less than `span` T* after the interval's start are
    passed over, except the last), near_wall_over_centre of the profile
    of its steps (_between)."""
    w = _running_profiles(p, ddir, cloud)
    out = []
    w0 = _release(p)
    for k, w1 in enumerate(w):
        # (span less a rounding: times are written to 10 digits)
        if w1["T"] - w0["T"] < span * (1 - 1e-6) and k < len(w) - 1:
            continue
        if w1["n"] > w0["n"]:
            out.append({"T0": w0["T"], "T1": w1["T"], "nearWallOverCentre":
                        near_wall_over_centre(_between(w0, w1))})
            w0 = w1
    return out


def dispersion_history(p, ddir, span=0.0, cloud="particles"):
    """concentration_history with, per interval, the rates of a cloud of
    the release and dispersion stages (the one of a configuration run
    alone, `particles`) from its stats.dat
    (cumulative counters, interpolated at the interval's ends):
    collisions per T* scaled to the paper's particle number (x s^2, as
    f_col of Eq. 87) and wall impacts per particle and T*. Collisions
    there rebound (agglomeration starts later), so this is the rate of
    contacts as the concentration builds up, not the window's f_col.
    A stats.dat that cannot be read yet (a run writing it) leaves the
    rates out."""
    out = concentration_history(p, ddir, span, cloud)
    try:
        st = read_stats(ddir, cloud)
    except (FileNotFoundError, ValueError):
        return out
    if not len(st["Time"]):
        return out
    T = st["Time"] / p["tScale"]
    s2 = (settings.N_PAPER / p["nParticles"])**2
    for x in out:
        dT = x["T1"] - x["T0"]
        if x["T1"] > T[-1] + 1e-9 or dT <= 0:
            continue
        dn = {c: float(np.interp(x["T1"], T, st[c])
                       - np.interp(x["T0"], T, st[c]))
              for c in ("nCol", "nWall")}
        x["fColScaled"] = dn["nCol"] / dT * s2
        x["wallImpacts_per_particle_T"] = dn["nWall"] / dT \
            / p["nParticles"]
    return out
