/*---------------------------------------------------------------------------*\
    Unit tests of the mesh-free pieces of the hard-sphere cloud: the
    contact-time quadratic (doc/models.md 6.3) and the smooth-wall impact
    (doc/models.md 7.1), against hand-computed values.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "pairContact.H"
#include "smoothWall.H"

using namespace Foam;

// Head-on: gap g, closing displacement v*dt over the step: s = g/(v dt)
TEST(PairContact, HeadOnContactTime)
{
    const scalar R = 12e-6, g = 1e-6, dx = 3e-6;
    pairContact pc;
    ASSERT_TRUE
    (
        pc.find
        (
            vector(0, 0, 0), vector(0.5*dx, 0, 0),
            vector(R + g, 0, 0), vector(-0.5*dx, 0, 0), R
        )
    );
    EXPECT_NEAR(pc.s, g/dx, 1e-14);
    EXPECT_FALSE(pc.overlapStart);
}

// Too far for this step; receding; missing sideways
TEST(PairContact, NoContact)
{
    const scalar R = 12e-6;
    pairContact pc;
    EXPECT_FALSE
    (
        pc.find(vector(0, 0, 0), vector(1e-6, 0, 0),
                vector(R + 3e-6, 0, 0), vector(-1e-6, 0, 0), R)
    );
    EXPECT_FALSE
    (
        pc.find(vector(0, 0, 0), vector(-1e-6, 0, 0),
                vector(R + 1e-7, 0, 0), vector(1e-6, 0, 0), R)
    );
    EXPECT_FALSE
    (
        pc.find(vector(0, 0, 0), vector(1e-5, 0, 0),
                vector(2e-5, 1.01*R, 0), vector(-1e-5, 0, 0), R)
    );
}

// Oblique: impact parameter b, relative displacement along -x:
// contact when (X - s w)^2 + b^2 = R^2
TEST(PairContact, ObliqueRoot)
{
    const scalar R = 12e-6, b = 6e-6, X = 20e-6, w = 20e-6;
    pairContact pc;
    ASSERT_TRUE
    (
        pc.find(vector(0, 0, 0), vector(Zero),
                vector(X, b, 0), vector(-w, 0, 0), R)
    );
    EXPECT_NEAR(pc.s, (X - Foam::sqrt(R*R - b*b))/w, 1e-13);
}

// Overlapping at step start: contact at s = 0 only if approaching
TEST(PairContact, OverlapStart)
{
    const scalar R = 12e-6;
    pairContact pc;
    ASSERT_TRUE
    (
        pc.find(vector(0, 0, 0), vector(1e-9, 0, 0),
                vector(0.9*R, 0, 0), vector(Zero), R)
    );
    EXPECT_EQ(pc.s, 0);
    EXPECT_TRUE(pc.overlapStart);
    EXPECT_FALSE
    (
        pc.find(vector(0, 0, 0), vector(-1e-9, 0, 0),
                vector(0.9*R, 0, 0), vector(Zero), R)
    );
}

// Sticking impact: u_n -> -e_n u_n, contact slip -> -e_t slip
TEST(SmoothWall, StickingReversesSlip)
{
    const collisionCoefficients c(0.8, 0.4, 0.3, 0.15);
    const vector n(0, 1, 0);
    const scalar d = 12e-6;
    vector U(1e-3, -10e-3, 0), omega(0, 0, 0);
    const vector uc0(U.x(), 0, 0);
    EXPECT_TRUE(smoothWall::smoothImpact(c, n, Zero, d, U, omega));
    EXPECT_NEAR(U.y(), 0.8*10e-3, 1e-15);
    const vector uc(U - (U & n)*n - 0.5*d*(omega ^ n));
    EXPECT_NEAR(uc.x(), -0.4*uc0.x(), 1e-15);
    // angular momentum about the contact point is conserved:
    // I omega_z - m r U_x, I = 0.1 m d^2 -> 0.1 d^2 omega_z - 0.5 d U_x
    EXPECT_NEAR
    (
        0.1*d*d*omega.z() - 0.5*d*U.x(), -0.5*d*1e-3, 1e-20
    );
}

// Sliding impact: tangential impulse muKin (1 + e_n)|u_n| against the slip
TEST(SmoothWall, SlidingImpulse)
{
    const collisionCoefficients c(0.8, 0.4, 0.3, 0.15);
    const vector n(0, 1, 0);
    vector U(30e-3, -10e-3, 0), omega(0, 0, 0);
    EXPECT_FALSE(smoothWall::smoothImpact(c, n, Zero, 12e-6, U, omega));
    EXPECT_NEAR(U.x(), 30e-3 - 0.15*1.8*10e-3, 1e-15);
    EXPECT_NEAR(U.y(), 8e-3, 1e-15);
}

// A moving wall: the impact is computed in the wall frame
TEST(SmoothWall, MovingWallFrame)
{
    const collisionCoefficients c(1, 1, 0, 0);
    const vector n(0, -1, 0), Uw(0.1, 0, 0);
    vector U(0.1, 2e-3, 0), omega(Zero);
    smoothWall::smoothImpact(c, n, Uw, 12e-6, U, omega);
    EXPECT_NEAR(U.x(), 0.1, 1e-15);
    EXPECT_NEAR(U.y(), -2e-3, 1e-15);
}
