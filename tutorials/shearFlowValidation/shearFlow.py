#!/usr/bin/env python3
"""shearFlowValidation: set-up and post-processing of the laminar shear-flow
validation (paper Appendix B; doc/cases.md B.1-B.6).

    shearFlow.py settings PRESET RUN   caseSettings of one run (stdout)
    shearFlow.py init CASE             exact Couette profile and particles
    shearFlow.py settle CASE           set aside a last time folder whose
                                       write was cut off (before a restart)
    shearFlow.py progress CASE         simulated time and ETA of a run
    shearFlow.py post PRESET           results/PRESET: summary.json, plots,
                                       regression.txt (exit 1 on a FAIL)

Runs: detect (ghost contacts, no agglomeration, first-contact counting, for
the Saffman-Turner check), EAM, MAM, and optionally bounce (physical
rebounds, no agglomeration: the secondary first-contact check of B.6).
"""

import json
import math
import sys
from pathlib import Path

import numpy as np

from aggloTools import (cloud, fields, placement, progress as prog,
                        regression as reg, render, stats, times)
from aggloTools import casesettings
from aggloTools.foamfile import check_keys

import shearStatements

HERE = Path(__file__).resolve().parent

# Physical data of doc/cases.md B.1 (the case files hold the same values)
H = 2.28e-21        # Hamaker constant of polystyrene [J]
MU = 1.0e-3         # water [Pa s]
RHO_P = 1050.0      # polystyrene [kg/m3]
LAMBDA = 1e-7       # van de Ven & Mason's lambda [m]
RUNS = ("detect", "EAM", "MAM", "bounce")


# ------------------------------------------------------------------ theory

def f_vdVM(d):
    """van de Ven & Mason's f: the tabulated 0.95, 0.87, 0.79 at d = 1, 2,
    4 um lie on a line in ln d (doc/cases.md B.2); a quadratic fit is this
    line."""
    return 0.95 - 0.08 * np.log2(np.asarray(d, float) / 1e-6)


def alpha_th(d, gamma=71.0, hamaker=H, mu=MU):
    """Eq. B.5: f(lambda/(pi d)) [8 H/(36 pi mu gamma d^3)]^0.18."""
    d = np.asarray(d, float)
    return f_vdVM(d) * (8 * hamaker / (36 * math.pi * mu * gamma * d**3))**0.18


def kernel_ST(d1, d2=None, gamma=71.0):
    """Eq. B.6: (4/3) gamma (r1 + r2)^3."""
    d2 = d1 if d2 is None else d2
    return 4.0 / 3.0 * gamma * (0.5 * (d1 + d2))**3


def decay_theory(np0, dncol, np_sim, alpha, form="consistent"):
    """The recursion of Eq. B.8 driven by the simulated kernel of Eq. B.7,
    K(t_n) = 2 V dN_col,n/(N_p(t_n)^2 dt):
        N(t_n+1) = N(t_n)/(1 + c alpha K(t_n) dt N(t_n)/V)
                 = N(t_n)/(1 + 2 c alpha dN_col,n N(t_n)/N_p(t_n)^2)
    with c = 1/2 (consistent) or 1 (printed). np_sim[n] is the simulated
    number before step n. Returns N(t_n) for n = 0 .. len(dncol)."""
    c = {"consistent": 0.5, "printed": 1.0}[form]
    out = np.empty(len(dncol) + 1)
    out[0] = np0
    for n, (dn, ns) in enumerate(zip(dncol, np_sim)):
        out[n + 1] = out[n] / (1 + 2 * c * alpha * dn * out[n] / ns**2)
    return out


# ---------------------------------------------------------------- settings

PRESET_KEYS = {"nx", "LxByDelta", "nParticles", "endGamma",
               "detectEndGamma", "detectDtGamma", "writes", "eventLog"}
COMMON_KEYS = {"gammaDot", "delta", "LzByDelta", "ny", "nz", "dParticle",
               "seed", "dtGamma", "detectDtGamma", "countFromGamma",
               "eventLog", "fluidTorque"}


def presets():
    """The presets file, every entry checked."""
    return casesettings.read_presets(HERE / "presets", PRESET_KEYS,
                                     {"common": COMMON_KEYS})


def on_off(v, where):
    return casesettings.choice(v, ("on", "off"), where)


#: The readings a study may vary (shearStudy.py), with their values; the
#: first value is the study's baseline (the tutorial's default before the
#: study; the tutorial's own readings are those of presets/common and the
#: models' defaults: tutorial_readings). impactVelocity<model>: v_E or v_M
#: of the model's coefficients (doc/models.md 2.2, 3.2); fluidTorque: the
#: rotationModel (on: fluidTorque, off: none; doc/models.md 8.5);
#: tangentialProjection: of the EAM (doc/models.md 2.5); overlapTreatment
#: (doc/models.md 6.6); dtGamma: the step of the EAM and MAM runs.
READINGS = {
    "impactVelocityEAM": ("normal", "full"),
    "impactVelocityMAM": ("normal", "full"),
    "fluidTorque": ("on", "off"),
    "tangentialProjection": ("paper", "full"),
    "overlapTreatment": ("none", "separate"),
    "dtGamma": None,
}


def check_reading(variant, where):
    """Stop on an unknown reading or value, naming it and the choices."""
    check_keys(variant, set(READINGS), where)
    for k, v in variant.items():
        choices = READINGS[k]
        if choices is None:
            if not (isinstance(v, (int, float)) and 0 < v <= 0.1):
                raise SystemExit(f"{where}: {k} {v!r} is not a number in "
                                 "(0, 0.1]")
        elif v not in choices:
            raise SystemExit(f"{where}: {k} '{v}' is not one of: "
                             + " ".join(choices))


def tutorial_readings():
    """The tutorial's own readings: presets/common's fluidTorque and
    dtGamma, the models' defaults for the rest."""
    c = presets()["common"]
    out = {k: v[0] for k, v in READINGS.items() if v}
    out["fluidTorque"] = on_off(c["fluidTorque"], "presets/common: "
                                "fluidTorque")
    out["dtGamma"] = float(c["dtGamma"])
    return out


def kernel_coeffs(model, variant):
    """The <model>Coeffs entries a variant sets (merged into the cloud's
    hardSphereCoeffs through caseSettings' kernelCoeffs): only those of
    the run's own model, since the other model's are unknown entries."""
    c = {}
    if model in ("EAM", "MAM"):
        iv = variant.get(f"impactVelocity{model}", "normal")
        if iv != "normal":
            c["impactVelocity"] = iv
    if model == "EAM" and variant.get("tangentialProjection",
                                      "paper") != "paper":
        c["tangentialProjection"] = variant["tangentialProjection"]
    return {f"{model}Coeffs": c} if c else {}


def settings(preset, run, variant=None):
    """The caseSettings dictionary of one run of a preset; variant: the
    readings that differ from the default (READINGS)."""
    check_reading(dict(variant or {}), f"variant of {preset}/{run}")
    variant = dict(tutorial_readings(), **(variant or {}))
    ps = presets()
    p = casesettings.named(ps, preset, "preset", "shearFlow.py",
                           exclude=("common",))
    casesettings.choice(run, RUNS, "shearFlow.py: run")
    c = ps["common"]
    gamma, delta = float(c["gammaDot"]), float(c["delta"])
    detect = run == "detect"
    dt_g = float(p.get("detectDtGamma", c["detectDtGamma"]) if detect
                 else variant["dtGamma"])
    end_g = float(p["detectEndGamma"] if detect else p["endGamma"])
    steps = round(end_g / dt_g)
    dt = dt_g / gamma
    model = run if run in ("EAM", "MAM") else "none"
    return {
        "preset": preset, "run": run,
        "gammaDot": gamma, "delta": delta, "yMin": -delta,
        "uWall": gamma * delta, "uLower": -gamma * delta,
        "Lx": float(p["LxByDelta"]) * delta,
        "Lz": float(c["LzByDelta"]) * delta,
        "nx": int(p["nx"]), "ny": int(c["ny"]), "nz": int(c["nz"]),
        "nParticles": int(p["nParticles"]),
        "dParticle": float(c["dParticle"]), "seed": int(c["seed"]),
        "deltaT": dt, "endTime": steps * dt,
        "writeInterval": steps * dt / int(p["writes"]),
        "countFrom": float(c["countFromGamma"]) / gamma,
        "agglomerationModel": model,
        "collisionResponse": "ghost" if detect else "physical",
        "eventLog": on_off(p.get("eventLog", c["eventLog"]),
                           f"presets/{preset}: eventLog"),
        "rotationModel": ("none" if variant.get("fluidTorque") == "off"
                          else "fluidTorque"),
        "overlapTreatment": variant.get("overlapTreatment", "none"),
        "kernelCoeffs": kernel_coeffs(model, variant),
    }


def settings_text(s):
    lines = ["// Written by shearFlow.py settings for the preset "
             f"{s['preset']}, run {s['run']}", ""]
    def body(d):
        return " ".join(f"{k} {{ {body(v)} }}" if isinstance(v, dict)
                        else f"{k} {v};" for k, v in d.items())

    for k, v in s.items():
        if k in ("preset", "run"):
            continue
        if isinstance(v, dict):
            lines.append(f"{k:<20}{{ {body(v)} }}")
        else:
            lines.append(f"{k:<20}{v!r};" if isinstance(v, float)
                         else f"{k:<20}{v};")
    return "\n".join(lines)


SETTINGS_KEYS = {"preset", "run", "gammaDot", "delta", "yMin", "uWall",
                 "uLower", "Lx", "Lz", "nx", "ny", "nz", "nParticles",
                 "dParticle", "seed", "deltaT", "endTime", "writeInterval",
                 "countFrom", "agglomerationModel", "collisionResponse",
                 "eventLog", "rotationModel", "overlapTreatment",
                 "kernelCoeffs"}


def read_settings(case):
    """The caseSettings of a run, every entry checked."""
    return casesettings.read_settings(case, SETTINGS_KEYS)


# -------------------------------------------------------------------- init

def random_positions(n, d, box, seed, wall_gap):
    """n non-overlapping centres (distance at least d), uniform in box =
    (Lx, ymin, ymax, Lz), periodic in x and z, at least wall_gap from the
    walls (seeded; aggloTools.placement)."""
    Lx, ymin, ymax, Lz = box
    return placement.place(n, d, (0, ymin + wall_gap, 0),
                           (Lx, ymax - wall_gap, Lz), (Lx, None, Lz),
                           np.random.default_rng(seed))


def init(case):
    """0/U: the exact profile u = gammaDot y e_x at the cell centres;
    0/lagrangian: the particles at rest at random positions."""
    case = Path(case)
    s = read_settings(case)
    gamma, delta = float(s["gammaDot"]), float(s["delta"])
    nx, ny, nz = int(s["nx"]), int(s["ny"]), int(s["nz"])
    Lx, Lz = float(s["Lx"]), float(s["Lz"])
    yc = -delta + (np.arange(ny) + 0.5) * 2 * delta / ny
    U = np.zeros((nx * ny * nz, 3))
    U[:, 0] = np.tile(np.repeat(gamma * yc, nx), nz)   # x fastest
    fields.set_internal_vector_field(case / "0" / "U", U)

    d = float(s["dParticle"])
    x = random_positions(int(s["nParticles"]), d, (Lx, -delta, delta, Lz),
                         int(s["seed"]), 0.5 * d)
    cloud.write_cloud(case, x, d, RHO_P)
    print(f"shearFlow.py init: {len(x)} particles, U = {gamma} y e_x in "
          f"{nx}x{ny}x{nz} cells")


# -------------------------------------------------------------- post

class Run:
    """The statistics of one finished run."""

    def __init__(self, case):
        self.case = Path(case)
        self.name = self.case.name
        self.s = read_settings(case)
        self.st = stats.read_stats(case)
        st = self.st
        self.t = st["Time"]
        self.gamma = float(self.s["gammaDot"])
        self.tg = self.t * self.gamma
        self.V = 2 * float(self.s["delta"]) * float(self.s["Lx"]) \
            * float(self.s["Lz"])
        self.d = float(self.s["dParticle"])
        self.np0 = int(round(st["nParticles"][0] + st["nAgg"][0]))
        self.np_after = st["nParticles"]
        self.np_before = np.concatenate(([self.np0], st["nParticles"][:-1]))
        self.dncol = np.diff(np.concatenate(([0.0], st["nCol"])))
        rt = self.case / "runTime"
        self.run_time = float(rt.read_text()) if rt.exists() else None

    def final(self, key):
        return float(self.st[key][-1])

    def alpha(self, first=False):
        col = self.st["nColFirst" if first else "nCol"]
        agg = self.st["nAggFirst" if first else "nAgg"]
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(col > 0, agg / np.maximum(col, 1), np.nan)

    def decay(self, alpha, form):
        return decay_theory(self.np0, self.dncol, self.np_before, alpha,
                            form)[1:] / self.np0

    def mass_error(self):
        m = self.st["mass"]
        return float(np.max(np.abs(m - m[0])) / m[0])


def row(name, value, expected, tol, ok, unit="", nr=None):
    """A regression row: ok True/False (PASS/FAIL), None (INFO); nr, the
    reason why the band cannot fail, makes it n/r."""
    r = reg.row(ok, nr, check=name, value=value, expected=expected,
                tolerance=tol)
    reason = r.pop("reason", None)
    r["unit"] = unit            # the field order of summary.json
    if reason:
        r["reason"] = reason
    return r


def post(preset, runs_dir=None, out_dir=None):
    runs_dir = Path(runs_dir or HERE / "runs" / preset)
    out = Path(out_dir or HERE / "results" / preset)
    out.mkdir(parents=True, exist_ok=True)
    runs = {r: Run(runs_dir / r) for r in RUNS
            if (runs_dir / r / "postProcessing").exists()}
    if not runs:
        raise SystemExit(f"no runs under {runs_dir}")
    any_run = next(iter(runs.values()))
    d, gamma, V = any_run.d, any_run.gamma, any_run.V
    np0 = any_run.np0
    n0 = np0 / V
    K_ST = kernel_ST(d, gamma=gamma)
    a_th = float(alpha_th(d, gamma))
    rows, summary = [], {
        "preset": preset, "V": V, "N0": np0, "n0": n0, "d": d,
        "gammaDot": gamma, "K_ST": K_ST, "alpha_th": a_th,
        "firstContactRate_ST": 0.5 * K_ST * n0**2 * V, "runs": {}}

    # Expected first contacts over the EAM/MAM runs: the statistical scale
    # of alpha (doc/cases.md B.5)
    phys = [r for r in ("EAM", "MAM") if r in runs]
    t_end = max((runs[r].t[-1] for r in phys), default=0.0)
    n_first_exp = 0.5 * K_ST * n0**2 * V * t_end
    sig_a = (math.sqrt((1 - a_th) / (a_th * n_first_exp))
             if n_first_exp > 0 else math.inf)
    band = (min(0.5, max(0.0, 1 - 3 * sig_a)), max(2.0, 1 + 3 * sig_a))
    # A band reaching 0 holds a run without any agglomeration: n/r
    band_nr = (f"the band {band[0]:.2f}-{band[1]:.2f} contains 0 "
               f"(sigma_alpha/alpha = {sig_a:.2f} with "
               f"{n_first_exp:.0f} expected first contacts)"
               if band[0] <= 0 else None)

    # Detection-only: first contacts against Saffman-Turner (B.6)
    if "detect" in runs:
        r = runs["detect"]
        t0 = float(r.s["countFrom"])
        k0 = int(np.argmin(np.abs(r.t - t0)))
        t0 = r.t[k0]
        nf = r.st["nColFirst"] - r.st["nColFirst"][k0]
        T = r.t[-1] - t0
        rate = 0.5 * K_ST * (r.np0 / r.V)**2 * r.V
        n_exp = rate * T
        n_sim = float(nf[-1])
        km = k0 + int(np.argmin(np.abs(r.t[k0:] - (t0 + 0.5 * T))))
        halves = [(float(nf[km]), rate * (r.t[km] - t0)),
                  (float(nf[-1] - nf[km]), rate * (r.t[-1] - r.t[km]))]
        ratio = n_sim / n_exp
        summary["detect"] = {
            "window_tGamma": [t0 * gamma, r.t[-1] * gamma],
            "N_first": n_sim, "N_expected": n_exp,
            "K_sim_over_K_ST": ratio, "sigma": 1 / math.sqrt(n_exp),
            "halves": halves, "N_all": r.final("nCol"),
            "N_overlapStart": r.final("nColOverlapStart"),
            "N_repeat": r.final("nColRepeat"), "run_time_s": r.run_time}
        rows.append(row("detect: K_first/K_ST (first contacts, ghost)",
                        ratio, 1.0, 3 / math.sqrt(n_exp),
                        abs(n_sim - n_exp) <= 3 * math.sqrt(n_exp)))
        for h, (ns, ne) in enumerate(halves):
            rows.append(row(f"detect: half {h + 1} N_first/N_expected",
                            ns / ne, 1.0, 3 / math.sqrt(ne),
                            abs(ns - ne) <= 3 * math.sqrt(ne)))

    # EAM and MAM
    for name in phys + (["bounce"] if "bounce" in runs else []):
        r = runs[name]
        a_all, a_first = r.alpha()[-1], r.alpha(first=True)[-1]
        info = {
            "tGamma_end": float(r.tg[-1]),
            "N_col": r.final("nCol"), "N_col_first": r.final("nColFirst"),
            "N_col_repeat": r.final("nColRepeat"),
            "N_col_overlapStart": r.final("nColOverlapStart"),
            "N_agg": r.final("nAgg"), "N_agg_first": r.final("nAggFirst"),
            "N_suppressed": r.final("nSuppressed"),
            "alpha": float(a_all), "alpha_first": float(a_first),
            "alpha_over_alpha_th": float(a_all / a_th),
            "alpha_first_over_alpha_th": float(a_first / a_th),
            "Ncol_all_over_first": r.final("nCol")
            / max(1.0, r.final("nColFirst")),
            "K_all_over_K_ST": r.final("nCol") / (0.5 * K_ST * n0**2 * V
                                                  * r.t[-1]),
            "K_first_over_K_ST": r.final("nColFirst")
            / (0.5 * K_ST * n0**2 * V * r.t[-1]),
            "Np_final_over_Np0": float(r.np_after[-1] / r.np0),
            "D10_final": r.final("D10"),
            "alpha_th_D10_final": float(alpha_th(r.final("D10"), gamma)),
            "maxPrimaries": r.final("maxPrimaries"),
            "mass_rel_error": r.mass_error(), "run_time_s": r.run_time,
            "steps": len(r.t)}
        if name in phys:
            for form in ("consistent", "printed"):
                th = r.decay(a_th, form)
                dev = float(np.max(np.abs(r.np_after / r.np0 - th) / th))
                info[f"Np_theory_{form}_final"] = float(th[-1])
                info[f"Np_max_deviation_{form}"] = dev
        summary["runs"][name] = info

        if name in phys:
            rows.append(row(f"{name}: alpha/alpha_th (all contacts)",
                            info["alpha_over_alpha_th"], 1.0,
                            f"{band[0]:.2f}-{band[1]:.2f}",
                            band[0] <= info["alpha_over_alpha_th"]
                            <= band[1], nr=band_nr))
            rows.append(row(f"{name}: alpha/alpha_th (first contacts)",
                            info["alpha_first_over_alpha_th"], 1.0,
                            f"{band[0]:.2f}-{band[1]:.2f}",
                            band[0] <= info["alpha_first_over_alpha_th"]
                            <= band[1], nr=band_nr))
            # The same against the binomial noise of the run's own first
            # contacts, under alpha = alpha_th: n/r while 3 sigma reaches 0
            nf = info["N_col_first"]
            sig = (math.sqrt((1 - a_th) / (a_th * nf)) if nf > 0
                   else math.inf)
            info["alpha_first_sigma_rel"] = sig
            ratio = info["alpha_first_over_alpha_th"]
            rows.append(row(f"{name}: alpha/alpha_th (first) within 3 sigma",
                            ratio, 1.0, 3 * sig, abs(ratio - 1) <= 3 * sig,
                            nr=(f"3 sigma_alpha/alpha = {3 * sig:.2f} with "
                                f"{nf:.0f} first contacts reaches 0"
                                if 3 * sig >= 1 else None)))
            rows.append(row(f"{name}: max |Np/Np0 - theory(own K)|/theory"
                            " consistent", info["Np_max_deviation_"
                                                "consistent"],
                            0.0, 0.05,
                            info["Np_max_deviation_consistent"] <= 0.05))
            rows.append(row(f"{name}: same, printed form (B.8 as printed)",
                            info["Np_max_deviation_printed"], 0.0, 0.05,
                            None))
        npp = r.st["nPrimaries"]
        rows.append(row(f"{name}: particle mass conserved", info[
            "mass_rel_error"], 0.0, 1e-12, info["mass_rel_error"] <= 1e-12))
        rows.append(row(f"{name}: primaries conserved, Np = Np0 - Nagg, "
                        "Np never increases",
                        float(np.max(np.abs(npp - npp[0]))), 0.0, 0,
                        bool(np.all(npp == npp[0])
                             and np.all(r.np_after == r.np0 - r.st["nAgg"])
                             and np.all(np.diff(r.np_after) <= 0))))

    if len(phys) == 2:
        # The paper's statements S1-S4 (shearStatements.py): the same rows
        # as the study's, judged on this preset's runs
        t_end_g = min(runs[k].tg[-1] for k in ("EAM", "MAM"))
        short = (f"the paper's statements concern t*gammaDot = "
                 f"{shearStatements.PAPER_END:g}; this preset ends at "
                 f"{t_end_g:g}" if t_end_g < shearStatements.PAPER_END
                 * (1 - 1e-6) else None)
        for r in shearStatements.statements(
                {k: runs[k] for k in ("EAM", "MAM")}, a_th, short):
            rows.append(row(f"{r['statement']}: {r['check']}", r["value"],
                            "-", r["tolerance"],
                            {reg.PASS: True, reg.FAIL: False}.get(
                                r["status"]), nr=r.get("reason")))
    summary["alpha_band"] = band
    summary["sigma_alpha_rel"] = sig_a
    summary["regression"] = rows

    (out / "summary.json").write_text(json.dumps(summary, indent=2,
                                                 default=float) + "\n")
    table = regression_table(preset, rows)
    (out / "regression.txt").write_text(table + "\n")
    print(table)
    plots(runs, out, a_th, K_ST, n0, gamma)
    picture(runs, out)
    return 0 if all(r["status"] != reg.FAIL for r in rows) else 1


def fmt(v):
    if isinstance(v, str):
        return v
    if v == 0 or 1e-3 <= abs(v) < 1e5:
        return f"{v:.4g}"
    return f"{v:.3e}"


def regression_table(preset, rows):
    w = max(len(r["check"]) for r in rows)
    cols = [reg.Column("check", "check", w),
            reg.Column("value", "value", 10, ">", fmt, "  "),
            reg.Column("expected", "expected", 9, ">", fmt, "  "),
            reg.Column("tolerance", "tolerance", 11, ">", fmt, "  "),
            reg.Column("status", "status", gap="  ")]
    head, *body = reg.table(rows, cols)
    lines = [f"shearFlowValidation regression, preset {preset}", head,
             "-" * (w + 46)] + body + ["-" * (w + 46)]
    for r in rows:
        if r["status"] == reg.NR:
            lines.append(f"n/r {r['check']}: {r['reason']}")
    lines.append(f"{len(rows)} rows, {reg.counts(rows)[reg.FAIL]} FAIL")
    return "\n".join(lines)


def plots(runs, out, a_th, K_ST, n0, gamma):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    phys = [r for r in ("EAM", "MAM") if r in runs]
    col = {"EAM": "C0", "MAM": "C3", "bounce": "C2", "detect": "k"}

    if phys:
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for name in phys:
            r = runs[name]
            ax.plot(r.tg, r.alpha(), color=col[name], label=f"{name}")
            ax.plot(r.tg, r.alpha(first=True), color=col[name], ls=":",
                    label=f"{name}, first contacts")
            ax.plot(r.tg, alpha_th(r.st["D10"], gamma), color=col[name],
                    ls="--", lw=0.8, label=rf"$\alpha_{{th}}(\bar d)$, {name}")
        ax.axhline(a_th, color="k", lw=0.8,
                   label=rf"$\alpha_{{th}}(d_p)$ = {100 * a_th:.2f} %")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_ylabel(r"$\alpha = N_{agg}/N_{col}$")
        ax.set_ylim(0, 0.1)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "alpha.png", dpi=120)
        plt.close(fig)

        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for name in phys:
            r = runs[name]
            ax.plot(r.tg, r.st["nCol"], color=col[name],
                    label=rf"$N_{{col}}$ {name}")
            ax.plot(r.tg, r.st["nColFirst"], color=col[name], ls=":",
                    label=rf"$N_{{col,first}}$ {name}")
            ax.plot(r.tg, 20 * r.st["nAgg"], color=col[name], ls="--",
                    label=rf"$20 N_{{agg}}$ {name}")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_ylabel("cumulative count")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "counts.png", dpi=120)
        plt.close(fig)

        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for name in phys:
            r = runs[name]
            ax.plot(r.tg, r.np_after / r.np0, color=col[name], lw=2,
                    label=f"{name}")
            ax.plot(r.tg, r.decay(a_th, "consistent"), color=col[name],
                    ls="--", label=f"theory, K from {name}, consistent")
            ax.plot(r.tg, r.decay(a_th, "printed"), color=col[name],
                    ls=":", label=f"theory, K from {name}, printed B.8")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_ylabel(r"$N_p(t)/N_p(0)$")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "decay.png", dpi=120)
        plt.close(fig)

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, r in runs.items():
        if name == "detect":
            t0 = float(r.s["countFrom"])
            k0 = int(np.argmin(np.abs(r.t - t0)))
            y = r.st["nColFirst"] - r.st["nColFirst"][k0]
            rate = 0.5 * K_ST * (r.np0 / r.V)**2 * r.V
            ax.plot(r.tg[k0:], y[k0:], color="k",
                    label="detection only (ghost), first contacts")
            ax.plot(r.tg[k0:], rate * (r.t[k0:] - r.t[k0]), "k--",
                    label=r"$\frac{1}{2} K_{ST} n_0^2 V (t - t_0)$")
        else:
            ax.plot(r.tg, r.st["nColFirst"], color=col[name],
                    label=f"{name}, first contacts")
    ax.set_xlabel(r"$t\dot\gamma$")
    ax.set_ylabel(r"$N_{col,first}$")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "firstContacts.png", dpi=120)
    plt.close(fig)


def picture(runs, out):
    """pyvista picture of the final particle field of each agglomerating
    run, coloured by primaries per agglomerate."""
    for name in ("EAM", "MAM"):
        if name not in runs:
            continue
        r = runs[name]
        tdirs = [p for p in times.time_dirs(r.case)
                 if (p / "lagrangian" / "kinematicCloud" / "positions")
                 .exists() and float(p.name) > 0]
        if not tdirs:
            continue
        lag = tdirs[-1] / "lagrangian" / "kinematicCloud"
        x = cloud.read_positions(lag / "positions")
        npr = cloud.read_lagrangian(lag / "nPrimary")
        delta, Lx, Lz = (float(r.s[k]) for k in ("delta", "Lx", "Lz"))
        n_ag = int(np.sum(npr > 1))
        render.particles_picture(
            out / f"particles{name}.png", x, npr,
            (0, Lx, -delta, delta, 0, Lz),
            title=f"{name}, t*gammaDot = {float(tdirs[-1].name) * r.gamma:.0f}"
                  f": {len(x)} particles, {n_ag} agglomerates (coloured)")


def progress(case):
    """One line: t*gammaDot, fraction done and ETA from the solver log."""
    s = read_settings(case)
    g, t_end = float(s["gammaDot"]), float(s["endTime"])
    now = prog.solver_progress(Path(case) / "log.aggloPimpleFoam", t_end,
                               float(s["deltaT"]))
    if now is None:
        return "starting"
    t, frac, eta = now
    return (f"t*gammaDot = {t * g:.1f}, run ends at {t_end * g:.0f} "
            + prog.line(frac, eta))


# -------------------------------------------------------------------- main

def main(argv):
    if len(argv) >= 3 and argv[0] == "settings":
        print(settings_text(settings(argv[1], argv[2])))
        return 0
    if len(argv) == 2 and argv[0] == "init":
        init(argv[1])
        return 0
    if len(argv) == 2 and argv[0] == "progress":
        print(progress(argv[1]))
        return 0
    if len(argv) == 2 and argv[0] == "settle":
        times.set_aside_incomplete_times(argv[1])
        return 0
    if len(argv) >= 2 and argv[0] == "post":
        return post(argv[1], *(argv[2:4]))
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
