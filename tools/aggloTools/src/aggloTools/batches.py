"""A variant against a base over paired batches (the same windows of two
runs from one start): the variant's bias per bin, its standard error from
the batches' differences, the base's own standard error (what a
regression over the window resolves), and whether the bias is both
significant and above that resolution."""

import math

import numpy as np

#: Two-sided 95 % quantiles of Student's t by degrees of freedom
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447,
        7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228, 11: 2.201, 12: 2.179,
        13: 2.160, 14: 2.145, 15: 2.131, 16: 2.120, 17: 2.110, 18: 2.101,
        19: 2.093, 20: 2.086, 25: 2.060, 30: 2.042}


def t975(dof):
    """The quantile at dof, or at the next smaller tabulated dof (larger,
    so conservative against a bias); dof 1-30 and more."""
    if dof < 1:
        raise ValueError(f"{dof} degrees of freedom: at least 1")
    return T975[max(k for k in T975 if k <= dof)]


def paired_bias(qb, qv):
    """qb, qv: (batches, bins) of the base and the variant. At the bin of
    the largest |bias|/sigma_run among the significant bins (|bias| >
    t975 SE), else among all: the bias, SE, sigma_run, their ratio, and
    visible: |bias| > sigma_run and significant. A run that has parted
    from the base differs from it by about sqrt(2) sigma_run by noise
    alone, so the bias must also exceed its own noise. A bin that never
    varies (a wall value) is visible by any bias."""
    qb, qv = np.atleast_2d(qb), np.atleast_2d(qv)
    n = len(qb)
    d = qv - qb
    bias = d.mean(axis=0)
    se = d.std(axis=0, ddof=1) / math.sqrt(n)
    srun = qb.std(axis=0, ddof=1) / math.sqrt(n)
    r = np.divide(np.abs(bias), srun, out=np.where(bias == 0, 0.0, np.inf),
                  where=srun > 0)
    sig = np.abs(bias) > t975(n - 1) * se
    i = int(np.argmax(np.where(sig, r, -1.0) if sig.any() else r))
    return {"bias": float(bias[i]), "biasSE": float(se[i]),
            "sigmaRun": float(srun[i]), "bin": i,
            "biasBySigmaRun": float(r[i]), "significant": bool(sig[i]),
            "mean": float(qb[:, i].mean()),
            "visible": bool(r[i] > 1 and sig[i])}
