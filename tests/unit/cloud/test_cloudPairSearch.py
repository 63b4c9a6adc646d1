"""The particleGrid pair search in the cloud against the O(N^2) search
over all particles and periodic images (pairSearch bruteForce;
pairSearchCheck true compares both candidate sets every step), on random
clouds of cloudBoxCases: a fast gas, a gas with fast particles, a
stream, a cloud packed at a wall, diameters of 12-60 um, serially and on
2 ranks."""

import re

import numpy as np
import pytest

from aggloTools.boxcase import box_case, kernel, run_case
from aggloTools.runner import foam_bin, run
from aggloTools.stats import stats_rows as stats
from cloudBoxCases import (D, add_hard_sphere_entries, cloud_state,
                           gas_kernel, gas_particles)


def oracle_cloud(case_dir, kind, decompose=(1, 1, 1)):
    """Random clouds for the search oracle: 'gas' (periodic in x, y, z,
    fast: about one cell per step), 'fast' (the gas with one particle in
    ten ten times faster: its box spans many bins of the others' size),
    'stream' (four gases side by side in a box 4 x 1 x 1, streaming at
    +3 m/s along x for 20 steps, one particle in ten at +2 m/s: per step
    they move more than a quarter of the short y and z periods, which
    only the per-axis reach check admits), 'wall' (periodic in x and z, packed
    against the lower wall, EAM),
    'poly' (diameters 12-60 um, agglomerates of up to 125 primaries,
    periodic in x and z, EAM)."""
    rng = np.random.default_rng(
        {"gas": 21, "fast": 25, "wall": 22, "poly": 23, "stream": 26}[kind])
    Lb = 2e-4
    if kind == "stream":
        parts = []
        for m in range(4):
            gas, d, U = gas_particles(400, Lb, 0.02, 0.05, seed=30 + m)
            for p in gas:
                x, u = p["x"], p["U"]
                p["x"] = (x[0] + m * Lb, x[1], x[2])
                p["id"] = len(parts)
                p["U"] = (u[0] + (2 if p["id"] % 10 == 0 else 3),
                          u[1], u[2])
                parts.append(p)
        box_case(case_dir, L=(4 * Lb, Lb, Lb), n=(20, 5, 5),
                 kinds=("cyclic",) * 3, particles=parts, dt=2e-5,
                 end_time=4e-4, write_interval=1,
                 hard_sphere=gas_kernel(0.9), decompose=decompose)
        return
    if kind in ("gas", "fast"):
        parts, d, U = gas_particles(400, Lb, 0.02, 0.05, seed=24)
        if kind == "fast":
            for p in parts[::10]:
                p["U"] = tuple(10 * u for u in p["U"])
        box_case(case_dir, L=(Lb,) * 3, n=(5, 5, 5), kinds=("cyclic",) * 3,
                 particles=parts, dt=2e-4 if kind == "gas" else 2e-5,
                 end_time=6e-3 if kind == "gas" else 2.4e-3, write_interval=1,
                 hard_sphere=gas_kernel(0.9), decompose=decompose)
        return
    xs, ds = [], []
    while len(xs) < 250:
        d = D if kind == "wall" else D * rng.integers(1, 6)
        lo = (0.6 * d, 0.6 * d, 0.6 * d)
        hi = (Lb - 0.6 * d, (0.25 if kind == "wall" else 1) * Lb - 0.6 * d,
              Lb - 0.6 * d)
        x = rng.uniform(lo, hi)
        if all(np.linalg.norm(x - y) > 0.55 * (d + e) * 1.02
               for y, e in zip(xs, ds)):
            xs.append(x)
            ds.append(d)
    U = rng.normal(0, 1.5e-3, (len(xs), 3))
    parts = [dict(x=tuple(x), U=tuple(u), d=d, id=i,
                  nPrimary=round((d / D) ** 3))
             for i, (x, u, d) in enumerate(zip(xs, U, ds))]
    box_case(case_dir, L=(Lb,) * 3, n=(6, 6, 6),
             kinds=("cyclic", "wall", "cyclic"), particles=parts, dt=1e-4,
             end_time=4e-3, write_interval=1, hard_sphere=kernel("EAM"),
             decompose=decompose)


def search_checks(case_dir):
    """The candidate counts of the pairSearchCheck lines of a run's log."""
    text = (case_dir / "log.aggloPimpleFoam").read_text()
    return [int(m) for m in re.findall(
        r"pairSearchCheck: (\d+) candidate pairs, identical", text)]


# The fast and stream boxes, the slowest of the suite (the O(N^2) search
# over 1,600 particles and 27 images is most of a stream step): 2-4.5
# minutes each beside three long runs, -m slow. The stream runs 20 steps
# (1,395 collisions, 64,350 candidate pairs checked serially): 60 steps
# checked no more of the per-axis reach, which every step exercises,
# for three times the CPU time (about 10 minutes of CI)
SLOW = pytest.mark.slow


@pytest.mark.parametrize("kind,ranks", [
    ("gas", 0), pytest.param("fast", 0, marks=SLOW), ("wall", 0),
    ("poly", 0), pytest.param("stream", 0, marks=SLOW), ("gas", 2),
    pytest.param("fast", 2, marks=SLOW), ("wall", 2),
    pytest.param("stream", 2, marks=SLOW)])
def test_pair_search_matches_brute_force(case_dir, foam_env, kind, ranks):
    """The particleGrid pair search finds exactly the candidate pairs of
    the O(N^2) search over all particles and all periodic images (the
    same swept-box predicate): pairSearchCheck compares the two sets,
    pair by pair with the partner's image position, every step on every
    rank and stops the run if they differ. Then the runs with either
    search give identical counters every step (any missed or extra
    candidate changes the events) and the same particles after the first
    step with a collision, serially and on 2 ranks; and so does the
    InteractionLists search (serial gas and wall, 2-rank wall), the
    baseline of bench/. The particle states agree to round-off only (a
    referred partner's end position is the barycentric position of a
    transformed copy in InteractionLists), and round-off grows
    chaotically with every later collision."""
    searches = ["particleGrid", "bruteForce"]
    if (kind, ranks) in (("gas", 0), ("wall", 0), ("wall", 2)):
        searches.append("interactionLists")
    out = {}
    for search in searches:
        c = case_dir / search
        oracle_cloud(c, kind, decompose=(2, 1, 1))
        add_hard_sphere_entries(c, f"pairSearch {search};"
                   + (" pairSearchCheck true;"
                      if search == "particleGrid" else ""))
        run_case(c, parallel=ranks)
        if ranks:
            run([foam_bin("reconstructPar")], c, "log.reconstructPar.all")
        rows = stats(c)
        # the first step with a collision
        first = next(r["Time"] for r in rows if r["nCol"] > 0)
        t = min((p.name for p in c.iterdir()
                 if re.fullmatch(r"[0-9.e-]+", p.name)),
                key=lambda name: abs(float(name) - first))
        out[search] = (rows, cloud_state(c, t))
    checks = search_checks(case_dir / "particleGrid")
    # one check per step, and candidates to check
    assert len(checks) == len(out["particleGrid"][0])
    assert sum(checks) >= 100
    rows, state = out["bruteForce"]
    assert rows[-1]["nCol"] >= 20
    if kind not in ("gas", "fast", "stream"):
        assert rows[-1]["nAgg"] > 0 and rows[-1]["nWall"] > 0
    for search in searches[:1] + searches[2:]:
        assert out[search][0] == rows, search
        other = out[search][1]
        assert other.keys() == state.keys()
        for name in ("nPrimary", "origId", "origProcId", "lastPartnerId"):
            assert np.array_equal(other[name], state[name]), (search, name)
        for name in ("U", "omega", "d", "rho", "lastContactTime"):
            np.testing.assert_allclose(other[name], state[name], rtol=1e-9,
                                       atol=1e-9, err_msg=(search, name))
