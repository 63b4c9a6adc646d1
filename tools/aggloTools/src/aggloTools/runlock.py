"""One run at a time per run folder. A driver that runs cases takes the
folder's lock (`<folder>/.aggloRun.lock`) before it touches anything and
gives it back when it ends; a second driver on the same folder is
refused with a message that names the holder. The lock lists the
driver's process and every process it starts (stages adds them), each
with its start time, so that

* a lock whose processes have all gone (a driver killed with kill -9,
  a machine that restarted) is stale: it is taken over, and said so;
* a lock whose driver was killed while its solver still runs is not:
  the solver would go on writing into the folder;
* a process number used again by another process is not taken for the
  holder (its start time differs).

    with runlock.held(Path("runs") / preset, "verticalChannel Allrun"):
        ...
"""

import contextlib
import os
import socket
import time
from pathlib import Path

NAME = ".aggloRun.lock"

#: The locks this process holds (stages.register adds its children)
_held = []


class Busy(Exception):
    """The folder is in use by a live run."""


def _boot():
    try:
        return Path("/proc/sys/kernel/random/boot_id").read_text().strip()
    except OSError:
        return "-"


def _started(pid):
    """The start time of a process (clock ticks since boot), None if it
    is not running."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    # the command name (field 2) may hold spaces: count after its ')'
    return stat.rsplit(")", 1)[1].split()[19]


def _line(pid):
    return f"process {pid} {_started(pid)}\n"


def _holder(lock):
    """(alive, description) of the run that holds a lock file."""
    try:
        lines = lock.read_text().splitlines()
    except OSError:
        return False, "-"
    head = dict(w.split("=", 1) for w in lines[0].split()[1:]
                if "=" in w) if lines and lines[0].startswith("lock") else {}
    what = head.get("what", "?").replace("_", " ")
    since = head.get("since", "?")
    desc = f"{what} since {since}"
    if head.get("host") != socket.gethostname():
        return True, desc + f" on {head.get('host', '?')}"
    if head.get("boot") != _boot():
        return False, desc
    for ln in lines[1:]:
        words = ln.split()
        if len(words) == 3 and words[0] == "process" \
                and words[2] != "None" and _started(words[1]) == words[2]:
            return True, desc + f" (process {words[1]} runs)"
    return False, desc


@contextlib.contextmanager
def held(folder, what):
    """Hold the lock of folder (made if missing) while the block runs;
    Busy if a live run holds it; a stale lock is taken over (said on
    standard output)."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    lock = folder / NAME
    head = (f"lock host={socket.gethostname()} boot={_boot()} "
            f"since={time.strftime('%Y-%m-%dT%H:%M:%S')} "
            f"what={what.replace(' ', '_')}\n")
    for _ in range(3):
        try:
            fd = os.open(lock, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
        except FileExistsError:
            alive, desc = _holder(lock)
            if alive:
                raise Busy(f"{folder} is in use by another run ({desc}); "
                           f"wait for it or stop it (if it is gone, remove "
                           f"{lock})") from None
            print(f"{folder}: a stale lock of a run that has ended "
                  f"({desc}) taken over", flush=True)
            lock.unlink(missing_ok=True)
            continue
        with os.fdopen(fd, "w") as f:
            f.write(head + _line(os.getpid()))
        break
    else:
        raise Busy(f"{folder}: could not take the lock {lock}")
    _held.append(lock)
    try:
        yield lock
    finally:
        _held.remove(lock)
        lock.unlink(missing_ok=True)


def release_all():
    """Give back every lock this process holds, for a driver that ends
    without leaving its `with held(...)` blocks (os._exit after an
    interrupt, once every process it started has ended): the next call
    finds the folder free instead of a stale lock to take over."""
    while _held:
        _held.pop().unlink(missing_ok=True)


def register(pid):
    """Add a process this one started to every lock it holds, so that
    the lock stays live while that process runs."""
    for lock in _held:
        with open(lock, "a") as f:
            f.write(_line(pid))
