"""verticalChannel: the regime study of the main case (README.md, "The
regime study"). Why is `small` another flow of collisions than the
paper's? Each variant is `small`'s configuration C1 (EAM and MAM as two
clouds of one LES) with one shortcut changed: the phase lengths, the grid
or the particle number. Each is a preset of the presets file, run by
./Allrun -preset NAME (resumable; the long ones from a clone outside the
work tree, --runs). Nothing is tuned: every variant run is reported.

    channelRegime.py list                   the variants and what each changes
    channelRegime.py run [-np N] [-j J] [--runs DIR] [VARIANT ...]
                                            ./Allrun each (default: all),
                                            J at a time (default 1; with
                                            J > 1 each one's output goes
                                            to runs/<variant>.log)
    channelRegime.py post [--runs DIR] [--out DIR]
                                            results/regime: regime.json,
                                            regime.txt, regime.png

--runs: the folder holding runs/<preset> (default: this tutorial's runs/);
post takes every variant with a finished agglomeration stage there and
names the missing ones."""

import argparse
import json
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

import channel
import channelPost as post
from aggloTools import eventlog
from aggloTools.stats import last_output, read_stats, read_table

HERE = channel.HERE

#: The variants, in order: name (= preset), what it changes from `small`
VARIANTS = (
    ("small", "the main job's preset: 32^3, 1e5, phases 60/10/30/60 T*"),
    ("regime32", "phases: the paper's 240/100/520/200 T* (window 100-200)"),
    ("regime48", "grid 48^3 at the paper's phases"),
    ("regime64short", "grid 64^3 at small's phases"),
    ("regime64", "grid 64^3 at the paper's phases"),
    ("regime32n3", "3e5 particles at 32^3 and the paper's phases"),
)
MODELS = ("EAM", "MAM")
#: AB16 Table 3 / D.6 (channel.TABLE_D6), C1, and the paper's u_tau/U_B
PAPER = {"f_col_scaled": channel.TABLE_D6["C1"]["fcol"],
         "f_agg_scaled": channel.TABLE_D6["C1"]["fagg"],
         "u_tau_over_U_B": 0.053}
#: Quantiles reported of the distributions at contact
QUANTILES = (0.1, 0.25, 0.5, 0.75, 0.9)


def runs_base(runs, name):
    return Path(runs or HERE / "runs") / name


def contact_distributions(adir, cloud, p, w0, w1):
    """The collisions of the window (T*agg w0-w1) from the event log: the
    normal approach speed |u_n| at contact and the wall distance of the
    contact (in delta), each as quantiles, for all counted contacts and
    for those that agglomerated, and the first/repeat split."""
    try:
        ev = eventlog.read_events(adir, cloud)
    except FileNotFoundError:
        return None
    t0 = channel.end_time(p, "dispersion")
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
            "_un": un, "_yw": yw}


def near_wall_over_centre(alpha):
    """The particle volume fraction of the slabs next to either wall over
    that of the middle quarter (None where the centre is empty)."""
    nb = len(alpha)
    wall = 0.5 * (alpha[0] + alpha[-1])
    mid = alpha[3 * nb // 8: nb - 3 * nb // 8].mean()
    return float(wall / mid) if mid > 0 else None


def concentration(p, ddir):
    """The particle volume fraction across the channel at the start of
    the agglomeration phase (the dispersion's last write): the near-wall
    peak (near_wall_over_centre) and the profile itself."""
    f = last_output(ddir, "particles", "profiles.dat")
    if f is None:
        return None
    t = read_table(f)
    a = np.asarray(t["alpha"], float)
    y = np.asarray(t["x"], float)
    return {"nearWallOverCentre": near_wall_over_centre(a),
            "y": y.tolist(), "alpha": a.tolist(), "file": str(f)}


def concentration_history(p, ddir):
    """How the near-wall peak grows over the release and dispersion
    stages: each write's profiles.dat averages the profile over all steps
    since the release ("N steps sampled"), so the profile of the steps
    between two writes is (N1 a1 - N0 a0) / (N1 - N0); per interval
    between writes (the first from the release, T* absolute),
    near_wall_over_centre of that profile."""
    base = Path(ddir) / "postProcessing" / "particlesHardSphere"
    files = sorted(base.glob("*/profiles.dat"),
                   key=lambda f: float(f.parent.name))
    out = []
    n0, a0, T0 = 0, 0.0, channel.end_time(p, "unladen") / p["tScale"]
    for f in files:
        m = re.search(r"(\d+) steps sampled", f.read_text().split("\n")[0])
        n1 = int(m.group(1)) if m else 0
        a1 = np.asarray(read_table(f)["alpha"], float)
        T1 = float(f.parent.name) / p["tScale"]
        if n1 > n0:
            out.append({"T0": T0, "T1": T1, "nearWallOverCentre":
                        near_wall_over_centre((n1 * a1 - n0 * a0)
                                              / (n1 - n0))})
            n0, a0, T0 = n1, a1, T1
    return out


def nprocs(d):
    return len(list(d.glob("processor*"))) or 1


def stage_times(base):
    """Wall-clock seconds of each stage (the done.<stage> markers) and the
    CPU seconds of the solver (the last ExecutionTime of each log, per
    rank), summed over the C1 stages of a preset's runs."""
    wall, cpu = {}, 0.0
    for d in [base / "unladen"] + sorted((base / "C1").glob("*")):
        for m in d.glob("done.*"):
            wall[f"{d.name}/{m.name[5:]}"] = float(m.read_text())
        log = d / "log.aggloPimpleFoam"
        if log.is_file():
            # a resumed run (-append) counts from zero again: each segment
            # adds its last value
            seg = 0.0
            for line in log.read_text(errors="replace").splitlines():
                if line.startswith("ExecutionTime = "):
                    x = float(line.split()[2])
                    if x < seg:
                        cpu += seg * nprocs(d)
                    seg = x
            cpu += seg * nprocs(d)
    return {"wall_s": wall, "wallTotal_s": sum(wall.values()),
            "cpu_s": cpu}


def analyse_variant(name, runs=None):
    """The study's quantities of one variant (None if its C1
    agglomeration stage has not finished)."""
    p = channel.preset(name)
    base = runs_base(runs, name)
    dirs = post.run_dirs(name, base)
    if not all(("C1", m) in dirs for m in MODELS):
        return None
    w0, w1 = p["window"]
    out = {"variant": name, "grid": p["n"], "dtStar": p["dtStar"],
           "nParticles": p["nParticles"],
           "phases": [p[k] for k in ("unladen", "release", "dispersion",
                                     "agglomeration")],
           "window": [w0, w1], "scale_s2": (channel.N_PAPER
                                            / p["nParticles"])**2,
           "models": {}}
    adir = dirs[("C1", "EAM")][0]
    for m in MODELS:
        r = post.analyse_run(p, *dirs[("C1", m)])
        st = read_stats(adir, m)
        Tn = (st["Time"] - channel.end_time(p, "dispersion")) / p["tScale"]
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
            "colFactorToPaper": r["f_col_scaled"]
            / PAPER["f_col_scaled"][m],
            "alphaFactorToPaper": (
                r["alpha_f"] / (PAPER["f_agg_scaled"][m]
                                / PAPER["f_col_scaled"][m])
                if r["alpha_f"] else None),
            "contacts": ({k2: v for k2, v in d.items()
                          if not k2.startswith("_")} if d else None)})
    ut_un, _ = post.u_tau(p, base / "unladen")
    ut_ag, _ = post.u_tau(p, adir)
    out["u_tau_over_U_B"] = {"unladen": ut_un / p["Ubar"] if ut_un else None,
                             "agglomeration": (ut_ag / p["Ubar"]
                                               if ut_ag else None)}
    out["concentration"] = concentration(p, adir.parent / "dispersion")
    out["concentrationHistory"] = concentration_history(
        p, adir.parent / "dispersion")
    out["times"] = stage_times(base)
    return out


def _g(v, fmt=".3g"):
    return "-" if v is None else format(v, fmt)


def table(res):
    """regime.txt: one row per variant and model."""
    lines = [
        "verticalChannel regime study, C1 (EAM and MAM clouds of one LES):"
        " one shortcut of `small` changed per variant (README.md, 'The"
        " regime study').",
        f"paper (Table 3/D.6): f_col x s^2 {PAPER['f_col_scaled']['EAM']:.3g}"
        f" / {PAPER['f_col_scaled']['MAM']:.3g}, alpha_f "
        f"{PAPER['f_agg_scaled']['EAM'] / PAPER['f_col_scaled']['EAM']:.3g}"
        f" / {PAPER['f_agg_scaled']['MAM'] / PAPER['f_col_scaled']['MAM']:.3g}"
        f" (EAM / MAM), u_tau/U_B {PAPER['u_tau_over_U_B']}", "",
        f"{'variant':14s} {'model':5s} {'fcol*s2':>9s} {'+-':>7s} "
        f"{'x paper':>7s} {'fagg*s2':>8s} {'alpha_f':>8s} {'x paper':>7s} "
        f"{'alpha_end':>9s} {'first/rep':>10s} {'|un| med':>8s} "
        f"{'y/d med':>7s} {'wall/N/T*':>9s} {'c_w/c_0':>7s} "
        f"{'u_tau/U_B':>9s} {'wall h':>6s} {'cpu h':>6s}"]
    for v in res["variants"]:
        r = v["result"]
        if r is None:
            lines.append(f"{v['name']:14s} not run (or not finished) in "
                         f"{v['runs']}")
            continue
        c = r["concentration"] or {}
        for m in MODELS:
            x = r["models"][m]
            ct = x["contacts"] or {}
            med = (lambda q: q[2] if q else None)
            lines.append(
                f"{v['name']:14s} {m:5s} {x['f_col_scaled']:9.4g} "
                f"{x['sigma_col_scaled']:7.3g} "
                f"{_g(x['colFactorToPaper']):>7s} "
                f"{x['f_agg_scaled']:8.4g} {_g(x['alpha_f']):>8s} "
                f"{_g(x['alphaFactorToPaper']):>7s} "
                f"{_g(x['alpha_end_of_phase']):>9s} "
                f"{int(x['nColFirst_end']):>5d}/{int(x['nColRepeat_end']):<4d}"
                f" {_g(med(ct.get('un_mm_s'))):>8s} "
                f"{_g(med(ct.get('wallDistance_delta'))):>7s} "
                f"{_g(x['wallImpacts_per_particle_T']):>9s} "
                f"{_g(c.get('nearWallOverCentre')):>7s} "
                f"{_g(r['u_tau_over_U_B']['agglomeration'], '.4f'):>9s} "
                f"{r['times']['wallTotal_s'] / 3600:6.2f} "
                f"{r['times']['cpu_s'] / 3600:6.2f}")
    lines += ["", "fcol*s2, fagg*s2: Eq. 87 over the window, scaled by "
              "(6e6/N)^2; +-: sigma (batch means or Poisson); x paper: "
              "sim/paper; alpha_end: N_agg/N_col at the window's end; "
              "first/rep: first and repeat contacts by then; |un| med: "
              "median normal approach speed at contact (mm/s), y/d med: "
              "median wall distance of the contacts (in delta), both over"
              " the window's contacts of the event log; wall/N/T*: wall "
              "impacts per particle and T*; c_w/c_0: particle volume "
              "fraction next to the walls over the centre's at the start "
              "of the agglomeration phase; wall h, cpu h: the C1 stages' "
              "wall-clock and CPU hours (all ranks)."]
    return "\n".join(lines) + "\n"


def plots(res, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [v for v in res["variants"] if v["result"]]
    if not done:
        return
    fig, ax = plt.subplots(1, 4, figsize=(18, 4.2))
    xs = np.arange(len(done))
    for k, m in enumerate(MODELS):
        f = [v["result"]["models"][m]["f_col_scaled"] for v in done]
        s = [v["result"]["models"][m]["sigma_col_scaled"] for v in done]
        a = [v["result"]["models"][m]["alpha_f"] or np.nan for v in done]
        ax[0].errorbar(xs + 0.1 * k, f, s, fmt="o", label=m)
        ax[1].plot(xs + 0.1 * k, a, "o", label=m)
        ax[0].axhline(PAPER["f_col_scaled"][m], ls="--", color=f"C{k}",
                      lw=0.8, label=f"paper {m}")
        ax[1].axhline(PAPER["f_agg_scaled"][m] / PAPER["f_col_scaled"][m],
                      ls="--", color=f"C{k}", lw=0.8, label=f"paper {m}")
    for a_ in ax[:2]:
        a_.set_xticks(xs)
        a_.set_xticklabels([v["name"] for v in done], rotation=30,
                           fontsize=8)
        a_.set_yscale("log")
        a_.legend(fontsize=7)
    ax[0].set_ylabel(r"$f_{col}\,s^2$ [1/T*]")
    ax[1].set_ylabel(r"$\alpha_f = f_{agg}/f_{col}$ [-]")
    for v in done:
        c = v["result"]["concentration"]
        if c:
            ax[2].plot(np.asarray(c["y"]) / 0.02, c["alpha"], label=v["name"])
    ax[2].set_xlabel(r"wall-normal position $y/\delta$ [-]")
    ax[2].set_ylabel("particle volume fraction [-]")
    ax[2].set_title("at the start of agglomeration", fontsize=9)
    ax[2].legend(fontsize=7)
    for v in done:
        h = v["result"].get("concentrationHistory")
        if h:
            ax[3].step([x["T1"] for x in h],
                       [x["nearWallOverCentre"] for x in h], where="pre",
                       label=v["name"])
    ax[3].axhline(1, color="0.6", lw=0.8)
    ax[3].set_xlabel(r"$T^*$ (release and dispersion) [-]")
    ax[3].set_ylabel("near-wall / centre volume fraction [-]")
    ax[3].set_title("between writes", fontsize=9)
    ax[3].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "regime.png", dpi=110)
    plt.close(fig)


def run_post(runs=None, out=None, names=None):
    out = Path(out or HERE / "results" / "regime")
    out.mkdir(parents=True, exist_ok=True)
    res = {"variants": []}
    what = dict(VARIANTS)
    for name in names or list(what):
        res["variants"].append({"name": name,
                                "changes": what.get(name, "-"),
                                "runs": str(runs_base(runs, name)),
                                "result": analyse_variant(name, runs)})
    (out / "regime.json").write_text(json.dumps(res, indent=1) + "\n")
    (out / "regime.txt").write_text(table(res))
    plots(res, out)
    print(table(res))
    return res


def run_variants(names, nprocs, jobs):
    """./Allrun -preset NAME -np nprocs of each variant, `jobs` at a time
    (on a machine of jobs x nprocs cores: two serial runs side by side
    make more steps per hour than one on two ranks, whose ranks wait on
    each other whenever another process takes a core). With jobs > 1
    each one's output goes to runs/<variant>.log. The exit status: the
    first failed variant's, in the order given."""
    def one(n):
        cmd = ["./Allrun", "-preset", n, "-np", str(nprocs)]
        if jobs == 1:
            return subprocess.call(cmd, cwd=HERE)
        log = HERE / "runs" / f"{n}.log"
        log.parent.mkdir(parents=True, exist_ok=True)
        with open(log, "a") as f:
            print(f"{n}: running, output in {log}", flush=True)
            rc = subprocess.call(cmd, cwd=HERE, stdout=f,
                                 stderr=subprocess.STDOUT)
        print(f"{n}: {'finished' if rc == 0 else f'failed ({rc})'}",
              flush=True)
        return rc

    with ThreadPoolExecutor(max_workers=jobs) as ex:
        rcs = list(ex.map(one, names))
    return next((rc for rc in rcs if rc), 0)


def main(argv):
    ap = argparse.ArgumentParser(prog="channelRegime.py",
                                 description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("list")
    r = sub.add_parser("run")
    r.add_argument("-np", type=int, default=1)
    r.add_argument("-j", type=int, default=1)
    r.add_argument("--runs")
    r.add_argument("variants", nargs="*")
    q = sub.add_parser("post")
    q.add_argument("--runs")
    q.add_argument("--out")
    q.add_argument("variants", nargs="*")
    a = ap.parse_args(argv[1:])
    if getattr(a, "j", 1) < 1 or getattr(a, "np", 1) < 1:
        ap.error("run: -np and -j need a positive number")
    known = [n for n, _ in VARIANTS]
    for v in getattr(a, "variants", []):
        if v not in known:
            ap.error(f"unknown variant '{v}'; valid: {' '.join(known)}")
    if a.cmd == "list":
        for n, what in VARIANTS:
            print(f"{n:14s} {what}")
    elif a.cmd == "run":
        if a.runs and Path(a.runs).resolve() != (HERE / "runs").resolve():
            ap.error("run: the runs go to this tutorial's runs/; run the "
                     "study from a clone outside the work tree instead")
        return run_variants(a.variants or known, a.np, a.j)
    else:
        run_post(a.runs, a.out, a.variants or None)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
