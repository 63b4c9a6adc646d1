"""breakupShear: agglomerates eroded by a laminar simple shear, at several
shear rates (doc/breakup.md). Eight CSM agglomerates of N0 quartz
primaries (12 um) sit on the centre plane of a frozen plane Couette flow
of water, spinning with it (omega = gamma/2); break-up (stressThreshold:
turbulence, drag, rotation; erosion) and EAM agglomeration are on. The
criterion predicts the size at which erosion stops (breakupTheory); the
fragments' collisions with the agglomerates add spin and slip, so the
simulated sizes end at or below it.

    ./Allrun [-preset default|ci] [-j N] [-post] [-reference] [-every S]

Runs: runs/<preset>/<series>-gamma<g> (a finished run is kept; an
interrupted one continues from its last complete write, a write cut off
by a kill set aside; one driver at a time per preset: runs/<preset> is
locked while it runs).
Report: runs/<preset>/report (-reference: results/<preset>): summary.json,
table.txt, sizes.png, distribution.png, criterion.png. Exit status 1 if
a row FAILs."""

import contextlib
import io
import json
import math
import shutil
import sys
import time
from pathlib import Path

import numpy as np

from aggloTools import boxcase, runtimes, stages, times
from aggloTools.cloud import read_cloud
from aggloTools.progress import line, solver_progress
from aggloTools.runner import foam_bin
from aggloTools.stats import read_stats
from aggloTools.times import last_time

from breakupTheory import Criterion

HERE = Path(__file__).resolve().parent

# Quartz primaries (boxcase.KERNEL: H 6.3e-20 J, delta0 0.2 nm) in water
DP, RHO_P, H, DELTA0 = 12e-6, 2200.0, 6.3e-20, 2e-10
NU, RHO_F = 1e-6, 1000.0
L, CELLS = (1e-3, 1e-3, 0.5e-3), (10, 10, 5)
N_AGG = 8

PRESETS = {
    # about 3 minutes on 2 cores
    "default": dict(gammas=[3e5, 3.5e5, 4e5, 5e5, 6e5], n0=200,
                    dt=1e-7, end=3e-3, write=1e-4),
    # the tests' preset: small agglomerates, high shear, about 20 s (2 ms:
    # long enough for erosion to stop, the fragments' placement among
    # their neighbours making some erosions wait a step)
    "ci": dict(gammas=[5e5, 6e5], n0=40, dt=1e-7, end=2e-3, write=1e-4),
}

# The two series: the stresses of the mean shear only (the criterion's
# prediction holds for them), and the model's default with drag too
SERIES = {
    "shear": "mechanisms (turbulence rotation); Cv 1; Ci 1;"
             " rotationFactor 0.0625;",
    "withDrag": "mechanisms (turbulence drag rotation); Cv 1; Ci 1; Cd 1;"
                " rotationFactor 0.0625;",
}


def breakup(series):
    return ("breakupModel stressThreshold;\n    stressThresholdCoeffs {"
            " strength { rumpfPrefactor 1.125;"
            " coordination exactSmallRumpf; }"
            " stresses { " + SERIES[series] + " }"
            " fragmentation { mode erosion; direction extensional;"
            " gap 1e-3; tries 6; spin conserveL; } }")


def criterion():
    return Criterion(DP, RHO_P, H, DELTA0, NU, RHO_F)


def build(case, series, gamma, p):
    """The box, the exact Couette profile, the agglomerates at rest on the
    centre plane spinning at -gamma/2 about z."""
    c = criterion()
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
                     nu=NU, rho_f=RHO_F, agglomeration="EAM",
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     forces="{ SchillerNaumannDrag; }", rotation=True,
                     breakup=breakup(series), write_format="binary")
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


def run_one(case, series, gamma, p, every=60):
    """Set up and run one case, continue it from its last complete write
    (a write cut off by a kill set aside) or keep it if it finished."""
    tag = f"    {case.name}"
    if finished(case):
        print(f"{tag}: finished earlier, kept", flush=True)
        return
    if not (case / "constant" / "polyMesh" / "faces").is_file():
        shutil.rmtree(case, ignore_errors=True)
        build(case, series, gamma, p)
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


def case_name(series, gamma):
    return f"{series}-gamma{gamma:.3g}"


def analyse(case, series, gamma, p):
    """The run's size history (stats.dat, every step), the final
    agglomerate sizes and the row of the table."""
    c = criterion()
    s = read_stats(case)
    t = s["Time"]
    n_pred = c.final_size(p["n0"], gamma)
    final = {}
    sizes = case / "postProcessing" / "kinematicCloudHardSphere" / \
        last_time(case) / "agglomerateSizes.dat"
    for line in sizes.read_text().splitlines():
        if line and not line.startswith("#"):
            k, n = line.split()
            final[int(k)] = int(n)
    # The share of the primaries in particles of k primaries, at the end
    npr = read_cloud(case, last_time(case), names=["nPrimary"])["nPrimary"]
    ks, counts = np.unique(npr.astype(int), return_counts=True)
    share = dict(k=ks.tolist(),
                 share=(ks * counts / npr.sum()).tolist())
    n_max = int(s["maxPrimaries"][-1])
    primaries = int(s["nPrimaries"][-1])
    # Still eroding: the largest agglomerate shrank in the last tenth of
    # the run (its size then says nothing of where erosion stops)
    tail = s["maxPrimaries"][t >= t[0] + 0.9 * (t[-1] - t[0])]
    eroding = bool(tail[0] > tail[-1])
    verdict = judge(n_max, n_pred, primaries, N_AGG * p["n0"], eroding)
    return dict(
        series=series, gamma=gamma, n0=p["n0"], nPredicted=n_pred,
        nMax=n_max,
        # None (JSON null, "—" in the table) when no agglomerate is left
        nMeanAgglomerate=(float(s["nPrimariesInAgglomerates"][-1]
                                / s["nAgglomerates"][-1])
                          if s["nAgglomerates"][-1] > 0 else None),
        nAgglomerates=int(s["nAgglomerates"][-1]), primaries=primaries,
        breakups={m: int(s[f"nBreakup{m}"][-1])
                  for m in ("Turbulence", "Drag", "Rotation")},
        reagglomerations=int(s["nAgg"][-1]), collisions=int(s["nCol"][-1]),
        finalSizes=final, finalPrimaryShare=share, stillEroding=eroding,
        verdict=verdict,
        history=dict(t=t[::50].tolist(),
                     nMax=s["maxPrimaries"][::50].tolist(),
                     # None where no agglomerate is left
                     nMean=[float(a / k) if k > 0 else None for a, k in
                            zip(s["nPrimariesInAgglomerates"][::50],
                                s["nAgglomerates"][::50])]))


def judge(n_max, n_pred, primaries, primaries0, eroding):
    """FAIL if primaries were lost or made, or if erosion has stopped with
    an agglomerate larger than the criterion allows (the fragments'
    collisions only add stress, so nothing may end above it); n/r while
    the largest agglomerate is still eroding; else PASS."""
    if primaries != primaries0 or (n_max > n_pred and not eroding):
        return "FAIL"
    return "n/r (still eroding)" if eroding else "PASS"


def mean_text(n):
    """The mean agglomerate size in the table's column ("—": none left)."""
    return f"{n:5.1f}" if n is not None else "    —"


def table(rows):
    out = ["series    gamma [1/s]  N0  predicted  max  mean   aggl.  turb"
           "  drag   rot  reaggl.  verdict"]
    for r in rows:
        b = r["breakups"]
        out.append(f"{r['series']:9s} {r['gamma']:11.3g} {r['n0']:4d}"
                   f" {r['nPredicted']:9d}"
                   f" {r['nMax']:4d} {mean_text(r['nMeanAgglomerate'])}"
                   f" {r['nAgglomerates']:6d} {b['Turbulence']:5d}"
                   f" {b['Drag']:5d} {b['Rotation']:5d}"
                   f" {r['reagglomerations']:8d}  {r['verdict']}")
    out.append("predicted: the size at which erosion stops in the mean "
               "shear (breakupTheory). PASS: the primaries are conserved "
               "and, once erosion has stopped, no agglomerate is larger; "
               "the fragments' collisions add spin and slip, so sizes may "
               "end below it. n/r: the largest was still eroding in the "
               "last tenth of the run.")
    return "\n".join(out) + "\n"


def plots(all_rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = [r for r in all_rows if r["series"] == "shear"]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in rows:
        h = r["history"]
        line, = ax.plot(1e3 * np.array(h["t"]), h["nMax"],
                        label=f"γ̇ = {r['gamma']:.3g} 1/s, max")
        ax.plot(1e3 * np.array(h["t"]), np.array(h["nMean"], float), ":",
                color=line.get_color())
        ax.axhline(r["nPredicted"], ls="--", lw=0.8,
                   color=line.get_color())
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("primaries per agglomerate")
    ax.set_title("Stresses of the mean shear: largest (solid) and mean "
                 "(dotted)\nagglomerate; dashed: where the criterion "
                 "stops erosion", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "sizes.png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in rows:
        # drawn on to N0, so that a cloud of primaries shows too
        k = np.append(r["finalPrimaryShare"]["k"], r["n0"])
        share = np.cumsum(r["finalPrimaryShare"]["share"] + [0.0])
        line, = ax.step(k, share, where="post",
                        label=f"γ̇ = {r['gamma']:.3g} 1/s")
        ax.axvline(r["nPredicted"], ls="--", lw=0.8,
                   color=line.get_color())
    ax.set_xscale("log")
    ax.set_xlim(0.8, 1.2 * rows[0]["n0"])
    ax.set_xlabel("primaries per particle k")
    ax.set_ylabel("share of the primaries in particles of <= k")
    ax.set_title("Stresses of the mean shear: the primaries' size "
                 "distribution at the end\n(k = 1: eroded primaries; "
                 "dashed: where the criterion stops erosion)",
                 fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(out / "distribution.png", dpi=120)
    plt.close(fig)

    c = criterion()
    n0 = rows[0]["n0"]
    g = np.geomspace(0.5 * min(r["gamma"] for r in rows),
                     1.5 * max(r["gamma"] for r in rows), 200)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(g, [c.final_size(n0, x) for x in g], "k-",
            label="criterion: size at which erosion stops")
    for series, mk in (("shear", "o"), ("withDrag", "^")):
        sel = [r for r in all_rows if r["series"] == series]
        ax.plot([r["gamma"] for r in sel], [r["nMax"] for r in sel],
                mk, ms=8, label=f"{series}: largest")
        has = [r for r in sel if r["nMeanAgglomerate"] is not None]
        none = ", ".join(f"{r['gamma']:.3g}" for r in sel
                         if r["nMeanAgglomerate"] is None)
        ax.plot([r["gamma"] for r in has],
                [r["nMeanAgglomerate"] for r in has], mk, mfc="none",
                ms=8, label=f"{series}: mean agglomerate"
                + (f" (none left at γ̇ = {none} 1/s)" if none else ""))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("shear rate γ̇ [1/s]")
    ax.set_ylabel("primaries per agglomerate")
    ax.set_title(f"Agglomerates of N0 = {n0} eroded by simple shear")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "criterion.png", dpi=120)
    plt.close(fig)


def options(argv):
    p = stages.Parser("breakupShear", __doc__)
    p.add_argument("-preset", default="default", choices=sorted(PRESETS),
                   help="the shear rates and sizes (default: default)")
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
    runs = [(s, g) for s in SERIES for g in p["gammas"]]
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
