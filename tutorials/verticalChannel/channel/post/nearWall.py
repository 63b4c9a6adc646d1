"""verticalChannel: the paper's statements on where the particles are,
judged on the concentration the agglomeration stage starts from. AB16
explains its configurations' collisions by the particles' place: the
three sub-models (and, in the earlier MAM study it summarises, the lift
forces and the particle SGS model each) move particles out of the
near-wall region, and so do rough walls (Sec. 5.3, 5.4). Each statement
is a row of the regression: the ratio of two configurations' c_w/c_0,
the particle volume fraction of the slabs next to the walls over the
centre's (channel.post.concentration.near_wall_over_centre), judged like
the statements of Table D.6 (channel.post.statements: PASS where the
stated direction holds beyond 3 sigma, FAIL where the opposite does,
n/r in between).

    rows += concentration_rows(R, p)

c_w/c_0 of a configuration is the mean over the dispersion's last
START_SPAN T* (the whole release and dispersion where they are shorter)
of its intervals between the preset's writes (writeStar; a resume's
write in between is passed over), its sigma their standard error (batch
means: the intervals taken as independent; at least MIN_BATCHES of them,
else n/r). The intervals come from the configuration's own release and
dispersion (a run alone or its cloud of a group; of the preset's
stagesFrom where it has one), finished (done.dispersion), or, for C1
where the preset has no such run, from the regime study's record of the
preset made with its settings (its concentrationHistory)."""

import math

import numpy as np

from aggloTools import regression as reg

from channel import TUTORIAL
from channel.case import groups, settings
from channel.post import concentration, statements
from channel.post.studyRuns import same_settings, study_record

#: The statements: the words, the configuration that should hold fewer
#: particles near the walls and the one it is compared with
STATEMENTS = (
    ("the three sub-models move particles from the near-wall region"
     " towards the centre (AB16 Sec. 5.3)", "C2", "C1"),
    ("the lift forces push particles away from the walls (AB16 Sec. 5.3,"
     " of Breuer & Almohammed 2015)", "C1lift", "C1"),
    ("the particle SGS model lowers the near-wall concentration (AB16"
     " Sec. 5.3, of Breuer & Almohammed 2015)", "C1sgs", "C1"),
    ("rough walls lower the near-wall volume fraction (AB16 Sec. 5.4)",
     "C3", "C2"),
)
#: The least number of intervals whose spread gives a sigma
MIN_BATCHES = 4


def window(p):
    """(T0, T1), T* absolute: the span whose concentration the
    agglomeration stage starts from."""
    t1 = settings.end_time(p, "dispersion") / p["tScale"]
    t0 = settings.end_time(p, "unladen") / p["tScale"]
    return max(t0, t1 - concentration.START_SPAN), t1


def batch_mean(p, intervals):
    """c_w/c_0 over window(p) from intervals ({T0, T1,
    nearWallOverCentre}, T* absolute): {value, sigma, n, T0, T1}, sigma
    None with fewer than MIN_BATCHES intervals; None without an interval
    or where one has an empty centre."""
    w0, w1 = window(p)
    tol = 1e-3 * p["writeStar"]
    x = [i for i in intervals
         if i["T0"] >= w0 - tol and i["T1"] <= w1 + tol]
    v = [i["nearWallOverCentre"] for i in x]
    if not x or any(c is None for c in v):
        return None
    n = len(v)
    return {"value": float(np.mean(v)),
            "sigma": (float(np.std(v, ddof=1) / math.sqrt(n))
                      if n >= MIN_BATCHES else None),
            "n": n, "T0": x[0]["T0"], "T1": x[-1]["T1"]}


def own_runs(p):
    """{configuration: (dispersion folder, cloud)} of the release and
    dispersion runs of p (or of its stagesFrom preset)."""
    base = TUTORIAL / "runs" / (p["stagesFrom"] or p["name"])
    return groups.dispersion_clouds(base)


def concentrations(p, configs):
    """{configuration: batch_mean or a reason (str)} of those of configs
    that ran (or that the study recorded, C1)."""
    out = {}
    runs = own_runs(p)
    for c in configs:
        if c in runs:
            ddir, cloud = runs[c]
            if not (ddir / "done.dispersion").is_file():
                out[c] = f"{c}'s dispersion not finished"
                continue
            pc = settings.preset(p["name"], c)
            out[c] = batch_mean(pc, concentration.concentration_history(
                pc, ddir, pc["writeStar"], cloud)) or \
                f"{c}: no concentration over the dispersion's end"
        elif c == "C1":
            v = study_record(p["stagesFrom"] or p["name"])
            pc = settings.preset(p["name"], "C1")
            if v and not same_settings(pc, v["result"]):
                out[c] = batch_mean(
                    pc, v["result"].get("concentrationHistory") or []) or \
                    "C1: the study's record has no concentration history"
    return out


def concentration_rows(R, p):
    """The statement rows of the configurations of p that ran (a
    statement whose two configurations did not is left out)."""
    rows = []
    con = concentrations(p, {c for _, a, b in STATEMENTS for c in (a, b)})
    for words, a, b in STATEMENTS:
        if a not in con or b not in con:
            continue
        name = f"statement c_w/c_0 {a}/{b}"
        why = [x for x in (con[a], con[b]) if isinstance(x, str)]
        if why:
            rows.append(R(name, None, None, None, None,
                          reg.NR, f"{words}: {'; '.join(why)}"))
            continue
        ca, cb = con[a], con[b]
        r = ca["value"] / cb["value"]
        few = [f"{k}: {x['n']}" for k, x in ((a, ca), (b, cb))
               if x["sigma"] is None]
        if few:
            s, status, note = None, reg.NR, (
                f"fewer than {MIN_BATCHES} intervals give no sigma ("
                + ", ".join(few) + ")")
        else:
            s = r * math.hypot(ca["sigma"] / ca["value"],
                               cb["sigma"] / cb["value"])
            status, note = statements.direction_status(r, s, -1)
        rows.append(R(name, r, s, None,
                      None if s is None
                      else statements.DIRECTION_SIGMAS * s, status,
                      f"{words}: {note}; c_w/c_0 {ca['value']:.3g}"
                      f" / {cb['value']:.3g} over T* {ca['T0']:.4g}-"
                      f"{ca['T1']:.4g}, {ca['n']} / {cb['n']} intervals"))
    return rows
