"""breakupShear's report: each run's row (the sizes, the break-ups by
mechanism, every logged break-up checked against the criterion), its
two-sided verdict, the table and the plots."""

import numpy as np

from aggloTools import breakuplog
from aggloTools.cloud import read_cloud
from aggloTools.stats import read_stats
from aggloTools.times import last_time

from breakupTheory import Criterion

# Quartz primaries (boxcase.KERNEL: H 6.3e-20 J, delta0 0.2 nm) in water
DP, RHO_P, H, DELTA0 = 12e-6, 2200.0, 6.3e-20, 2e-10
NU, RHO_F = 1e-6, 1000.0
N_AGG = 8

#: The mechanisms of the break-up log this tutorial checks by the theory
#: (the drag of the withDrag series is not in breakupTheory)
CHECKED = {"turbulence": 0, "rotation": 1}


def criterion(reading):
    return Criterion(DP, RHO_P, H, DELTA0, NU, RHO_F, reading=reading)


def unjustified(case, gamma, reading):
    """The logged break-ups by turbulence or rotation that the criterion
    does not allow for their parent (its primaries and its logged spin,
    in the shear gamma), and how many were checked."""
    c = criterion(reading)
    names = breakuplog.header(case)["mechanisms"]
    ev = breakuplog.read_breakup_events(case)
    bad, checked = 0, 0
    for e in ev:
        mech = names[e["mechanism"]]
        if mech not in CHECKED:
            continue
        n = int(e["nPrimary_p"])
        turb, _ = c.stresses(n, gamma)
        rot = c.rot * c.density(n) * float(np.sum(e["omega_p"] ** 2)) \
            * c.diameter(n) ** 2
        stress = turb if mech == "turbulence" else rot
        checked += 1
        bad += stress <= c.strength(n) * (1 + 1e-9)
    return bad, checked


def judge(r):
    """Two-sided: FAIL if primaries were lost or made, if a logged
    break-up by turbulence or rotation is one the criterion does not
    allow for its parent (too much), or if the largest agglomerate ended
    above the criterion's size once erosion stopped (too little: the
    collisions only add stress); n/r while still eroding; else PASS."""
    if r["primaries"] != r["primaries0"] or r["unjustified"] > 0:
        return "FAIL"
    if r["stillEroding"]:
        return "n/r (still eroding)"
    return "FAIL" if r["nMax"] > r["nPredicted"] else "PASS"


def analyse(case, series, reading, gamma, p):
    """The run's size history (stats.dat, every step), the final
    agglomerate sizes, the agglomerates no collision touched, the logged
    break-ups the criterion does not allow, and the row of the table."""
    c = criterion(reading)
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
    # Still eroding: the largest agglomerate shrank in the last tenth of
    # the run (its size then says nothing of where erosion stops)
    tail = s["maxPrimaries"][t >= t[0] + 0.9 * (t[-1] - t[0])]
    bad, checked = unjustified(case, gamma, reading)
    row = dict(
        series=series, reading=reading, gamma=gamma, n0=p["n0"],
        nPredicted=n_pred, nMax=int(s["maxPrimaries"][-1]),
        # None (JSON null, "—" in the table) when no agglomerate is left
        nMeanAgglomerate=(float(s["nPrimariesInAgglomerates"][-1]
                                / s["nAgglomerates"][-1])
                          if s["nAgglomerates"][-1] > 0 else None),
        nAgglomerates=int(s["nAgglomerates"][-1]),
        primaries=int(s["nPrimaries"][-1]), primaries0=N_AGG * p["n0"],
        breakups={m: int(s[f"nBreakup{m}"][-1])
                  for m in ("Turbulence", "Drag", "Rotation")},
        waitedForRoom=int(s["nBreakupNoRoom"][-1]),
        reagglomerations=int(s["nAgg"][-1]), collisions=int(s["nCol"][-1]),
        unjustified=bad, checkedBreakups=checked,
        finalSizes=final, finalPrimaryShare=share,
        stillEroding=bool(tail[0] > tail[-1]),
        history=dict(t=t[::50].tolist(),
                     nMax=s["maxPrimaries"][::50].tolist(),
                     # None where no agglomerate is left
                     nMean=[float(a / k) if k > 0 else None for a, k in
                            zip(s["nPrimariesInAgglomerates"][::50],
                                s["nAgglomerates"][::50])]))
    row["verdict"] = judge(row)
    return row


def mean_text(n):
    """The mean agglomerate size in the table's column ("—": none left)."""
    return f"{n:5.1f}" if n is not None else "    —"


def table(rows):
    out = ["series   reading        gamma [1/s]  N0  pred.  max  mean"
           "  aggl.  turb  drag   rot  wait  unallowed  verdict"]
    for r in rows:
        b = r["breakups"]
        out.append(f"{r['series']:8s} {r['reading']:13s}"
                   f" {r['gamma']:12.3g} {r['n0']:4d}"
                   f" {r['nPredicted']:5d}"
                   f" {r['nMax']:4d} {mean_text(r['nMeanAgglomerate'])}"
                   f" {r['nAgglomerates']:6d} {b['Turbulence']:5d}"
                   f" {b['Drag']:5d} {b['Rotation']:5d}"
                   f" {r['waitedForRoom']:5d}"
                   f" {r['unjustified']:4d}/{r['checkedBreakups']:<5d}"
                   f"  {r['verdict']}")
    out.append("pred.: the size at which erosion stops in the mean shear "
               "(breakupTheory, by the reading). wait: break-ups that "
               "waited a step for room. unallowed: the logged break-ups by "
               "turbulence or rotation whose stress (at the parent's own "
               "spin) the criterion puts below the strength, of those "
               "checked. PASS: primaries conserved, no unallowed "
               "break-up, and no agglomerate above pred. once erosion "
               "stopped (the collisions add spin and slip, so sizes may "
               "end below). n/r: the largest was still eroding in the "
               "last tenth of the run.")
    return "\n".join(out) + "\n"


def plots(all_rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # the first series of the preset
    first = (all_rows[0]["series"], all_rows[0]["reading"])
    rows = [r for r in all_rows if (r["series"], r["reading"]) == first]
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

    n0 = rows[0]["n0"]
    g = np.geomspace(0.5 * min(r["gamma"] for r in rows),
                     1.5 * max(r["gamma"] for r in rows), 200)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    readings = sorted({r["reading"] for r in all_rows})
    for reading, ls in zip(readings, ("-", "--", ":")):
        c = criterion(reading)
        ax.plot(g, [c.final_size(n0, x) for x in g], "k" + ls,
                label=f"criterion ({reading}): where erosion stops")
    pairs = list(dict.fromkeys((r["series"], r["reading"])
                               for r in all_rows))
    for (series, reading), mk in zip(pairs, ("o", "^", "s", "v")):
        sel = [r for r in all_rows
               if (r["series"], r["reading"]) == (series, reading)]
        tag = f"{series}, {reading}"
        ax.plot([r["gamma"] for r in sel], [r["nMax"] for r in sel],
                mk, ms=8, label=f"{tag}: largest")
        has = [r for r in sel if r["nMeanAgglomerate"] is not None]
        none = ", ".join(f"{r['gamma']:.3g}" for r in sel
                         if r["nMeanAgglomerate"] is None)
        ax.plot([r["gamma"] for r in has],
                [r["nMeanAgglomerate"] for r in has], mk, mfc="none",
                ms=8, label=f"{tag}: mean agglomerate"
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


