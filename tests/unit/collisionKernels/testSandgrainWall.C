/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           | www.openfoam.com
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2026 agglomerationHardSphere project contributors
-------------------------------------------------------------------------------
License
    This file is part of the agglomerationHardSphere extension of OpenFOAM.

    It is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.

Description
    Unit tests of the sandgrain rough-wall model (doc/models.md 7.2; check
    S3 of 12.2): the tilt distribution, the shadow modes, multiple impacts
    and the smooth limit.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "../testHelpers.H"
#include "keyedRandom.H"
#include "sandgrainWall.H"
#include "smoothWall.H"
#include "unitConversion.H"

namespace Foam
{

// * * * * * * * * * * * * * * * Sandgrain wall  * * * * * * * * * * * * * * //

namespace
{
    const collisionCoefficients roughCoeffs(0.9, 0.3, 0.5, 0.4);
}

// S3: sigma_gamma for Rz = 10 um, C = 3 (doc/models.md 7.2)
TEST(SandgrainWall, SigmaGammaValues)
{
    const sandgrainWall w1(roughCoeffs, 10e-6, 3);
    EXPECT_NEAR(radToDeg(w1.sigmaGamma(12e-6)), 9.0, 0.05);
    EXPECT_NEAR(radToDeg(w1.sigmaGamma(4e-6)), 15.2, 0.05);
    const sandgrainWall w2(roughCoeffs, 10e-6, 3, 2);
    EXPECT_NEAR(radToDeg(w2.sigmaGamma(12e-6)), 12.9, 0.05);
    EXPECT_NEAR(radToDeg(w2.sigmaGamma(4e-6)), 18.8, 0.05);
    const sandgrainWall w3(roughCoeffs, 10e-6, 3, 1, degToRad(4.0));
    EXPECT_NEAR(radToDeg(w3.sigmaGamma(12e-6)), 4.0, 1e-12);
}

// Normal incidence: no facet is shadowed, so the sampled tilts have the
// requested standard deviation (2 %) and zero mean
TEST(SandgrainWall, TiltStandardDeviation)
{
    const sandgrainWall w(roughCoeffs, 10e-6, 3);
    const scalar sigma = w.sigmaGamma(12e-6);
    const vector nw(0, 1, 0), u(0, -1, 0);
    const label N = 100000;
    scalar s1 = 0, s2 = 0, t1 = 0, t2 = 0;
    for (label k = 0; k < N; ++k)
    {
        keyedRandom r(11, 2, 0, k, 0, 2.0);
        scalar g1, g2;
        const vector n = w.sampleNormal(nw, u, 12e-6, r, g1, g2);
        ASSERT_LT(u & n, 0);
        s1 += g1; s2 += g1*g1; t1 += g2; t2 += g2*g2;
    }
    EXPECT_LT(mag(sqrt(s2/N)/sigma - 1), 0.02);
    EXPECT_LT(mag(sqrt(t2/N)/sigma - 1), 0.02);
    EXPECT_LT(mag(s1/N), 4*sigma/sqrt(scalar(N)));
}

// Grazing incidence: no accepted facet faces away from the particle (both
// shadow modes); after the multiple-impact loop u+.n_w > 0 always (S3)
TEST(SandgrainWall, ShadowAndMultipleImpacts)
{
    const vector nw(0, 1, 0);
    for (const auto mode :
        {sandgrainWall::SHADOW_REJECT, sandgrainWall::SHADOW_WEIGHTED})
    {
        const sandgrainWall w(roughCoeffs, 10e-6, 3, 1, -1, mode);
        label nTilted = 0;
        for (label k = 0; k < 20000; ++k)
        {
            const scalar alpha = degToRad(0.5 + 10.0*(k % 20)/20.0);
            const vector u(cos(alpha), -sin(alpha), 0.1*sin(0.3*k));
            keyedRandom r(5, 2, 0, k, 0, 2.0);
            scalar g1, g2;
            const vector n = w.sampleNormal(nw, u, 4e-6, r, g1, g2);
            ASSERT_LT(u & n, 0);
            nTilted += (g1 != 0);

            vector U(u), omega(0, 0, 1e4*sin(1.0*k));
            keyedRandom r2(5, 2, 1, k, 0, 2.0);
            w.impact(nw, vector::zero, 4e-6, U, omega, r2);
            ASSERT_GT(U & nw, 0) << "impact " << k;
        }
        EXPECT_GT(nTilted, 19000);
    }
}

// sigma_gamma -> 0 reproduces the smooth impact with the rough coefficients
TEST(SandgrainWall, ZeroTiltIsSmoothImpact)
{
    const sandgrainWall w(roughCoeffs, 10e-6, 3, 1, 0.0);
    const vector nw(0, 0, 1);
    for (const scalar ut : {0.5, 1.0, 2.5, 3.0, 8.0})
    {
        vector U1(ut, 0.3, -1), om1(100, -50, 20), U2(U1), om2(om1);
        keyedRandom r(1, 2, 0, 0, 0, 2.0);
        w.impact(nw, vector::zero, 12e-6, U1, om1, r);
        smoothWall::smoothImpact(roughCoeffs, nw, vector::zero, 12e-6, U2, om2);
        EXPECT_LT(mag(U1 - U2), 1e-15);
        EXPECT_LT(mag(om1 - om2), 1e-9);
    }
}


} // End namespace Foam

// ************************************************************************* //
