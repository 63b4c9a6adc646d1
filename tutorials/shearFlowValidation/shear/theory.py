"""shearFlowValidation: the theory of the laminar shear-flow validation
(paper Appendix B; doc/cases.md B.2-B.6): van de Ven & Mason's collision
efficiency, the Saffman-Turner shear kernel and the decay of the number
of particles (B.8)."""

import math

import numpy as np

# Physical data of doc/cases.md B.1 (the case files hold the same values)
H = 2.28e-21        # Hamaker constant of polystyrene [J]
MU = 1.0e-3         # water [Pa s]
RHO_P = 1050.0      # polystyrene [kg/m3]
LAMBDA = 1e-7       # van de Ven & Mason's lambda [m]


def f_vdVM(d):
    """van de Ven & Mason's f: the tabulated 0.95, 0.87, 0.79 at d = 1, 2,
    4 um lie on a line in ln d (doc/cases.md B.2); a quadratic fit is this
    line."""
    return 0.95 - 0.08 * np.log2(np.asarray(d, float) / 1e-6)


def alpha_th(d, gamma=71.0, hamaker=H, mu=MU):
    """Eq. B.5: f(lambda/(pi d)) [8 H/(36 pi mu gamma d^3)]^0.18."""
    d = np.asarray(d, float)
    return f_vdVM(d) * (8 * hamaker / (36 * math.pi * mu * gamma * d**3))**0.18


def kernel_ST(d1, d2=None, gamma=71.0):
    """Eq. B.6: (4/3) gamma (r1 + r2)^3."""
    d2 = d1 if d2 is None else d2
    return 4.0 / 3.0 * gamma * (0.5 * (d1 + d2))**3


def decay_theory(np0, dncol, np_sim, alpha, form="consistent"):
    """The recursion of Eq. B.8 driven by the simulated kernel of Eq. B.7,
    K(t_n) = 2 V dN_col,n/(N_p(t_n)^2 dt):
        N(t_n+1) = N(t_n)/(1 + c alpha K(t_n) dt N(t_n)/V)
                 = N(t_n)/(1 + 2 c alpha dN_col,n N(t_n)/N_p(t_n)^2)
    with c = 1/2 (consistent) or 1 (printed). np_sim[n] is the simulated
    number before step n. Returns N(t_n) for n = 0 .. len(dncol)."""
    c = {"consistent": 0.5, "printed": 1.0}[form]
    out = np.empty(len(dncol) + 1)
    out[0] = np0
    for n, (dn, ns) in enumerate(zip(dncol, np_sim)):
        out[n + 1] = out[n] / (1 + 2 * c * alpha * dn * out[n] / ns**2)
    return out
