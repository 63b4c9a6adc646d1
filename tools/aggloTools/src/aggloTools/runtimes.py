"""The project's run times, stated once: the table of README.md, 'Run
times' (measured on the idle 2-core development machine). The drivers
print their own wall time beside the stated one, so that a figure that no
longer holds shows at the end of every run instead of drifting silently.

    >>> stated("verticalChannel small C1")      # minutes, or None
    12.0
    >>> verdict(30.0, 12.0)
    'within the factor 3 a busy machine adds'
"""
import re

from aggloTools import runner

#: A busy machine (other runs, the test suite) takes up to this factor
#: longer; outside [1/FACTOR, FACTOR] the stated figure is out of date.
FACTOR = 3.0

_UNITS = {"s": 1.0 / 60.0, "min": 1.0, "h": 60.0}
_ROW = re.compile(r"^\|\s*`([^`]+)`\s*\|(.*)\|\s*$")
_TIME = re.compile(r"^\s*(?:about\s+)?([0-9]+(?:\.[0-9]+)?)\s*(s|min|h)\b")
_HEADING = "## Run times"


def table(readme=None):
    """{job id: minutes} from README.md's 'Run times' table: the rows whose
    first cell is a job id in backticks and whose last cell starts with
    a time ('12 min', 'about 14 h', '25 s'). A malformed time is an
    error naming the row, never a silent omission."""
    path = readme or runner.project_dir() / "README.md"
    text = path.read_text().split("\n")
    try:
        start = text.index(_HEADING)
    except ValueError:
        raise ValueError(f"{path}: no '{_HEADING}' section") from None
    jobs = {}
    for line in text[start + 1:]:
        if line.startswith("## "):
            break
        m = _ROW.match(line)
        if not m:
            continue
        job, rest = m.group(1), m.group(2).split("|")[-1]
        t = _TIME.match(rest)
        if not t:
            raise ValueError(f"{path}, 'Run times': the row of {job!r}"
                             f" has no time ('12 min', '14 h') in its last"
                             f" column: {rest.strip()!r}")
        if job in jobs:
            raise ValueError(f"{path}, 'Run times': {job!r} twice")
        jobs[job] = float(t.group(1)) * _UNITS[t.group(2)]
    if not jobs:
        raise ValueError(f"{path}, 'Run times': no rows")
    return jobs


def stated(job, readme=None):
    """The minutes README.md states for `job`, or None if it states none."""
    return table(readme).get(job)


def verdict(measured, expected):
    """How a measured wall time (min) stands to the stated one (min)."""
    if measured <= 0 or expected <= 0:
        raise ValueError("run times must be positive")
    r = measured / expected
    if r > FACTOR:
        return (f"{r:.1f} times the stated time: a very busy machine, or"
                " the README's figure is out of date")
    if r < 1.0 / FACTOR:
        return (f"{1 / r:.1f} times faster than stated: the README's"
                " figure is out of date")
    return f"within the factor {FACTOR:g} a busy machine adds"


def _fmt(minutes):
    if minutes >= 120:
        return f"{minutes / 60:.1f} h"
    if minutes >= 2:
        return f"{minutes:.1f} min"
    return f"{minutes * 60:.0f} s"


def line(job, seconds, whole=True, readme=None):
    """The driver's closing line: its wall time beside README.md's for
    `job` (or that README.md states none for it). A call that kept or
    continued earlier runs (`whole` false) is not the job: its time is
    printed without the comparison."""
    m = seconds / 60.0
    if not whole:
        return (f"Run time {_fmt(m)} (earlier runs kept or continued, or"
                f" the post-processing only: not compared with README.md's"
                f" figure for {job}).")
    e = stated(job, readme)
    if e is None:
        return (f"Run time {_fmt(m)} ({job}: README.md, 'Run times',"
                " states no figure for this job).")
    return (f"Run time {_fmt(m)}; README.md, 'Run times', states"
            f" {_fmt(e)} for {job} on the idle 2-core development"
            f" machine: {verdict(m, e)}.")
