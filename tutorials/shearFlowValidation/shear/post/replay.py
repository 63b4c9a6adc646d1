"""shearFlowValidation: the collision-event logs of a preset's runs
replayed through EAM and MAM at e_n = 0.97, 0.80 and 0.60 (doc/eventLog.md):
alpha per first contact of each run's own first-contact ensemble, with
95 % intervals, against van de Ven & Mason's alpha_th.

    python -m shear.post.replay PRESET [OUT]
        OUT (default results/PRESET): replay.json, replay.txt,
        alphaReplay<run>.png (nothing without logs)

The replay freezes each run's collisions: every first contact meets its
partner as it did in the run, only the outcome is computed anew; what a
changed outcome would do to later collisions is not included. The detect
run's first contacts (ghost: particles pass through each other) are the
undisturbed ensemble of the Saffman-Turner kernel."""

import argparse
import json
import sys
from pathlib import Path

from aggloTools import eventlog, regression as reg
from aggloTools.eventlog import BASE, EN_SCAN as EN

from shear import TUTORIAL
from shear.case import entries

MODELS = ("EAM", "MAM")


def replay(preset, runs_dir=None, out_dir=None):
    runs_dir = Path(runs_dir or TUTORIAL / "runs" / preset)
    out = Path(out_dir or TUTORIAL / "results" / preset)
    found = entries.logged_runs(runs_dir, "shear.post.replay")
    if found is None:
        return None
    logs, _, a_th = found
    out.mkdir(parents=True, exist_ok=True)
    summary = {"preset": preset, "en": list(EN), "alpha_th": a_th,
               "events": "first contacts", "ensembles": {}}
    rows = []
    for r in logs:
        res = eventlog.replay(runs_dir / r, eventlog.en_variants(EN, MODELS),
                              events="first", base=BASE)
        res = eventlog.portable(res, f"runs/{preset}/{r}")
        summary["ensembles"][r] = res
        rows += eventlog.scan_rows(
            res, r, lambda c: dict(byTheory=c["alpha"] / a_th))
        eventlog.plot_alpha_en(
            res, out / f"alphaReplay{r}.png",
            f"shearFlowValidation {preset}: the {res['events']} first "
            f"contacts of run {r}, replayed", EN, MODELS,
            reference=(a_th, r"$\alpha_{th}$ (van de Ven & Mason)"))
    (out / "replay.json").write_text(json.dumps(summary, indent=1) + "\n")

    text = eventlog.scan_table(
        f"shearFlowValidation {preset}: replay of the first contacts of"
        f" each run's collision-event log (doc/eventLog.md);"
        f" alpha_th = {a_th:.4g}", rows, "shear/post/replay.py",
        extra_columns=[reg.Column("alpha/alpha_th", "byTheory", 15, ">",
                                  lambda v: f"{v:.4g}")])
    (out / "replay.txt").write_text(text + "\n")
    print(text)
    return summary


def main(argv):
    ap = argparse.ArgumentParser(
        prog="shear.post.replay", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("preset", help="the preset whose runs are replayed")
    ap.add_argument("out", nargs="?", help="the output folder (default "
                    "results/PRESET)")
    a = ap.parse_args(argv)
    replay(a.preset, None, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
