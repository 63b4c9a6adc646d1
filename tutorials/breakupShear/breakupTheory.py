"""breakupShear: what the stress-threshold criterion predicts for
agglomerates spinning with a laminar simple shear (doc/breakup.md 1, 2),
written here from the formulas of the document, independently of the C++
kernels: the effective size and density of the CSM structure, the Rumpf
strength (the weakest plane for N <= 4), the three stresses and the size
at which erosion stops."""

import math

# CSM packing fractions f(N), N = 0..30 (doc/models.md 4.3), f = 0.52 above
CSM_TABLE = (
    1, 1, 0.26683, 0.31574, 0.42099, 0.38507, 0.42841, 0.45890, 0.52360,
    0.47106, 0.41216, 0.41239, 0.44653, 0.48374, 0.52095, 0.44686,
    0.45022, 0.47836, 0.49845, 0.48923, 0.47572, 0.47319, 0.47831,
    0.48356, 0.49221, 0.49445, 0.50459, 0.52360, 0.48210, 0.49932,
    0.51654)
F_LARGE = 0.52


class Criterion:
    """The criterion for primaries of diameter dp [m], density rho_p,
    Hamaker constant H [J] and contact distance delta0 [m] in a fluid of
    kinematic viscosity nu and density rho_f; coefficients as in the
    stresses dictionary (dissipation, Cv, Ci, rotationFactor) and the
    Rumpf prefactor c_R (coordination exactSmallRumpf). The reading of
    the dissipation rate (doc/breakup.md 1.1) in laminar shear, where
    all of it is resolved (eps_res = nu gamma^2, eps_sgs = 0): total
    puts eps_res into the subrange forms, subgrid has no turbulent
    stress, resolvedShear the viscous C_v mu gamma at any size."""

    READINGS = ("total", "subgrid", "resolvedShear")

    def __init__(self, dp, rho_p, H, delta0, nu, rho_f, c_r=1.125,
                 Cv=1.0, Ci=1.0, rotation_factor=1 / 16,
                 reading="total"):
        if reading not in self.READINGS:
            raise ValueError(f"reading {reading!r}: one of "
                             f"{', '.join(self.READINGS)}")
        self.dp, self.rho_p, self.H, self.delta0 = dp, rho_p, H, delta0
        self.nu, self.rho_f = nu, rho_f
        self.c_r, self.Cv, self.Ci = c_r, Cv, Ci
        self.rot = rotation_factor
        self.reading = reading

    @staticmethod
    def packing(n):
        return CSM_TABLE[n] if n < len(CSM_TABLE) else F_LARGE

    def diameter(self, n):
        """CSM: d_a = d_p (N/f(N))^(1/3)."""
        return self.dp * (n / self.packing(n)) ** (1 / 3)

    def density(self, n):
        """CSM: rho_a = f(N) rho_p."""
        return self.packing(n) * self.rho_p

    def bond_force(self):
        """Two equal primaries at the contact distance: A d_p/(24
        delta0^2) (the agglomeration model's vdW force)."""
        return self.H * self.dp / (24 * self.delta0 ** 2)

    def strength(self, n):
        """Rumpf c_R (1 - eps) k F/(pi d_p^2), k = pi/eps, eps = 1 - f;
        for N <= 4 the weakest plane (N - 1) F/(pi d_a^2/4)."""
        F = self.bond_force()
        if n <= 4:
            return (n - 1) * F / (math.pi * self.diameter(n) ** 2 / 4)
        eps = 1 - self.packing(n)
        return self.c_r * (1 - eps) * (math.pi / eps) * F / (
            math.pi * self.dp ** 2)

    def stresses(self, n, gamma):
        """(turbulent, rotational) stress of an agglomerate at rest in
        the simple shear gamma [1/s], spinning at gamma/2: eps = nu
        gamma^2, by the reading; viscous C_v mu (eps/nu)^(1/2) for d_a <=
        eta, inertial C_i rho_f (eps d_a)^(2/3) above; rotation c_r rho_a
        omega^2 d_a^2. No slip: no drag stress."""
        eps = self.nu * gamma ** 2
        eta = (self.nu ** 3 / eps) ** 0.25
        da = self.diameter(n)
        viscous = self.Cv * self.nu * self.rho_f * math.sqrt(eps / self.nu)
        if self.reading == "subgrid":
            turb = 0.0
        elif self.reading == "resolvedShear" or da <= eta:
            turb = viscous
        else:
            turb = self.Ci * self.rho_f * (eps * da) ** (2 / 3)
        rot = self.rot * self.density(n) * (gamma / 2) ** 2 * da ** 2
        return turb, rot

    def stable(self, n, gamma):
        return n < 2 or max(self.stresses(n, gamma)) <= self.strength(n)

    def final_size(self, n0, gamma):
        """Erosion takes one primary at a time while the agglomerate is
        unstable: it stops at the largest stable N <= n0 (1: it dissolves
        into primaries)."""
        n = n0
        while not self.stable(n, gamma):
            n -= 1
        return n

    def critical_shear(self, n, lo=1.0, hi=1e9):
        """The shear rate at which N becomes unstable (bisection in
        log gamma; the stresses grow with gamma)."""
        for _ in range(200):
            mid = math.sqrt(lo * hi)
            lo, hi = (mid, hi) if self.stable(n, mid) else (lo, mid)
        return hi
