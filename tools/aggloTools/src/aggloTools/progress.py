"""Progress of a running solver from its log: simulated time, the share of
this invocation done and the estimated time to its end (from the
ExecutionTime of the log), for the tutorials' progress lines."""

import re
from pathlib import Path


def hms(sec):
    """Seconds as 1h02m or 3m07s."""
    sec = int(round(sec))
    return (f"{sec // 3600}h{sec % 3600 // 60:02d}m" if sec >= 3600
            else f"{sec // 60}m{sec % 60:02d}s")


def solver_progress(log, t_end, dt):
    """(t, frac, eta) of the solver writing log: its latest time t, the
    fraction of this invocation done (from its first step, dt before the
    first `Time =` after the last `Starting time loop`, to t_end) and the
    ETA in seconds from the wall-clock time so far (the log's ClockTime:
    on a loaded machine the CPU time of ExecutionTime runs slower than
    the clock; None before the first step reports one); None if no step
    has been logged."""
    log = Path(log)
    if not log.exists():
        return None
    text = log.read_text(errors="replace")
    start = text.rfind("Starting time loop")
    times = re.findall(r"^Time = ([-+0-9.eE]+)", text[max(start, 0):],
                       re.M)
    if not times:
        return None
    t = float(times[-1])
    t0 = float(times[0]) - dt
    clock = re.findall(r"ClockTime = ([0-9.eE+-]+) s", text[start:])
    frac = (t - t0) / max(t_end - t0, 1e-30)
    eta = (float(clock[-1]) * (1 - frac) / frac if clock and frac > 0
           else None)
    return t, min(frac, 1.0), eta


def line(frac, eta):
    """The common ending of a progress line: '(42 % of this run, ETA
    3m07s)'."""
    return (f"({100 * frac:.0f} % of this run"
            + (f", ETA {hms(eta)})" if eta is not None else ")"))
