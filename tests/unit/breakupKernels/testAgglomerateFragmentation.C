/*---------------------------------------------------------------------------*\
Description
    The fragments of a break-up (doc/breakup.md 3): conservation on 10^4
    random parents (V4: primaries exact; mass, centre of mass, momentum
    and angular momentum about the origin to 1e-12 relative; no overlap),
    the rigid-body option's known angular-momentum change, the erosion
    sequence and the binary halving tree (V5), the beta mode's draws
    against its beta-binomial law (chi-square), the split direction in
    simple shear (45 degrees in the shear plane, V2) and perpendicular to
    the spin, and the input checks.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "agglomerateFragmentation.H"
#include "tensor.H"
#include <random>
#include <vector>

using namespace Foam;
using namespace aggloTest;

namespace
{

const char* quartz =
    "H 6.3e-20; E 7.2e10; nu 0.17; pMax 1.6e9; delta0 2e-10; rho0 2200;";

struct fragmentationCase
{
    hardSphereMaterial material;
    autoPtr<structureModel> structure;
    agglomerateFragmentation frag;

    fragmentationCase
    (
        const std::string& structureName,
        const std::string& fragDict
    )
    :
        material(makeDict(quartz)),
        structure
        (
            structureModel::New
            (
                makeDict("structureModel " + structureName + ";"),
                material
            )
        ),
        frag(makeDict(fragDict), structure(), material.rho0())
    {}

    //- An agglomerate of N primaries of diameter dp
    hardSphereState parent
    (
        const label N,
        const scalar dp,
        const point& x,
        const vector& U,
        const vector& omega
    ) const
    {
        return hardSphereState
        (
            x, U, omega, structure->diameter(N, dp), structure->density(N),
            N
        );
    }
};

const std::string erosion =
    "mode erosion; direction extensional; gap 1e-3; tries 6;"
    " spin conserveL;";

vector angularMomentum(const hardSphereState& s)
{
    return s.angularMomentum(point::zero);
}

} // End anonymous namespace


TEST(AgglomerateFragmentation, V4ConservationOnRandomParents)
{
    std::mt19937_64 gen(2024);
    std::uniform_real_distribution<scalar> uni(-1, 1);
    std::uniform_int_distribution<int> nDist(2, 1000);
    const char* modes[] = {"erosion", "binary", "beta"};
    label nTested = 0;
    for (const std::string st : {"VSM", "CSM"})
    {
        for (const char* mode : modes)
        {
            fragmentationCase c
            (
                st,
                std::string("mode ") + mode + "; direction extensional;"
                " gap 1e-3; tries 6; spin conserveL;"
              + (std::string(mode) == "beta" ? " betaAlpha 0.7;" : "")
            );
            for (label i = 0; i < 1700; ++i)
            {
                const label N = nDist(gen);
                const hardSphereState p = c.parent
                (
                    N, 2e-6,
                    point(uni(gen), uni(gen), uni(gen)),
                    vector(uni(gen), uni(gen), uni(gen)),
                    1e5*vector(uni(gen), uni(gen), uni(gen))
                );
                keyedRandom rnd(1, 2, 3, i, N);
                const label N1 = c.frag.fragmentSize(N, rnd);
                vector e(uni(gen), uni(gen), uni(gen));
                e /= mag(e);
                const agglomerateFragmentation::fragments f =
                    c.frag.split(p, N1, e);
                ++nTested;

                ASSERT_EQ(f.a.nPrimary + f.b.nPrimary, N);
                ASSERT_GE(f.a.nPrimary, 1);
                ASSERT_GE(f.b.nPrimary, 1);

                const scalar M = p.mass();
                EXPECT_TRUE(near(f.a.mass() + f.b.mass(), M, 1e-12));
                const point xc =
                    (f.a.mass()*f.a.x + f.b.mass()*f.b.x)
                   /(f.a.mass() + f.b.mass());
                EXPECT_LE(mag(xc - p.x), 1e-12*(mag(p.x) + p.d));

                const vector P0 = p.momentum();
                const vector P1 = f.a.momentum() + f.b.momentum();
                EXPECT_LE(mag(P1 - P0), 1e-12*M*mag(p.U)) << i;

                const vector L0 = angularMomentum(p);
                const vector L1 = angularMomentum(f.a) + angularMomentum(f.b);
                const scalar scaleL =
                    M*mag(p.x)*mag(p.U) + p.inertia()*mag(p.omega);
                EXPECT_LE(mag(L1 - L0), 1e-12*scaleL) << i;

                // apart by the gap, not overlapping
                const scalar gapDist =
                    mag(f.b.x - f.a.x) - 0.5*(f.a.d + f.b.d);
                const scalar dp = p.primaryDiameter(2200);
                EXPECT_TRUE(near(gapDist, 1e-3*dp, 1e-6, 1e-20)) << i;
                EXPECT_GT(gapDist, 0);
            }
        }
    }
    EXPECT_EQ(nTested, 10200);
}


TEST(AgglomerateFragmentation, RigidBodyKeepsMomentumNotSpinMomentum)
{
    fragmentationCase c
    (
        "VSM",
        "mode binary; direction extensional; gap 0; tries 6; spin rigidBody;"
    );
    const hardSphereState p =
        c.parent(100, 2e-6, point(1, 2, 3), vector(0.1, 0, 0),
            vector(0, 0, 1e5));
    const vector e(1, 0, 0);
    const agglomerateFragmentation::fragments f = c.frag.split(p, 50, e);
    EXPECT_EQ(f.a.omega, p.omega);
    EXPECT_LE(mag(f.a.momentum() + f.b.momentum() - p.momentum()),
        1e-13*mag(p.momentum()));

    // L changes by (J - I_a 1) omega (doc/breakup.md 3.3)
    const vector r1(f.a.x - p.x), r2(f.b.x - p.x);
    const tensor J =
        (f.a.inertia() + f.b.inertia())*tensor::I
      + f.a.mass()*(magSqr(r1)*tensor::I - sqr(r1))
      + f.b.mass()*(magSqr(r2)*tensor::I - sqr(r2));
    const vector dL =
        angularMomentum(f.a) + angularMomentum(f.b) - angularMomentum(p);
    const vector expect((J - p.inertia()*tensor::I) & p.omega);
    EXPECT_LE(mag(dL - expect), 1e-9*mag(expect));
    EXPECT_GT(mag(expect), 0);

    // the equal VSM split: centres (1/2)^(1/3) d_a/2 = 0.40 d_a from the
    // parent's (gap 0), inside it
    EXPECT_TRUE(near(mag(r1)/p.d, 0.5*std::cbrt(0.5), 1e-12));
    EXPECT_LT(mag(r1), 0.5*p.d);
}


TEST(AgglomerateFragmentation, V5ErosionSequenceAndBinaryTree)
{
    fragmentationCase c("CSM", erosion);
    hardSphereState p =
        c.parent(500, 2e-6, point::zero, vector::zero, vector::zero);
    keyedRandom rnd(0, 0, 0, 0, 0);
    for (label k = 1; k <= 10; ++k)
    {
        const label N1 = c.frag.fragmentSize(p.nPrimary, rnd);
        ASSERT_EQ(N1, 1);
        const agglomerateFragmentation::fragments f =
            c.frag.split(p, N1, vector(0, 0, 1));
        EXPECT_EQ(f.a.nPrimary, 1);
        EXPECT_EQ(f.b.nPrimary, 500 - k);
        p = f.b;
    }

    // binary: the deterministic halving tree down to primaries
    fragmentationCase b
    (
        "CSM",
        "mode binary; direction extensional; gap 0; tries 6; spin conserveL;"
    );
    std::vector<label> pending({500});
    label leaves = 0, splits = 0;
    while (!pending.empty())
    {
        const label N = pending.back();
        pending.pop_back();
        if (N == 1)
        {
            ++leaves;
            continue;
        }
        const label N1 = b.frag.fragmentSize(N, rnd);
        EXPECT_EQ(N1, N/2);
        pending.push_back(N1);
        pending.push_back(N - N1);
        ++splits;
    }
    EXPECT_EQ(leaves, 500);
    EXPECT_EQ(splits, 499);
}


TEST(AgglomerateFragmentation, V5BetaModeFollowsItsLaw)
{
    fragmentationCase c
    (
        "CSM",
        "mode beta; betaAlpha 0.5; direction extensional; gap 0;"
        " tries 6; spin conserveL;"
    );
    const label N = 20, n = 20000;
    scalar total = 0;
    for (label k = 0; k <= N; ++k)
    {
        total += c.frag.betaProbability(k, N);
    }
    EXPECT_TRUE(near(total, 1, 1e-12));
    EXPECT_EQ(c.frag.betaProbability(0, N), 0);
    EXPECT_EQ(c.frag.betaProbability(N, N), 0);

    List<label> count(N + 1, Zero);
    for (label i = 0; i < n; ++i)
    {
        keyedRandom rnd(7, 1, 0, i, 0);
        ++count[c.frag.fragmentSize(N, rnd)];
    }
    // chi-square with 18 degrees of freedom: 42.3 at p = 0.001
    scalar chi2 = 0;
    for (label k = 1; k < N; ++k)
    {
        const scalar expect = n*c.frag.betaProbability(k, N);
        chi2 += sqr(count[k] - expect)/expect;
    }
    EXPECT_LT(chi2, 42.3);
    // alpha < 1: U-shaped, the ends more likely than the middle
    EXPECT_GT(count[1], 2*count[10]);
}


TEST(AgglomerateFragmentation, V2DirectionInSimpleShear)
{
    // U = (gammaDot y, 0, 0): S = gammaDot/2 (e_x e_y + e_y e_x)
    const scalar g = 100;
    const symmTensor S(0, 0.5*g, 0, 0, 0, 0);
    fragmentationCase c("CSM", erosion);
    fragmentationCase d
    (
        "CSM",
        "mode erosion; direction deformationPlane; gap 1e-3; tries 6;"
        " spin conserveL;"
    );
    const vector diag(1/std::sqrt(2.0), 1/std::sqrt(2.0), 0);
    label plus = 0;
    for (label i = 0; i < 200; ++i)
    {
        keyedRandom rnd(3, 4, 0, i, 0);
        const vector e = c.frag.direction(S, vector::zero, false, rnd);
        EXPECT_TRUE(near(mag(e & diag), 1, 1e-12));
        plus += (e & diag) > 0;

        // the deformation plane is the shear plane x-y
        const vector ed = d.frag.direction(S, vector::zero, false, rnd);
        EXPECT_LE(mag(ed.z()), 1e-12);
        EXPECT_TRUE(near(mag(ed), 1, 1e-12));

        // by rotation: perpendicular to the spin
        const vector w(0.3, -0.2, 0.9);
        const vector er = c.frag.direction(S, w, true, rnd);
        EXPECT_LE(mag(er & w), 1e-12*mag(w));
        EXPECT_TRUE(near(mag(er), 1, 1e-12));

        // still fluid: a random unit vector
        const vector e0 = c.frag.direction(symmTensor::zero, w, false, rnd);
        EXPECT_TRUE(near(mag(e0), 1, 1e-12));
    }
    // the sign is drawn
    EXPECT_GT(plus, 60);
    EXPECT_LT(plus, 140);
}


TEST(AgglomerateFragmentation, RetriesTheOppositeThenInTheDeformationPlane)
{
    // Shear and stretching: the deformation plane is spanned by the most
    // extensional and the most compressive eigenvectors, normal to the
    // intermediate one
    const symmTensor S(3, 1, 0.5, -1, 0.2, -2);
    const vector middle(eigenVectors(S).y());
    fragmentationCase c("CSM", erosion);
    const vector w(0.3, -0.2, 0.9);
    const label tries = c.frag.tries();
    EXPECT_EQ(tries, 6);
    for (label i = 0; i < 50; ++i)
    {
        keyedRandom rnd(3, 4, 0, i, 0);
        const vector e0 = c.frag.direction(S, vector::zero, false, rnd);
        EXPECT_EQ(c.frag.retryDirection(e0, S, w, false, 0, rnd), e0);
        EXPECT_EQ(c.frag.retryDirection(e0, S, w, false, 1, rnd), -e0);
        for (label t = 2; t < tries; ++t)
        {
            keyedRandom rt(3, 4, 0, i, 0, t);
            const vector e = c.frag.retryDirection(e0, S, w, false, t, rt);
            EXPECT_TRUE(near(mag(e), 1, 1e-12));
            EXPECT_LE(mag(e & middle), 1e-12);
            EXPECT_GT(mag(e - e0), 1e-6);
            EXPECT_GT(mag(e + e0), 1e-6);
            // by rotation: perpendicular to the spin
            keyedRandom rr(3, 4, 0, i, 0, t);
            const vector er = c.frag.retryDirection(e0, S, w, true, t, rr);
            EXPECT_LE(mag(er & w), 1e-12*mag(w));
            EXPECT_TRUE(near(mag(er), 1, 1e-12));
        }
    }
}


TEST(AgglomerateFragmentation, BadInputIsFatal)
{
    const hardSphereMaterial m(makeDict(quartz));
    const autoPtr<structureModel> s
    (
        structureModel::New(makeDict("structureModel CSM;"), m)
    );
    auto msg = [&](const std::string& text)
    {
        return errorMessage
        (
            [&]{ agglomerateFragmentation(makeDict(text), s(), 2200); }
        );
    };
    EXPECT_NE(msg("mode erode; direction extensional; gap 0; tries 6;"
        " spin conserveL;").find("erosion"), std::string::npos);
    EXPECT_NE(msg("mode beta; direction extensional; gap 0; tries 6;"
        " spin conserveL;").find("betaAlpha"), std::string::npos);
    // The tries: required, 1-20
    for (const char* tries : {"", " tries 0;", " tries 21;"})
    {
        EXPECT_NE(msg(std::string("mode erosion; direction extensional;"
            " gap 0; spin conserveL;") + tries).find("tries"),
            std::string::npos) << tries;
    }
    EXPECT_NE(msg(erosion + " betaAlpha 0.5;").find("Unknown entry"),
        std::string::npos);
    EXPECT_NE(msg("mode erosion; direction extensional; gap 2;"
        " tries 6; spin conserveL;").find("gap"), std::string::npos);
}


// ************************************************************************* //
