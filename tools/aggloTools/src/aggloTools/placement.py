"""Random non-overlapping particle placement in a box, periodic along
some axes (minimum image) and bounded along the others (a clearance from
the walls is part of the bounds), and the overlap search behind it: a
vectorised grid search.

    rng = np.random.default_rng(seed)
    x = place(N, 1.001 * d, lo=(0, 0.5 * d, 0), hi=(Lx, Ly - 0.5 * d, Lz),
              periods=(Lx, None, Lz), rng=rng)
"""

import numpy as np


def overlaps(x, dmin, periods, query=None):
    """Sorted indices max(i, j) of the pairs closer than dmin (centre
    distance), among the pairs with i in query (default: all particles).
    periods: per axis the period (minimum image; positions in [0, L)) or
    None (bounded axis). Cells of at least dmin (about one particle per
    cell) tile the periods; the particles are counting-sorted by cell and
    the 27 neighbour cells of every queried particle are looked up
    directly."""
    x = np.asarray(x, float)
    n = len(x)
    q = np.arange(n) if query is None else np.asarray(query, np.int64)
    if n == 0 or len(q) == 0:
        return np.zeros(0, int)
    span = [L if L else np.ptp(x[:, a]) for a, L in enumerate(periods)]
    h = max(dmin, (span[0] * span[1] * span[2] / max(n, 1))**(1 / 3))
    nc, idx = [], []
    for a, L in enumerate(periods):
        if L:
            m = max(1, int(L // h))
            idx.append(np.floor(x[:, a] / (L / m)).astype(np.int64) % m)
        else:
            lo = x[:, a].min()
            m = int((x[:, a].max() - lo) // h) + 1
            idx.append(np.minimum(np.floor((x[:, a] - lo) / h)
                                  .astype(np.int64), m - 1))
        nc.append(m)
    i, j, k = idx
    nx, ny, nz = nc
    key = i + nx * (j + ny * k)
    order = np.argsort(key, kind="stable")
    count = np.bincount(key, minlength=nx * ny * nz)
    start = np.concatenate(([0], np.cumsum(count)[:-1]))
    per = np.array([L or 0.0 for L in periods])
    wrap = per > 0
    bad = []
    for a in (-1, 0, 1):
        ia = i[q] + a
        okA = np.ones(len(q), bool) if periods[0] else (ia >= 0) & (ia < nx)
        for b in (-1, 0, 1):
            jb = j[q] + b
            okB = okA & (np.ones(len(q), bool) if periods[1]
                         else (jb >= 0) & (jb < ny))
            for c in (-1, 0, 1):
                kc = k[q] + c
                inside = okB & (np.ones(len(q), bool) if periods[2]
                                else (kc >= 0) & (kc < nz))
                sel = q[inside]
                nk = (ia[inside] % nx
                      + nx * (jb[inside] % ny + ny * (kc[inside] % nz)))
                cnt, st = count[nk], start[nk]
                for m in range(int(cnt.max(initial=0))):
                    has = cnt > m
                    sel, cnt, st = sel[has], cnt[has], st[has]
                    other = order[st + m]
                    ok = other != sel
                    s1, o1 = sel[ok], other[ok]
                    r = x[s1] - x[o1]
                    r[:, wrap] -= per[wrap] * np.round(r[:, wrap]
                                                       / per[wrap])
                    close = np.einsum("ij,ij->i", r, r) < dmin**2
                    bad.append(np.maximum(s1[close], o1[close]))
    return np.unique(np.concatenate(bad)) if bad else np.zeros(0, int)


def place(N, dmin, lo, hi, periods, rng, rounds=100):
    """N positions uniform in [lo, hi) with centre distances of at least
    dmin (periodic axes by minimum image): uniform random draws; of every
    overlapping pair the particle of the higher index is drawn again, and
    only the redrawn particles are checked again (the others do not
    overlap each other). Raises RuntimeError if overlaps remain after
    `rounds` redraws (the box is too full)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    x = rng.uniform(lo, hi, (N, 3))
    query = None
    for _ in range(rounds):
        bad = overlaps(x, dmin, periods, query)
        if not len(bad):
            return x
        x[bad] = rng.uniform(lo, hi, (len(bad), 3))
        query = bad
    raise RuntimeError(f"could not place {N} particles of spacing {dmin:g}"
                       f" in the box {lo.tolist()}-{hi.tolist()} in {rounds}"
                       " rounds: the box is too full")
