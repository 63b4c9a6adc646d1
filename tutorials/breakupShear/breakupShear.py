"""breakupShear: agglomerates eroded by a laminar simple shear, at several
shear rates (doc/breakup.md). Eight CSM agglomerates of N0 quartz
primaries (12 um) sit on the centre plane of a frozen plane Couette flow
of water, spinning with it (omega = gamma/2); break-up (stressThreshold:
turbulence, drag, rotation; erosion) and EAM agglomeration are on. The
criterion predicts the size at which erosion stops (breakupTheory); the
fragments' collisions with the agglomerates add spin and slip, so the
simulated sizes end at or below it; every logged break-up is checked
against the criterion. The preset readings runs the mean-shear series
under each reading of the dissipation rate (doc/breakup.md 1.1).

    ./Allrun [-preset default|ci|readings] [-j N] [-post] [-reference]
             [-every S]

Runs: runs/<preset>/<series>-<reading>-gamma<g> (a finished run is kept; an
interrupted one continues from its last complete write, a write cut off
by a kill set aside; one driver at a time per preset: runs/<preset> is
locked while it runs).
Report: runs/<preset>/report (-reference: results/<preset>): summary.json,
table.txt, sizes.png, distribution.png, criterion.png. Exit status 1 if
a row FAILs."""

import contextlib
import io
import json
import shutil
import sys
import time
from pathlib import Path

from aggloTools import boxcase, runtimes, stages, times
from aggloTools.progress import line, solver_progress
from aggloTools.runner import foam_bin

from breakupShearReport import N_AGG, analyse, criterion, plots, table

HERE = Path(__file__).resolve().parent

L, CELLS = (1e-3, 1e-3, 0.5e-3), (10, 10, 5)

# The reading of the dissipation rate of the tutorials (doc/breakup.md
# 1.1), decided by the preset readings (README)
READING = "resolvedShear"

PRESETS = {
    # about 3 minutes on 2 cores
    "default": dict(gammas=[3e5, 3.5e5, 4e5, 5e5, 6e5], n0=200,
                    dt=1e-7, end=3e-3, write=1e-4,
                    series=[("shear", READING), ("withDrag", READING)]),
    # the tests' preset: small agglomerates, high shear, about 20 s (2 ms:
    # long enough for erosion to stop, the fragments' placement among
    # their neighbours making some erosions wait a step)
    "ci": dict(gammas=[5e5, 6e5], n0=40, dt=1e-7, end=2e-3, write=1e-4,
               series=[("shear", READING), ("withDrag", READING)]),
    # the study of the readings: the mean-shear series under each, about
    # 4 minutes on 2 cores
    "readings": dict(gammas=[3e5, 4e5, 5e5, 6e5], n0=200, dt=1e-7,
                     end=3e-3, write=1e-4,
                     series=[("shear", "total"), ("shear", "subgrid"),
                             ("shear", "resolvedShear")]),
}

# The two series: the stresses of the mean shear only (the criterion's
# prediction holds for them), and the model's default with drag too
SERIES = {
    "shear": {"mechanisms": ("turbulence", "rotation"), "Cv": 1, "Ci": 1,
              "rotationFactor": 0.0625},
    "withDrag": {"mechanisms": ("turbulence", "drag", "rotation"), "Cv": 1,
                 "Ci": 1, "Cd": 1, "rotationFactor": 0.0625},
}


def breakup(series, reading):
    """The cloud's drag, the fluid's torque and the break-up model's
    entries, its event log on."""
    coeffs = {
        "strength": {"rumpfPrefactor": 1.125,
                     "coordination": "exactSmallRumpf"},
        "stresses": {**SERIES[series], "dissipation": reading},
        "fragmentation": {"mode": "erosion", "direction": "extensional",
                          "gap": 1e-3, "tries": 6, "spin": "conserveL"},
        "eventLog": True}
    return {"subModels": {"particleForces": boxcase.DRAG,
                          "rotationModel": "fluidTorque",
                          "breakupModel": "stressThreshold",
                          "stressThresholdCoeffs": coeffs}}


def build(case, series, reading, gamma, p):
    """The box, the exact Couette profile, the agglomerates at rest on the
    centre plane spinning at -gamma/2 about z; the break-up log on (the
    report checks every break-up)."""
    c = criterion(reading)
    n0 = p["n0"]
    parts = [dict(x=(L[0] * (i + 0.5) / N_AGG, L[1] / 2,
                     L[2] * (0.25 if i % 2 == 0 else 0.75)),
                  U=(0, 0, 0), d=c.diameter(n0), rho=c.density(n0),
                  nPrimary=n0, omega=(0, 0, -gamma / 2))
             for i in range(N_AGG)]
    uw = gamma * L[1] / 2
    steps = round(p["end"] / p["dt"])
    boxcase.box_case(case, L=L, n=CELLS, kinds=("cyclic", "wall", "cyclic"),
                     particles=parts, dt=p["dt"], end_time=p["end"],
                     write_interval=round(p["write"] / p["dt"]),
                     nu=c.nu, rho_f=c.rho_f,
                     hard_sphere=boxcase.kernel("EAM"),
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     cloud=breakup(series, reading), write_format="binary")
    boxcase.write_internal_U(case, L, CELLS,
                             lambda x, y, z: (gamma * (y - L[1] / 2), 0, 0))
    assert steps > 0


def finished(case):
    """The run ended and its statistics are there (a folder left with its
    logs only is run again)."""
    log = case / "log.aggloPimpleFoam"
    stats = case / "postProcessing" / "kinematicCloudHardSphere"
    return log.is_file() and "\nEnd\n" in log.read_text() \
        and stats.is_dir()


def run_one(case, series, reading, gamma, p, every=60):
    """Set up and run one case, continue it from its last complete write
    (a write cut off by a kill set aside) or keep it if it finished."""
    tag = f"    {case.name}"
    if finished(case):
        print(f"{tag}: finished earlier, kept", flush=True)
        return
    if not (case / "constant" / "polyMesh" / "faces").is_file():
        shutil.rmtree(case, ignore_errors=True)
        build(case, series, reading, gamma, p)
        stages.run_logged([foam_bin("blockMesh")], case, "log.blockMesh")
        append = False
    else:
        said = io.StringIO()
        with contextlib.redirect_stdout(said):
            times.set_aside_incomplete_times(case)
        # (not `line`: that name is the progress line below)
        for text in said.getvalue().splitlines():
            print(f"{tag}: {text}", flush=True)
        print(f"{tag}: continuing from the last written time", flush=True)
        append = True

    def progress(c):
        at = solver_progress(c / "log.aggloPimpleFoam", p["end"], p["dt"])
        return "starting" if at is None else \
            f"t = {at[0]:.4g} s of {p['end']:g} s {line(at[1], at[2])}"
    wall = stages.run_solver(case, [foam_bin("aggloPimpleFoam")],
                             case.name, progress, every, append=append)
    print(f"{tag}: done in {round(wall)} s", flush=True)


def case_name(series, reading, gamma):
    return f"{series}-{reading}-gamma{gamma:.3g}"


def options(argv):
    p = stages.Parser("breakupShear", __doc__)
    p.add_argument("-preset", default="default", choices=sorted(PRESETS),
                   help="the shear rates, sizes and series (default:"
                   " default)")
    p.add_argument("-j", type=stages.positive("-j"), default=2,
                   help="runs at a time (default 2)")
    p.add_argument("-post", action="store_true",
                   help="only the report of the finished runs")
    p.add_argument("-reference", action="store_true",
                   help="write the report into results/<preset>")
    p.add_argument("-every", type=stages.positive("-every"), default=60,
                   help="seconds between progress lines (default 60)")
    return p.parse_args(argv)


def work(a):
    p = PRESETS[a.preset]
    base = HERE / "runs" / a.preset
    runs = [(s, r, g) for s, r in p["series"] for g in p["gammas"]]
    cases = {r: base / case_name(*r) for r in runs}
    start = time.monotonic()
    whole = not a.post and not any(c.exists() for c in cases.values())

    if not a.post:
        print(f"breakupShear: preset {a.preset}, {len(runs)} runs, {a.j} "
              "at a time", flush=True)
        with stages.one_run(base, f"breakupShear -preset {a.preset}"):
            failed = stages.pool(
                runs, lambda r: run_one(cases[r], *r, p, a.every), a.j)
        if failed:
            sys.stderr.write("Allrun: a run failed\n")
            return 1
    missing = [c.name for c in cases.values() if not finished(c)]
    if missing:
        sys.stderr.write(f"Allrun: no finished run of {' '.join(missing)} "
                         f"under {base}: run ./Allrun -preset {a.preset} "
                         "first\n")
        return 1

    rows = [analyse(cases[r], *r, p) for r in runs]
    out = HERE / "results" / a.preset if a.reference else base / "report"
    out.mkdir(parents=True, exist_ok=True)
    (out / "summary.json").write_text(
        json.dumps(dict(preset=a.preset, settings=p, rows=rows), indent=1)
        + "\n")
    text = table(rows)
    (out / "table.txt").write_text(text)
    plots(rows, out)
    print(text + f"Results: {out}")
    print(runtimes.line(f"breakupShear {a.preset}",
                        time.monotonic() - start, whole))
    return 1 if any(r["verdict"] == "FAIL" for r in rows) else 0


def main(argv=None):
    return stages.drive(HERE, options, work,
                        sys.argv[1:] if argv is None else argv)


if __name__ == "__main__":
    sys.exit(main())
