/*---------------------------------------------------------------------------*\
Description
    Whether an agglomerate breaks (doc/breakup.md 1, 5): the dissipation
    of laminar simple shear with and without the Smagorinsky term, the
    critical shear rate gammaDot_crit = sigma_T/(C_v mu) crossed at +-1 %
    and its Smagorinsky shift against the root of the closed form (V2),
    the critical slip of Stokes drag at +-1 % (V3), the mechanism of the
    largest ratio, and a primary that never breaks.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "breakupCriterion.H"

using namespace Foam;
using namespace aggloTest;

namespace
{

//- A weak material (H = 1e-24 J) in water: gammaDot_crit of a few hundred
//  1/s, in the viscous subrange
const char* weak =
    "H 1e-24; E 7.2e10; nu 0.17; pMax 1.6e9; delta0 4e-10; rho0 1050;";

const scalar nu = 1e-6, rhoF = 1000, mu = nu*rhoF;

struct criterionCase
{
    hardSphereMaterial material;
    autoPtr<structureModel> structure;
    breakupCriterion criterion;

    explicit criterionCase(const std::string& stresses)
    :
        material(makeDict(weak)),
        structure
        (
            structureModel::New(makeDict("structureModel CSM;"), material)
        ),
        criterion
        (
            makeDict
            (
                "strength { rumpfPrefactor 1.125;"
                " coordination exactSmallRumpf; } stresses { "
              + stresses + " }"
            ),
            material,
            structure(),
            0.5
        )
    {}

    //- An agglomerate of N primaries of 1 um at rest
    hardSphereState agglomerate(const label N) const
    {
        return hardSphereState
        (
            point::zero, vector::zero, vector::zero,
            structure->diameter(N, 1e-6), structure->density(N), N
        );
    }
};

//- Simple shear U = (gammaDot y, 0, 0)
symmTensor shear(const scalar g)
{
    return symmTensor(0, 0.5*g, 0, 0, 0, 0);
}

breakupStresses::load shearLoad(const scalar eps)
{
    return breakupStresses::load
    {
        eps, nu, rhoF, vector::zero, vector::zero, 0, eps
    };
}

} // End anonymous namespace


TEST(BreakupCriterion, V2CriticalShearRateAndSmagorinskyShift)
{
    criterionCase c
    (
        "mechanisms (turbulence); dissipation total; Cv 2.5; Ci 2.5;"
    );
    const hardSphereState s = c.agglomerate(10);
    const scalar sigmaT =
        c.criterion.check(s, shearLoad(0)).sigmaT;
    ASSERT_GT(sigmaT, 0);

    // eps = nu gammaDot^2 in laminar shear
    EXPECT_TRUE(near(breakupCriterion::dissipation(nu, 0, shear(300)),
        nu*sqr(300.0), 1e-14));

    // C_s = 0: gammaDot_crit = sigma_T/(C_v mu), in the viscous subrange
    const scalar gc = sigmaT/(2.5*mu);
    EXPECT_GT(gc, 10);
    EXPECT_LT(gc, 1e4);
    EXPECT_LT(s.d, std::sqrt(nu/gc));
    for (const scalar f : {0.99, 1.01})
    {
        const scalar eps =
            breakupCriterion::dissipation(nu, 0, shear(f*gc));
        const breakupCriterion::verdict v =
            c.criterion.check(s, shearLoad(eps));
        EXPECT_EQ(v.breaks(), f > 1) << f;
        EXPECT_EQ(v.mechanism, label(breakupStresses::TURBULENCE));
        EXPECT_TRUE(near(v.ratio, f, 1e-9));
    }

    // Smagorinsky on: eps = nu g^2 + (C_s Delta)^2 g^3 breaks earlier;
    // the critical rate is the root of g^2 (1 + L^2 g/nu) = gc^2
    const scalar L = 2e-4;          // C_s Delta [m]
    EXPECT_TRUE(near(breakupCriterion::dissipation(nu, sqr(L)*300,
        shear(300)), nu*sqr(300.0) + sqr(L)*std::pow(300.0, 3), 1e-14));
    scalar lo = 0, hi = gc;
    for (int i = 0; i < 200; ++i)
    {
        const scalar g = 0.5*(lo + hi);
        (sqr(g)*(1 + sqr(L)*g/nu) < sqr(gc) ? lo : hi) = g;
    }
    const scalar gL = 0.5*(lo + hi);
    EXPECT_LT(gL, 0.9*gc);
    for (const scalar f : {0.99, 1.01})
    {
        const scalar g = f*gL;
        const scalar eps =
            breakupCriterion::dissipation(nu, sqr(L)*g, shear(g));
        EXPECT_LT(s.d, std::pow(nu*nu*nu/eps, 0.25));
        EXPECT_EQ(c.criterion.check(s, shearLoad(eps)).breaks(), f > 1)
            << f;
    }
}


TEST(BreakupCriterion, V3CriticalSlipOfStokesDrag)
{
    criterionCase c
    (
        "mechanisms (turbulence drag); dissipation total; Cv 1; Ci 1;"
        " Cd 1;"
    );
    const hardSphereState s = c.agglomerate(30);
    const scalar sigmaT = c.criterion.check(s, shearLoad(0)).sigmaT;

    // sigma_d = 3 mu U0/d_a for Stokes drag: U0 at 0.99 and 1.01 sigma_T
    for (const scalar f : {0.99, 1.01})
    {
        const scalar U0 = f*sigmaT*s.d/(3*mu);
        const vector F(3*constant::mathematical::pi*mu*s.d*U0, 0, 0);
        const breakupCriterion::verdict v = c.criterion.check
        (
            s, breakupStresses::load{0, nu, rhoF, F, vector::zero, 0, 0}
        );
        EXPECT_EQ(v.breaks(), f > 1) << f;
        EXPECT_EQ(v.mechanism, label(breakupStresses::DRAG));
    }
}


TEST(BreakupCriterion, LargestRatioAndPrimaries)
{
    criterionCase c
    (
        "mechanisms (turbulence drag rotation); dissipation total;"
        " Cv 1; Ci 1; Cd 1;"
        " rotationFactor 0.0625;"
    );
    const hardSphereState s = c.agglomerate(4);
    const scalar sigmaT = c.criterion.check(s, shearLoad(0)).sigmaT;

    // spin at twice the critical: rotation, ratio 4
    const scalar wc = 4/s.d*std::sqrt(sigmaT/s.rho);
    const breakupCriterion::verdict v = c.criterion.check
    (
        s,
        breakupStresses::load
        {
            nu*sqr(10.0), nu, rhoF, vector(1e-20, 0, 0),
            vector(0, 0, 2*wc), 0, nu*sqr(10.0)
        }
    );
    EXPECT_EQ(v.mechanism, label(breakupStresses::ROTATION));
    EXPECT_TRUE(near(v.ratio, 4, 1e-12));

    // a primary never breaks
    const hardSphereState p = c.agglomerate(1);
    const breakupCriterion::verdict vp = c.criterion.check
    (
        p, breakupStresses::load{1e9, nu, rhoF, vector(1, 0, 0),
            vector(0, 0, 1e9), 0, 1e9}
    );
    EXPECT_FALSE(vp.breaks());
    EXPECT_EQ(vp.mechanism, -1);
}


TEST(BreakupCriterion, WallImpactCriticalSpeed)
{
    // doc/breakup.md 1.5 [rec]: C_w M v^2/2 > n_b dE_vdW(v), with the EAM
    // bond energy of two primaries, AB16 Eq. 37, linear in v:
    // dE = c v, c = H/(12 delta0^2) d^4 (rho^2 (1 - en^2)
    // /(6 pMax 2d 2 rho d^3))^(1/2); so v_crit = 2 n_b c/(C_w M), with
    // n_b = N - 1 (N <= 4) or k/2, k = pi/eps (Rumpf), eps = 1 - f(N)
    const scalar Cw = 2;
    criterionCase c("mechanisms (wallImpact); Cw 2;");
    const scalar H = 1e-24, delta0 = 4e-10, pMax = 1.6e9, rho = 1050;
    const scalar en = 0.5, d = 1e-6;
    const scalar cE =
        H/(12*sqr(delta0))*std::pow(d, 4)
       *std::sqrt(sqr(rho)*(1 - sqr(en))/(6*pMax*2*d*2*rho*std::pow(d, 3)));
    const scalar f10 = 0.41216;
    for (const label N : {2, 3, 4, 10})
    {
        const scalar nb =
            N <= 4 ? N - 1 : 0.5*constant::mathematical::pi/(1 - f10);
        hardSphereState s = c.agglomerate(N);
        const scalar M = N*rho*constant::mathematical::pi*std::pow(d, 3)/6;
        const scalar vCrit = 2*nb*cE/(Cw*M);
        EXPECT_TRUE(near(c.criterion.impactBonds(N), nb, 1e-4)) << N;
        for (const scalar f : {0.99, 1.01})
        {
            const breakupCriterion::verdict v = c.criterion.check
            (
                s,
                breakupStresses::load
                {
                    0, nu, rhoF, vector::zero, vector::zero, f*vCrit, 0
                }
            );
            EXPECT_EQ(v.breaks(), f > 1) << N << " " << f;
            EXPECT_EQ(v.mechanism, label(breakupStresses::WALL_IMPACT));
            EXPECT_TRUE(near(v.ratio, f, 1e-4)) << N << " " << v.ratio;
        }

        // no impact in the step: no verdict
        const breakupCriterion::verdict v0 = c.criterion.check
        (
            s, breakupStresses::load{0, nu, rhoF, vector::zero,
                vector::zero, 0, 0}
        );
        EXPECT_FALSE(v0.breaks());
    }
}


// ************************************************************************* //
