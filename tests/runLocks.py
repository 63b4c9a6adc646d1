"""The text of a run folder's lock (aggloTools.runlock) held by given
processes of this machine, for the tests of the lock and the drivers."""

import socket

from aggloTools import runlock


def lock_text(*pids, starts=None):
    """The lock of processes pids (their start times: starts, default
    their own) of this machine and boot."""
    head = (f"lock host={socket.gethostname()} boot={runlock._boot()} "
            "since=2026-01-01T00:00:00 what=test_driver\n")
    starts = starts or [runlock._started(p) for p in pids]
    return head + "".join(f"process {p} {s}\n" for p, s in zip(pids, starts))
