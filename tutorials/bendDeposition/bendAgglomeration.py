"""The agglomeration variant of bendDeposition: a dense, polydisperse
cloud through the bend with the collision stage and an agglomeration
model on. Its row (what became of the primaries, the collisions and
agglomerations, agglomerates deposited whole), its verdicts and its
table."""

from aggloTools.stats import stats_rows

from bendEfficiency import counts

#: The walls of the pipe, where particles deposit
WALLS = ("inletPipe", "bend", "outletPipe")


def analyse(case, p, g):
    """The run's row: counts per patch (parcels, primaries, mass), the
    primaries in flight, the collision and agglomeration counters at the
    end (stats.dat), the bend's efficiency by mass of what deposited or
    left."""
    c = counts(case, g)
    last = stats_rows(case)[-1]
    dep_p, esc_p = c["depositedPrimaries"], c["escapedPrimaries"]
    mass = c["depositedMass"]
    wall_mass = sum(mass.get(w, 0.0) for w in WALLS)
    return dict(
        model=p["model"], sizes=list(p["sizes"]), injected=p["parcels"],
        deposited=c["deposited"], escaped=c["escaped"],
        depositedPrimaries=dep_p, escapedPrimaries=esc_p,
        depositedMass=mass, inFlight=c["inFlight"],
        inFlightPrimaries=c["inFlightPrimaries"],
        accounted=(c["inFlightPrimaries"] + sum(dep_p.values())
                   + sum(esc_p.values())),
        nCol=int(last["nCol"]), nAgg=int(last["nAgg"]),
        agglomeratesInFlight=int(last["nAgglomerates"]),
        bendShareOfWallMass=(mass.get("bend", 0.0) / wall_mass
                             if wall_mass else float("nan")))


def judge(row):
    """Each verdict PASS or FAIL: every injected primary accounted for
    (in flight + deposited + escaped = the preset's number, exactly);
    agglomerates formed (nAgg > 0: else the variant shows nothing); and
    agglomerates deposited as one body (on the walls more primaries
    than parcels)."""
    walls = [w for w in WALLS if w in row["deposited"]]
    whole = sum(row["depositedPrimaries"][w] - row["deposited"][w]
                for w in walls)
    row["checks"] = {
        "every primary accounted for": row["accounted"] == row["injected"],
        "agglomerates formed": row["nAgg"] > 0,
        "agglomerates deposited whole": whole > 0,
    }
    row["primariesInDepositedAgglomerates"] = int(whole)
    row["verdict"] = "PASS" if all(row["checks"].values()) else "FAIL"
    return row


def table(row):
    out = [f"{row['model']}: {row['injected']} primaries of "
           f"{1e6 * row['sizes'][0]:g}-{1e6 * row['sizes'][1]:g} um; "
           f"{row['nCol']} collisions, {row['nAgg']} agglomerations",
           "patch        parcels  primaries      mass [kg]"]
    for way in ("deposited", "escaped"):
        for k, n in row[way].items():
            out.append(f"{k:11s} {n:8d} {row[way + 'Primaries'][k]:10d}"
                       f"  {row['depositedMass'][k]:13.6e}"
                       if way == "deposited" else
                       f"{k:11s} {n:8d} {row[way + 'Primaries'][k]:10d}"
                       "  (escaped)")
    out.append(f"in flight   {row['inFlight']:8d} "
               f"{row['inFlightPrimaries']:10d}")
    out.append(f"bend's share of the mass deposited on the walls: "
               f"{row['bendShareOfWallMass']:.3f}")
    for k, ok in row["checks"].items():
        out.append(f"  {'PASS' if ok else 'FAIL'}  {k}")
    if "serial" in row:
        out.append(f"  serial run: {row['serial']}")
    out.append(f"verdict: {row['verdict']}")
    return "\n".join(out) + "\n"
