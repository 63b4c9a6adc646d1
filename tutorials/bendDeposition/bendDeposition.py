"""bendDeposition: particles through a 90-degree bend of circular
cross-section in developed laminar flow (Re = 1000), deposited where they
touch the wall (wallModel stick), against the Stokes number (README.md).
An O-grid pipe (aggloTools.bendmesh) with straight inlet and outlet
pipes; the flow solved first (aggloPimpleFoam, no particles), then, in
the frozen flow, one run per Stokes number: single particles injected
over the inlet with the inflow (keyedPatchInjection, placement flux: a
uniform concentration in the incoming air) at the air's velocity there,
one-way coupled, Schiller-Naumann drag, no gravity, no
collisions between them (dilute), until every particle has deposited or
left. The preset `agglomeration` is the dense variant: one run of
polydisperse primaries with the collision stage and EAM agglomeration on
(bendAgglomeration.py).

    ./Allrun [-preset default|coarseWall|mediumWall|fineWall|
                      fineSection|finerSection|ci|agglomeration]
             [-np N] [-j N] [-post] [-reference] [-every S]

coarseWall, mediumWall, fineWall, fineSection and finerSection: the
study of the resolution (README.md, "The resolution"), default's pipe
with other ring blocks or more cells across the section.

St = rho_p d_p^2 U / (9 mu D) = tau_p U / a (tau_p = rho_p d_p^2 / (18
mu), U the mean velocity, D = 2a the pipe diameter; no slip correction).
The deposition efficiency of the bend: eta = N_bend / N_entered, the
particles deposited in the bend among those that entered it (less those
still in the inlet pipe or the bend at the end), with the binomial sigma
sqrt(eta (1 - eta) / n).

-np N runs the particles on N ranks (the flow stays serial), decomposed
by aggloTools.decomposition.scattered (planes at arbitrary angles, where
a user would take scotch, a dummy library in Debian's v1912), in
runs/<preset>-np<N>; the report then compares every count with the
serial runs of the preset (a difference FAILs the row).

Runs: runs/<preset>[-np<N>]/flow and .../St<St> (a finished run is
kept; an interrupted one continues from its last complete write; one
driver at a time per preset). Report: <runs>/report (-reference:
results/<preset>[-np<N>]): summary.json, table.txt, efficiency.png,
deposits.png. Exit status 1 if a row FAILs its gate (the balance, the
theory's limits, the serial counts); the comparison with Pui et al.'s
measurements (bendMeasured) is a column of its own, a result."""

import json
import math
import shutil
import sys
import time
from pathlib import Path

from aggloTools import (bendmesh, boxcase, decomposition, runtimes, stages,
                        times)
from aggloTools.progress import line, solver_progress
from aggloTools.runner import foam_bin
from aggloTools.times import last_time

import bendAgglomeration
import bendEfficiency
import bendMeasured
from bendPlots import deposits_plot, efficiency_plot
from bendPresets import PRESETS

HERE = Path(__file__).resolve().parent

# Air; the pipe (D = 5 mm); Re = U D / nu = 1000
NU, RHO_F = 1.5e-5, 1.2
MU = NU * RHO_F
D, RE = 5e-3, 1000
U_MEAN = RE * NU / D
# Curvature ratio R/a [rec]: set in the presets (README.md)
RHO_P = 2200.0                     # the material's rho0 (box kernel)
# A particle run lasts the injection plus this many transits at the mean
# velocity: the slowest, next to the wall, are then out (or counted)
TRANSITS = 6


def geometry(p):
    a = D / 2
    return bendmesh.Geometry(a=a, R=p["curvature"] * a,
                             L_in=p["straight"] * D, L_out=p["straight"] * D)


def diameter(st):
    """The particle diameter of a Stokes number (St = rho_p d^2 U/(9 mu D))."""
    return math.sqrt(st * 9 * MU * D / (RHO_P * U_MEAN))


def transit(p):
    """The time a particle at the mean velocity needs through the pipe."""
    g = geometry(p)
    return (g.L_in + g.bend_length + g.L_out) / U_MEAN


def particle_runs(p):
    """The particle runs of a preset: name -> (size distribution entries,
    agglomeration model)."""
    if "sizes" in p:
        lo, hi = p["sizes"]
        return {p["model"]: ({"type": "uniform", "uniformDistribution":
                              {"minValue": lo, "maxValue": hi}},
                             p["model"])}
    return {case_name(st): ({"type": "fixedValue", "fixedValueDistribution":
                             {"value": diameter(st)}}, "none")
            for st in p["stokes"]}


#: The pipe's ends let particles escape, its walls (where the collision
#: model does not take them) rebound
ESCAPE = {"patchInteractionModel": "localInteraction",
          "localInteractionCoeffs": {
              "patches": '( "(inlet|outlet)" { type escape; } '
                         '"(inletPipe|bend|outletPipe)" '
                         '{ type rebound; e 1; mu 0; } )'}}


def stick(model):
    """The collision model's body: quartz, sticking walls, the
    agglomeration model (none: collisions only)."""
    return boxcase.kernel(model, walls={
        '"(inletPipe|bend|outletPipe)"': {"wallModel": "stick"}})


def injector(p, sizes):
    """keyedPatchInjection at the inlet with the fluid's face flux: the
    preset's parcels over its injection time, of the size distribution
    sizes."""
    return {"inlet": {
        "type": "keyedPatchInjection", "patch": "inlet", "SOI": 0,
        "duration": p["inject"],
        "parcelsPerSecond": p["parcels"] / p["inject"],
        "placement": "flux", "massTotal": 0, "parcelBasisType": "fixed",
        "nParticle": 1, "sizeDistribution": sizes}}


def build_flow(case, p):
    g = geometry(p)
    steps = round(p["flow_end"] / p["dt"])
    bendmesh.pipe_case(case, g, n=p["n"], n_ring=p["n_ring"],
                       n_axial=p["n_axial"], ring_grading=p["grading"],
                       inlet_velocity=(0, 0, U_MEAN),
                       particles=[], hard_sphere="none",
                       cloud={"subModels": ESCAPE},
                       dt=p["dt"], end_time=p["flow_end"],
                       write_interval=steps, frozen=False, nu=NU,
                       rho_f=RHO_F, tol=1e-7)
    stages.run_logged([foam_bin("blockMesh")], case, "log.blockMesh")
    bendmesh.bend_points(case, g)
    bendmesh.developed_inlet(case, g, U_MEAN)


def run_end(p):
    """A particle run's end: the injection and the preset's transits
    (TRANSITS where it names none)."""
    return p["inject"] + p.get("transits", TRANSITS) * transit(p)


def build_particles(case, flow, p, sizes, model, ranks):
    """The particle run: the flow's mesh and final fields at time 0,
    frozen, the injector at the inlet, sticking walls; on ranks > 1
    decomposed (scattered)."""
    g = geometry(p)
    end = run_end(p)
    steps = round(end / p["dt"])
    bendmesh.pipe_case(case, g, n=p["n"], n_ring=p["n_ring"],
                       n_axial=p["n_axial"], ring_grading=p["grading"],
                       particles=[], hard_sphere=stick(model),
                       dt=p["dt"], end_time=end, write_interval=steps,
                       frozen=True, nu=NU, rho_f=RHO_F,
                       cloud={"solution": {
                           "integrationSchemes": {"U": "analytical"}},
                           "subModels": {
                               **ESCAPE, "particleForces": boxcase.DRAG,
                               "injectionModels": injector(p, sizes)}})
    shutil.copytree(flow / "constant" / "polyMesh",
                    case / "constant" / "polyMesh", dirs_exist_ok=True)
    t = last_time(flow)
    for f in ("U", "p", "phi"):
        shutil.copy(flow / t / f, case / "0" / f)
    shutil.rmtree(case / "0" / "lagrangian", ignore_errors=True)
    shutil.rmtree(case / "0" / "uniform", ignore_errors=True)
    if ranks > 1:
        decomposition.scattered(case, ranks)
        stages.decompose(case)


#: Written when a run on N ranks has been reconstructed
RECONSTRUCTED = "done.reconstructPar"


def finished(case):
    log = case / "log.aggloPimpleFoam"
    done = log.is_file() and "\nEnd\n" in log.read_text()
    if done and list(case.glob("processor[0-9]*")):
        return (case / RECONSTRUCTED).is_file()
    return done


def run_one(case, label, build, end, dt, every, ranks=1):
    """Build (unless there) and run one case to its end, continuing from
    its last complete write (serial; on N ranks a particle run writes
    only at its end and is run again whole)."""
    tag = f"    {label}"
    if finished(case):
        print(f"{tag}: finished earlier, kept", flush=True)
        return
    append = ranks == 1 and (case / "constant" / "polyMesh" /
                             "faces").is_file()
    if append:
        times.set_aside_incomplete_times(case)
    else:
        shutil.rmtree(case, ignore_errors=True)
        build()

    def progress(c):
        log = c / "log.aggloPimpleFoam"
        at = solver_progress(log, end, dt) if log.is_file() else None
        return "starting" if at is None else \
            f"t = {at[0]:.4g} s of {end:.4g} s {line(at[1], at[2])}"
    cmd = [foam_bin("aggloPimpleFoam")]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), cmd[0], "-parallel"]
    wall = stages.run_solver(case, cmd, label, progress, every,
                             append=append)
    if ranks > 1:
        stages.run_logged([foam_bin("reconstructPar"), "-latestTime"], case,
                          "log.reconstructPar")
        (case / RECONSTRUCTED).write_text("\n")
    print(f"{tag}: done in {round(wall)} s", flush=True)


def case_name(st):
    return f"St{st:g}"


def options(argv):
    p = stages.Parser("bendDeposition", __doc__)
    p.add_argument("-preset", default="default", choices=sorted(PRESETS),
                   help="the Stokes numbers, mesh and particles "
                   "(default: default)")
    p.add_argument("-np", type=stages.positive("-np"), default=1,
                   help="ranks of each particle run (default 1: serial; "
                   "above 1 the report compares with the serial runs)")
    p.add_argument("-j", type=stages.positive("-j"), default=2,
                   help="particle runs at a time (default 2)")
    p.add_argument("-post", action="store_true",
                   help="only the report of the finished runs")
    p.add_argument("-reference", action="store_true",
                   help="write the report into results/<preset> "
                   "(results/<preset>-np<N> with -np N)")
    p.add_argument("-every", type=stages.positive("-every"), default=60,
                   help="seconds between progress lines (default 60)")
    a = p.parse_args(argv)
    stages.within_cores(p, a.np)
    return a


def base_of(preset, ranks):
    name = preset if ranks == 1 else f"{preset}-np{ranks}"
    return HERE / "runs" / name


def rows_of(base, p):
    """The report's rows of a preset's finished runs under base."""
    g = geometry(p)
    if "sizes" in p:
        return [bendAgglomeration.analyse(base / p["model"], p, g)]
    return [bendEfficiency.analyse(base / case_name(st), st, diameter(st),
                                   p, g) for st in p["stokes"]]


def verdicts(rows, p, serial):
    """The rows judged (and compared with the serial rows, if given);
    the report's text."""
    if "sizes" in p:
        row = bendAgglomeration.judge(rows[0])
        if serial is not False:
            same = ("deposited", "escaped", "depositedPrimaries",
                    "escapedPrimaries", "inFlight", "inFlightPrimaries",
                    "nCol", "nAgg")
            bendEfficiency.compare(rows, serial, key="model", same=same)
        return bendAgglomeration.table(row)
    bendEfficiency.judge(rows)
    if serial is not False:
        bendEfficiency.compare(rows, serial)
    bendMeasured.compare(rows, RE, p["curvature"])
    return bendEfficiency.table(rows, bendMeasured.summary(rows))


def simulate(a, p, base, cases):
    """The flow, then the particle runs; 1 if one failed."""
    flow = base / "flow"
    print(f"bendDeposition: preset {a.preset}, the flow, then "
          f"{len(cases)} particle run(s) on {a.np} rank(s), {a.j} at a "
          "time", flush=True)
    with stages.one_run(base, f"bendDeposition -preset {a.preset}"):
        run_one(flow, "flow", lambda: build_flow(flow, p),
                p["flow_end"], p["dt"], a.every)
        runs = particle_runs(p)
        failed = stages.pool(
            list(cases), lambda name: run_one(
                cases[name], name,
                lambda: build_particles(cases[name], flow, p,
                                        *runs[name], a.np),
                run_end(p), p["dt"], a.every, a.np), a.j)
    if failed:
        sys.stderr.write("Allrun: a run failed\n")
        return 1
    return 0


def work(a):
    p = PRESETS[a.preset]
    base = base_of(a.preset, a.np)
    cases = {name: base / name for name in particle_runs(p)}
    start = time.monotonic()
    whole = not a.post and not (base / "flow").exists()
    if not a.post and simulate(a, p, base, cases):
        return 1
    missing = [c.name for c in [base / "flow", *cases.values()]
               if not finished(c)]
    if missing:
        sys.stderr.write(f"Allrun: no finished run of {' '.join(missing)} "
                         f"under {base}: run ./Allrun -preset {a.preset}"
                         f"{'' if a.np == 1 else f' -np {a.np}'} first\n")
        return 1
    rows = rows_of(base, p)
    serial = False
    if a.np > 1:
        one = base_of(a.preset, 1)
        serial = rows_of(one, p) if all(
            finished(one / c.name) for c in cases.values()) else None
    text = verdicts(rows, p, serial)
    out = HERE / "results" / base.name if a.reference else base / "report"
    out.mkdir(parents=True, exist_ok=True)
    (out / "summary.json").write_text(json.dumps(
        dict(preset=a.preset, ranks=a.np, settings=p, Re=RE, D=D, U=U_MEAN,
             rho_p=RHO_P, rows=rows), indent=1) + "\n")
    (out / "table.txt").write_text(text)
    g = geometry(p)
    if "stokes" in p:
        efficiency_plot(rows, g, out, bendMeasured.eta_pui if not
                        bendMeasured.not_applicable(RE, p["curvature"])
                        else None)
    shown = list(cases.values())[len(cases) // 2]
    deposits_plot(shown, "the agglomeration variant" if "sizes" in p
                  else f"St = {shown.name[2:]}", out)
    print(text + f"Results: {out}")
    print(runtimes.line(f"bendDeposition {a.preset}"
                        + ("" if a.np == 1 else f" -np {a.np}"),
                        time.monotonic() - start, whole))
    return 1 if any(r["verdict"] == "FAIL" for r in rows) else 0


def main(argv=None):
    return stages.drive(HERE, options, work,
                        sys.argv[1:] if argv is None else argv)


if __name__ == "__main__":
    sys.exit(main())
