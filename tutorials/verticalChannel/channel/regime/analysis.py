"""verticalChannel regime study: what each variant's runs show (the
quantities of regime.json): the rates and alpha over the window, the
contacts' approach speeds and wall distances from the event log, the
particle concentration across the channel and its growth, u_tau/U_B and
the stages' times. channel.regime runs the variants and writes the
report."""

import re
from pathlib import Path

import numpy as np

from aggloTools import times, uncertainty
from aggloTools.stats import read_stats, read_table

from channel import TUTORIAL
from channel.case import settings
from channel.post import postprocess as post
from channel.post.contacts import contact_distributions


MODELS = settings.MODELS
#: AB16 Table 3 / D.6 (settings.TABLE_D6), C1, and the paper's u_tau/U_B
PAPER = {"f_col_scaled": settings.TABLE_D6["C1"]["fcol"],
         "f_agg_scaled": settings.TABLE_D6["C1"]["fagg"],
         "u_tau_over_U_B": 0.053}


def paper_alpha(m):
    """The paper's alpha_f = f_agg / f_col of model m (C1)."""
    return PAPER["f_agg_scaled"][m] / PAPER["f_col_scaled"][m]


def factors_to_paper(m, f_col_scaled, alpha_f):
    """sim / paper of f_col x s^2 and of alpha_f (None without one)."""
    return {"colFactorToPaper": f_col_scaled / PAPER["f_col_scaled"][m],
            "alphaFactorToPaper": (alpha_f / paper_alpha(m)
                                   if alpha_f else None)}


def runs_base(runs, name):
    return Path(runs or TUTORIAL / "runs") / name


def variant_history(v):
    """A variant's release and dispersion history (finished or not) from
    run_post's record of it."""
    if v["result"]:
        return v["result"].get("concentrationHistory") or []
    return (v.get("progress") or {}).get("history") or []


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


#: The least part of the window (T*) an interim rates over
MIN_PART_TSTAR = 10.0


def agglomeration_so_far(p, adir, last_Tstar):
    """An unfinished agglomeration stage up to its last complete write
    (last_Tstar: T* from the start of the unladen LES), per model whose
    stats.dat can be read: T*agg reached, the collisions and
    agglomerations by then and their ratio and, once the window has run
    MIN_PART_TSTAR, Eq. 87 over its part so far (uncertainty.window_rate,
    sigma the larger of batch means and Poisson as for a finished
    window), scaled by s^2, alpha_f and their factors to the paper. An
    interim: the rates of a part of the window, not the window's."""
    t0 = settings.end_time(p, "dispersion")
    last = last_Tstar - t0 / p["tScale"]
    w0, w1 = p["window"]
    s2 = (settings.N_PAPER / p["nParticles"])**2
    out = {}
    for m in MODELS:
        try:
            st = read_stats(adir, m)
        except (FileNotFoundError, ValueError):
            continue
        T = (st["Time"] - t0) / p["tScale"]
        keep = T <= last + 1e-9
        if not keep.any():
            continue
        T = np.concatenate(([0.0], T[keep]))
        n = {c: np.concatenate(([0.0], st[c][keep]))
             for c in ("nCol", "nAgg")}
        x = {"TstarAgg": float(T[-1]), "nCol": float(n["nCol"][-1]),
             "nAgg": float(n["nAgg"][-1]),
             "alpha": (float(n["nAgg"][-1] / n["nCol"][-1])
                       if n["nCol"][-1] > 0 else None)}
        end = min(w1, T[-1])
        if end - w0 >= MIN_PART_TSTAR:
            col = uncertainty.window_rate(T, n["nCol"], w0, end)
            agg = uncertainty.window_rate(T, n["nAgg"], w0, end)
            alpha = agg[0] / col[0] if col[0] > 0 else None
            x.update({
                "window": [w0, end],
                "f_col_scaled": col[0] * s2,
                "sigma_col_scaled": max(col[1], col[2]) * s2,
                "f_agg_scaled": agg[0] * s2,
                "sigma_agg_scaled": max(agg[1], agg[2]) * s2,
                "alpha_f": alpha,
                **factors_to_paper(m, col[0] * s2, alpha)})
        out[m] = x
    return out


#: The stage folders of a variant's C1, in order
STAGE_DIRS = (("unladen", "unladen", ("unladen",)),
              ("C1/dispersion", "dispersion", ("release", "dispersion")),
              ("C1/agglomeration", "agglomeration", ("agglomeration",)))


def progress(name, runs=None):
    """Where a variant stands that has not finished (an interim, not the
    study's window): per stage folder of C1 that exists, its last
    complete write and the stage's end (T* from the start of the
    unladen LES) and the stages done; the release and dispersion history
    so far (dispersion_history), the concentration at the start of
    agglomeration once the dispersion is done (concentration; None
    before) and the agglomeration stage's so far (agglomeration_so_far).
    None where nothing has run."""
    p = settings.preset(name, "C1")
    base = runs_base(runs, name)
    stages = {}
    for folder, last, markers in STAGE_DIRS:
        d = base / folder
        if not d.is_dir():
            continue
        root = d / "processor0" if (d / "processor0").is_dir() else d
        cut = times.incomplete_time(root)
        ts = [t for t in times.time_dirs(root) if t != cut]
        stages[folder] = {
            "lastWrite_Tstar": (float(ts[-1].name) / p["tScale"]
                                if ts else None),
            "end_Tstar": settings.end_time(p, last) / p["tScale"],
            "done": [m for m in markers if (d / f"done.{m}").is_file()]}
    if not stages:
        return None
    ddir = base / "C1" / "dispersion"
    agg = stages.get("C1/agglomeration", {}).get("lastWrite_Tstar")
    dispersed = "dispersion" in stages.get("C1/dispersion",
                                           {}).get("done", [])
    return {"stages": stages,
            "history": (dispersion_history(p, ddir)
                        if ddir.is_dir() else []),
            "concentration": concentration(p, ddir) if dispersed else None,
            "agglomeration": (agglomeration_so_far(
                p, base / "C1" / "agglomeration", agg) if agg else {})}


def nprocs(d):
    return len(list(d.glob("processor*"))) or 1


def log_times(log):
    """CPU and wall-clock seconds of one solver log: the last
    ExecutionTime and ClockTime of each segment, summed (a resumed run,
    -append, counts from zero again)."""
    cpu = wall = 0.0
    seg = (0.0, 0.0)
    for line in log.read_text(errors="replace").splitlines():
        if line.startswith("ExecutionTime = "):
            w = line.split()
            x = (float(w[2]), float(w[6]))
            if x[0] < seg[0]:
                cpu, wall = cpu + seg[0], wall + seg[1]
            seg = x
    return cpu + seg[0], wall + seg[1]


def stage_times(base):
    """Per C1 stage folder (unladen, C1/dispersion with the release,
    C1/agglomeration), the solver's wall-clock seconds and, summed over
    them, its CPU seconds (all ranks), every resumed segment counted."""
    wall, cpu = {}, 0.0
    for d in [base / "unladen"] + sorted((base / "C1").glob("*")):
        log = d / "log.aggloPimpleFoam"
        if log.is_file():
            c, w = log_times(log)
            cpu += c * nprocs(d)
            wall[str(d.relative_to(base))] = w
    return {"wall_s": wall, "wallTotal_s": sum(wall.values()),
            "cpu_s": cpu}


def analyse_variant(name, runs=None):
    """The study's quantities of one variant (None if its C1
    agglomeration stage has not finished)."""
    p = settings.preset(name, "C1")
    base = runs_base(runs, name)
    dirs = post.run_dirs(name, base)
    if not all(("C1", m) in dirs for m in MODELS):
        return None
    w0, w1 = p["window"]
    out = {"variant": name, "grid": p["n"], "dtStar": p["dtStar"],
           "nParticles": p["nParticles"],
           "phases": [p[k] for k in ("unladen", "release", "dispersion",
                                     "agglomeration")],
           "window": [w0, w1], "scale_s2": (settings.N_PAPER
                                            / p["nParticles"])**2,
           "models": {}}
    adir = dirs[("C1", "EAM")][0]
    for m in MODELS:
        r = post.analyse_run(p, *dirs[("C1", m)])
        st = read_stats(adir, m)
        Tn = (st["Time"] - settings.end_time(p, "dispersion")) / p["tScale"]
        k = int(np.searchsorted(Tn, w1 - 1e-9))
        k = min(k, len(Tn) - 1)
        d = contact_distributions(adir, m, p, w0, w1)
        out["models"][m] = {
            key: r[key] for key in (
                "f_col_scaled", "f_agg_scaled", "alpha_f", "events_col",
                "events_agg", "sigma_col", "sigma_agg")}
        out["models"][m].update({
            "sigma_col_scaled": r["sigma_col"] * r["scale"],
            "sigma_agg_scaled": r["sigma_agg"] * r["scale"],
            "alpha_end_of_phase": (float(st["nAgg"][k] / st["nCol"][k])
                                   if st["nCol"][k] > 0 else None),
            "nColFirst_end": float(st["nColFirst"][k]),
            "nColRepeat_end": float(st["nColRepeat"][k]),
            "nAggFirst_end": float(st["nAggFirst"][k]),
            "nAggRepeat_end": float(st["nAggRepeat"][k]),
            "wallImpacts_per_particle_T": r["f_wall"] / p["nParticles"],
            **factors_to_paper(m, r["f_col_scaled"], r["alpha_f"]),
            "contacts": ({k2: v for k2, v in d.items()
                          if not k2.startswith("_")} if d else None)})
    ut_un, _ = post.u_tau(p, base / "unladen")
    ut_ag, _ = post.u_tau(p, adir)
    out["u_tau_over_U_B"] = {"unladen": ut_un / p["Ubar"] if ut_un else None,
                             "agglomeration": (ut_ag / p["Ubar"]
                                               if ut_ag else None)}
    out["concentration"] = concentration(p, adir.parent / "dispersion")
    out["concentrationHistory"] = dispersion_history(
        p, adir.parent / "dispersion")
    out["times"] = stage_times(base)
    return out
