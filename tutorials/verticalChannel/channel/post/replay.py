"""verticalChannel: the collision-event logs of a preset's agglomeration
stages replayed through EAM and MAM at e_n = 0.97, 0.80 and 0.60
(doc/eventLog.md): alpha per first contact of each cloud's own
first-contact ensemble, with 95 % intervals.

    channel.post.replay PRESET [RUNS] [--reference]
                              runs/PRESET/report (results/PRESET with
                              --reference): replay.json, replay.txt,
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

from aggloTools import eventlog
from aggloTools.eventlog import BASE, EN_SCAN as EN

from channel.case import settings
from channel.post import postprocess

MODELS = settings.MODELS


def replay(pname, runs_dir=None, reference=False):
    out = settings.report_dir(pname, reference)
    runs = {k: v for k, v in postprocess.run_dirs(pname, runs_dir).items()
            if eventlog.folder(*v).is_dir()}
    if not runs:
        print(f"channel.post.replay: no collision event logs under "
              f"runs/{pname}")
        return None
    out.mkdir(parents=True, exist_ok=True)
    summary = {"preset": pname, "en": list(EN), "events": "first contacts",
               "ensembles": {}}
    rows = []
    for (c, m), (adir, cloud) in sorted(runs.items()):
        res = eventlog.replay(adir, eventlog.en_variants(EN, MODELS),
                              cloud=cloud, events="first", base=BASE)
        res = eventlog.portable(res, str(Path(*adir.parts[-4:])))
        summary["ensembles"][f"{c} {m}"] = res
        rows += eventlog.scan_rows(res, f"{c} {m}")
        d6 = settings.TABLE_D6.get(c)
        paper = [(d6["fagg"][k] / d6["fcol"][k], f"paper {c} {k}: alpha_f"
                  " of Table D.6 (all contacts)") for k in MODELS] \
            if d6 else None
        eventlog.plot_alpha_en(
            res, out / f"alphaReplay{c}{m}.png",
            f"verticalChannel {pname} {c}: the {res['events']} first "
            f"contacts of cloud {m}, replayed", EN, MODELS,
            reference=paper)
    (out / "replay.json").write_text(json.dumps(summary, indent=1) + "\n")

    text = eventlog.scan_table(
        f"verticalChannel {pname}: replay of the first contacts of each"
        " agglomeration-stage cloud's collision-event log"
        " (doc/eventLog.md)", rows, "channel/post/replay.py")
    (out / "replay.txt").write_text(text + "\n")
    print(text)
    return summary


def main(argv):
    def run(a):
        replay(a.preset, a.runs, a.reference)
        return 0
    return postprocess.command(
        argv, "channel.post.replay", __doc__, run,
        "the preset whose runs are replayed",
        "write into the committed results/PRESET",
        runs_help="the folder holding the preset's runs (default: "
        "runs/PRESET)")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
