"""The project's estimators and their standard errors, in one place: the
rate of a cumulative count over a window (Eq. 87) with its batch-means
and Poisson errors, binomial fractions (standard error, Wilson interval),
ratios and their propagated errors, and the weighted power-law fit of the
regime study with its chi-square probability (scipy's distribution).

    >>> ratio(6.0, 0.3, 3.0, 0.3)       # (r, sigma_r)
    (2.0, 0.2236...)
    >>> wilson(0, 10)                   # 95 % interval of 0/10
    (0.0, 0.2775...)
"""
import math

import numpy as np
from scipy import stats

#: Sub-windows whose rates give a windowed rate's batch-means sigma
N_BATCH = 10
#: The normal quantile of the 95 % intervals (the replays' C++ uses the
#: same rounded value, so both print the same interval)
Z95 = 1.96


# ----------------------------------------------------------- counts, rates

def window_rate(t, n, w0, w1, nbatch=N_BATCH):
    """The rate of a cumulative count n(t) over [w0, w1] (Eq. 87: the
    events of the window over its length), with its batch-means standard
    error (the rates of nbatch equal sub-windows) and its Poisson one:
    (f, sigma_batch, sigma_poisson, events)."""
    def at(x):
        return float(np.interp(x, t, n))
    dn = at(w1) - at(w0)
    f = dn / (w1 - w0)
    edges = np.linspace(w0, w1, nbatch + 1)
    slopes = np.diff([at(e) for e in edges]) / np.diff(edges)
    sb = float(np.std(slopes, ddof=1) / math.sqrt(nbatch))
    return f, sb, poisson_rate_sigma(dn, w1 - w0), dn


def poisson_rate_sigma(events, length):
    """The Poisson standard error of a rate of `events` over `length`,
    at least that of one event (a window without events is not exact)."""
    return math.sqrt(max(events, 1.0)) / length


def binomial_sigma(k, n):
    """The standard error of a fraction k/n, at least that of one event
    in n (a fraction of 0 or 1 is not exact)."""
    p = k / n
    return math.sqrt(max(p * (1 - p), 1.0 / n) / n)


def wilson(k, n, z=Z95):
    """The Wilson interval of a binomial fraction k/n (95 % at z = 1.96);
    (None, None) without trials."""
    if n == 0:
        return (None, None)
    p = k / n
    c = (p + z * z / (2 * n)) / (1 + z * z / n)
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return (c - h, c + h)


# ------------------------------------------------------------------ ratios

def relative_error(*pairs):
    """The relative standard error of a product or ratio of independent
    values, from (value, sigma) pairs: their relative errors in
    quadrature."""
    return math.hypot(*(s / v for v, s in pairs))


def ratio(a, sa, b, sb):
    """a/b with its propagated standard error; (None, None) where either
    value is not positive."""
    if a <= 0 or b <= 0:
        return None, None
    r = a / b
    return r, r * relative_error((a, sa), (b, sb))


# --------------------------------------------------------------- power law

def chi2_sf(x, dof):
    """P(chi^2_dof >= x): the probability of a chi-square at least as
    large on dof degrees of freedom (scipy)."""
    if dof < 1 or int(dof) != dof:
        raise ValueError(f"{dof} degrees of freedom: a positive integer")
    return float(stats.chi2.sf(x, dof))


def power_law(n, v, sigma, at):
    """Weighted fit of ln v = a + b ln n (the weight of a point 1 /
    (sigma/v)^2, its relative error), the covariance scaled by chi^2/dof
    where the points scatter more than their sigmas, and the value at n =
    at with its 68 % band: {"a", "b", "cov", "sigmaB", "at", "value",
    "low", "high", "chi2", "dof", "p" (chi2_sf, None without dof)}, or
    None with fewer than two usable points (v > 0, sigma > 0)."""
    n, v, s = (np.asarray(x, float) for x in (n, v, sigma))
    ok = (v > 0) & (s > 0)
    if ok.sum() < 2:
        return None
    x, y, w = np.log(n[ok]), np.log(v[ok]), (v[ok] / s[ok])**2
    A = np.column_stack([np.ones_like(x), x])
    cov = np.linalg.inv(A.T @ (w[:, None] * A))
    a, b = cov @ (A.T @ (w * y))
    dof = len(x) - 2
    chi2 = float(np.sum(w * (y - a - b * x)**2))
    if dof > 0:
        cov = cov * max(1.0, chi2 / dof)
    g = np.array([1.0, math.log(at)])
    ln_v, se = a + b * g[1], math.sqrt(float(g @ cov @ g))
    return {"a": float(a), "b": float(b), "cov": cov.tolist(),
            "sigmaB": math.sqrt(float(cov[1, 1])),
            "at": at, "value": math.exp(ln_v),
            "low": math.exp(ln_v - se), "high": math.exp(ln_v + se),
            "chi2": chi2, "dof": dof,
            "p": chi2_sf(chi2, dof) if dof > 0 else None}
