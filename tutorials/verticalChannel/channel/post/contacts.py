"""verticalChannel: where and how fast the particles collide, from a
cloud's collision-event log (doc/eventLog.md): the contacts of a window
by wall distance, their normal approach speeds, and the share near the
walls that the report's head states. Used by the report (channel.post)
and the regime study (channel.regime.analysis)."""

import numpy as np

from channel.case import settings
from aggloTools import eventlog, uncertainty

#: Quantiles reported of the distributions at contact
QUANTILES = (0.1, 0.25, 0.5, 0.75, 0.9)
#: Bins of the contacts' wall distance (y/delta; the last holds the centre)
WALL_BINS = (0.0, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0)
#: A contact "at the wall" lies within this distance of one (y/delta):
#: the regime study's C1 at 64^3 has 82-83 % of its window's contacts
#: there (README.md, 'The study's result'), as the paper describes its
#: collisions
NEAR_WALL = 0.02


def by_wall_distance(un, yw, agg, edges=WALL_BINS):
    """The contacts per bin of wall distance yw (y/delta): how many, how
    many agglomerated, their ratio (alpha of the bin; None where empty)
    and the median normal approach speed (un in m/s; mm/s)."""
    k = np.clip(np.searchsorted(edges, yw, side="right") - 1, 0,
                len(edges) - 2)
    out = {"edges": list(edges), "n": [], "nAgg": [], "alpha": [],
           "unMedian_mm_s": []}
    for b in range(len(edges) - 1):
        s = k == b
        n, na = int(s.sum()), int((s & agg).sum())
        out["n"].append(n)
        out["nAgg"].append(na)
        out["alpha"].append(na / n if n else None)
        out["unMedian_mm_s"].append(float(1e3 * np.median(un[s]))
                                    if n else None)
    return out


def contact_distributions(adir, cloud, p, w0, w1):
    """The collisions of the window (T*agg w0-w1) from the event log: the
    normal approach speed |u_n| at contact and the wall distance of the
    contact (in delta), each as quantiles, for all counted contacts and
    for those that agglomerated, the first/repeat split, and both per bin
    of wall distance (by_wall_distance)."""
    try:
        ev = eventlog.read_events(adir, cloud)
    except FileNotFoundError:
        return None
    t0 = settings.end_time(p, "dispersion")
    T = (ev["time"] - t0) / p["tScale"]
    ev = ev[(T >= w0) & (T <= w1) & (ev["category"] < 2)]
    if not len(ev):
        return {"n": 0}
    dx = ev["x2"] - ev["x1"]
    n = dx / np.linalg.norm(dx, axis=1)[:, None]
    un = np.abs(np.einsum("ij,ij->i", ev["U1"] - ev["U2"], n))
    # the contact point's distance to the nearer wall (y in 0-2 delta)
    yc = 0.5 * (ev["x1"][:, 1] + ev["x2"][:, 1])
    yw = np.minimum(yc, 2 * p["delta"] - yc) / p["delta"]
    agg = ev["agglomerates"] == 1

    def q(a):
        return ([float(v) for v in np.quantile(a, QUANTILES)]
                if len(a) else None)
    return {"n": int(len(ev)), "nFirst": int((ev["category"] == 0).sum()),
            "nRepeat": int((ev["category"] == 1).sum()),
            "nAgg": int(agg.sum()), "quantiles": list(QUANTILES),
            "un_mm_s": q(1e3 * un), "un_mm_s_agg": q(1e3 * un[agg]),
            "wallDistance_delta": q(yw),
            "wallDistance_delta_agg": q(yw[agg]),
            "byWallDistance": by_wall_distance(un, yw, agg),
            "_un": un, "_yw": yw}


def near_wall_share(cd, edge=NEAR_WALL):
    """The share of a window's contacts (contact_distributions) within
    `edge` of a wall, and its binomial standard error; (None, None)
    without contacts."""
    if not cd or not cd.get("n"):
        return None, None
    n = cd["n"]
    k = int((cd["_yw"] < edge).sum())
    return k / n, uncertainty.binomial_sigma(k, n)
