"""verticalChannel: set-up and post-processing of the paper's main case
(downward turbulent channel flow; doc/cases.md Part A).

    channel.case settings [-np N] PRESET CONFIG STAGE [MODEL ...]
                                  caseSettings of one stage (stdout) for
                                  N MPI ranks (default 1); CONFIG may be
                                  a group of one-way configurations
                                  (R80+R60: channel.case.groups)
    channel.case init CASE          initial flow: mean profile plus seeded
                                  divergence-free perturbations (at time 0)

The particles (release, the smoke preset's seeded pairs, the branch into
one cloud per model): channel.case.particles; the break-up entry:
channel.case.breakup; the presets file read and checked:
channel.case.presets (preset and configuration, offered here too). The
stages are run by channel.case.runs (./Allrun), which calls preset and
configuration directly.

Post-processing: channel.post PRESET.

Stages: unladen (single phase), release and dispersion (one cloud
"particles", collisions on, agglomeration off), agglomeration (clouds EAM
and MAM, or the preset's `models`, in one run for one-way coupled
configurations, one per run for the two-way coupled ones; counters zeroed
at its start). A preset with `stagesFrom NAME` runs the agglomeration
stage only, branched from runs/NAME's dispersion (shared_stages).
"""

import argparse
import sys
from pathlib import Path

import numpy as np

from aggloTools import casesettings, fields
from channel import TUTORIAL
from channel.case import groups
from channel.case.breakup import breakup_entry
# the presets' reader (its own module); the other modules reach it here
from channel.case.presets import (MODELS, PI, configuration,  # noqa: F401
                                  preset, read_presets)


def report_dir(pname, reference=False):
    """Where the post-processing of a preset writes: its runs' report
    (runs/<preset>/report), or the committed reference (results/<preset>)
    with reference."""
    return (TUTORIAL / "results" / pname if reference
            else TUTORIAL / "runs" / pname / "report")

STAGES = ("unladen", "release", "dispersion", "agglomeration")
N_PAPER = 6.0e6
#: AB16 Tab. D.6: f_col, f_agg per model (per T*, the paper's 6e6
#: particles)
TABLE_D6 = {
    "C1": {"fcol": {"EAM": 8.14e4, "MAM": 7.79e4},
           "fagg": {"EAM": 6.67e2, "MAM": 5.39e2}},
    "C2": {"fcol": {"EAM": 5.85e4, "MAM": 5.83e4},
           "fagg": {"EAM": 1.72e2, "MAM": 1.29e2}},
    "C3": {"fcol": {"EAM": 3.91e4, "MAM": 3.88e4},
           "fagg": {"EAM": 1.93e2, "MAM": 1.39e2}},
    "C4": {"fcol": {"EAM": 1.24e3, "MAM": 1.23e3},
           "fagg": {"EAM": 2.1e1, "MAM": 1.36e1}},
}


def steps(p, stage):
    """Cumulative step number at the end of a stage."""
    n = 0
    for s in STAGES:
        n += int(round(p[s] / p["dtStar"]))
        if s == stage:
            return n
    raise ValueError(stage)


def end_time(p, stage):
    return steps(p, stage) * p["deltaT"]


def collision(c):
    """The caseSettings values of a configuration c that are its clouds'
    own in a group (groups.OWN): e_n,p and the wall, as text."""
    if c["wall"] == "rough":
        wall = ("wallModel sandgrain; sandgrainCoeffs { en 0.9; et 0.3;"
                " muSt 0.5; muKin 0.4; Rz 10e-6; CSurface 3; }")
    else:
        wall = (f"wallModel smooth; smoothCoeffs {{ en {c['en']}; et 0.44;"
                " muSt 0.94; muKin 0.092; }")
    return {"enParticle": str(c["en"]), "wallType": c["wall"],
            "wallCoeffs": f"{{ {wall} }}"}


def forces(c):
    """The caseSettings values of a configuration c that follow from the
    sub-models it switches on (presets.SUB_MODELS), apart from the
    coupling: the clouds' forces (drag and gravity, plus the lift forces
    switched on) and the SGS velocity's model, as text; a group's
    members' own (groups.OWN)."""
    on = c["switched"]
    lift = (("SaffmanMeiLiftForce { U U; }",) if "shearLift" in on else ()) \
        + (("rotationLift { model OesterleBuiDinh; }",)
           if "rotationLift" in on else ())
    return {"cloudForces": "{ " + " ".join(
                ("SchillerNaumannDrag;",) + lift + ("gravity;",)) + " }",
            "dispersionModel": ("PozorskiApte" if "sgsDispersion" in on
                                else "none")}


def member_entries(name):
    """A group member's own caseSettings values (groups.OWN): its
    sub-models, forces, SGS model and collision coefficients."""
    c = configuration(name)
    return dict(subModels=c["subModels"], **forces(c), **collision(c))


def settings(pname, cname, stage, models=(), nprocs=1):
    """The caseSettings of one stage of a configuration, or of a group
    of one-way configurations run as clouds of one LES (groups)."""
    group = groups.is_group(cname)
    if group:
        groups.check(pname, cname)
    p = preset(pname, groups.lead(cname))
    c = configuration(groups.lead(cname))
    casesettings.choice(stage, STAGES, "channel.case: stage")
    for m in models:
        casesettings.choice(m, MODELS, "channel.case: model")
    if stage == "agglomeration":
        if not models:
            models = p["models"][:1] if c["twoWay"] else p["models"]
        if c["twoWay"] and len(models) != 1:
            sys.exit("channel.case: a two-way coupled configuration runs one"
                     " agglomeration model per run")
    clouds = "(" + " ".join(groups.clouds(cname, stage, models)) + ")"
    on = c["twoWay"]
    clouds_comment = (
        "// Clouds of this stage: none (unladen), particles (release, "
        "dispersion:\n// no agglomeration), then one cloud per "
        "agglomeration model")
    if group:
        clouds_comment = (
            "// Clouds of this stage: one per configuration of the group "
            "(release,\n// dispersion), one per configuration and model "
            "(agglomeration)")
        own = groups.entries(cname, member_entries)
        sub = ""
    else:
        own = "\n".join(f"{k:<15} {v}" + ("" if v.startswith("{") else ";")
                        for k, v in dict(forces(c), **collision(c)).items())
        sub = (f"subModels       {c['subModels']};    // " + (
            "two-way coupling + lift + SGS" if c["subModels"] in
            ("on", "off") else "those switched on") + "\n")
    Lx, Ly, Lz = p["L"]
    nx, ny, nz = p["n"]
    write_steps = max(1, int(round(p["writeStar"] / p["dtStar"])))
    t_scale = f"{p['tScale']:.6g}"
    stage_end = f"{steps(p, stage) * p['dtStar']:.6g}"
    positions = 1 if p['writePositions'] == 'on' else 0
    return f"""\
/*--------------------------------*- C++ -*----------------------------------*\\
| agglomerationHardSphere: verticalChannel                                    |
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "system";
    object      caseSettings;
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// The parameters of one stage of one run, in one place: written by
//     python -m channel.case settings {pname} {cname} {stage} \
{' '.join(models)}
// (./Allrun does it) from the presets and configurations files and
// #included by the other dictionaries. Times in s; delta/U_B = {t_scale} s.

preset          {pname};
configuration   {cname};
stage           {stage};

// Mesh: 2 pi delta x 2 delta x pi delta, wall-graded in y
Lx              {Lx:.10g};
Ly              {Ly:.10g};
Lz              {Lz:.10g};
nx              {nx};
ny              {ny};
nz              {nz};
yGrading        {p['yGrading']};
yGradingInv     {1 / p['yGrading']:.10g};

// Time: dt* = {p['dtStar']}; this stage ends at T* = {stage_end}
deltaT          {p['deltaT']:.10g};
endTime         {end_time(p, stage):.10g};
writeSteps      {write_steps};
writeFormat     {p['writeFormat']};
purgeWrite      {p['purgeWrite']};      // keep the last N writes (0: all)
writePositions  {positions};  // legacy positions too
ddtScheme       {p['ddtScheme']};
UTolerance      {p['UTolerance']:g};   // the velocity solver's (fvSolution)

// Flow (Re_b = 11900)
Ubar            {p['Ubar']};
nProcs          {nprocs};

// Particles: configuration {cname}
dParticle       {c['d']};
nParticles      {int(p['nParticles'])};
seed            {p['seed']};
{sub}coupled         {'true' if on else 'false'};
couplingScale   {p['couplingScale'] if on else 1};
{own}
profileBins     {p['profileBins']};

{clouds_comment}
clouds          {clouds};

// The collision-event log of the agglomeration stage (doc/eventLog.md)
eventLog        {p['eventLog'] if stage == 'agglomeration' else 'off'};

// Break-up (the preset's `breakup`, breakupModels: {p['breakup']}), merged
// into the clouds' subModels; in the agglomeration stage only
{breakup_entry(p, stage)}

// ************************************************************************* //
"""


# ------------------------------------------------------------ mesh helpers

SETTINGS_KEYS = {"preset", "configuration", "stage", "Lx", "Ly", "Lz", "nx",
                 "ny", "nz", "yGrading", "yGradingInv", "deltaT", "endTime",
                 "writeSteps", "writeFormat", "purgeWrite",
                 "writePositions", "ddtScheme", "UTolerance", "Ubar",
                 "nProcs",
                 "dParticle", "nParticles", "seed", "subModels", "coupled",
                 "couplingScale", "cloudForces", "dispersionModel",
                 "enParticle", "wallType", "wallCoeffs", "profileBins",
                 "clouds", "eventLog", "breakup"}


def read_settings(case):
    """The caseSettings of a stage, every entry checked (a group's
    members' entries too: groups)."""
    return casesettings.read_settings(
        case, SETTINGS_KEYS,
        lambda s: groups.own_entries(str(s.get("configuration", ""))))


def cell_centres(case, time="0"):
    """Cell centres (postProcess -func writeCellCentres must have run)."""
    return fields.read_internal(Path(case) / time / "C")


# ------------------------------------------------------------------- init

def init(case):
    """Initial flow at time 0: the 1/7 power-law profile with bulk velocity
    U_B plus seeded perturbations of amplitude perturb*U_B: three
    streamwise vortices psi = f(y) sin(kz z + phase) (v = dpsi/dz,
    w = -dpsi/dy: divergence free) and three streak modes
    u' = f(y) sin(kx x + phase) cos(kz z) with the w' that makes them
    divergence free, f = (1 - (y/delta - 1)^2)^2, plus 5 % white noise
    (removed by the first pressure projection)."""
    case = Path(case)
    s = read_settings(case)
    p = preset(s["preset"])
    C = cell_centres(case)
    d, Ub, A = p["delta"], p["Ubar"], p["perturb"]
    Lx, _, Lz = p["L"]
    x, y, z = C[:, 0], C[:, 1], C[:, 2]
    eta = np.clip(1 - np.abs(y - d) / d, 0, 1)      # 0 at walls, 1 centre
    U = np.zeros_like(C)
    U[:, 0] = Ub * 8 / 7 * eta**(1 / 7)
    rng = np.random.default_rng(int(p["seed"]))
    yy = (y - d) / d
    f = (1 - yy**2)**2
    dfdy = -4 * yy * (1 - yy**2) / d
    amp = A * Ub / 3
    for kz_n, kx_n in ((4, 2), (6, 3), (8, 1)):
        ph = rng.uniform(0, 2 * PI, 2)
        kz, kx = 2 * PI * kz_n / Lz, 2 * PI * kx_n / Lx
        U[:, 1] += amp * f * np.cos(kz * z + ph[0])
        U[:, 2] -= amp / kz * dfdy * np.sin(kz * z + ph[0])
        U[:, 0] += amp * f * np.sin(kx * x + ph[1]) * np.cos(kz * z)
        U[:, 2] -= (amp * f * kx / kz * np.cos(kx * x + ph[1])
                    * np.sin(kz * z))
    U += A * Ub * 0.05 * rng.standard_normal(U.shape) * f[:, None]
    fields.set_internal_vector_field(case / "0/U", U)


# ------------------------------------------------------------------- main

def main(argv):
    ap = argparse.ArgumentParser(
        prog="channel.case", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    st = sub.add_parser("settings", help="the caseSettings of one stage, "
                        "on standard output")
    st.add_argument("-np", type=int, default=1,
                    help="MPI ranks of the stage (default 1)")
    st.add_argument("preset", help="a preset of the presets file")
    st.add_argument("config", help="a configuration (C1 ... R60), or "
                    "one-way ones joined with '+' (R80+R60: groups)")
    st.add_argument("stage", choices=STAGES, help="the stage")
    st.add_argument("models", nargs="*", help="the agglomeration stage's "
                    "clouds (EAM, MAM)")
    it = sub.add_parser("init", help="the initial flow of the unladen "
                        "stage (mean profile and seeded perturbations)")
    it.add_argument("case", help="the unladen case folder")
    a = ap.parse_args(argv[1:])
    if a.cmd == "settings":
        if a.np < 1:
            ap.error("settings: -np needs a positive number of ranks")
        sys.stdout.write(settings(a.preset, a.config, a.stage,
                                  tuple(a.models), a.np))
    else:
        init(a.case)
    return 0

