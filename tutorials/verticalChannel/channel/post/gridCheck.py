"""verticalChannel: the grid robustness of the paper's comparisons
(README.md, "Regression"). At the preset for comparisons with the paper
(64^3) each ratio of two runs that the report judges (a configuration
over another: C2/C1, C3/C2, C4/C2 of f_col, f_agg and alpha_f; EAM over
MAM in a configuration) is computed at the coarser grid too (48^3,
preset regime48, whose C1 is the regime study's) where both runs exist
there, and the two grids are compared: a direction (the ratio above or
below 1 beyond 3 sigma) found at both grids holds (PASS); one that flips
between the grids is grid-dependent (FAIL: not an agreement); where
either grid leaves it within 3 sigma of 1 it is undecided (n/r). The
note gives both ratios and the z of their difference.

    rows += grid_rows(R, res, load(GRID_CHECK[p["name"]]), "48^3")
"""

import math

from aggloTools import regression as reg
from channel.post.statements import DIRECTION_SIGMAS, quantity_ratio

#: The preset whose comparisons are checked at another grid, and that
#: grid's preset
GRID_CHECK = {"regime64": "regime48"}
CONFIG_RATIOS = (("C2", "C1"), ("C3", "C2"), ("C4", "C2"))
QUANTITIES = ("col", "agg", "alpha")
MODELS = ("EAM", "MAM")


def direction(r, s):
    """+1 or -1 where r - 1 has that sign beyond DIRECTION_SIGMAS sigma,
    0 where it does not, None without events."""
    if r is None:
        return None
    if abs(r - 1) <= DIRECTION_SIGMAS * s:
        return 0
    return 1 if r > 1 else -1


def words(d):
    return {1: "above 1", -1: "below 1", 0: "within 3 sigma of 1",
            None: "no events"}[d]


def verdict(here, there, grids):
    """(status, note) of one ratio at two grids: here and there are
    (ratio, sigma); grids their names."""
    (r1, s1), (r2, s2) = here, there
    d1, d2 = direction(r1, s1), direction(r2, s2)
    seen = (f"{grids[0]} {words(d1)}, {grids[1]} {words(d2)}")
    if r1 is not None and r2 is not None:
        s = math.hypot(s1, s2)
        seen += (f"; {grids[0]} {r1:.3g} +- {s1:.2g}, {grids[1]}"
                 f" {r2:.3g} +- {s2:.2g}"
                 + (f", z {(r1 - r2) / s:+.1f}" if s > 0 else ""))
    if d1 is None or d2 is None:
        return reg.NR, "no events at a grid: " + seen
    if d1 and d2 and d1 != d2:
        return reg.FAIL, "grid-dependent: " + seen
    if d1 and d1 == d2:
        return reg.PASS, "holds at both grids: " + seen
    return reg.NR, "undecided: " + seen


def pairs(res):
    """The ratios of two runs of res the report judges: (name, run a,
    run b, quantity)."""
    out = []
    for a, b in CONFIG_RATIOS:
        for m in MODELS:
            if (a, m) in res and (b, m) in res:
                for q in QUANTITIES:
                    out.append((f"{m} {q} {a}/{b}", (a, m), (b, m), q))
    for c in sorted({c for c, _ in res}):
        if (c, "EAM") in res and (c, "MAM") in res:
            for q in ("col", "agg"):
                out.append((f"{c} {q} EAM/MAM", (c, "EAM"), (c, "MAM"), q))
    return out


def grid_rows(R, res, other, grid="48^3", here="64^3"):
    """The rows comparing each judged ratio of res (this grid's runs)
    with the same ratio of other (the other grid's runs), where both
    grids have both runs; one row saying so where the other grid has no
    runs at all."""
    if not other:
        return [R(f"grid {here} vs {grid}", None, None, None, None,
                  reg.NR, f"no finished runs at {grid}")]
    rows = []
    for name, a, b, q in pairs(res):
        if a not in other or b not in other:
            continue
        r1, s1 = quantity_ratio(res[a], res[b], q)
        r2, s2 = quantity_ratio(other[a], other[b], q)
        status, note = verdict((r1, s1), (r2, s2), (here, grid))
        x = (r1 / r2 if r1 is not None and r2 is not None else None)
        sx = (x * math.hypot(s1 / r1, s2 / r2) if x is not None else None)
        label = name.replace(" alpha ", " alpha_f ").replace(
            " col ", " f_col ").replace(" agg ", " f_agg ")
        rows.append(R(f"grid {label} ({here}/{grid})", x, sx, None, None,
                      status, note))
    return rows
