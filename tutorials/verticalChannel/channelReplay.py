#!/usr/bin/env python3
"""verticalChannel: the collision-event logs of a preset's agglomeration
stages replayed through EAM and MAM at e_n = 0.97, 0.80 and 0.60
(doc/eventLog.md): alpha per first contact of each cloud's own
first-contact ensemble, with 95 % intervals.

    channelReplay.py PRESET [RUNS]
                              results/PRESET: replay.json, replay.txt,
                              alphaReplay<config><cloud>.png of the runs
                              under runs/PRESET (or RUNS); nothing
                              without logs

The replay freezes each cloud's collisions: every first contact meets its
partner as it did in the run, only the outcome is computed anew; what a
changed outcome would do to later collisions, to the agglomerates and
(two-way coupled) to the flow is not included."""

import json
import sys
from pathlib import Path

from aggloTools import eventlog, regression as reg

import channelPost

HERE = channelPost.HERE
EN = (0.97, 0.80, 0.60)
MODELS = ("EAM", "MAM")
BASE = "EAM097"     # the paired comparisons are with EAM at e_n = 0.97


def paired(p):
    """The paired columns of a configuration (none for the base): the
    events only the base / only this one agglomerates, and the ratio of
    the alphas with its 95 % interval."""
    if p is None:
        return dict(only="(base)", ratio=None, ratioCI="")
    ci = ("-" if p["ratioLow"] is None
          else f"{p['ratioLow']:.3g}-{p['ratioHigh']:.3g}")
    return dict(only=f"{p['onlyA']} / {p['onlyB']}", ratio=p["ratio"],
                ratioCI=ci)


def replay(pname, base=None):
    out = HERE / "results" / pname
    runs = {k: v for k, v in channelPost.run_dirs(pname, base).items()
            if eventlog.folder(*v).is_dir()}
    if not runs:
        print(f"channelReplay.py: no collision event logs under "
              f"runs/{pname}")
        return None
    out.mkdir(parents=True, exist_ok=True)
    summary = {"preset": pname, "en": list(EN), "events": "first contacts",
               "ensembles": {}}
    rows = []
    for (c, m), (adir, cloud) in sorted(runs.items()):
        res = eventlog.replay(adir, eventlog.en_variants(EN, MODELS),
                              cloud=cloud, events="first", base=BASE)
        pairs = {p["b"]: p for p in res["paired"]}
        res = eventlog.portable(res, str(Path(*adir.parts[-4:])))
        summary["ensembles"][f"{c} {m}"] = res
        for conf in res["configurations"][1:]:
            rows.append(dict(ensemble=f"{c} {m}",
                             configuration=conf["name"],
                             events=conf["events"],
                             agg=conf["agglomerations"],
                             alpha=conf["alpha"], low=conf["alphaLow"],
                             high=conf["alphaHigh"],
                             **paired(pairs.get(conf["name"]))))
        eventlog.plot_alpha_en(
            res, out / f"alphaReplay{c}{m}.png",
            f"verticalChannel {pname} {c}: the {res['events']} first "
            f"contacts of cloud {m}, replayed", EN, MODELS)
    (out / "replay.json").write_text(json.dumps(summary, indent=1) + "\n")

    def g(v):
        return "-" if v is None else f"{v:.4g}"
    cols = [reg.Column("ensemble", "ensemble", 8),
            reg.Column("kernel", "configuration", 7, gap="  "),
            reg.Column("first", "events", 6, ">", str),
            reg.Column("agg", "agg", 5, ">", str),
            reg.Column("alpha", "alpha", 10, ">", g),
            reg.Column("95 % low", "low", 10, ">", g),
            reg.Column("95 % high", "high", 10, ">", g),
            reg.Column(f"vs {BASE}: only", "only", 15, ">", str),
            reg.Column("ratio", "ratio", 7, ">", g),
            reg.Column("95 %", "ratioCI", 15, ">", str)]
    text = "\n".join(
        [f"verticalChannel {pname}: replay of the first contacts of each"
         " agglomeration-stage cloud's collision-event log"
         " (doc/eventLog.md)", ""] + reg.table(rows, cols)
        + ["", "Kernel <model><100 e_n>: the run's kernel with that"
           " agglomeration model and e_n. The replay freezes the"
           " collisions (see the header of channelReplay.py)."])
    (out / "replay.txt").write_text(text + "\n")
    print(text)
    return summary


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    replay(*sys.argv[1:])
    sys.exit(0)
