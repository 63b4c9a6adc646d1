/*---------------------------------------------------------------------------*\
Description
    The strength and the loading stresses of an agglomerate
    (doc/breakup.md 1, 2): the hand values of doc/breakup.md 1.7 (bond
    force, Rumpf strength, diameter, critical spin), the small-N weakest
    plane, the coordination rules, the turbulent stress continuous at the
    Kolmogorov length and equal to C_v mu gammaDot in laminar shear, the
    Stokes drag stress 3 mu u/d, the critical spin at +-1 % (V1), and the
    input checks.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "agglomerateStrength.H"
#include "breakupStresses.H"

using namespace Foam;
using namespace aggloTest;

namespace
{

//- The material of doc/breakup.md 1.7: A = 6.5e-20 J, delta0 = 0.4 nm,
//  rho_p = 2500 kg/m3 (E, nu, pMax do not enter)
const char* material17 =
    "H 6.5e-20; E 7.2e10; nu 0.17; pMax 1.6e9; delta0 4e-10; rho0 2500;";

struct strengthCase
{
    hardSphereMaterial material;
    autoPtr<structureModel> structure;
    agglomerateStrength strength;

    strengthCase
    (
        const std::string& structureName,
        const std::string& strengthDict
    )
    :
        material(makeDict(material17)),
        structure
        (
            structureModel::New
            (
                makeDict("structureModel " + structureName + ";"),
                material
            )
        ),
        strength(makeDict(strengthDict), material, structure())
    {}
};

const std::string rumpf1 = "rumpfPrefactor 1; coordination rumpf;";
const std::string exact98 =
    "rumpfPrefactor 1.125; coordination exactSmallRumpf;";

const scalar dp = 2e-6;

} // End anonymous namespace


TEST(AgglomerateStrength, HandValuesOfSection1_7)
{
    strengthCase c("CSM", rumpf1);

    // F = A d_p/(24 delta0^2) = 3.4e-8 N
    const scalar F = c.strength.bondForce(dp);
    EXPECT_TRUE(near(F, 6.5e-20*dp/(24*sqr(4e-10)), 1e-14));
    EXPECT_TRUE(near(F, 3.4e-8, 0.01));

    // sigma_T = (1 - eps)/eps F/d_p^2 with eps = 0.48: 9.2 kPa
    const label N = 1000;
    const scalar sigmaT = c.strength.tensileStrength(N, dp);
    EXPECT_TRUE(near(sigmaT, 0.52/0.48*F/sqr(dp), 1e-12));
    EXPECT_TRUE(near(sigmaT, 9.2e3, 0.005));

    // d_a = 24.9 um, omega_crit = (4/d_a)(sigma_T/rho_a)^1/2 = 4.3e5 rad/s
    const scalar da = c.structure->diameter(N, dp);
    const scalar rhoA = c.structure->density(N);
    EXPECT_TRUE(near(da, 24.9e-6, 0.002));
    const scalar omegaCrit = 4/da*std::sqrt(sigmaT/rhoA);
    EXPECT_TRUE(near(omegaCrit, 4.3e5, 0.01));

    // the coordination numbers at large N: pi/eps = 6.5, 15 phi^1.2 = 6.8
    EXPECT_TRUE(near(c.strength.coordination(N), 6.5, 0.01));
    strengthCase p("CSM", "rumpfPrefactor 1; coordination porosityPower;");
    EXPECT_TRUE(near(p.strength.coordination(N), 6.8, 0.01));
}


TEST(AgglomerateStrength, SmallNWeakestPlaneAndPrefactor)
{
    strengthCase c("CSM", exact98);
    strengthCase r("CSM", rumpf1);
    const scalar F = c.strength.bondForce(dp);
    const scalar fPack[] = {0, 0, 0.26683, 0.31574, 0.42099};
    for (label N = 2; N <= 4; ++N)
    {
        // n_b = N - 1 bonds over the cross-section of the CSM agglomerate
        const scalar da = dp*std::cbrt(N/fPack[N]);
        const scalar expect =
            (N - 1)*F/(0.25*constant::mathematical::pi*sqr(da));
        EXPECT_TRUE(near(c.strength.tensileStrength(N, dp), expect, 1e-12))
            << N;
    }
    // beyond N = 4 the Rumpf strength with c_R = 9/8
    for (const label N : {5, 30, 1000})
    {
        EXPECT_TRUE
        (
            near
            (
                c.strength.tensileStrength(N, dp),
                1.125*r.strength.tensileStrength(N, dp),
                1e-14
            )
        ) << N;
    }
}


TEST(AgglomerateStrength, VSMTakesThePorosityOfCSMsTable)
{
    strengthCase v("VSM", rumpf1);
    strengthCase c("CSM", rumpf1);
    for (const label N : {2, 7, 30, 31, 1000})
    {
        EXPECT_EQ(v.structure->porosity(N), c.structure->porosity(N)) << N;
        EXPECT_EQ
        (
            v.strength.tensileStrength(N, dp),
            c.strength.tensileStrength(N, dp)
        ) << N;
    }
    EXPECT_EQ(v.structure->porosity(1), 0);
    EXPECT_TRUE(near(c.structure->porosity(1000), 0.48, 1e-14));
}


TEST(AgglomerateStrength, BadInputIsFatal)
{
    const hardSphereMaterial m(makeDict(material17));
    const autoPtr<structureModel> s
    (
        structureModel::New(makeDict("structureModel CSM;"), m)
    );
    auto msg = [&](const std::string& text)
    {
        return errorMessage
        (
            [&]{ agglomerateStrength(makeDict(text), m, s()); }
        );
    };
    EXPECT_NE
    (
        msg("rumpfPrefactor 1.3; coordination rumpf;").find("[1, 1.125]"),
        std::string::npos
    );
    EXPECT_NE
    (
        msg("rumpfPrefactor 1; coordination rumph;").find("rumpf"),
        std::string::npos
    );
    EXPECT_NE(msg("coordination rumpf;").find("rumpfPrefactor"),
        std::string::npos);
    EXPECT_NE
    (
        msg(rumpf1 + " Cv 1;").find("Unknown entry 'Cv'"),
        std::string::npos
    );
}


TEST(BreakupStresses, TurbulentStressLimits)
{
    const breakupStresses s
    (
        makeDict
        (
            "mechanisms (turbulence); dissipation total; Cv 2.5; Ci 2.5;"
        )
    );
    const scalar nu = 1.5e-5, rhoF = 1.2, mu = nu*rhoF;

    // laminar simple shear: eps = nu gammaDot^2 gives C_v mu gammaDot
    const scalar gammaDot = 1e3;
    const scalar eps = nu*sqr(gammaDot);
    const scalar eta = std::pow(nu*nu*nu/eps, 0.25);
    EXPECT_TRUE(near(s.turbulent(eps, nu, rhoF, 0.5*eta), 2.5*mu*gammaDot,
        1e-12));

    // continuous at the Kolmogorov length when C_v = C_i
    const scalar below = s.turbulent(eps, nu, rhoF, eta*(1 - 1e-9));
    const scalar above = s.turbulent(eps, nu, rhoF, eta*(1 + 1e-9));
    EXPECT_TRUE(near(below, above, 1e-8));

    // inertial subrange: C_i rho_f (eps d)^2/3
    EXPECT_TRUE(near(s.turbulent(eps, nu, rhoF, 10*eta),
        2.5*rhoF*std::pow(eps*10*eta, 2.0/3.0), 1e-12));

    // still fluid: no stress
    EXPECT_EQ(s.turbulent(0, nu, rhoF, eta), 0);
}


TEST(BreakupStresses, DissipationReadingsAgainstHandValues)
{
    // Water in simple shear gammaDot = 5e5 1/s (doc/breakup.md 1.1):
    // eps_res = nu gammaDot^2 = 2.5e5 m2/s3, eta = (nu^3/eps)^1/4 =
    // 1.41 um; a 30 um agglomerate lies in the inertial range, a 1 um one
    // in the viscous range
    const scalar nu = 1e-6, rhoF = 1000, mu = nu*rhoF, g = 5e5;
    const scalar epsRes = nu*g*g;
    auto stress = [&](const word& reading, const scalar nut, scalar d)
    {
        const breakupStresses s
        (
            makeDict
            (
                "mechanisms (turbulence); dissipation " + reading
              + "; Cv 1; Ci 1;"
            )
        );
        breakupStresses::load L{(nu + nut)*g*g, nu, rhoF, vector::zero,
            vector::zero, 0, epsRes};
        return s.stresses(L, d, 2500)[breakupStresses::TURBULENCE];
    };
    const scalar d = 30e-6, small = 1e-6;
    const scalar inertial = rhoF*std::cbrt(sqr(epsRes*d));    // 3831 Pa
    EXPECT_TRUE(near(inertial, 3831.2, 1e-4));

    // laminar: the resolved shear only
    EXPECT_TRUE(near(stress("total", 0, d), inertial, 1e-12));
    EXPECT_EQ(stress("subgrid", 0, d), 0);
    EXPECT_TRUE(near(stress("resolvedShear", 0, d), mu*g, 1e-12));

    // a Smagorinsky part nu_t = nu: eps = 2 nu gammaDot^2, eps_sgs = eps_res
    EXPECT_TRUE(near(stress("total", nu, d),
        rhoF*std::cbrt(sqr(2*epsRes*d)), 1e-12));
    EXPECT_TRUE(near(stress("subgrid", nu, d), inertial, 1e-12));
    EXPECT_TRUE(near(stress("resolvedShear", nu, d),
        std::sqrt(sqr(mu*g) + sqr(inertial)), 1e-12));

    // viscous range: resolvedShear equals total (sqrt(2) mu gammaDot)
    EXPECT_TRUE(near(stress("total", nu, small), std::sqrt(2.0)*mu*g,
        1e-12));
    EXPECT_TRUE(near(stress("resolvedShear", nu, small),
        std::sqrt(2.0)*mu*g, 1e-12));
    EXPECT_TRUE(near(stress("subgrid", nu, small), mu*g, 1e-12));
}


TEST(BreakupStresses, StokesDragAndCriticalSpin)
{
    const breakupStresses s
    (
        makeDict("mechanisms (drag rotation); Cd 1; rotationFactor 0.0625;")
    );

    // Stokes drag 3 pi mu d u gives the traction 3 mu u/d
    const scalar mu = 1.8e-5, d = 20e-6, u = 0.3;
    const scalar F = 3*constant::mathematical::pi*mu*d*u;
    EXPECT_TRUE(near(s.drag(F, d), 3*mu*u/d, 1e-14));

    // V1: sigma_r = rho_a omega^2 d_a^2/16 crosses sigma_T at
    // omega_crit = (4/d_a)(sigma_T/rho_a)^1/2, for N = 2, 3, 4, 10, 1000
    // and both structure models
    for (const std::string st : {"VSM", "CSM"})
    {
        strengthCase c(st, exact98);
        for (const label N : {2, 3, 4, 10, 1000})
        {
            const scalar da = c.structure->diameter(N, dp);
            const scalar rhoA = c.structure->density(N);
            const scalar sigmaT = c.strength.tensileStrength(N, dp);
            const scalar wc = 4/da*std::sqrt(sigmaT/rhoA);
            const vector axis(0.6, 0, 0.8);
            EXPECT_LT(s.rotational(rhoA, 0.99*wc*axis, da), sigmaT)
                << st << " " << N;
            EXPECT_GT(s.rotational(rhoA, 1.01*wc*axis, da), sigmaT)
                << st << " " << N;
        }
    }

    // the mechanisms off give no stress
    breakupStresses::load L{1e4, 1.5e-5, 1.2, vector(F, 0, 0),
        vector(0, 0, 1e5), 0, 1e4};
    const FixedList<scalar, 3> all(s.stresses(L, d, 2500));
    EXPECT_EQ(all[breakupStresses::TURBULENCE], 0);
    EXPECT_GT(all[breakupStresses::DRAG], 0);
    EXPECT_GT(all[breakupStresses::ROTATION], 0);
}


TEST(BreakupStresses, BadInputIsFatal)
{
    auto msg = [](const std::string& text)
    {
        return errorMessage([&]{ breakupStresses(makeDict(text)); });
    };
    EXPECT_NE(msg("mechanisms (turbulnce); Cv 1; Ci 1;")
        .find("Valid mechanisms"), std::string::npos);
    EXPECT_NE(msg("mechanisms ();").find("empty"), std::string::npos);
    EXPECT_NE(msg("mechanisms (drag); Cd 1; Cv 1;")
        .find("mechanism that is off"), std::string::npos);
    EXPECT_NE(msg("mechanisms (drag); Cd 0;").find("Cd"), std::string::npos);
    EXPECT_NE(msg("mechanisms (rotation);").find("rotationFactor"),
        std::string::npos);
    // the reading of the dissipation rate: required with turbulence, one
    // of the three, refused without it
    EXPECT_NE(msg("mechanisms (turbulence); Cv 1; Ci 1;")
        .find("dissipation"), std::string::npos);
    EXPECT_NE(msg("mechanisms (turbulence); dissipation resolved; Cv 1;"
        " Ci 1;").find("resolvedShear"), std::string::npos);
    EXPECT_NE(msg("mechanisms (drag); Cd 1; dissipation total;")
        .find("mechanism that is off"), std::string::npos);
}


// ************************************************************************* //
