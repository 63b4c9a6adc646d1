/*---------------------------------------------------------------------------*\
Description
    Limits, monotonicity and scaling of the kernels (doc/models.md 12.1):
    T9 Hiller limit, T13 monotonicity in the impact speed, T20 scaling
    laws, and the critical velocities of 12.5 by bisection on the full
    algorithm.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include <cmath>

using namespace Foam;
using namespace aggloTest;

namespace
{

//- Agglomerates? for a head-on collision of equal spheres at speed v
bool headOnAgglomerates
(
    const hardSphereCollisionKernel& kernel,
    const scalar v,
    const scalar d,
    const scalar rho,
    const scalar thetaDeg = 0
)
{
    hardSphereState p1, p2;
    referencePair(v, thetaDeg, 0, 0, p1, p2, d, rho);
    return kernel.collide(p1, p2).agglomerates;
}


//- Critical velocity by bisection on the full algorithm
scalar criticalVelocity
(
    const hardSphereCollisionKernel& kernel,
    const scalar d,
    const scalar rho,
    const scalar thetaDeg = 0
)
{
    scalar lo = 1e-9, hi = 10;
    for (int it = 0; it < 200 && hi/lo > 1 + 1e-12; ++it)
    {
        const scalar mid = std::sqrt(lo*hi);
        if (headOnAgglomerates(kernel, mid, d, rho, thetaDeg))
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return std::sqrt(lo*hi);
}


} // End anonymous namespace


TEST(Invariants, T9EAMHillerLimit)
{
    const dictionary dict(kernelDict("EAM"));
    const hardSphereCollisionKernel eam(dict);
    hardSphereState p1, p2;
    const scalar v = 5e-3;
    referencePair(v, 0, 0, 0, p1, p2);
    const collisionOutcome o(eam.collide(p1, p2));
    ASSERT_FALSE(o.agglomerates);
    const scalar wn = (o.p2.U - o.p1.U).x();
    const scalar mHat = binaryCollision(p1, p2).mHat();
    EXPECT_TRUE(near(wn, 3.5379326820e-3, 1e-9));
    const scalar dE = value(eam, o, "dEvdW");
    EXPECT_TRUE(near(wn, std::sqrt(sqr(0.97*v) - 2*dE/mHat), 1e-12));
}



TEST(Invariants, T13MonotoneInImpactSpeed)
{
    const char* models[4] = {"EAM", "EAMAlletto2014", "MAM", "MAM_hertz"};
    for (const char* m : models)
    {
        const std::string model(m);
        const dictionary dict
        (
            model == "MAM_hertz"
          ? kernelDict("MAM", "CSM", "MAMCoeffs { closure hertzRebound; }")
          : kernelDict(model)
        );
        const hardSphereCollisionKernel k(dict);
        for (int theta = 0; theta < 90; theta += 7)
        {
            const scalar vc = criticalVelocity(k, 12e-6, 2200, theta);
            for (int j = 0; j < 40; ++j)
            {
                const scalar v = vc*std::pow(10.0, -2 + 4*j/39.0);
                if (std::abs(v/vc - 1) < 1e-9) continue;
                EXPECT_EQ(headOnAgglomerates(k, v, 12e-6, 2200, theta),
                    v < vc) << model << " theta " << theta << " v " << v;
            }
        }
    }
}


TEST(Invariants, Section12_5CriticalVelocities)
{
    struct caseData
    {
        std::string material;
        scalar d, rho, en, eam, mamTable4, mamHertz;
    };
    const std::string quartz =
        "material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9;"
        " delta0 2e-10; rho0 2200; }";
    const std::string ps =
        "material { H 2.28e-21; E 3e9; nu 0.34; pMax 1.66161e8;"
        " delta0 2e-10; rho0 1050; }";
    const caseData cases[] =
    {
        {quartz, 12e-6, 2200, 0.97, 2.339e-3, 8.579e-4, 4.061e-4},
        {quartz, 12e-6, 2200, 0.80, 8.488e-3, 5.425e-3, 2.547e-3},
        {quartz, 12e-6, 2200, 0.60, 2.012e-2, 1.426e-2, 6.614e-3},
        {quartz, 4e-6, 2200, 0.97, 7.018e-3, 2.143e-3, 1.014e-3},
        {quartz, 4e-6, 2200, 0.80, 2.546e-2, 1.355e-2, 6.363e-3},
        {quartz, 4e-6, 2200, 0.60, 6.036e-2, 3.563e-2, 1.652e-2},
        {ps, 25e-6, 1050, 0.97, 1.833e-4, 1.185e-4, 5.610e-5},
        {ps, 25e-6, 1050, 0.80, 6.650e-4, 7.495e-4, 3.519e-4},
        {ps, 25e-6, 1050, 0.60, 1.576e-3, 1.970e-3, 9.137e-4}
    };
    for (const caseData& c : cases)
    {
        const std::string coeffs =
            " particleCollision { en " + std::to_string(c.en)
          + "; et 0.44; muSt 0.94; muKin 0.092; } structureModel CSM;";
        const hardSphereCollisionKernel eam
            (makeDict(c.material + coeffs + " agglomerationModel EAM;"));
        const hardSphereCollisionKernel mam
            (makeDict(c.material + coeffs + " agglomerationModel MAM;"));
        const hardSphereCollisionKernel mamH
        (
            makeDict(c.material + coeffs + " agglomerationModel MAM;"
                " MAMCoeffs { closure hertzRebound; }")
        );
        EXPECT_TRUE(near(criticalVelocity(eam, c.d, c.rho), c.eam, 1e-3))
            << "EAM d " << c.d << " en " << c.en;
        EXPECT_TRUE(near(criticalVelocity(mam, c.d, c.rho), c.mamTable4,
            1e-3)) << "MAM table4 d " << c.d << " en " << c.en;
        EXPECT_TRUE(near(criticalVelocity(mamH, c.d, c.rho), c.mamHertz,
            1e-3)) << "MAM hertzRebound d " << c.d << " en " << c.en;
    }
}


TEST(Invariants, T20ScalingLaws)
{
    const hardSphereMaterial mat(6.3e-20, 7.2e10, 0.17, 1.612985e9, 2e-10,
        2200);

    // dE ~ d^2 rho^0.5 v^1 (equal spheres)
    const scalar f = 1.1;
    const scalar dE0 = mat.vanDerWaalsEnergy(0.97, 12e-6, 2200, 12e-6,
        2200, 1e-3);
    const scalar sd = std::log(mat.vanDerWaalsEnergy(0.97, f*12e-6,
        2200, f*12e-6, 2200, 1e-3)/dE0)/std::log(f);
    const scalar sr = std::log(mat.vanDerWaalsEnergy(0.97, 12e-6,
        f*2200, 12e-6, f*2200, 1e-3)/dE0)/std::log(f);
    const scalar sv = std::log(mat.vanDerWaalsEnergy(0.97, 12e-6,
        2200, 12e-6, 2200, f*1e-3)/dE0)/std::log(f);
    EXPECT_TRUE(near(sd, 2.0, 0, 1e-3));
    EXPECT_TRUE(near(sr, 0.5, 0, 1e-3));
    EXPECT_TRUE(near(sv, 1.0, 0, 1e-3));

    // dE(e)/dE(0.97)
    EXPECT_TRUE(near(mat.vanDerWaalsEnergy(0.80, 12e-6, 2200, 12e-6,
        2200, 1e-3)/dE0, 2.4681, 1e-4));
    EXPECT_TRUE(near(mat.vanDerWaalsEnergy(0.60, 12e-6, 2200, 12e-6,
        2200, 1e-3)/dE0, 3.2908, 1e-4));

    // f*_nc ~ d^-1 rho^-0.6 v^-0.2 (Eq. 89)
    const dictionary dict(kernelDict("MAM"));
    const hardSphereCollisionKernel mam(dict);
    auto fStar = [&](scalar d, scalar rho, scalar v)
    {
        hardSphereState p1, p2;
        referencePair(v, 0, 0, 0, p1, p2, d, rho);
        return value(mam, mam.collide(p1, p2), "fncStar");
    };
    const scalar F0 = fStar(12e-6, 2200, 1e-2);
    EXPECT_TRUE(near(std::log(fStar(f*12e-6, 2200, 1e-2)/F0)/std::log(f),
        -1.0, 0, 1e-3));
    EXPECT_TRUE(near(std::log(fStar(12e-6, f*2200, 1e-2)/F0)/std::log(f),
        -0.6, 0, 1e-3));
    EXPECT_TRUE(near(std::log(fStar(12e-6, 2200, f*1e-2)/F0)/std::log(f),
        -0.2, 0, 1e-3));
}
