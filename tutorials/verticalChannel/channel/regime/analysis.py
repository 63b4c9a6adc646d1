"""verticalChannel regime study: what each variant's runs show (the
quantities of regime.json): the rates and alpha over the window, the
contacts' approach speeds and wall distances from the event log, the
particle concentration across the channel and its growth, u_tau/U_B and
the stages' times. channel.regime runs the variants and writes the
report."""

from pathlib import Path

import numpy as np

from aggloTools import times, uncertainty
from aggloTools.stats import read_stats

from channel import TUTORIAL
from channel.case import settings
from channel.post import postprocess as post
from channel.post.concentration import concentration, dispersion_history
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
           "nParticles": p["nParticles"], "UTolerance": p["UTolerance"],
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
