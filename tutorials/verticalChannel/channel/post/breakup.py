"""verticalChannel: the break-up of a preset's agglomeration stages (a
preset with `breakup NAME;`, doc/breakup.md): what broke, by which
mechanism and when, how near the agglomerates came to breaking, the
agglomerate sizes over time and whether they settle, the kinetic energy
of the splits, and the logged break-ups replayed through
variants of the model.

    channel.post.breakup PRESET [--reference]
        runs/PRESET/report (results/PRESET with --reference):
        breakup.json, breakup.txt, breakupHistory.png, breakupSizes.png;
        nothing for a preset without break-up

Per run (a cloud of an agglomeration stage whose caseSettings names a
break-up model):
- the break-ups per mechanism: the counters nBreakup<Mechanism> of
  stats.dat over T*agg, their window rates (Eq. 87's window) with sigma;
- the largest load/strength ratio of the agglomerates checked in each
  step (the driver's log line; 1 breaks);
- the agglomerates per size at every write; the size distribution is
  called steady over the window's second half when neither N_a nor the
  mean number of primaries per agglomerate changes there by more than
  twice its error (steadiness(): a least-squares line through every
  step's statistics, its change over that half against sqrt(N_a) and
  the standard error of the mean size);
- with the event log: every break-up's kinetic energy change (the
  fragments' against the parent's, translational and rotational, as the
  driver's log line sums it for each step), relative to the
  parent's rotational energy (its energy in its own centre-of-mass frame);
  breakupReplay -check (each logged fragment reproduced) and the
  variants of the run's coefficients (variants()): how many of the logged
  break-ups each keeps."""

import json
import math
import sys

import numpy as np

from aggloTools import breakuplog, uncertainty
from aggloTools.runner import CommandError
from aggloTools.stats import read_stats, read_table

from channel import TUTORIAL
from channel.case import settings
from channel.plots.breakup import plots
from channel.post import postprocess

#: The stress coefficients of stressThreshold (doc/breakup.md 1.1-1.5)
STRESS_COEFFICIENTS = ("Cv", "Ci", "Cd", "rotationFactor", "Cw")


def variants(coeffs):
    """breakupReplay variants of the run's own <model>Coeffs (a dict of
    its caseSettings): every stress coefficient halved (keeps the logged
    break-ups that the halved loads still break), binary splits instead of
    the run's sizes (the same parents, other fragments), and the spin's
    mechanism off (when the run has it). {} for a model without stresses
    (only -check then)."""
    st = coeffs.get("stresses")
    if not isinstance(st, dict):
        return {}
    out = {"stressesHalved": {"stresses": {
        k: 0.5 * float(st[k]) for k in STRESS_COEFFICIENTS if k in st}}}
    frag = coeffs.get("fragmentation", {})
    if frag.get("mode") != "binary":
        out["binary"] = {"fragmentation": {"mode": "binary"}}
        if "betaAlpha" in frag:
            out["binary"]["remove"] = "(fragmentation.betaAlpha)"
    mech = [str(m).strip("()") for m in (st.get("mechanisms") if
            isinstance(st.get("mechanisms"), list) else
            [st.get("mechanisms", "")])]
    mech = " ".join(mech).split()
    if "rotation" in mech and len(mech) > 1:
        out["noRotation"] = {
            "stresses": {"mechanisms": "(" + " ".join(
                m for m in mech if m != "rotation") + ")"},
            "remove": "(stresses.rotationFactor)"}
    return out


def breakup_runs(pname):
    """(config, model) -> (case, cloud, break-up model) of the finished
    agglomeration stages of a preset that run break-up."""
    out = {}
    for k, (adir, cloud) in postprocess.run_dirs(pname).items():
        b = settings.read_settings(adir).get("breakup", {})
        model = b.get("breakupModel", "none") if isinstance(b, dict) \
            else "none"
        if model != "none":
            out[k] = (adir, cloud, model)
    return out


def size_history(p, adir, cloud):
    """T*agg, N_a, mean and largest primaries per agglomerate and the
    counts per size of every write's agglomerateSizes.dat."""
    t0 = settings.end_time(p, "dispersion")
    base = adir / "postProcessing" / f"{cloud}HardSphere"
    rows = []
    for f in sorted(base.glob("*/agglomerateSizes.dat"),
                    key=lambda f: float(f.parent.name)):
        t = read_table(f)
        k, n = np.asarray(t["k"], float), np.asarray(t["count"], float)
        na = float(n.sum())
        mean = float((k * n).sum() / na) if na else 0.0
        var = float(((k - mean)**2 * n).sum() / na) if na else 0.0
        rows.append({"T": (float(f.parent.name) - t0) / p["tScale"],
                     "N_a": na, "meanSize": mean,
                     "sigmaMeanSize": math.sqrt(var / na) if na else 0.0,
                     "maxSize": float(k.max()) if na else 0.0,
                     "counts": {str(int(a)): int(b) for a, b in zip(k, n)}})
    return rows


def steadiness(T, na, npp, w0, w1, spread=None):
    """Whether N_a and the mean size (primaries in agglomerates over N_a)
    settle over the window's second half, from the statistics of every
    step (T*agg, N_a, N_pp): the change of a least-squares line through
    that half against twice the Poisson error of N_a at its end
    (sqrt(N_a)) and twice the standard error of the mean size (spread,
    the standard deviation of the sizes, over sqrt(N_a); the last write's
    distribution; at least 1/N_a); None if fewer than three steps lie
    there."""
    T, na, npp = (np.asarray(x, float) for x in (T, na, npp))
    half = ((w0 + w1) / 2 <= T) & (T <= w1 + 1e-9) & (na > 0)
    if half.sum() < 3:
        return None
    T, na, npp = T[half], na[half], npp[half]
    out = {"from": float(T[0]), "to": float(T[-1]), "steps": int(len(T))}
    sd = 0.0 if spread is None else float(spread)
    # the mean size's error at least one primary more in one agglomerate
    # (sizes all alike have no spread, yet are not known exactly)
    for q, y, sigma in (("N_a", na, math.sqrt(na[-1])),
                        ("meanSize", npp / na, max(sd / math.sqrt(na[-1]),
                                                   1 / na[-1]))):
        change = float(np.polyfit(T, y, 1)[0] * (T[-1] - T[0]))
        out[q] = {"change": change, "sigma": float(sigma),
                  "steady": bool(abs(change) <= 2 * sigma)}
    out["steady"] = out["N_a"]["steady"] and out["meanSize"]["steady"]
    return out


def energy(ev):
    """Per logged break-up: the kinetic energy change of the split and
    the parent's rotational energy [J] (hardSphereState's energies)."""
    def parts(s):
        m = ev[f"rho_{s}"] * math.pi / 6 * ev[f"d_{s}"]**3
        rot = 0.5 * 0.1 * m * ev[f"d_{s}"]**2 * (ev[f"omega_{s}"]**2).sum(1)
        return 0.5 * m * (ev[f"U_{s}"]**2).sum(1) + rot, rot
    (ep, rp), (ea, _), (eb, _) = parts("p"), parts("a"), parts("b")
    return ea + eb - ep, rp


def analyse(p, adir, cloud, model):
    st = read_stats(adir, cloud)
    t0 = settings.end_time(p, "dispersion")
    T = np.concatenate(([0.0], (st["Time"] - t0) / p["tScale"]))
    w0, w1 = p["window"]
    # the case relative to the tutorial where it lies in it
    try:
        case = str(adir.relative_to(TUTORIAL))
    except ValueError:
        case = str(adir)
    r = {"case": case, "cloud": cloud, "model": model, "mechanisms": {},
         # every step's series, for the pictures (not in breakup.json)
         "_series": {"T": T[1:], "nAgglomerates": st["nAgglomerates"],
                     "nAgg": st["nAgg"]}}
    for col in sorted(c for c in st if c.startswith("nBreakup")):
        n = np.concatenate(([0.0], st[col]))
        f, sb, sp, dn = uncertainty.window_rate(T, n, w0, w1)
        r["mechanisms"][col[len("nBreakup"):]] = {
            "stage": float(n[-1]), "window": dn, "rate": f,
            "sigma": max(sb, sp)}
        r["_series"][col] = st[col]
    log = (adir / "log.aggloPimpleFoam").read_text(errors="replace")
    # the driver's kinetic energy change of each step's splits
    r["energyChangeLog"] = float(sum(postprocess.step_values(
        log, r"kinetic energy change ([-0-9.eE+]+) J")))
    tr = postprocess.step_values(log, r"agglomerates checked, largest "
                                 r"\w+ ([-0-9.eE+]+)", times=True)
    ratio = [v for _, v in tr]
    r["largestRatio"] = max(ratio) if ratio else None
    r["largestRatioSteps"] = len(ratio)
    r["_series"]["ratio"] = (np.array([(t - t0) / p["tScale"]
                                       for t, _ in tr]), np.array(ratio))
    r["sizes"] = size_history(p, adir, cloud)
    last = r["sizes"][-1] if r["sizes"] else None
    r["steady"] = steadiness(
        T[1:], st["nAgglomerates"], st["nPrimariesInAgglomerates"], w0, w1,
        last["sigmaMeanSize"] * math.sqrt(last["N_a"])
        if last and last["N_a"] else None)
    b = settings.read_settings(adir)["breakup"]
    r["events"] = events(adir, cloud, b.get(f"{model}Coeffs", {}))
    return r


def events(adir, cloud, coeffs):
    """The event log's break-ups: counts, energies, the replay."""
    if not breakuplog.folder(adir, cloud).is_dir():
        return None
    ev = breakuplog.read_breakup_events(adir, cloud)
    out = {"logged": int(len(ev))}
    if not len(ev):
        out["replay"] = "nothing logged: nothing to replay"
        return out
    dke, rot = energy(ev)
    frac = dke[rot > 0] / rot[rot > 0]
    out["energyChange"] = {"sum": float(dke.sum()), "splits": len(frac)}
    if len(frac):
        q = np.percentile(frac, [0, 50, 100])
        out["energyChange"].update(
            {"ofRotationalMin": float(q[0]), "ofRotationalMedian":
             float(q[1]), "ofRotationalMax": float(q[2])})
    out["variants"] = variants(coeffs)
    try:
        res = breakuplog.replay_breakups(adir, out["variants"], cloud,
                                         check=True)
        out["replay"] = res
    except CommandError as e:
        out["replay"] = f"breakupReplay failed: {e}"
    return out


def without_breakup(p, r):
    """The same agglomeration stage without break-up, where the preset
    shares its earlier stages (stagesFrom) and that preset has run it:
    {"case", "equal": whether every statistics column both have is equal
    at every step, "firstDifference": T*agg of the first step that
    differs (or the shorter run's last)}; None otherwise. A run in which
    nothing breaks must equal it (the break-up model draws nothing)."""
    base = p.get("stagesFrom")
    if not base:
        return None
    adir = TUTORIAL / r["case"]
    other = TUTORIAL / "runs" / base / adir.parent.name / adir.name
    if not (other / "done.agglomeration").is_file():
        return None
    st, ot = read_stats(adir, r["cloud"]), read_stats(other, r["cloud"])
    n = min(len(st["Time"]), len(ot["Time"]))
    same = np.ones(n, bool)
    for col in set(st) & set(ot):
        same &= st[col][:n] == ot[col][:n]
    if not same.all():
        first = float(r["_series"]["T"][int(np.argmin(same))])
    elif len(st["Time"]) != len(ot["Time"]):
        first = float(r["_series"]["T"][n - 1])    # one run is longer
    else:
        first = None
    return {"case": str(other.relative_to(TUTORIAL)),
            "equal": first is None, "firstDifference": first}


def replay_lines(rep):
    """The replay's lines of the report."""
    if not isinstance(rep, dict):
        return [f"  replay: {rep}"]
    lines = []
    mech = ", ".join(rep.get("mechanisms", []))
    for c in rep["configurations"]:
        line = (f"  replay {c['name']:<16} breaks {c['breaks']} of "
                f"{rep['events']} logged (by mechanism, {mech}: "
                f"{c['byMechanism']}")
        if c["name"] == "run":
            line += f"; -check: {c['reproduced']} reproduced bit for bit)"
        else:
            line += f"; by another mechanism {c['mechanismChanged']})"
        lines.append(line)
    return lines


def text(pname, res):
    lines = [f"verticalChannel {pname}: break-up in the agglomeration "
             "stage (channel/post/breakup.py; doc/breakup.md)", ""]
    for (c, m), r in sorted(res.items()):
        lines.append(f"{c} {m} (cloud {r['cloud']}, model {r['model']}):")
        for mech, v in r["mechanisms"].items():
            lines.append(f"  {mech:<12} stage {v['stage']:8.0f}  window "
                         f"{v['window']:8.0f}  rate {v['rate']:.4g} +- "
                         f"{v['sigma']:.2g} per T*")
        lr = r["largestRatio"]
        lines.append("  largest load/strength ratio of the agglomerates "
                     "checked: " + (f"{lr:.3g} over {r['largestRatioSteps']}"
                                      " steps (a ratio of 1 breaks)"
                                      if lr is not None else "none checked"))
        if r["sizes"]:
            e = r["sizes"][-1]
            lines.append(f"  at T*agg {e['T']:.4g}: N_a {e['N_a']:.0f}, mean "
                         f"{e['meanSize']:.3f} +- {e['sigmaMeanSize']:.2g} "
                         f"primaries, largest {e['maxSize']:.0f}")
        s = r["steady"]
        if s is None:
            lines.append("  steady sizes: n/r (fewer than three steps with "
                         "agglomerates in the window's second half)")
        else:
            lines.append(
                f"  steady sizes over T*agg {s['from']:.0f}-{s['to']:.0f}: "
                f"{'yes' if s['steady'] else 'no'} (N_a changes by "
                f"{s['N_a']['change']:.3g} +- {s['N_a']['sigma']:.2g}, the "
                f"mean size by {s['meanSize']['change']:.3g} +- "
                f"{s['meanSize']['sigma']:.2g}; steady within 2 sigma)")
        wo = r.get("withoutBreakup")
        if wo:
            lines.append(f"  the same stage without break-up ({wo['case']}):"
                         + (" every statistics column equal at every step"
                            if wo["equal"] else " differs from T*agg "
                            f"{wo['firstDifference']:.4g}"))
        ev = r["events"]
        if ev is None:
            lines.append("  event log: off")
            continue
        lines.append(f"  event log: {ev['logged']} break-ups")
        if "energyChange" in ev:
            e = ev["energyChange"]
            lines.append(f"  kinetic energy change of the splits: "
                         f"{e['sum']:.4g} J (the solver log's steps: "
                         f"{r['energyChangeLog']:.4g} J)")
            if e["splits"]:
                lines.append(
                    "  per split, over the parent's rotational energy: "
                    f"least {e['ofRotationalMin']:.3g}, median "
                    f"{e['ofRotationalMedian']:.3g}, largest "
                    f"{e['ofRotationalMax']:.3g} ({e['splits']} splits of"
                    " a spinning parent)")
        lines += replay_lines(ev["replay"])
    return "\n".join(lines) + "\n"


def post(pname, reference=False):
    p = settings.preset(pname)
    runs = breakup_runs(pname)
    if not runs:
        print(f"channel.post.breakup: no finished run with break-up under "
              f"runs/{pname}: nothing written")
        return 0
    out = settings.report_dir(pname, reference)
    out.mkdir(parents=True, exist_ok=True)
    res = {k: analyse(p, *v) for k, v in runs.items()}
    for r in res.values():
        r["withoutBreakup"] = without_breakup(p, r)
    (out / "breakup.json").write_text(json.dumps(
        {f"{c} {m}": {k: v for k, v in r.items() if not k.startswith("_")}
         for (c, m), r in sorted(res.items())}, indent=1) + "\n")
    t = text(pname, res)
    (out / "breakup.txt").write_text(t)
    print(t, end="")
    plots(out, p, res)
    # a replay that failed (its -check included) fails the report
    failed = [k for k, r in res.items() if r["events"] and str(
        r["events"].get("replay", "")).startswith("breakupReplay failed")]
    return 1 if failed else 0


def main(argv):
    return postprocess.command(
        argv, "channel.post.breakup", __doc__,
        lambda a: post(a.preset, a.reference),
        "the preset whose runs are reported",
        "write into the committed results/PRESET")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
