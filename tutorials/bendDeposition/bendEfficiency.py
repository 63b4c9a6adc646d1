"""The efficiency of the bend against the Stokes number (bendDeposition):
one row per run from the cloud's record and mass balance at its end, the
verdicts of the theory's limits, the table, and the comparison of a run
on N ranks with the serial one."""

import math

import numpy as np

from aggloTools.cloud import (cloud_dir, read_mass_balance, read_positions,
                              read_record)
from aggloTools.times import last_time


def where(x, g):
    """Which part of the pipe points are in: 'inletPipe', 'bend' or
    'outletPipe' (the planes z = L_in and x = R)."""
    return np.where(x[:, 2] <= g.L_in, "inletPipe",
                    np.where(x[:, 0] >= g.R, "outletPipe", "bend"))


def counts(case, g):
    """What became of a run's particles at its end: parcels and primaries
    deposited and escaped per patch (the mass balance), in flight (the
    cloud's record) and, of those, passed (in the outlet pipe)."""
    t = last_time(case)
    bal = read_mass_balance(case, t)
    rec = read_record(case, t, "kinematicCloud")
    in_flight = rec["nParticlesTotal"]
    x = read_positions(cloud_dir(case, t) / "positions") if in_flight \
        else np.zeros((0, 3))
    return dict(
        deposited={k: v["nParcels"] for k, v in bal["deposited"].items()},
        escaped={k: v["nParcels"] for k, v in bal["escaped"].items()},
        depositedPrimaries={k: v["nPrimaries"]
                            for k, v in bal["deposited"].items()},
        escapedPrimaries={k: v["nPrimaries"]
                          for k, v in bal["escaped"].items()},
        depositedMass={k: v["mass"] for k, v in bal["deposited"].items()},
        inFlight=in_flight,
        inFlightPrimaries=rec.get("nPrimariesTotal", in_flight),
        passed=int((where(x, g) == "outletPipe").sum()))


def analyse(case, st, d, p, g):
    """The row of one Stokes number (particle diameter d). A particle
    still in flight in the outlet pipe has passed the bend; one in the
    inlet pipe or the bend is undecided and left out. eta = deposited in
    the bend / entered, with the binomial sigma."""
    c = counts(case, g)
    dep, esc, in_flight = c["deposited"], c["escaped"], c["inFlight"]
    undecided = in_flight - c["passed"]
    injected = in_flight + sum(dep.values()) + sum(esc.values())
    entered = injected - dep.get("inletPipe", 0) - undecided
    n_bend = dep.get("bend", 0)
    eta = n_bend / entered if entered else float("nan")
    sigma = math.sqrt(eta * (1 - eta) / entered) if entered else float("nan")
    return dict(St=st, d=d, injected=injected, expected=p["parcels"],
                entered=entered, deposited=dep, escaped=esc,
                inFlight=in_flight, undecided=undecided, eta=eta,
                sigma=sigma)


def judge(rows):
    """The gate, the theory's limits (the measurements are compared by
    bendMeasured, not here): the preset's parcels injected and at most
    2 % undecided (in flight before the end of the bend: left out of
    eta); eta does not fall from one St to the next by more than 2 sigma
    (both rows' binomial sigma combined); the smallest St below 0.1
    deposits less than 10 %, the largest above 3 more than 90 % (the
    inertial limits: tracers follow the flow, ballistic particles hit
    the outer wall). Each row PASS or FAIL."""
    verdicts = {}
    for r in rows:
        ok = (r["undecided"] <= 0.02 * r["injected"] and r["entered"] > 0
              and r["injected"] == r["expected"])
        verdicts[r["St"]] = "PASS" if ok else "FAIL"
    for a, b in zip(rows, rows[1:]):
        s = math.hypot(a["sigma"], b["sigma"])
        if b["eta"] < a["eta"] - 2 * s:
            verdicts[b["St"]] = "FAIL"
    lo, hi = rows[0], rows[-1]
    if lo["St"] < 0.1 and not lo["eta"] < 0.1:
        verdicts[lo["St"]] = "FAIL"
    if hi["St"] > 3 and not hi["eta"] > 0.9:
        verdicts[hi["St"]] = "FAIL"
    for r in rows:
        r["verdict"] = verdicts[r["St"]]
    return rows


#: What a run on N ranks must repeat of the serial run exactly
SAME = ("deposited", "escaped", "inFlight", "undecided", "injected")


def compare(rows, serial, key="St", same=SAME):
    """Runs on N ranks against the serial runs of the same inputs: every
    row's entries `same` equal, else the row FAILs (rows matched by
    `key`). serial: the serial rows, or None when the serial runs are not
    there (the rows keep their verdicts; 'serial' says n/r). Returns the
    rows."""
    by_key = {r[key]: r for r in serial or []}
    for r in rows:
        s = by_key.get(r[key])
        if s is None:
            r["serial"] = "n/r (no finished serial run)"
            continue
        diff = [k for k in same if r[k] != s[k]]
        r["serial"] = "same counts" if not diff else \
            "differs: " + ", ".join(diff)
        if diff:
            r["verdict"] = "FAIL"
    return rows


def table(rows, measured=None):
    """The report's table; `measured`: the line on the comparison with
    the measurements (bendMeasured.summary), whose columns (the
    expression's eta and the row's verdict against it) follow the
    gate's verdict where the rows have them."""
    vs = any("measured" in r for r in rows)
    out = ["    St   d [um]  injected  entered  bend  inletPipe  "
           "outletPipe  outlet  flight     eta   sigma  verdict"
           + ("    Pui87  measured" if vs else "")]
    for r in rows:
        dep, esc = r["deposited"], r["escaped"]
        out.append(f"{r['St']:6.3g} {1e6 * r['d']:8.2f} {r['injected']:9d}"
                   f" {r['entered']:8d} {dep.get('bend', 0):5d}"
                   f" {dep.get('inletPipe', 0):10d}"
                   f" {dep.get('outletPipe', 0):11d}"
                   f" {esc.get('outlet', 0):7d} {r['inFlight']:7d}"
                   f" {r['eta']:7.3f}"
                   f" {r['sigma']:7.3f}  {r['verdict']:>7}"
                   + (f"  {r['etaPui']:7.3f}  {r['measured']}"
                      if "etaPui" in r else
                      f"  {'-':>7}  {r['measured']}" if vs else "")
                   + (f"  (serial: {r['serial']})" if "serial" in r else ""))
    out.append("eta: deposited in the bend / entered the bend (flight: "
               "still in the pipe at the end; those in the outlet pipe "
               "passed the bend, the others are left out); sigma: binomial. "
               "Verdicts: the balance and the theory's limits"
               + ("; on N ranks also the serial run's counts exactly."
                  if any("serial" in r for r in rows) else "."))
    if measured:
        out.append(measured)
    return "\n".join(out) + "\n"
