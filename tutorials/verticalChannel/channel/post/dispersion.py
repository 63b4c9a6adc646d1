"""verticalChannel: the release and dispersion stages of a preset's runs,
configuration by configuration: how the particles reach the walls before
the agglomeration stage starts. It is the measure that shows which of
C2's sub-models drives its particles to the walls (README.md, "Which
sub-model drives C2's particles to the walls"; the presets' sub-model
variants C1sgs ... C2oneWay).

    channel.post.dispersion PRESET [--span T] [--reference]
        runs/PRESET/report (results/PRESET with --reference):
        dispersion.json, dispersion.txt

Per configuration (a run alone, or a cloud of a group of one-way
configurations) and per interval between writes at least `span` T*
apart (the first from the release; T* absolute), from the cloud's
stats.dat and profiles.dat
(channel.post.concentration.dispersion_history):
the wall impacts per particle and T* (the counter nWall), the collisions
per T* scaled to the paper's particle number (x s^2; they rebound here,
agglomeration starts later) and the particle volume fraction of the
slabs next to the walls over that of the centre (c_w/c_0)."""

import argparse
import json
import sys

from channel import TUTORIAL
from channel.case import groups, settings
from channel.post import concentration, postprocess

#: The interval of the table when none is given (T*)
SPAN = 10.0


def runs(pname):
    """{configuration: (dispersion folder, its cloud)} of every
    configuration run (or begun) under runs/PRESET."""
    return groups.dispersion_clouds(TUTORIAL / "runs" / pname)


def history(p, pname, span):
    """{configuration: {subModels, folder, cloud, intervals}}."""
    out = {}
    for c, (ddir, cloud) in sorted(runs(pname).items()):
        out[c] = {"subModels": settings.configuration(c)["subModels"],
                  "folder": str(ddir.relative_to(TUTORIAL)),
                  "cloud": cloud,
                  "intervals": concentration.dispersion_history(
                      p, ddir, span, cloud)}
    return out


def text(pname, span, res):
    lines = [
        f"verticalChannel {pname}: release and dispersion, per "
        f"configuration and interval (at least {span:g} T* between "
        "writes; T* absolute)",
        "wall/N/T*: wall impacts per particle and T*; col x s^2/T*: "
        "collisions (rebounds) per T*, scaled to 6e6 particles; c_w/c_0: "
        "near-wall over centre concentration", "",
        f"{'configuration':<16} {'subModels':<46} {'T*':>11} "
        f"{'wall/N/T*':>10} {'col x s^2/T*':>12} {'c_w/c_0':>8}"]
    for c, r in res.items():
        for x in r["intervals"]:
            w = x.get("wallImpacts_per_particle_T")
            f = x.get("fColScaled")
            cw = x["nearWallOverCentre"]
            lines.append(
                f"{c:<16} {r['subModels']:<46} "
                f"{x['T0']:5.0f}-{x['T1']:<5.0f} "
                + (f"{w:10.3g} " if w is not None else f"{'-':>10} ")
                + (f"{f:12.3g} " if f is not None else f"{'-':>12} ")
                + (f"{cw:8.3g}" if cw is not None else f"{'-':>8}"))
    return "\n".join(lines) + "\n"


def post(pname, reference=False, span=SPAN):
    p = settings.preset(pname)
    res = history(p, pname, span)
    if not res:
        print(f"channel.post.dispersion: no release under runs/{pname}: "
              "nothing written")
        return 0
    out = settings.report_dir(pname, reference)
    out.mkdir(parents=True, exist_ok=True)
    (out / "dispersion.json").write_text(
        json.dumps({"span": span, "runs": res}, indent=1) + "\n")
    t = text(pname, span, res)
    (out / "dispersion.txt").write_text(t)
    print(t, end="")
    return 0


def span_value(text):
    """--span: a number of T*, >= 0."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number")
    if not v >= 0:
        raise argparse.ArgumentTypeError(f"{text} must be >= 0")
    return v


def main(argv):
    return postprocess.command(
        argv, "channel.post.dispersion", __doc__,
        lambda a: post(a.preset, a.reference, a.span),
        "the preset whose runs are reported",
        "write into the committed results/PRESET",
        options=lambda ap: ap.add_argument(
            "--span", type=span_value, default=SPAN,
            help=f"least T* between the writes of an interval (default "
                 f"{SPAN:g})"))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
