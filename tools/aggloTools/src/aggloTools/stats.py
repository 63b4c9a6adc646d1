"""The outputs of the hardSphereStatistics cloud function object:
stats.dat (joined over restarts), profiles.dat and agglomerateSizes.dat."""

from pathlib import Path

import numpy as np


def name_precision(name):
    """Half the last digit of a time folder's name (0.1767760468:
    5e-11): the times that the name stands for, rounded, lie within it
    (and within 1e-12 of it, relative, whatever the name)."""
    mantissa = name.lower().split("e")[0]
    exponent = int(name.lower().split("e")[1]) if "e" in name.lower() else 0
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return max(0.5 * 10.0 ** (exponent - decimals),
               1e-12 * max(1.0, abs(float(name))))


def read_stats(case, cloud="kinematicCloud"):
    """The rows of postProcessing/<cloud>HardSphere/<t>/stats.dat as a dict
    of numpy arrays. Restarted runs write a new start-time folder; the rows
    are joined in time order (later folders win after the restart's time:
    the row at it, written by the earlier run, is kept)."""
    base = Path(case) / "postProcessing" / f"{cloud}HardSphere"
    cols, rows = None, []
    files = [sub / "stats.dat" for sub in sorted(
        base.iterdir(), key=lambda p: float(p.name))
        if (sub / "stats.dat").exists()]
    for k, f in enumerate(files):
        new = []
        lines = f.read_text().splitlines()
        for n, line in enumerate(lines):
            if line.startswith("# Time"):
                cols = line[2:].split()
            elif line and not line.startswith("#"):
                if cols is None:
                    raise ValueError(f"{f}, line {n + 1}: a row before the"
                                     " '# Time ...' header")
                try:
                    row = [float(c) for c in line.split()]
                except ValueError:
                    row = []
                if len(row) != len(cols):
                    # a row cut off by a kill: harmless only where a
                    # restart's file follows (its rows replace it)
                    if n == len(lines) - 1 and k < len(files) - 1:
                        continue
                    raise ValueError(
                        f"{f}, line {n + 1}: {len(row) or 'unreadable'} "
                        f"values for {len(cols)} columns (a write cut "
                        "off? restart the run from its last written time)")
                new.append(row)
        # the earlier rows up to the restart's time and before its first
        # row: the folder's name is that time rounded to the case's
        # timePrecision where the rows hold 17 digits, so the row at the
        # restart time (the earlier run's) is kept, however it rounds
        cut = float(f.parent.name) + name_precision(f.parent.name)
        rows = [r for r in rows
                if r[0] <= cut and (not new or r[0] < new[0][0])] + new
    if cols is None:
        raise FileNotFoundError(f"no stats.dat under {base}")
    arr = np.array(rows).reshape(-1, len(cols))
    return {c: arr[:, i] for i, c in enumerate(cols)}




def stats_rows(case, cloud="kinematicCloud"):
    """read_stats as a list of rows, each a dict column -> value."""
    st = read_stats(case, cloud)
    cols = list(st)
    return [dict(zip(cols, map(float, r)))
            for r in zip(*(st[c] for c in cols))]


def last_output(case, cloud, name):
    """The file `name` (profiles.dat, agglomerateSizes.dat) of the latest
    start-time folder of postProcessing/<cloud>HardSphere, or None."""
    base = Path(case) / "postProcessing" / f"{cloud}HardSphere"
    files = sorted(base.glob(f"*/{name}"), key=lambda f: float(f.parent.name))
    return files[-1] if files else None


def read_table(path):
    """The columns of agglomerateSizes.dat or profiles.dat (header line
    '# k ...' or '# x ...') as a dict of numpy arrays; a file without
    its header or with a row cut off (a kill during the write) is a
    ValueError naming the file and the line."""
    cols, rows = None, []
    for n, line in enumerate(Path(path).read_text().splitlines(), 1):
        if line.startswith(("# x ", "# k ")):
            cols = line[2:].split()
        elif line and not line.startswith("#"):
            if cols is None:
                raise ValueError(f"{path}, line {n}: a row before the "
                                 "header ('# k ...' or '# x ...')")
            try:
                row = [float(c) for c in line.split()]
            except ValueError:
                row = []
            if len(row) != len(cols):
                raise ValueError(f"{path}, line {n}: {len(line.split())} "
                                 f"values for {len(cols)} columns (a row "
                                 "cut off?)")
            rows.append(row)
    if cols is None:
        raise ValueError(f"{path}: no header ('# k ...' or '# x ...')")
    a = np.array(rows) if rows else np.zeros((0, len(cols)))
    return {c: a[:, i] for i, c in enumerate(cols)}
