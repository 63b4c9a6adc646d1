"""shearFlowValidation: why the runs' first contacts agglomerate less
often than the undisturbed ones (doc/models.md 2.6). The first contacts
of each run's collision-event log differ from the ghost run's in two ways
that the log records: the partners spin (without the fluid torque the
spin comes from earlier collisions and never relaxes; a ghost particle
never spins) and a partner may be an agglomerate. Each is measured on
the run's own contacts:

  spin        the first contacts replayed once as logged and once with
              both spins set to zero (the ghost's), through EAM and MAM
              at e_n = 0.97: the paired change in alpha. The MAM's test
              (Eq. 75 (i)) takes the normal relative speed only, which
              the spins do not change, so its change is zero exactly;
  partners    alpha over the contacts of two primaries and over those
              with an agglomerate, as logged and spinless.

What is left between the spinless primary pairs and the detect run's
replay is the approach itself (and the noise of both ensembles).

    python -m shear.post.contacts PRESET [RUNS] [OUT]
        RUNS: the folder holding the preset's runs (default runs/PRESET);
        OUT (default results/PRESET): firstContactsSpinless.json, .txt
"""

import argparse
import json
import shutil
import sys
from pathlib import Path

import numpy as np

from aggloTools import eventlog, regression as reg
from aggloTools.uncertainty import wilson

from shear import TUTORIAL
from shear.case import entries

KERNELS = eventlog.en_variants((0.97,), ("EAM", "MAM"))
#: The quantiles of the spin at contact that are reported
QUANTILES = (0.1, 0.5, 0.9)


def spinless_case(run, where):
    """A replay case beside the run: its constant and system, and its
    first contacts with both spins set to zero (one log file, in the
    replay's order); returns the case and the records."""
    ev = eventlog.read_events(run)
    ev = ev[ev["category"] == 0].copy()
    ev["omega1"] = 0.0
    ev["omega2"] = 0.0
    if where.exists():
        shutil.rmtree(where)
    logs = eventlog.folder(where)
    logs.mkdir(parents=True)
    for d in ("constant", "system"):
        (where / d).symlink_to(Path(run).resolve() / d)
    head = sorted(eventlog.folder(run).glob("events*.bin"))[0]
    (logs / "events0.bin").write_bytes(
        head.read_bytes()[:eventlog.HEADER_BYTES] + ev.tobytes())
    return where


def outcomes(case):
    """The first contacts of a case replayed through KERNELS: the
    per-event columns (hardSphereReplay -eventsOut, beside its JSON in
    the case's log folder)."""
    f = eventlog.folder(Path(case).resolve()) / "spinlessReplay"
    eventlog.replay(case, KERNELS, events="first",
                    out=f.with_suffix(".json"),
                    events_out=f.with_suffix(".csv"))
    return eventlog.read_replay_events(f.with_suffix(".csv"))


def fraction(agg, sel):
    k, n = int(agg[sel].sum()), int(sel.sum())
    lo, hi = wilson(k, n)
    return {"events": n, "agg": k, "alpha": k / n if n else None,
            "low": lo, "high": hi}


def ensemble(run, gamma_dot):
    """The measurements of one run's first contacts."""
    logged = outcomes(run)
    spinless = outcomes(spinless_case(run, Path(run) / "firstSpinless"))
    key = ("timeIndex", "proc1", "id1", "proc2", "id2")
    if any(not np.array_equal(logged[k], spinless[k]) for k in key):
        raise ValueError(f"{run}: the spinless replay lists other events")
    agglo = (logged["nPrimary1"] > 1) | (logged["nPrimary2"] > 1)
    spin = np.concatenate([logged["omega1"], logged["omega2"]])
    out = {"events": int(len(agglo)),
           "withAgglomerate": int(agglo.sum()),
           "spinOverHalfGammaDot": {
               "quantiles": list(QUANTILES),
               "values": [float(v) for v in np.quantile(
                   spin / (0.5 * gamma_dot), QUANTILES)]
               if len(spin) else None},
           "medianAbsUn": float(np.median(np.abs(logged["un"])))
           if len(agglo) else None,
           "kernels": {}}
    subsets = {"all": np.ones_like(agglo), "primaries": ~agglo,
               "withAgglomerate": agglo}
    for k in KERNELS:
        a, b = logged[f"{k}.agglomerates"] > 0, \
            spinless[f"{k}.agglomerates"] > 0
        out["kernels"][k] = {
            s: {"logged": fraction(a, sel), "spinless": fraction(b, sel),
                "onlyLogged": int((a & ~b)[sel].sum()),
                "onlySpinless": int((b & ~a)[sel].sum())}
            for s, sel in subsets.items()}
    return out


def _r(v, a_th):
    return "-" if v is None else f"{v / a_th:.3f}"


def _ci(f, a_th):
    return "-" if f["low"] is None else \
        f"{_r(f['low'], a_th)}-{_r(f['high'], a_th)}"


def table(res):
    a_th = res["alpha_th"]
    rows = []
    for name, e in res["ensembles"].items():
        for k, by in e["kernels"].items():
            for s, f in by.items():
                lg, sp = f["logged"], f["spinless"]
                rows.append(dict(
                    ens=name, kernel=k, subset=s, n=lg["events"],
                    a=_r(lg["alpha"], a_th),
                    aci=_ci(lg, a_th),
                    s=_r(sp["alpha"], a_th),
                    sci=_ci(sp, a_th),
                    pair=f"{f['onlyLogged']} / {f['onlySpinless']}"))
    cols = [reg.Column("ensemble", "ens", 8),
            reg.Column("kernel", "kernel", 7, gap="  "),
            reg.Column("contacts", "subset", 16, gap="  "),
            reg.Column("first", "n", 6, ">", str),
            reg.Column("as logged", "a", 10, ">"),
            reg.Column("95 %", "aci", 12, ">"),
            reg.Column("spinless", "s", 9, ">"),
            reg.Column("95 %", "sci", 12, ">"),
            reg.Column("only logged / only spinless", "pair", 28, ">")]
    lines = [f"shearFlowValidation {res['preset']}: alpha/alpha_th of the"
             " first contacts, as logged and with both spins zero"
             f" (shear.post.contacts); alpha_th = {a_th:.4g}", ""]
    lines += reg.table(rows, cols)
    lines.append("")
    for name, e in res["ensembles"].items():
        q = e["spinOverHalfGammaDot"]["values"]
        lines.append(
            f"{name}: {e['events']} first contacts, {e['withAgglomerate']}"
            " with an agglomerate; spin at contact / (gammaDot/2), 10/50/90"
            " %: " + ("-" if q is None else
                      " / ".join(f"{v:.3g}" for v in q))
            + f"; median |u_n| {e['medianAbsUn']:.4g} m/s"
            if e["medianAbsUn"] is not None else f"{name}: no contacts")
    lines += ["", "The replay freezes the contacts (shear.post.replay); only"
              " the spins before the collision are changed."]
    return "\n".join(lines) + "\n"


def measure(preset, runs_dir=None, out_dir=None):
    runs_dir = Path(runs_dir or TUTORIAL / "runs" / preset)
    out = Path(out_dir or TUTORIAL / "results" / preset)
    found = entries.logged_runs(runs_dir, "shear.post.contacts")
    if found is None:
        return None
    runs, s, a_th = found
    g = float(s["gammaDot"])
    res = {"preset": preset, "gammaDot": g, "alpha_th": a_th,
           "ensembles": {r: ensemble(runs_dir / r, g) for r in runs}}
    out.mkdir(parents=True, exist_ok=True)
    (out / "firstContactsSpinless.json").write_text(
        json.dumps(res, indent=1) + "\n")
    text = table(res)
    (out / "firstContactsSpinless.txt").write_text(text)
    print(text, end="")
    return res


def main(argv):
    ap = argparse.ArgumentParser(
        prog="shear.post.contacts", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("preset", help="the preset whose runs are measured")
    ap.add_argument("runs", nargs="?", help="the folder holding its runs "
                    "(default runs/PRESET)")
    ap.add_argument("out", nargs="?", help="the output folder (default "
                    "results/PRESET)")
    a = ap.parse_args(argv)
    measure(a.preset, a.runs, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
