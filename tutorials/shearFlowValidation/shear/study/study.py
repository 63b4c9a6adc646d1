"""shearFlowValidation: the sensitivity study of the readings of the
paper's Appendix B that its text leaves open (file study; doc/models.md
2.6). Each variant is an EAM and a MAM run of a preset; the ghost detect
runs (fluid torque on and off) give the undisturbed first contacts that
each variant's kernels replay.

    python -m shear.study list PRESET
        the runs: "variant run" lines
    python -m shear.study settings PRESET VARIANT RUN
        caseSettings of one run
    python -m shear.study post PRESET [OUT]
        OUT (default results/study[-PRESET]): study.json, study.txt,
        plots (exit 1 if a run is missing)

Runs live in runs/<preset>/study/<variant>/<run>; ./Allrun -study runs
them (resumable) and then the post-processing.
"""

import argparse
import json
from pathlib import Path

import numpy as np

from aggloTools import eventlog
from aggloTools.foamfile import check_keys, read_dict

from shear import TUTORIAL, theory
from shear.case import settings
from shear.post import postprocess, statements
from shear.study import diagnosis
from shear.study.report import plots, study_table

MODELS = ("EAM", "MAM")
#: The study's baseline: the tutorial's readings before the study
BASELINE = "normal-torque-dt0.005"
#: The runs whose logs the diagnosis replays (shear.study.diagnosis)
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


def variants(path=TUTORIAL / "study"):
    """The declared variants, in order: name -> readings that differ from
    the default (settings.READINGS); the default is the first."""
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
        settings.check_reading(v, f"{path}: variant {name}")
    if BASELINE not in out:
        raise SystemExit(f"{path}: the matrix must hold the baseline "
                         f"{BASELINE}")
    return out


def full_reading(v):
    """A variant's every reading, defaults filled in."""
    out = {k: (c[0] if c else 0.005) for k, c in
           settings.READINGS.items()}
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
        s = dict(settings.settings(preset, run, full_reading(v)))
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
        s = settings.settings(preset, run, full_reading(
            {"fluidTorque": torque}))
    elif variant in vs:
        if run not in MODELS:
            raise SystemExit(f"a variant holds the runs {MODELS}")
        # every reading given: independent of the tutorial's defaults
        s = settings.settings(preset, run, full_reading(vs[variant]))
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
    entries.update(settings.kernel_coeffs(model, full_reading(reading)))
    return entries


def run_info(case, a_th):
    """The counts of one run: stats.dat and its collision-event log."""
    r = postprocess.Run(case)
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
    runs_dir = Path(runs_dir or TUTORIAL / "runs" / preset / "study")
    out = Path(out_dir or TUTORIAL / "results" / ("study" if preset == "small"
                                               else f"study-{preset}"))
    vs = variants()
    missing = [f"{v}/{r}" for v, r in run_list(preset)
               if not (runs_dir / v / r / "runTime").exists()]
    if missing:
        print("shear.study: runs not finished: " + " ".join(missing))
        return 1
    d = settings.settings(preset, "EAM")
    a_th = float(theory.alpha_th(d["dParticle"], d["gammaDot"]))
    und = undisturbed(runs_dir, vs)
    mine = settings.tutorial_readings()
    default = next((n for n, v in vs.items() if full_reading(v) == mine),
                   None)
    result = {"preset": preset, "alpha_th": a_th, "baseline": BASELINE,
              "default": default,
              "statementsText": statements.__doc__.strip(),
              "variants": []}
    for name, v in vs.items():
        entry = {"name": name, "settings": full_reading(v)}
        runs = {}
        for m in MODELS:
            case = runs_dir / canonical(preset, name, m) / m
            runs[m], entry[m] = run_info(case, a_th)
        rows = statements.statements(
            {m: runs[m].series(a_th) for m in MODELS}, a_th,
            gamma_dot=float(d["gammaDot"]))
        entry["statements"] = statements.verdicts(rows)
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
        tag: diagnosis.diagnose(runs_dir / v / "EAM", out,
                                     tag)["categories"]
        for tag, v in DIAGNOSED.items() if v in vs}
    (out / "study.json").write_text(json.dumps(result, indent=1,
                                               default=float) + "\n")
    text = study_table(result, MODELS, DIAGNOSED)
    (out / "study.txt").write_text(text + "\n")
    print(text)
    plots(result, out, MODELS)
    return 0


# ------------------------------------------------------------------ main

def main(argv):
    ap = argparse.ArgumentParser(
        prog="shear.study", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("list", help="the study's runs, 'variant run' lines"
                   ).add_argument("preset", help="the preset")
    s = sub.add_parser("settings", help="the caseSettings of one run")
    for name, what in (("preset", "the preset"),
                       ("variant", "a variant of the study file"),
                       ("run", "the run (EAM, MAM, detect...)")):
        s.add_argument(name, help=what)
    p = sub.add_parser("post", help="study.json, study.txt and the plots "
                       "(exit 1 if a run is missing)")
    p.add_argument("preset", help="the preset")
    p.add_argument("out", nargs="?", help="the output folder (default "
                   "results/study[-PRESET])")
    a = ap.parse_args(argv)
    if a.cmd == "list":
        settings.presets()
        for variant, run in run_list(a.preset):
            print(variant, run)
        return 0
    if a.cmd == "settings":
        print(settings.settings_text(run_settings(a.preset, a.variant,
                                                   a.run)))
        return 0
    return post(a.preset, None, a.out)

