#!/usr/bin/env python3
"""shearFlowValidation: the sensitivity study of the readings of the
paper's Appendix B that its text leaves open (file study; doc/models.md
2.6). Each variant is an EAM and a MAM run of a preset; the ghost detect
runs (fluid torque on and off) give the undisturbed first contacts that
each variant's kernels replay.

    shearStudy.py list PRESET                 the runs: "variant run" lines
    shearStudy.py settings PRESET VARIANT RUN caseSettings of one run
    shearStudy.py post PRESET [OUT]           OUT (default
                                              results/study[-PRESET]):
                                              study.json, study.txt, plots
                                              (exit 1 if a run is missing)

Runs live in runs/<preset>/study/<variant>/<run>; ./Allrun -study runs
them (resumable) and then the post-processing.
"""

import json
import math
import sys
from pathlib import Path

import numpy as np

from aggloTools import eventlog, regression as reg
from aggloTools.foamfile import check_keys, read_dict

import shearDiagnosis
import shearFlow
import shearPost
import shearStatements
import shearTheory

HERE = Path(__file__).resolve().parent
MODELS = ("EAM", "MAM")
#: The study's baseline: the tutorial's readings before the study
BASELINE = "normal-torque-dt0.005"
#: The runs whose logs the diagnosis replays (shearDiagnosis.py)
DIAGNOSED = {"Baseline": BASELINE, "NoTorque": "normal-noTorque-dt0.005"}
#: The undisturbed ensembles: ghost runs with the fluid torque on and off
UNDISTURBED = {"on": "undisturbed", "off": "undisturbed-noTorque"}


# ------------------------------------------------------------ the matrix

def _values(v):
    """A parsed list entry "(a b)" as a list of values."""
    v = v if isinstance(v, list) else [v]
    out = [str(x).strip("()") if isinstance(x, str) else x for x in v]
    return [x for x in out if x != ""]


def _number(x):
    return float(x) if not isinstance(x, (int, float)) else x


def variants(path=HERE / "study"):
    """The declared variants, in order: name -> readings that differ from
    the default (shearFlow.READINGS); the default is the first."""
    d = read_dict(path)
    check_keys(d, {"matrix", "singles"}, str(path))
    m = d.get("matrix", {})
    check_keys(m, {"impactVelocity", "fluidTorque", "dtGamma"},
               f"{path}: matrix")
    ivs = _values(m.get("impactVelocity", ["normal"]))
    torques = _values(m.get("fluidTorque", ["on"]))
    dts = [_number(x) for x in _values(m.get("dtGamma", [0.005]))]
    out = {}
    for iv in ivs:
        for tq in torques:
            for dt in dts:
                name = (f"{iv}-{'torque' if tq == 'on' else 'noTorque'}"
                        f"-dt{dt:g}")
                v = {"impactVelocityEAM": iv, "impactVelocityMAM": iv,
                     "fluidTorque": tq, "dtGamma": dt}
                out[name] = v
    for name, v in d.get("singles", {}).items():
        if name in out:
            raise SystemExit(f"{path}: single '{name}' repeats a matrix "
                             "variant")
        v = {k: (_number(x) if k == "dtGamma" else x)
             for k, x in v.items()}
        out[name] = v
    for name, v in out.items():
        shearFlow.check_reading(v, f"{path}: variant {name}")
    if BASELINE not in out:
        raise SystemExit(f"{path}: the matrix must hold the baseline "
                         f"{BASELINE}")
    return out


def full_reading(v):
    """A variant's every reading, defaults filled in."""
    out = {k: (c[0] if c else 0.005) for k, c in
           shearFlow.READINGS.items()}
    out.update(v)
    return out


def run_list(preset):
    """(variant, run) of every run of the study; a run whose settings are
    those of an earlier one (the MAM of an EAM-only reading) is not run
    again (canonical)."""
    vs = variants()
    out = [(UNDISTURBED[t], "detect") for t in ("on", "off")
           if any(full_reading(v)["fluidTorque"] == t for v in vs.values())]
    return out + [(name, m) for name in vs for m in MODELS
                  if canonical(preset, name, m) == name]


def canonical(preset, variant, run):
    """The first variant whose run has the same settings as this one."""
    def key(v):
        s = dict(shearFlow.settings(preset, run, full_reading(v)))
        s.pop("run")
        return s
    vs = variants()
    mine = key(vs[variant])
    return next(n for n, v in vs.items() if key(v) == mine)


def run_settings(preset, variant, run):
    vs = variants()
    if variant in UNDISTURBED.values():
        if run != "detect":
            raise SystemExit(f"{variant} holds the detect run only")
        torque = [t for t, n in UNDISTURBED.items() if n == variant][0]
        s = shearFlow.settings(preset, run, full_reading(
            {"fluidTorque": torque}))
    elif variant in vs:
        if run not in MODELS:
            raise SystemExit(f"a variant holds the runs {MODELS}")
        # every reading given: independent of the tutorial's defaults
        s = shearFlow.settings(preset, run, full_reading(vs[variant]))
    else:
        raise SystemExit(f"unknown variant {variant!r}: valid are "
                         + " ".join(list(UNDISTURBED.values()) + list(vs)))
    s["run"] = f"{variant}/{run}"
    return s



# ------------------------------------------------------------------ post

def kernel_name(model, reading):
    """The replay configuration of a model under a reading."""
    r = full_reading(reading)
    name = f"{model}-{r['impactVelocity' + model]}"
    return name + (f"-{r['tangentialProjection']}" if model == "EAM"
                   else "")


def kernel_entries(model, reading):
    entries = {"agglomerationModel": model}
    entries.update(shearFlow.kernel_coeffs(model, full_reading(reading)))
    return entries


def run_info(case, a_th):
    """The counts of one run: stats.dat and its collision-event log."""
    r = shearPost.Run(case)
    ev = eventlog.read_events(case)
    info = {"run": f"{case.parent.name}/{case.name}",
            "N_col": r.final("nCol"), "N_agg": r.final("nAgg")}
    for k, cat in enumerate(eventlog.CATEGORIES):
        sel = ev["category"] == k
        info[f"N_col_{cat}"] = int(np.sum(sel))
        info[f"N_agg_{cat}"] = int(np.sum(ev["agglomerates"][sel]))
    info["alpha_all"] = info["N_agg"] / max(info["N_col"], 1.0)
    info["alpha_first"] = info["N_agg_first"] / max(info["N_col_first"], 1)
    info["alpha_all_over_alpha_th"] = info["alpha_all"] / a_th
    info["alpha_first_over_alpha_th"] = info["alpha_first"] / a_th
    info["Np_final_over_Np0"] = float(r.np_after[-1] / r.np0)
    info["run_time_s"] = r.run_time
    # The log and the counters are one record of the same contacts
    if len(ev) != info["N_col"]:
        raise SystemExit(f"{case}: {len(ev)} logged events against "
                         f"{info['N_col']:.0f} counted collisions")
    return r, info


def undisturbed(runs_dir, vs):
    """Alpha per first contact of each variant's kernels on the ghost
    runs' first contacts: {torque: replay result by configuration}."""
    out = {}
    for torque, name in UNDISTURBED.items():
        case = runs_dir / name / "detect"
        confs = {}
        for v in vs.values():
            if full_reading(v)["fluidTorque"] != torque:
                continue
            for m in MODELS:
                confs[kernel_name(m, v)] = kernel_entries(m, v)
        if not confs:
            continue
        res = eventlog.replay(case, confs, events="first",
                              base=next(iter(confs)))
        out[torque] = {c["name"]: c for c in res["configurations"]}
    return out


def post(preset, runs_dir=None, out_dir=None):
    runs_dir = Path(runs_dir or HERE / "runs" / preset / "study")
    out = Path(out_dir or HERE / "results" / ("study" if preset == "small"
                                               else f"study-{preset}"))
    vs = variants()
    missing = [f"{v}/{r}" for v, r in run_list(preset)
               if not (runs_dir / v / r / "runTime").exists()]
    if missing:
        print("shearStudy.py: runs not finished: " + " ".join(missing))
        return 1
    d = shearFlow.settings(preset, "EAM")
    a_th = float(shearTheory.alpha_th(d["dParticle"], d["gammaDot"]))
    und = undisturbed(runs_dir, vs)
    mine = shearFlow.tutorial_readings()
    default = next((n for n, v in vs.items() if full_reading(v) == mine),
                   None)
    result = {"preset": preset, "alpha_th": a_th, "baseline": BASELINE,
              "default": default,
              "statementsText": shearStatements.__doc__.strip(),
              "variants": []}
    for name, v in vs.items():
        entry = {"name": name, "settings": full_reading(v)}
        runs = {}
        for m in MODELS:
            case = runs_dir / canonical(preset, name, m) / m
            runs[m], entry[m] = run_info(case, a_th)
        rows = shearStatements.statements(
            {m: runs[m].series(a_th) for m in MODELS}, a_th,
            gamma_dot=float(d["gammaDot"]))
        entry["statements"] = shearStatements.verdicts(rows)
        entry["statementRows"] = rows
        tq = entry["settings"]["fluidTorque"]
        entry["undisturbedAlphaFirst"] = {
            m: und[tq][kernel_name(m, v)]["alpha"] for m in MODELS}
        entry["undisturbedAlphaFirstCI"] = {
            m: [und[tq][kernel_name(m, v)][k]
                for k in ("alphaLow", "alphaHigh")] for m in MODELS}
        entry["undisturbedFirstContacts"] = \
            und[tq][kernel_name("EAM", v)]["events"]
        result["variants"].append(entry)
    out.mkdir(parents=True, exist_ok=True)
    # Where the models part: the EAM runs' contacts replayed through EAM
    # (both readings of v_E) and MAM
    result["diagnosis"] = {
        tag: shearDiagnosis.diagnose(runs_dir / v / "EAM", out,
                                     tag)["categories"]
        for tag, v in DIAGNOSED.items() if v in vs}
    (out / "study.json").write_text(json.dumps(result, indent=1,
                                               default=float) + "\n")
    text = study_table(result)
    (out / "study.txt").write_text(text + "\n")
    print(text)
    plots(result, out)
    return 0


def _f(v, fmt=".3g"):
    return "-" if v is None else format(v, fmt)


def study_table(res):
    a_th = res["alpha_th"]
    runs = [dict(variant=v["name"], model=m, **v[m]) for v in
            res["variants"] for m in MODELS]
    cols = [reg.Column("variant", "variant", 24),
            reg.Column("model", "model", 5),
            reg.Column("N_col", "N_col", 7, ">", lambda x: f"{x:.0f}"),
            reg.Column("first", "N_col_first", 6, ">", str),
            reg.Column("repeat", "N_col_repeat", 7, ">", str),
            reg.Column("ovlStart", "N_col_overlapStart", 8, ">", str),
            reg.Column("N_agg", "N_agg", 6, ">", lambda x: f"{x:.0f}"),
            reg.Column("first", "N_agg_first", 5, ">", str),
            reg.Column("repeat", "N_agg_repeat", 6, ">", str),
            reg.Column("ovlStart", "N_agg_overlapStart", 8, ">", str),
            reg.Column("a_all/a_th", "alpha_all_over_alpha_th", 10, ">", _f),
            reg.Column("a_first/a_th", "alpha_first_over_alpha_th", 12,
                       ">", _f),
            reg.Column("Np/Np0", "Np_final_over_Np0", 7, ">",
                       lambda x: f"{x:.4f}"),
            reg.Column("time s", "run_time_s", 6, ">", lambda x: _f(x, ".0f"))]
    lines = [f"shearFlowValidation study, preset {res['preset']}: "
             f"alpha_th = {a_th:.4g} (van de Ven & Mason); baseline "
             f"{res['baseline']} (the readings before the study), the "
             f"tutorial's default {res['default']}", ""]
    lines += reg.table(runs, cols)
    srows = []
    for v in res["variants"]:
        s = v["settings"]
        u = v["undisturbedAlphaFirst"]
        srows.append(dict(
            variant=v["name"],
            reading=(f"vE {s['impactVelocityEAM']}/{s['impactVelocityMAM']}"
                     f", torque {s['fluidTorque']}, dt*g {s['dtGamma']:g}"
                     f", tp {s['tangentialProjection']}"
                     f", ovl {s['overlapTreatment']}"),
            **v["statements"],
            uE=u["EAM"] / a_th, uM=u["MAM"] / a_th,
            n=v["undisturbedFirstContacts"]))
    cols = [reg.Column("variant", "variant", 24),
            reg.Column("reading", "reading", 72),
            *[reg.Column(k, k, 4) for k in shearStatements.IDS],
            reg.Column("undisturbed a_first/a_th EAM", "uE", 29, ">", _f),
            reg.Column("MAM", "uM", 6, ">", _f),
            reg.Column("of", "n", 5, ">", str)]
    lines += ["", "The paper's statements (shearStatements.py) and alpha "
              "per first contact on the undisturbed ensemble (the ghost "
              "run's first contacts replayed through the variant's "
              "kernels)", ""] + reg.table(srows, cols)
    for tag, cats in res.get("diagnosis", {}).items():
        run = DIAGNOSED[tag]
        lines += ["", f"Diagnosis {tag} ({run}/EAM, its contacts replayed;"
                  " shearDiagnosis.py): per category the agglomerating"
                  " fraction under each kernel, and Eq. 21 with and without"
                  " its spin term (EAM, v_E = |u_n|)"]
        drows = [dict(cat=c, **r) for c, r in cats.items()]
        dcols = [reg.Column("category", "cat", 12),
                 reg.Column("events", "events", 7, ">", str),
                 reg.Column("EAM |u_n|", "alpha_EAMnormal", 10, ">", _f),
                 reg.Column("EAM |u_r|", "alpha_EAMfull", 10, ">", _f),
                 reg.Column("MAM", "alpha_MAM", 8, ">", _f),
                 reg.Column("Eq21 no spin", "EAMnormal_translationOnly", 13,
                            ">", _f),
                 reg.Column("Eq21", "EAMnormal_withSpin", 8, ">", _f),
                 reg.Column("spin>0", "EAMnormal_spinTermPositive", 7, ">",
                            _f),
                 reg.Column("med |u_n|", "median_abs_un", 10, ">", _f),
                 reg.Column("med |u_t|", "median_utCentres", 10, ">", _f),
                 reg.Column("med |w|", "median_omega", 8, ">", _f)]
        lines += reg.table(drows, dcols)
    lines += ["", "Statements and tolerances (the tolerances of the first"
              " variant; each variant's are in study.json):"]
    for r in res["variants"][0]["statementRows"]:
        lines.append(f"  {r['statement']}: {r['check']} "
                     f"(tolerance {r['tolerance']})")
    return "\n".join(lines)


def plots(res, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    a_th = res["alpha_th"]
    names = [v["name"] for v in res["variants"]]
    x = np.arange(len(names))
    fig, axs = plt.subplots(2, 1, figsize=(10, 7.5), sharex=True)
    ax = axs[0]
    for k, m in enumerate(MODELS):
        c = "C0" if m == "EAM" else "C3"
        a = [v[m]["alpha_all_over_alpha_th"] for v in res["variants"]]
        f = [v[m]["alpha_first_over_alpha_th"] for v in res["variants"]]
        u = [v["undisturbedAlphaFirst"][m] / a_th for v in res["variants"]]
        ax.plot(x + 0.1 * (k - 0.5), a, "o", color=c,
                label=f"{m}: all contacts")
        ax.plot(x + 0.1 * (k - 0.5), f, "s", mfc="none", color=c,
                label=f"{m}: first contacts")
        ax.plot(x + 0.1 * (k - 0.5), u, "x", color=c,
                label=f"{m}: first contacts, undisturbed ensemble")
    ax.axhline(1, color="k", lw=0.8)
    ax.axhspan(*shearStatements.S1_BAND, color="0.9", zorder=0,
               label="S1 band")
    ax.set_yscale("log")
    ax.set_ylabel(r"$\alpha/\alpha_{th}$")
    ax.legend(fontsize=7, ncol=3)
    ax = axs[1]
    for k, m in enumerate(MODELS):
        c = "C0" if m == "EAM" else "C3"
        ax.bar(x + 0.4 * (k - 0.5), [v[m]["N_agg"] for v in
                                     res["variants"]], 0.4, color=c,
               label=f"{m}: N_agg")
    ax.set_ylabel(r"$N_{agg}$")
    ax.set_xticks(x)
    ax.set_xticklabels(names, rotation=40, ha="right", fontsize=8)
    ax.legend(fontsize=8)
    fig.suptitle(f"shearFlowValidation study, {res['preset']}: "
                 r"$\alpha_{th}$ = " f"{100 * a_th:.2f} %")
    fig.tight_layout()
    fig.savefig(out / "study.png", dpi=110)
    plt.close(fig)


# ------------------------------------------------------------------ main

def main(argv):
    if len(argv) == 2 and argv[0] == "list":
        shearFlow.presets()
        for variant, run in run_list(argv[1]):
            print(variant, run)
        return 0
    if len(argv) == 4 and argv[0] == "settings":
        print(shearFlow.settings_text(run_settings(*argv[1:])))
        return 0
    if len(argv) in (2, 3) and argv[0] == "post":
        return post(argv[1], None, argv[2] if len(argv) == 3 else None)
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
