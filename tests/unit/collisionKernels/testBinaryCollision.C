/*---------------------------------------------------------------------------*\
Description
    The no-cohesion hard-sphere collision (AB16 Eqs. 1-17): restitution,
    sticking and sliding slip laws, the sticking/sliding boundary, the
    elastic smooth limit, and the EAM/MAM limits e_n = 1 (doc/models.md
    12.1, T4-T8, T14).
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include <random>

using namespace Foam;
using namespace aggloTest;

namespace
{

//- Slip of the contact point for the states (normal from p1 to p2)
vector slip(const hardSphereState& a, const hardSphereState& b)
{
    return binaryCollision(a, b).uc();
}

} // End anonymous namespace


TEST(BinaryCollision, T7StickingSlidingBoundaryIsExact)
{
    // en = 1, et = 0.75, muSt = 2: threshold 7 muSt fna/(2(1 + et)) = 4 fna
    // exactly; u_n = -0.125 gives fna = 0.25 and threshold 1 = s
    const collisionCoefficients coeffs(1, 0.75, 2, 0.1);
    hardSphereState p1(point(0, 0, 0), vector(0, 0, 0), vector::zero,
        1e-5, 2000);
    hardSphereState p2(point(1e-5, 0, 0), vector(-0.125, 1, 0),
        vector::zero, 1e-5, 2000);

    const binaryCollision atBoundary(p1, p2);
    EXPECT_EQ(atBoundary.s(), 1.0);
    EXPECT_EQ(atBoundary.fna(1), 0.25);
    EXPECT_TRUE(atBoundary.sticking(coeffs, atBoundary.fna(1)));

    p2.U.y() = 1 + 1e-12;
    const binaryCollision beyond(p1, p2);
    EXPECT_FALSE(beyond.sticking(coeffs, beyond.fna(1)));
}


TEST(BinaryCollision, T5T6T8RestitutionAndSlipLaws)
{
    const dictionary dict(kernelDict("none"));
    const hardSphereCollisionKernel kernel(dict);
    const collisionCoefficients& c = kernel.coeffs();

    std::mt19937 gen(12345);
    std::uniform_real_distribution<scalar> uni(-1, 1);
    label nStick = 0, nSlide = 0;

    for (label i = 0; i < 2000; ++i)
    {
        const vector n = vector(uni(gen), uni(gen), uni(gen));
        if (mag(n) < 1e-3) continue;
        const vector nn = n/mag(n);
        hardSphereState p1(point(0, 0, 0),
            1e-3*vector(uni(gen), uni(gen), uni(gen)),
            1e2*vector(uni(gen), uni(gen), uni(gen)), 12e-6, 2200);
        hardSphereState p2(12e-6*nn,
            1e-3*vector(uni(gen), uni(gen), uni(gen)),
            1e2*vector(uni(gen), uni(gen), uni(gen)), 12e-6, 2200);
        const binaryCollision pair(p1, p2);
        if (!pair.approaching()) continue;

        const collisionOutcome out(kernel.collide(p1, p2));
        const vector w = out.p2.U - out.p1.U;

        // T8: (u2+ - u1+).n = -e_n u_n
        EXPECT_TRUE(near(w & pair.n(), -c.en()*pair.un(), 1e-12));

        const vector ucPlus = slip(out.p1, out.p2);
        if (out.isSticking())
        {
            // T5: u_c+ = -e_t u_c-
            ++nStick;
            EXPECT_TRUE(near(mag(ucPlus + c.et()*pair.uc()), 0, 0,
                1e-12*pair.s()));
        }
        else
        {
            // T6: u_c+ = u_c- - (7/2) mu_kin f_na t
            ++nSlide;
            const vector expect =
                pair.uc() - 3.5*c.muKin()*pair.fna(c.en())*pair.t();
            EXPECT_TRUE(near(mag(ucPlus - expect), 0, 0, 1e-12*pair.s()));
        }
    }
    // Both branches exercised
    EXPECT_GT(nStick, 100);
    EXPECT_GT(nSlide, 100);
}


TEST(BinaryCollision, T4ElasticSmoothLimit)
{
    const std::string elastic =
        "material { H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.612985e9;"
        " delta0 2e-10; rho0 2200; }"
        " particleCollision { en 1; et 0.44; muSt 0; muKin 0; }"
        " structureModel CSM;";
    const hardSphereCollisionKernel none
    (
        makeDict(elastic + " agglomerationModel none;")
    );
    const hardSphereCollisionKernel eam
    (
        makeDict(elastic + " agglomerationModel EAM;")
    );
    const hardSphereCollisionKernel mam
    (
        makeDict(elastic + " agglomerationModel MAM;")
    );

    std::mt19937 gen(4);
    std::uniform_real_distribution<scalar> uni(-1, 1);
    label nTested = 0;
    label nMamAgg = 0;
    while (nTested < 500)
    {
        vector n(uni(gen), uni(gen), uni(gen));
        if (mag(n) < 1e-3) continue;
        n /= mag(n);
        const scalar d2 = (nTested % 3 == 0 ? 4e-6 : 20e-6);
        hardSphereState p1(point(0, 0, 0),
            1e-3*vector(uni(gen), uni(gen), uni(gen)),
            1e3*vector(uni(gen), uni(gen), uni(gen)), 12e-6, 2200);
        hardSphereState p2(0.5*(12e-6 + d2)*n,
            1e-3*vector(uni(gen), uni(gen), uni(gen)),
            1e3*vector(uni(gen), uni(gen), uni(gen)), d2, 2200);
        if (!binaryCollision(p1, p2).approaching()) continue;
        ++nTested;

        const collisionOutcome o(none.collide(p1, p2));
        const scalar KE0 = p1.kineticEnergy() + p2.kineticEnergy();
        const scalar KE1 = o.p1.kineticEnergy() + o.p2.kineticEnergy();
        EXPECT_TRUE(near(KE1, KE0, 1e-12));
        EXPECT_LE(mag(o.p1.omega - p1.omega), 1e-12*mag(p1.omega));
        EXPECT_LE(mag(o.p2.omega - p2.omega), 1e-12*mag(p2.omega));

        // EAM identical to no cohesion, dE = 0
        const collisionOutcome oe(eam.collide(p1, p2));
        EXPECT_EQ(value(eam, oe, "dEvdW"), 0);
        EXPECT_FALSE(oe.agglomerates);
        EXPECT_TRUE(near(mag(oe.p1.U - o.p1.U), 0, 0, 1e-15));
        EXPECT_TRUE(near(mag(oe.p2.U - o.p2.U), 0, 0, 1e-15));

        // MAM: f*_nc = 0 and never agglomerates
        const collisionOutcome om(mam.collide(p1, p2));
        EXPECT_EQ(value(mam, om, "fncStar"), 0);
        if (om.agglomerates) ++nMamAgg;
    }
    EXPECT_EQ(nMamAgg, 0);
}


TEST(BinaryCollision, T14NoCohesionAtEn1)
{
    const hardSphereMaterial mat(6.3e-20, 7.2e10, 0.17, 1.612985e9, 2e-10,
        2200);
    // dE_vdW(e_n = 1) = 0 exactly (AB16 remark after Eq. 37)
    EXPECT_EQ
    (
        mat.vanDerWaalsEnergy
        (
            1, 12e-6, 2200, 12e-6, 2200, 1e-3
        ),
        0
    );
}


TEST(BinaryCollision, NotApproachingIsAnError)
{
    const dictionary dict(kernelDict("EAM"));
    const hardSphereCollisionKernel kernel(dict);
    hardSphereState p1, p2;
    referencePair(1e-3, 0, 0, 0, p1, p2);
    // Reverse the velocities: separating
    p1.U = -p1.U;
    p2.U = -p2.U;
    EXPECT_THROW(kernel.collide(p1, p2), Foam::error);
}
