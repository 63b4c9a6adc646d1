"""shearFlowValidation: the post-processing of the runs (paper Appendix
B; doc/cases.md B.4-B.6): each run's statistics, the regression rows
(the paper's statements of App. B among them, shear.post.statements),
summary.json, regression.txt and the plots of results/<preset>/.

    python -m shear.post PRESET [RUNS_DIR [OUT_DIR]]
        (also: python -m shear.case post)
    python -m shear.post rejudge PRESET
        the statements judged again on results/PRESET/summary.json
"""

import argparse
import json
import math
import re
from pathlib import Path

import numpy as np

from aggloTools import regression as reg, stats

from shear import TUTORIAL
from shear.case.entries import RUNS, read_settings
from shear.post import statements
from shear.post.plots import picture, plots
from shear.theory import alpha_th, decay_theory, kernel_ST



class Run:
    """The statistics of one finished run."""

    def __init__(self, case):
        self.case = Path(case)
        self.name = self.case.name
        self.s = read_settings(case)
        self.st = stats.read_stats(case)
        st = self.st
        self.t = st["Time"]
        self.gamma = float(self.s["gammaDot"])
        self.tg = self.t * self.gamma
        self.V = 2 * float(self.s["delta"]) * float(self.s["Lx"]) \
            * float(self.s["Lz"])
        self.d = float(self.s["dParticle"])
        self.np0 = int(round(st["nParticles"][0] + st["nAgg"][0]))
        self.np_after = st["nParticles"]
        self.np_before = np.concatenate(([self.np0], st["nParticles"][:-1]))
        self.dncol = np.diff(np.concatenate(([0.0], st["nCol"])))
        rt = self.case / "runTime"
        self.run_time = float(rt.read_text()) if rt.exists() else None

    def final(self, key):
        return float(self.st[key][-1])

    def alpha(self, first=False):
        col = self.st["nColFirst" if first else "nCol"]
        agg = self.st["nAggFirst" if first else "nAgg"]
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(col > 0, agg / np.maximum(col, 1), np.nan)

    def decay(self, alpha, form):
        return decay_theory(self.np0, self.dncol, self.np_before, alpha,
                            form)[1:] / self.np0

    def series(self, alpha_th, n_max=1001):
        """The time series the statements judge (shear.post.statements), at
        most n_max samples (every step's counters are cumulative, so a
        sample holds them exactly; the last step is always one): t gammaDot,
        N_p, the cumulative N_col, N_agg and first contacts, D10 and the
        B.8 curve (consistent form, driven by the run's own kernel)."""
        n = len(self.tg)
        k = np.unique(np.linspace(0, n - 1, min(n, n_max)).astype(int))
        th = self.decay(alpha_th, "consistent") * self.np0
        st = self.st
        return {"np0": self.np0, "tg": self.tg[k], "Np": self.np_after[k],
                "nCol": st["nCol"][k], "nAgg": st["nAgg"][k],
                "nColFirst": st["nColFirst"][k], "D10": st["D10"][k],
                "theory": th[k]}

    def mass_error(self):
        m = self.st["mass"]
        return float(np.max(np.abs(m - m[0])) / m[0])


def row(name, value, expected, tol, ok, unit="", nr=None):
    """A regression row: ok True/False (PASS/FAIL), None (INFO); nr, the
    reason why the band cannot fail, makes it n/r."""
    r = reg.row(ok, nr, check=name, value=value, expected=expected,
                tolerance=tol)
    reason = r.pop("reason", None)
    r["unit"] = unit            # the field order of summary.json
    if reason:
        r["reason"] = reason
    return r


def post(preset, runs_dir=None, out_dir=None):
    runs_dir = Path(runs_dir or TUTORIAL / "runs" / preset)
    out = Path(out_dir or TUTORIAL / "results" / preset)
    out.mkdir(parents=True, exist_ok=True)
    runs = {r: Run(runs_dir / r) for r in RUNS
            if (runs_dir / r / "postProcessing").exists()}
    if not runs:
        raise SystemExit(f"no runs under {runs_dir}")
    any_run = next(iter(runs.values()))
    d, gamma, V = any_run.d, any_run.gamma, any_run.V
    np0 = any_run.np0
    n0 = np0 / V
    K_ST = kernel_ST(d, gamma=gamma)
    a_th = float(alpha_th(d, gamma))
    rows, summary = [], {
        "preset": preset, "V": V, "N0": np0, "n0": n0, "d": d,
        "gammaDot": gamma, "K_ST": K_ST, "alpha_th": a_th,
        "firstContactRate_ST": 0.5 * K_ST * n0**2 * V, "runs": {}}

    # Expected first contacts over the EAM/MAM runs: the statistical scale
    # of alpha (doc/cases.md B.5)
    phys = [r for r in ("EAM", "MAM") if r in runs]
    t_end = max((runs[r].t[-1] for r in phys), default=0.0)
    n_first_exp = 0.5 * K_ST * n0**2 * V * t_end
    sig_a = (math.sqrt((1 - a_th) / (a_th * n_first_exp))
             if n_first_exp > 0 else math.inf)
    band = (min(0.5, max(0.0, 1 - 3 * sig_a)), max(2.0, 1 + 3 * sig_a))
    # A band reaching 0 holds a run without any agglomeration: n/r
    band_nr = (f"the band {band[0]:.2f}-{band[1]:.2f} contains 0 "
               f"(sigma_alpha/alpha = {sig_a:.2f} with "
               f"{n_first_exp:.0f} expected first contacts)"
               if band[0] <= 0 else None)

    # Detection-only: first contacts against Saffman-Turner (B.6)
    if "detect" in runs:
        r = runs["detect"]
        t0 = float(r.s["countFrom"])
        k0 = int(np.argmin(np.abs(r.t - t0)))
        t0 = r.t[k0]
        nf = r.st["nColFirst"] - r.st["nColFirst"][k0]
        T = r.t[-1] - t0
        rate = 0.5 * K_ST * (r.np0 / r.V)**2 * r.V
        n_exp = rate * T
        n_sim = float(nf[-1])
        km = k0 + int(np.argmin(np.abs(r.t[k0:] - (t0 + 0.5 * T))))
        halves = [(float(nf[km]), rate * (r.t[km] - t0)),
                  (float(nf[-1] - nf[km]), rate * (r.t[-1] - r.t[km]))]
        ratio = n_sim / n_exp
        summary["detect"] = {
            "window_tGamma": [t0 * gamma, r.t[-1] * gamma],
            "N_first": n_sim, "N_expected": n_exp,
            "K_sim_over_K_ST": ratio, "sigma": 1 / math.sqrt(n_exp),
            "halves": halves, "N_all": r.final("nCol"),
            "N_overlapStart": r.final("nColOverlapStart"),
            "N_repeat": r.final("nColRepeat"), "run_time_s": r.run_time}
        rows.append(row("detect: K_first/K_ST (first contacts, ghost)",
                        ratio, 1.0, 3 / math.sqrt(n_exp),
                        abs(n_sim - n_exp) <= 3 * math.sqrt(n_exp)))
        for h, (ns, ne) in enumerate(halves):
            rows.append(row(f"detect: half {h + 1} N_first/N_expected",
                            ns / ne, 1.0, 3 / math.sqrt(ne),
                            abs(ns - ne) <= 3 * math.sqrt(ne)))

    # EAM and MAM
    for name in phys + (["bounce"] if "bounce" in runs else []):
        r = runs[name]
        a_all, a_first = r.alpha()[-1], r.alpha(first=True)[-1]
        info = {
            "tGamma_end": float(r.tg[-1]),
            "N_col": r.final("nCol"), "N_col_first": r.final("nColFirst"),
            "N_col_repeat": r.final("nColRepeat"),
            "N_col_overlapStart": r.final("nColOverlapStart"),
            "N_agg": r.final("nAgg"), "N_agg_first": r.final("nAggFirst"),
            "N_suppressed": r.final("nSuppressed"),
            "alpha": float(a_all), "alpha_first": float(a_first),
            "alpha_over_alpha_th": float(a_all / a_th),
            "alpha_first_over_alpha_th": float(a_first / a_th),
            "Ncol_all_over_first": r.final("nCol")
            / max(1.0, r.final("nColFirst")),
            "K_all_over_K_ST": r.final("nCol") / (0.5 * K_ST * n0**2 * V
                                                  * r.t[-1]),
            "K_first_over_K_ST": r.final("nColFirst")
            / (0.5 * K_ST * n0**2 * V * r.t[-1]),
            "Np_final_over_Np0": float(r.np_after[-1] / r.np0),
            "D10_final": r.final("D10"),
            "alpha_th_D10_final": float(alpha_th(r.final("D10"), gamma)),
            "maxPrimaries": r.final("maxPrimaries"),
            "mass_rel_error": r.mass_error(), "run_time_s": r.run_time,
            "steps": len(r.t)}
        if name in phys:
            for form in ("consistent", "printed"):
                th = r.decay(a_th, form)
                dev = float(np.max(np.abs(r.np_after / r.np0 - th) / th))
                info[f"Np_theory_{form}_final"] = float(th[-1])
                info[f"Np_max_deviation_{form}"] = dev
        summary["runs"][name] = info

        if name in phys:
            rows.append(row(f"{name}: alpha/alpha_th (all contacts)",
                            info["alpha_over_alpha_th"], 1.0,
                            f"{band[0]:.2f}-{band[1]:.2f}",
                            band[0] <= info["alpha_over_alpha_th"]
                            <= band[1], nr=band_nr))
            rows.append(row(f"{name}: alpha/alpha_th (first contacts)",
                            info["alpha_first_over_alpha_th"], 1.0,
                            f"{band[0]:.2f}-{band[1]:.2f}",
                            band[0] <= info["alpha_first_over_alpha_th"]
                            <= band[1], nr=band_nr))
            # The same against the binomial noise of the run's own first
            # contacts, under alpha = alpha_th: n/r while 3 sigma reaches 0
            nf = info["N_col_first"]
            sig = (math.sqrt((1 - a_th) / (a_th * nf)) if nf > 0
                   else math.inf)
            info["alpha_first_sigma_rel"] = sig
            ratio = info["alpha_first_over_alpha_th"]
            rows.append(row(f"{name}: alpha/alpha_th (first) within 3 sigma",
                            ratio, 1.0, 3 * sig, abs(ratio - 1) <= 3 * sig,
                            nr=(f"3 sigma_alpha/alpha = {3 * sig:.2f} with "
                                f"{nf:.0f} first contacts reaches 0"
                                if 3 * sig >= 1 else None)))
            rows.append(row(f"{name}: max |Np/Np0 - theory(own K)|/theory"
                            " consistent", info["Np_max_deviation_"
                                                "consistent"],
                            0.0, 0.05,
                            info["Np_max_deviation_consistent"] <= 0.05))
            rows.append(row(f"{name}: same, printed form (B.8 as printed)",
                            info["Np_max_deviation_printed"], 0.0, 0.05,
                            None))
        npp = r.st["nPrimaries"]
        rows.append(row(f"{name}: particle mass conserved", info[
            "mass_rel_error"], 0.0, 1e-12, info["mass_rel_error"] <= 1e-12))
        rows.append(row(f"{name}: primaries conserved, Np = Np0 - Nagg, "
                        "Np never increases",
                        float(np.max(np.abs(npp - npp[0]))), 0.0, 0,
                        bool(np.all(npp == npp[0])
                             and np.all(r.np_after == r.np0 - r.st["nAgg"])
                             and np.all(np.diff(r.np_after) <= 0))))

    if len(phys) == 2:
        # The paper's statements of App. B (shear.post.statements), judged on
        # the series kept in series.json (rejudge reads them back)
        series = {k: runs[k].series(a_th) for k in ("EAM", "MAM")}
        (out / "series.json").write_text(statements.series_text(
            series))
        rows += statement_rows(series, a_th, gamma,
                               min(runs[k].tg[-1] for k in ("EAM", "MAM")))
    summary["alpha_band"] = band
    summary["sigma_alpha_rel"] = sig_a
    summary["regression"] = rows

    status = write_report(out, preset, summary, rows)
    plots(runs, out, a_th, K_ST, n0, gamma)
    picture(runs, out)
    return status


def fmt(v):
    if isinstance(v, str):
        return v
    if v == 0 or 1e-3 <= abs(v) < 1e5:
        return f"{v:.4g}"
    return f"{v:.3e}"


def statement_rows(series, a_th, gamma, t_end_g):
    """The statement rows of App. B (shear.post.statements) in the form of
    this regression table; n/r where the preset ends before the
    paper's duration."""
    short = (f"the paper's statements concern t*gammaDot = "
             f"{statements.PAPER_END:g}; this preset ends at "
             f"{t_end_g:g}" if t_end_g < statements.PAPER_END
             * (1 - 1e-6) else None)
    return [row(f"{r['statement']}: {r['check']}", r["value"], "-",
                r["tolerance"], {reg.PASS: True, reg.FAIL: False}.get(
                    r["status"]), nr=r.get("reason"))
            for r in statements.statements(series, a_th, short, gamma)]


def rejudge(preset, out_dir=None):
    """The statements judged again on a committed summary.json and the
    runs' series.json beside it (without it, the summary's final values:
    the rows that need the series n/r); summary.json and regression.txt
    rewritten."""
    out = Path(out_dir or TUTORIAL / "results" / preset)
    summary = json.loads((out / "summary.json").read_text())
    runs = summary["runs"]
    kept = statements.read_series(out / "series.json")
    series = {k: kept.get(k) or statements.from_summary(
        runs[k], summary["N0"]) for k in ("EAM", "MAM")}
    t_end = min(runs[k]["tGamma_end"] for k in ("EAM", "MAM"))
    rows = [r for r in summary["regression"]
            if not re.match(r"S\d+[a-z]*: ", r["check"])]
    rows += statement_rows(series, summary["alpha_th"], summary["gammaDot"],
                           t_end)
    summary["regression"] = rows
    return write_report(out, preset, summary, rows)


def write_report(out, preset, summary, rows):
    """summary.json and regression.txt (printed) of out; the exit status:
    1 on a FAIL."""
    (out / "summary.json").write_text(json.dumps(summary, indent=2,
                                                 default=float) + "\n")
    table = regression_table(preset, rows)
    (out / "regression.txt").write_text(table + "\n")
    print(table)
    return 0 if all(r["status"] != reg.FAIL for r in rows) else 1


def regression_table(preset, rows):
    w = max(len(r["check"]) for r in rows)
    cols = [reg.Column("check", "check", w),
            reg.Column("value", "value", 10, ">", fmt, "  "),
            reg.Column("expected", "expected", 9, ">", fmt, "  "),
            reg.Column("tolerance", "tolerance", 11, ">", fmt, "  "),
            reg.Column("status", "status", gap="  ")]
    head, *body = reg.table(rows, cols)
    lines = [f"shearFlowValidation regression, preset {preset}", head,
             "-" * (w + 46)] + body + ["-" * (w + 46)]
    for r in rows:
        if r["status"] == reg.NR:
            lines.append(f"n/r {r['check']}: {r['reason']}")
    lines.append(f"{len(rows)} rows, {reg.counts(rows)[reg.FAIL]} FAIL")
    return "\n".join(lines)


def main(argv):
    ap = argparse.ArgumentParser(
        prog="shear.post", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("post", help="the report of a preset's runs (exit "
                       "1 on a FAIL)")
    p.add_argument("preset", help="the preset")
    p.add_argument("runs", nargs="?", help="the folder holding its runs "
                   "(default runs/PRESET)")
    p.add_argument("out", nargs="?", help="the report's folder (default "
                   "results/PRESET)")
    r = sub.add_parser("rejudge", help="the statements judged again on "
                       "results/PRESET/summary.json")
    r.add_argument("preset", help="the preset")
    # 'python -m shear.post PRESET ...' (no subcommand) is post
    if argv and argv[0] not in ("post", "rejudge", "-h", "--help"):
        argv = ["post"] + list(argv)
    a = ap.parse_args(argv)
    if a.cmd == "rejudge":
        return rejudge(a.preset)
    return post(a.preset, a.runs or None, a.out or None)

