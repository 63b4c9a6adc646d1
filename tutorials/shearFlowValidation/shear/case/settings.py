"""shearFlowValidation: set-up of the laminar shear-flow validation (paper
Appendix B; doc/cases.md B.1-B.6) and the command line of the tutorial.
The theory is in shear.theory, the post-processing in shear.post.

    python -m shear.case settings PRESET RUN
        caseSettings of one run (stdout)
    python -m shear.case init CASE
        exact Couette profile and particles
    python -m shear.case settle CASE
        set aside a last time folder whose write was cut off (before a
        restart)
    python -m shear.case progress CASE
        simulated time and ETA of a run
    python -m shear.case post PRESET
        results/PRESET: summary.json, plots, regression.txt (exit 1 on a
        FAIL; shear.post)

Runs: detect (ghost contacts, no agglomeration, first-contact counting, for
the Saffman-Turner check), EAM, MAM, and optionally bounce (physical
rebounds, no agglomeration: the secondary first-contact check of B.6).
"""

import argparse
from pathlib import Path

import numpy as np

from aggloTools import cloud, fields, placement, progress as prog, times
from aggloTools import casesettings
from aggloTools.foamfile import check_keys

from shear import TUTORIAL
from shear.case.entries import RUNS, read_settings
from shear.theory import RHO_P


# ---------------------------------------------------------------- settings

PRESET_KEYS = {"nx", "LxByDelta", "nParticles", "endGamma",
               "detectEndGamma", "detectDtGamma", "writes", "eventLog"}
COMMON_KEYS = {"gammaDot", "delta", "LzByDelta", "ny", "nz", "dParticle",
               "seed", "dtGamma", "detectDtGamma", "countFromGamma",
               "eventLog", "fluidTorque"}


N = casesettings.Number
#: What each numeric entry must be (the steps: check_step)
NUMBERS = {"nx": N(int, 1), "ny": N(int, 1), "nz": N(int, 1),
           "LxByDelta": N(float, 0, open_lo=True),
           "LzByDelta": N(float, 0, open_lo=True), "nParticles": N(int, 1),
           "endGamma": N(float, 0, open_lo=True),
           "detectEndGamma": N(float, 0, open_lo=True), "writes": N(int, 1),
           "gammaDot": N(float, 0, open_lo=True),
           "delta": N(float, 0, open_lo=True),
           "dParticle": N(float, 0, open_lo=True), "seed": N(int, 0),
           "countFromGamma": N(float, 0)}


def presets():
    """The presets file, every entry checked (its keys, and the numbers
    of NUMBERS: type and range)."""
    ps = casesettings.read_presets(TUTORIAL / "presets", PRESET_KEYS,
                                   {"common": COMMON_KEYS})
    return {name: casesettings.checked(p, NUMBERS, f"presets/{name}")
            for name, p in ps.items()}


def on_off(v, where):
    return casesettings.choice(v, ("on", "off"), where)


#: The readings a study may vary (shear.study), with their values; the
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


#: The range of a step dt*gammaDot (dtGamma, detectDtGamma): positive
#: (a negative one ran the solver backwards in time) and not so small that
#: a run takes billions of steps
DT_GAMMA_RANGE = (1e-4, 0.1)


def check_step(v, where):
    """v as a step dt*gammaDot, or stop naming where and the range."""
    lo, hi = DT_GAMMA_RANGE
    try:
        x = float(v)
    except (TypeError, ValueError):
        x = None
    if isinstance(v, bool) or x is None or not lo <= x <= hi:
        raise SystemExit(f"{where} {v!r} is not a number in [{lo:g}, "
                         f"{hi:g}]")
    return x


def check_reading(variant, where):
    """Stop on an unknown reading or value, naming it and the choices."""
    check_keys(variant, set(READINGS), where)
    for k, v in variant.items():
        choices = READINGS[k]
        if choices is None:
            if not isinstance(v, (int, float)):
                raise SystemExit(f"{where}: {k} {v!r} is not a number")
            check_step(v, f"{where}: {k}")
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
    out["dtGamma"] = check_step(c["dtGamma"], "presets/common: dtGamma")
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
    p = casesettings.named(ps, preset, "preset", "shear.case",
                           exclude=("common",))
    casesettings.choice(run, RUNS, "shear.case: run")
    c = ps["common"]
    gamma, delta = float(c["gammaDot"]), float(c["delta"])
    detect = run == "detect"
    dt_g = (check_step(p.get("detectDtGamma", c["detectDtGamma"]),
                       f"presets/{preset}: detectDtGamma") if detect
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
    lines = ["// Written by python -m shear.case settings for the preset "
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
    print(f"shear.case init: {len(x)} particles, U = {gamma} y e_x in "
          f"{nx}x{ny}x{nz} cells")

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
    ap = argparse.ArgumentParser(
        prog="shear.case", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("settings", help="the caseSettings of one run, on "
                       "standard output")
    s.add_argument("preset", help="a preset of the presets file")
    s.add_argument("run", choices=RUNS, help="the run")
    for name, what in (("init", "the exact Couette profile and the "
                        "particles"), ("settle", "set aside a last time "
                        "folder whose write was cut off"),
                       ("progress", "simulated time and ETA of a run")):
        sub.add_parser(name, help=what).add_argument(
            "case", help="the run's case folder")
    p = sub.add_parser("post", help="the report of a preset's runs "
                       "(shear.post; exit 1 on a FAIL)")
    p.add_argument("preset", help="the preset")
    p.add_argument("runs", nargs="?", help="the folder holding its runs "
                   "(default runs/PRESET)")
    p.add_argument("out", nargs="?", help="the report's folder (default "
                   "results/PRESET)")
    a = ap.parse_args(argv)
    if a.cmd == "settings":
        print(settings_text(settings(a.preset, a.run)))
    elif a.cmd == "init":
        init(a.case)
    elif a.cmd == "progress":
        print(progress(a.case))
    elif a.cmd == "settle":
        times.set_aside_incomplete_times(a.case)
    else:
        from shear.post import postprocess
        return postprocess.post(a.preset, a.runs or None, a.out or None)
    return 0

