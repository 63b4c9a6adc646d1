"""The collision-event log of a run (hardSphereCoeffs: eventLog true;
doc/eventLog.md): its records read into numpy, replays through kernel
variants with the hardSphereReplay utility, and the plot of alpha against
the restitution coefficient for EAM and MAM.

    ev = read_events(case)                      # structured array
    res = replay(case, {"EAM080": {"agglomerationModel": "EAM",
                                   "particleCollision": {"en": 0.8}}})
"""

import json
from pathlib import Path

import numpy as np

from .runner import foam_bin, run

HEADER_BYTES = 128

_STATE = [("x{k}", "<f8", 3), ("U{k}", "<f8", 3), ("omega{k}", "<f8", 3),
          ("d{k}", "<f8"), ("rho{k}", "<f8")]

#: One record (collisionEvent.H), little-endian
DTYPE = np.dtype(
    [("timeIndex", "<i4"), ("category", "u1"), ("branch", "u1"),
     ("agglomerates", "u1"), ("type", "u1"), ("time", "<f8"),
     ("proc1", "<i4"), ("id1", "<i4"), ("proc2", "<i4"), ("id2", "<i4")]
    + [(n.format(k=1),) + tuple(t) for n, *t in _STATE]
    + [(n.format(k=2),) + tuple(t) for n, *t in _STATE]
    + [("nPrimary1", "<i4"), ("nPrimary2", "<i4"),
       ("wallDistance", "<f4")])

#: Contact categories, by code (encounterMemory::categoryType)
CATEGORIES = ("first", "repeat", "overlapStart")
#: The branch code of a ghost contact (detected, not applied); the other
#: codes index the branch names of the file's header (the run's
#: agglomeration model names them: agglomerationModel::branchNames)
GHOST = 255


#: The bounds of a record's values, as the C++ reader checks them
#: (collisionEventFile.C; doc/eventLog.md, "Valid records")
D_RANGE = (1e-9, 1.0)            # m
RHO_RANGE = (1e-3, 1e6)          # kg/m3
X_MAX, U_MAX, OMEGA_MAX = 1e6, 1e4, 1e12   # per component
#: The origProc of the parcels break-up makes (fragmentIds::origProc)
FRAGMENT_PROC = -2
#: The origProc of injected parcels (particleIds::injected)
INJECTED_PROC = -3


def invalid_record(r, nb):
    """The reason why the record r of a log whose header names nb
    branches cannot be a logged collision, in the C++ reader's words and
    order ('' if it can be one)."""
    if r["timeIndex"] < 0:
        return f"time index {r['timeIndex']} (valid: >= 0)"
    if r["category"] > 2:
        return (f"category {r['category']} (valid: 0 first, 1 repeat, 2 "
                "overlap at the start of the step)")
    if r["branch"] != GHOST and r["branch"] >= nb:
        return (f"branch {r['branch']} (valid: 0-{nb - 1}, {GHOST} "
                "ghost)")
    if r["agglomerates"] > 1:
        return f"agglomerates {r['agglomerates']} (valid: 0, 1)"
    if r["type"] > 1:
        return f"collision type {r['type']} (valid: 0 sticking, 1 sliding)"
    if not np.isfinite(r["time"]):
        return f"contact time {r['time']} (valid: finite)"
    if not (np.isfinite(r["wallDistance"]) and r["wallDistance"] >= 0):
        return f"wall distance {r['wallDistance']:g} (valid: finite, >= 0)"
    for k in (1, 2):
        proc, pid = r[f"proc{k}"], r[f"id{k}"]
        if (proc < 0 and proc not in (FRAGMENT_PROC, INJECTED_PROC)) \
                or pid < 0:
            return (f"partner {k}: origProc {proc}, origId {pid} (valid: "
                    "origProc a rank >= 0, -2 (a fragment) or -3 "
                    "(injected), origId >= 0)")
    for k in (1, 2):
        d, rho = r[f"d{k}"], r[f"rho{k}"]
        if not D_RANGE[0] <= d <= D_RANGE[1]:
            return f"partner {k}: d {d:g} (valid: {D_RANGE[0]:g} - " \
                f"{D_RANGE[1]:g} m)"
        if not RHO_RANGE[0] <= rho <= RHO_RANGE[1]:
            return f"partner {k}: rho {rho:g} (valid: {RHO_RANGE[0]:g} - " \
                f"{RHO_RANGE[1]:g} kg/m3)"
        if r[f"nPrimary{k}"] < 1:
            return f"partner {k}: nPrimary {r[f'nPrimary{k}']} (valid: >= 1)"
        for name, what, bound, unit in (("x", "position", X_MAX, "m"),
                                        ("U", "velocity", U_MAX, "m/s"),
                                        ("omega", "spin", OMEGA_MAX,
                                         "rad/s")):
            v = r[f"{name}{k}"]
            if not (np.all(np.isfinite(v)) and np.all(np.abs(v) <= bound)):
                return (f"partner {k}: {what} {tuple(v.tolist())} (valid: "
                        f"finite, each component within +-{bound:g} {unit})")
    return ""


def check_records(records, path, nb):
    """Stop (ValueError naming the file, the record and the value) at the
    first record that cannot be a logged collision of a log with nb
    branches, as the C++ reader does."""
    r = records
    with np.errstate(invalid="ignore"):
        bad = ((r["timeIndex"] < 0) | (r["category"] > 2)
               | ((r["branch"] != GHOST) & (r["branch"] >= nb))
               | (r["agglomerates"] > 1) | (r["type"] > 1)
               | ~np.isfinite(r["time"])
               | ~(np.isfinite(r["wallDistance"])
                   & (r["wallDistance"] >= 0)))
        for k in (1, 2):
            proc = r[f"proc{k}"]
            bad |= ((proc < 0) & (proc != FRAGMENT_PROC)
                    & (proc != INJECTED_PROC)) | (r[f"id{k}"] < 0)
            d, rho = r[f"d{k}"], r[f"rho{k}"]
            bad |= ~((d >= D_RANGE[0]) & (d <= D_RANGE[1]))
            bad |= ~((rho >= RHO_RANGE[0]) & (rho <= RHO_RANGE[1]))
            bad |= r[f"nPrimary{k}"] < 1
            for name, bound in (("x", X_MAX), ("U", U_MAX),
                                ("omega", OMEGA_MAX)):
                v = r[f"{name}{k}"]
                bad |= ~np.all(np.isfinite(v) & (np.abs(v) <= bound), axis=1)
    if bad.any():
        k = int(np.argmax(bad))
        raise ValueError(f"{path}: record {k}: {invalid_record(r[k], nb)}; "
                         "the file is corrupt")


def folder(case, cloud="kinematicCloud"):
    return Path(case) / "postProcessing" / f"{cloud}CollisionEvents"


def read_header(path):
    """The branch names that the header of an events<rank>.bin file gives
    (ValueError if it is not a log of this layout)."""
    head = Path(path).read_bytes()[:HEADER_BYTES].decode(errors="replace")
    want = (f"aggloCollisionEvents 2 recordBytes {DTYPE.itemsize} arch LSB;"
            "label=32;scalar=64 branches ")
    if not head.startswith(want) or not head[len(want):].split():
        raise ValueError(f"{path}: not a collision event file of this"
                         f" layout (header {head.strip()!r})")
    return tuple(head[len(want):].split()[0].split(","))


def body_records(path, data, dtype, header_bytes=HEADER_BYTES):
    """The records of dtype after the header of an event file's bytes
    (ValueError on a partial record at the end)."""
    body = len(data) - header_bytes
    if body < 0 or body % dtype.itemsize:
        raise ValueError(f"{path}: a partial record at the end (a write"
                         " cut off; a restart of the run cuts it back)")
    return np.frombuffer(data, dtype, body // dtype.itemsize, header_bytes)


def read_file(path):
    """The records of one events<rank>.bin file."""
    branches = read_header(path)
    records = body_records(path, Path(path).read_bytes(), DTYPE)
    check_records(records, path, len(branches))
    return records


def branches(case, cloud="kinematicCloud"):
    """The branch names of the case's logs (one model: every file's
    header names the same; ValueError otherwise)."""
    files = sorted(folder(case, cloud).glob("events*.bin"))
    if not files:
        raise FileNotFoundError(f"no collision event log in "
                                f"{folder(case, cloud)}")
    names = {read_header(f) for f in files}
    if len(names) != 1:
        raise ValueError(f"{folder(case, cloud)}: the log files name "
                         f"different branches {sorted(names)}")
    return names.pop()


def read_events(case, cloud="kinematicCloud"):
    """Every event of the case's logs (all ranks), in the order of the
    replay: time index, contact time, then the ids. The files must name
    the same branches (ValueError otherwise: their codes would mean
    different branches)."""
    branches(case, cloud)
    files = sorted(folder(case, cloud).glob("events*.bin"))
    ev = np.concatenate([read_file(f) for f in files])
    order = np.lexsort((ev["id2"], ev["proc2"], ev["id1"], ev["proc1"],
                        ev["time"], ev["timeIndex"]))
    return ev[order]


def variants_text(variants):
    """A variants dictionary of hardSphereReplay: name -> entries (nested
    dicts for sub-dictionaries)."""
    def body(d):
        return " ".join(f"{k} {{ {body(v)} }}" if isinstance(v, dict)
                        else f"{k} {v};" for k, v in d.items())
    return "\n".join(f"{name} {{ {body(d)} }}" for name, d in
                     variants.items()) + "\n"


def replay(case, variants=None, cloud="kinematicCloud", events="all",
           check=False, out=None, base=None, events_out=None):
    """Run hardSphereReplay on the case: the run's own kernel and the
    variants (name -> entries merged into it), the others paired with
    base (default: the run's kernel); returns its JSON as a dict. out:
    where the JSON goes (default: replay-<events>.json in the log
    folder); events_out: where the per-event CSV goes (-eventsOut).
    check: the run's kernel must reproduce every logged outcome (a
    failed check raises runner.CommandError)."""
    case = Path(case).resolve()
    out = Path(out or folder(case, cloud) / f"replay-{events}.json")
    cmd = [foam_bin("hardSphereReplay"), "-case", str(case), "-cloud",
           cloud, "-events", events, "-json", str(out)]
    if events_out:
        cmd += ["-eventsOut", str(events_out)]
    if base:
        cmd += ["-base", base]
    return run_replay(cmd, case, out, variants, check,
                      f"log.hardSphereReplay.{events}")


def run_replay(cmd, case, out, variants, check, log):
    """Run a replay utility's command with the variants (written beside
    the JSON out) and -check; returns its JSON as a dict."""
    if variants:
        vfile = out.with_suffix(".variants")
        vfile.write_text(variants_text(variants))
        cmd = cmd + ["-variants", str(vfile)]
    if check:
        cmd = cmd + ["-check"]
    run(cmd, case, log)
    return json.loads(out.read_text())


def read_replay_events(path):
    """The per-event CSV of hardSphereReplay -eventsOut as a dict of
    column name -> numpy array (configuration columns <name>.<field>)."""
    path = Path(path)
    with open(path) as f:
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.shape[1] != len(names):
        raise ValueError(f"{path}: {data.shape[1]} columns for "
                         f"{len(names)} names")
    return {n: data[:, k] for k, n in enumerate(names)}


def replay_events(case, variants, cloud="kinematicCloud", events="all"):
    """Replay with the per-event output: (the JSON result, the columns of
    read_replay_events)."""
    f = folder(Path(case).resolve(), cloud) / f"replay-{events}-events.csv"
    res = replay(case, variants, cloud, events, events_out=f)
    return res, read_replay_events(f)


def en_variants(ens, models=("EAM", "MAM")):
    """The variants of a restitution scan: <model><100 en>."""
    return {f"{m}{round(100 * en):03d}": {
        "agglomerationModel": m, "particleCollision": {"en": en}}
        for m in models for en in ens}


def plot_alpha_en(results, path, title, ens, models=("EAM", "MAM"),
                  reference=None):
    """alpha against e_n per model with the 95 % Wilson intervals of the
    replay (hardSphereReplay), from the replay results of en_variants
    (one log: the same collisions); reference: (value, label) of a
    horizontal line (a theory, the paper's value), or a list of them."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    conf = {c["name"]: c for c in results["configurations"]}
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for k, m in enumerate(models):
        rows = [conf[f"{m}{round(100 * en):03d}"] for en in ens]
        a = np.array([r["alpha"] for r in rows], float)
        lo = np.array([r["alphaLow"] for r in rows], float)
        hi = np.array([r["alphaHigh"] for r in rows], float)
        x = np.array(ens) + (k - 0.5) * 0.006
        # the interval's ends as written (10 digits) may pass alpha by a
        # round-off
        err = [np.clip(a - lo, 0, None), np.clip(hi - a, 0, None)]
        ax.errorbar(x, a, yerr=err, marker="os"[k % 2], capsize=4,
                    label=m)
    refs = [reference] if reference and not isinstance(
        reference[0], (list, tuple)) else (reference or [])
    for j, (value, label) in enumerate(refs):
        ax.axhline(value, color=f"C{j}" if len(refs) > 1 else "0.4",
                   ls="--", lw=1, label=label)
    ax.set_xlabel("restitution coefficient $e_n$")
    ax.set_ylabel(r"$\alpha = N_{agg}/N_{col}$ (bars: 95 % Wilson"
                  " interval)")
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def portable(res, case_name):
    """A replay result without machine paths (for committed results):
    the case as case_name, sources by file name."""
    out = dict(res, case=case_name)
    out["configurations"] = [dict(c, source=Path(c["source"]).name)
                             for c in res["configurations"]]
    return out


#: The restitution scan of the tutorials and its reference configuration
EN_SCAN = (0.97, 0.80, 0.60)
BASE = "EAM097"


def _g(v):
    return "-" if v is None else f"{v:.4g}"


def _paired(p):
    """The paired fields of a configuration (none for the base): the
    events only the base / only this one agglomerates, and the ratio of
    the alphas with its 95 % interval."""
    if p is None:
        return dict(only="(base)", ratio=None, ratioCI="")
    ci = ("-" if p["ratioLow"] is None
          else f"{p['ratioLow']:.3g}-{p['ratioHigh']:.3g}")
    return dict(only=f"{p['onlyA']} / {p['onlyB']}", ratio=p["ratio"],
                ratioCI=ci)


def scan_rows(res, ensemble, extra=None):
    """The table rows of a replay result (its variants, not the run's own
    kernel): alpha with its interval and the pairing with the base;
    extra(configuration) adds fields."""
    pairs = {p["b"]: p for p in res["paired"]}
    return [dict(ensemble=ensemble, configuration=c["name"],
                 events=c["events"], agg=c["agglomerations"],
                 alpha=c["alpha"], low=c["alphaLow"], high=c["alphaHigh"],
                 **(extra(c) if extra else {}),
                 **_paired(pairs.get(c["name"])))
            for c in res["configurations"][1:]]


def scan_table(title, rows, script, base=BASE, extra_columns=()):
    """The text of a restitution-scan table (regression.Column objects
    of extra fields go after the interval)."""
    from . import regression as reg
    cols = ([reg.Column("ensemble", "ensemble", 8),
             reg.Column("kernel", "configuration", 7, gap="  "),
             reg.Column("first", "events", 6, ">", str),
             reg.Column("agg", "agg", 5, ">", str),
             reg.Column("alpha", "alpha", 10, ">", _g),
             reg.Column("95 % low", "low", 10, ">", _g),
             reg.Column("95 % high", "high", 10, ">", _g)]
            + list(extra_columns)
            + [reg.Column(f"vs {base}: only", "only", 15, ">", str),
               reg.Column("ratio", "ratio", 7, ">", _g),
               reg.Column("95 %", "ratioCI", 15, ">", str)])
    return "\n".join(
        [title, ""] + reg.table(rows, cols)
        + ["", "Kernel <model><100 e_n>: the run's kernel with that"
           " agglomeration model and e_n. The replay freezes the"
           f" collisions (see the header of {script})."])
