"""verticalChannel: the report's text (its head computed from the run's
own numbers: what it resolves, where its collisions are, how far from the
paper; the regression table of channel.post.regression) and its comparison
with the committed reference (which runs each is, every row against the
reference's with both sigmas)."""

import json
import math

from channel.case import settings
from channel.post import contacts
from aggloTools import regression as reg
from channel.post.statements import PAPER_REGIME

TABLE_D6 = settings.TABLE_D6


def fmt(v):
    return "-" if v is None else f"{v:.4g}"


COLUMNS = [reg.Column("quantity", "quantity", 44),
           reg.Column("sim", "sim", 11, ">", fmt),
           reg.Column("sigma", "sigma", 11, ">", fmt),
           reg.Column("paper", "paper", 11, ">", fmt),
           reg.Column("sim/paper", "factor", 10, ">", fmt),
           reg.Column("tolerance", "tolerance", 11, ">", fmt),
           reg.Column("status", "status", 6),
           reg.Column("note", "note", gap="  ")]


#: The factor of the paper within which a run counts as near the
#: paper's regime (the regime study's verdict, README.md)
REGIME_FACTOR = 2.0


def _factor(v, ref):
    return max(v / ref, ref / v) if v and ref else None


def _range(vals, fmt):
    vals = [v for v in vals if v is not None]
    if not vals:
        return "-"
    lo, hi = min(vals), max(vals)
    return fmt(lo) if fmt(lo) == fmt(hi) else f"{fmt(lo)}-{fmt(hi)}"


def resolves(p, res):
    """What the run resolves, from its own numbers: the sim/paper
    factors of its first configuration with published values (C1 where
    it ran), the share of its window's contacts at the walls, and the
    verdict by the regime study's factor."""
    if p["name"] == "smoke":
        return ("nothing of the physics: it checks the stages, IO,"
                " decomposition and conservation")
    configs = sorted({c for c, _ in res if c in TABLE_D6},
                     key=lambda c: (c != "C1", c))
    if not configs:
        return "no configuration with published values has run"
    c = configs[0]
    ref = TABLE_D6[c]
    fcol, alpha, near, worst = [], [], [], []
    for m in ("EAM", "MAM"):
        r = res.get((c, m))
        if not r:
            continue
        fcol.append(r["f_col_scaled"] / ref["fcol"][m])
        a = r["alpha_f"]
        alpha.append(a / (ref["fagg"][m] / ref["fcol"][m]) if a else None)
        near.append(r.get("nearWallShare"))
        worst += [_factor(fcol[-1], 1.0), _factor(alpha[-1], 1.0)]
    models = "/".join(m for m in ("EAM", "MAM") if (c, m) in res)
    text = (f"{c} f_col x s^2 {_range(fcol, lambda v: f'{v:.2g}')} of"
            f" Table D.6 and alpha_f {_range(alpha, lambda v: f'{v:.2g}')}"
            f" times the paper's ({models})")
    if any(x is None for x in alpha):
        text += " (alpha_f: no agglomeration in a window)"
    text += ("; " + _range(near, lambda v: f"{100 * v:.0f}") + " % of"
             " the window's collisions within"
             f" {contacts.NEAR_WALL:g} delta of a wall (the regime study's"
             " 64^3 C1: 82-83 %; the paper's are at the walls)"
             if any(x is not None for x in near) else
             "; no event log: where the collisions are is not known")
    if None in worst:
        return text + "; not judged against the paper's regime"
    w = max(worst)
    if w <= REGIME_FACTOR:
        return (text + f": within a factor {REGIME_FACTOR:g} of the paper"
                " on all of them, near the paper's regime")
    return (text + f": worst factor {w:.2g}, so not the paper's regime;"
            " only conservation is judged at this preset, the rest is"
            " reported" if p["name"] not in ("paper", PAPER_REGIME) else
            text + f": worst factor {w:.2g}, outside the factor"
            f" {REGIME_FACTOR:g} of the paper's regime")


def report_head(p, res):
    """The report's first lines: what the run resolves (from its own
    numbers), and the preset for comparisons with the paper, its results
    and the command that runs one configuration of it."""
    what = resolves(p, res)
    head = "What preset smoke resolves: " if p["name"] == "smoke" else \
        f"What this run of preset {p['name']} resolves (its own numbers): "
    return [head + what + ".",
            f"For comparisons with the paper: preset {PAPER_REGIME} (the"
            " regime study's closest variant, results/regime/regime.txt;"
            f" its Table D.6 matrix: results/{PAPER_REGIME}/); one"
            f" configuration: ./Allrun -preset {PAPER_REGIME} -configs C2"
            " -np 1 (README.md, 'Run times').", ""]


def particle_numbers(p, res):
    """'N = 100000 per cloud' and, where a configuration's runs released
    another number (the preset's perConfiguration), '(C4: 300000)'; and
    the s^2 likewise."""
    own = sorted({(c, r["nParticles"]) for (c, _), r in res.items()
                  if r["nParticles"] != p["nParticles"]})

    def text(f):
        extra = "; ".join(f"{c}: {f(n)}" for c, n in own)
        return f"{f(p['nParticles'])}" + (f" ({extra})" if extra else "")
    return (text(lambda n: f"{n:g}"),
            text(lambda n: f"{(settings.N_PAPER / n)**2:g}"))


def write_regression(path, p, rows, fluid, res):
    n, s2 = particle_numbers(p, res)
    lines = report_head(p, res) + [
             f"verticalChannel regression, preset {p['name']}:"
             f" N = {n} per cloud, frequencies by Eq. 87"
             f" over T*agg = {p['window'][0]:g}-{p['window'][1]:g},",
             f"scaled to the paper by s^2 = (6e6/N)^2 = {s2};"
             " ratios pass if |sim - paper| <= max(3 sigma, 15 % paper)"
             " (doc/cases.md A.9), sigma from batch means",
             "(10 sub-windows) or Poisson, whichever is larger."
             + (" Absolute scaled frequencies are gated only at `paper`."
                if p["name"] != PAPER_REGIME else
                " At this preset the absolute rows are judged within a"
                " factor 2 of the paper, the ratios only where sigma is"
                " below a third of the paper's effect |paper - 1|."),
             ""]
    for k, v in fluid.items():
        lines.append(f"fluid {k}: u_tau/U_B = {v['uTauByUb']:.4f}"
                     f" (paper 0.053; nominal 0.0541)" + (
                         f", mean gradient {v['gradient']:.4g} m/s2"
                         if v["gradient"] is not None else ""))
    lines.append("")
    lines += reg.table(rows, COLUMNS)
    n = reg.counts(rows)
    lines += ["", f"{n[reg.PASS]} PASS, {n[reg.FAIL]} FAIL,"
              f" {n[reg.NR]} n/r (not resolved or"
              " not gated at this preset, or no events: reported, the"
              " reason in the note)"]
    (path).write_text("\n".join(lines) + "\n")
    return n[reg.FAIL]


# ------------------------------------------------- against the reference

def ranks(runs):
    """'serial', 'N ranks' or 'unknown ranks' of a summary's runs."""
    n = {r.get("nProcs") for r in runs.values()}
    if len(n) != 1 or None in n:
        return "unknown ranks" if None in n or not n else \
            "mixed ranks " + "/".join(str(x) for x in sorted(n))
    k = n.pop()
    return "serial" if k == 1 else f"{k} ranks"


def same_run_line(mine, theirs):
    """Which reference the report is compared with, and why a run on
    another number of ranks does not repeat its digits."""
    line = f"This run: {mine}; the reference: {theirs}."
    if mine != theirs:
        line += (" On another number of ranks the same LES sums its"
                 " parts in another order: the flow parts from the"
                 " reference's in the last digits and the turbulence"
                 " amplifies that, so its rows are another sample of"
                 " the same statistics: they agree within their sigma"
                 " (z below), not digit for digit.")
    else:
        line += (" Same ranks: with the same build and settings the rows"
                 " repeat exactly.")
    return line


def compare(rows, ref_file, runs=None):
    """The text comparing a report's regression rows with the committed
    reference's: which runs each is (serial or on ranks), each value
    against the reference's with both sigmas (z = difference / combined
    sigma; they agree within 3), and the status then and now. runs: this
    report's summary runs (their nProcs)."""
    if not ref_file.is_file():
        return f"no committed reference {ref_file}"
    summary = json.loads(ref_file.read_text())
    ref = {r["quantity"]: r for r in summary.get("regression", [])}
    lines = [f"This report against the committed reference {ref_file}:",
             same_run_line(ranks(runs or {}),
                           ranks(summary.get("runs", {}))),
             f"{'check':<52} {'value':>10} {'sigma':>9} {'reference':>10}"
             f" {'sigma':>9} {'z':>6}  agree  status (reference)"]

    def val(x):
        return f"{x:.4g}" if isinstance(x, (int, float)) else "-"

    n = {"agree": 0, "differ": 0, "-": 0}
    same = 0
    for r in rows:
        o = ref.get(r["quantity"])
        if o is None:
            lines.append(f"{r['quantity'][:52]:<52} {val(r['sim']):>10} "
                         f"{val(r['sigma']):>9} {'-':>10} {'-':>9} {'-':>6}"
                         f"  -      {r['status']} (not in the reference)")
            n["-"] += 1
            continue
        same += o["status"] == r["status"]
        z, verdict = None, "-"
        if all(isinstance(x, (int, float)) for x in
               (r["sim"], o["sim"])):
            s = math.hypot(r["sigma"] or 0.0, o.get("sigma") or 0.0)
            if s > 0:
                z = (r["sim"] - o["sim"]) / s
                verdict = "agree" if abs(z) <= 3 else "differ"
            else:
                verdict = "agree" if r["sim"] == o["sim"] else "differ"
        n[verdict] += 1
        lines.append(f"{r['quantity'][:52]:<52} {val(r['sim']):>10} "
                     f"{val(r['sigma']):>9} {val(o['sim']):>10} "
                     f"{val(o.get('sigma')):>9} {val(z):>6}  {verdict:<6} "
                     f"{r['status']} ({o['status']})")
    lines.append(f"{n['agree']} of {len(rows)} rows agree with the "
                 f"reference within 3 combined sigma, {n['differ']} differ,"
                 f" {n['-']} not comparable; {same} with the reference's "
                 "status")
    return "\n".join(lines)
