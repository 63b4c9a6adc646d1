"""verticalChannel regime study: its variants, in order (a preset each),
with what each changes from `small`, the entries in which two of them
differ (shortcut) and which is another at a larger step (larger_step);
channelRegime runs and posts them, channelRegimePairs and
channelRegimeTrend derive from their presets which pairs are one
shortcut apart and which variants refine the grid alone."""

from channel.case import settings


#: The variants, in order: name (= preset), what it changes from `small`
VARIANTS = (
    ("small", "the main job's preset: 32^3, 1e5, phases 60/10/30/60 T*"),
    ("regime32", "phases: the paper's 240/100/520/200 T* (window 100-200)"),
    ("regime48", "grid 48^3 at the paper's phases"),
    ("regime64short", "grid 64^3 at small's phases"),
    ("regime64", "grid 64^3 at the paper's phases"),
    ("regime32n3", "3e5 particles at 32^3 and the paper's phases"),
    ("regime48n3", "3e5 particles at 48^3 and the paper's phases"),
    ("printed", "regime64 at the wall-normal grid the paper prints "
                "(64 x 128 x 64, y+ 0.63, dt* 0.005)"),
    ("regime64dt2", "regime64 at twice its step (dt* 0.02): the cheaper "
                    "matrix if C1 is the same"),
)

#: Variants the study no longer runs, and why: `channel.regime run`
#: without names leaves them out (by name they still run) and the report
#: says so where they have no result
DROPPED = {
    "regime48n3": "paused for regime64short in an earlier clone (gone):"
                  " the s^2 scaling it would check at 48^3 holds at 32^3"
                  " (regime32n3: every quantity within 0.5 sigma of 1);"
                  " its 10-11 CPU hours went to the Table D.6 matrix and"
                  " the printed resolution, which keep the two cores"
                  " busy for weeks",
}


#: Entries in which two presets may differ without being another
#: shortcut: the step in seconds (dtStar's), the write interval, and the
#: velocity solver's tolerance (1e-6 or 1e-8 give the same flow within
#: what a regression over 100 T* resolves: bench/channelSolverSettings.py,
#: README)
NOT_A_SHORTCUT = {"deltaT", "writeStar", "UTolerance"}


def shortcut(a, b):
    """The entries in which presets a and b differ (settings dicts of
    settings.preset), but NOT_A_SHORTCUT."""
    keys = (set(a) | set(b)) - NOT_A_SHORTCUT - {"name"}
    return {k for k in keys if a.get(k) != b.get(k)}


def presets(names=None):
    """The settings of the presets names (default: every variant's)."""
    return {n: settings.preset(n, "C1")
            for n in names or [n for n, _ in VARIANTS]}


def larger_step(name, p):
    """True if the preset name (settings p: name -> settings) is another
    of them at a larger step and nothing else changed: the time-step
    check's variant, which neither refines the grid (the grid trend) nor
    is a base of the wall-normal check."""
    return any(shortcut(p[name], q) == {"dtStar"}
               and p[name]["dtStar"] > q["dtStar"]
               for other, q in p.items() if other != name)
