"""The break-up tests' shared parts (doc/breakup.md): the box cases'
kernel with EAM, the stressThreshold settings of verification case V1,
the spec's hand formulas (packing, size and density, Rumpf's tensile
strength, the critical spin), the state of a written cloud and its
totals (number, mass, momentum, angular momentum), and the laminar shear
of V2."""

import math

import numpy as np

from aggloTools import boxcase
from aggloTools.cloud import cloud_positions, read_cloud
from aggloTools.foamfile import merged

H, DELTA0, RHO_P, DP = 6.3e-20, 2e-10, 2200.0, 12e-6   # boxcase.MATERIAL
GAP = 1e-3                                             # delta_gap/d_p
CSM_F = {2: 0.26683, 3: 0.31574, 4: 0.42099, 9: 0.47106, 10: 0.41216}
F_LARGE = 0.52

#: Verification case V1's stressThreshold coefficients (rotation alone)
BREAKUP_COEFFS = {
    "strength": {"rumpfPrefactor": 1, "coordination": "exactSmallRumpf"},
    "stresses": {"mechanisms": ("rotation",), "rotationFactor": 0.0625},
    "fragmentation": {"mode": "erosion", "direction": "extensional",
                      "gap": GAP, "tries": 6, "spin": "conserveL"},
}


def breakup(stresses=None, fragmentation=None, drag=False, rotation=False,
            **entries):
    """The cloud entries (boxcase.cloud_properties) of stressThreshold
    break-up: BREAKUP_COEFFS with stresses replaced where given,
    fragmentation's entries changed and further coefficients (rate,
    eventLog) added; drag: Schiller-Naumann's; rotation: the fluid's
    torque."""
    coeffs = merged(BREAKUP_COEFFS,
                    {"fragmentation": fragmentation or {}, **entries})
    if stresses is not None:
        coeffs["stresses"] = stresses
    sub = {"breakupModel": "stressThreshold",
           "stressThresholdCoeffs": coeffs}
    if drag:
        sub["particleForces"] = boxcase.DRAG
    if rotation:
        sub["rotationModel"] = "fluidTorque"
    return {"subModels": sub}


BREAKUP = breakup()


def kernel(hamaker=None, structure="CSM"):
    """The box cases' kernel (boxcase.kernel) with EAM, smooth walls and,
    where given, another Hamaker constant or structure model."""
    material = {} if hamaker is None else {"H": hamaker}
    return boxcase.kernel("EAM", structureModel=structure,
                          material=material)


def packing(n):
    return CSM_F.get(n, F_LARGE)


def size_density(n, structure):
    """Effective diameter and density (doc/breakup.md 1)."""
    if n == 1:
        return DP, RHO_P
    if structure == "VSM":
        return DP * n ** (1 / 3), RHO_P
    f = packing(n)
    return DP * (n / f) ** (1 / 3), f * RHO_P


def tensile_strength(n, structure):
    """Rumpf with c_R = 1 and k = pi/eps, the weakest plane for N <= 4
    (doc/breakup.md 2); the bond force of two equal primaries
    A d_p/(24 delta0^2); VSM takes the CSM porosity for the strength."""
    F = H * DP / (24 * DELTA0 ** 2)
    if n <= 4:
        da = size_density(n, structure)[0]
        return (n - 1) * F / (math.pi * da ** 2 / 4)
    eps = 1 - packing(n)
    return (1 - eps) * (math.pi / eps) * F / (math.pi * DP ** 2)


def omega_crit(n, structure):
    """sigma_r = rho_a omega^2 d_a^2/16 = sigma_T (doc/breakup.md 1.4)."""
    da, rho = size_density(n, structure)
    return 4 / da * math.sqrt(tensile_strength(n, structure) / rho)


def state(case, t):
    c = read_cloud(case, t)
    x = cloud_positions(case, t)
    m = c["rho"] * math.pi * c["d"] ** 3 / 6
    return c, x, m


def totals(c, x, m):
    """Primaries, mass, momentum and angular momentum about the origin."""
    L = (0.1 * m * c["d"] ** 2)[:, None] * c["omega"] \
        + m[:, None] * np.cross(x, c["U"])
    return (int(c["nPrimary"].sum()), m.sum(),
            (m[:, None] * c["U"]).sum(0), L.sum(0))


def by_id(c, x):
    """Rows sorted by the global id (origProcId, origId)."""
    order = np.lexsort((c["origId"], c["origProcId"]))
    return {k: v[order] for k, v in c.items()}, x[order]


NU_F, RHO_F = 1.5e-5, 1.2
GAMMA_CRIT = 1e4          # the bonds are weakened to give it
L_C, N_C = (0.01, 0.01, 0.005), (5, 10, 2)
