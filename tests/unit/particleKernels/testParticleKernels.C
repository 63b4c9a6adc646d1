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
    Unit tests of the fluid-particle kernels (doc/models.md 8, 9; checks
    S4-S8 of 12.2) and the keyed random numbers.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "../testHelpers.H"
#include "particleKernels.H"
#include "keyedRandom.H"
#include "unitConversion.H"

namespace Foam
{

using namespace particleKernels;

// * * * * * * * * * * * * * * * Random numbers  * * * * * * * * * * * * * * //

TEST(KeyedRandom, SameKeySameStreamOtherKeyOther)
{
    keyedRandom a(1, 3, 0, 17, 42, 0.25), b(1, 3, 0, 17, 42, 0.25);
    keyedRandom c(1, 3, 0, 18, 42, 0.25), e(1, 3, 0, 17, 42, 0.5);
    int same = 0;
    for (int i = 0; i < 100; ++i)
    {
        const scalar x = a.sample01();
        EXPECT_EQ(x, b.sample01());
        same += (x == c.sample01()) + (x == e.sample01());
    }
    EXPECT_EQ(same, 0);
}

// Moments of the normal samples: mean 0, variance 1, kurtosis 3
TEST(KeyedRandom, NormalMoments)
{
    const label N = 400000;
    scalar s1 = 0, s2 = 0, s4 = 0;
    for (label k = 0; k < N/4; ++k)
    {
        keyedRandom r(7, 1, 0, k, 5, 0.0);
        for (int i = 0; i < 4; ++i)
        {
            const scalar x = r.GaussNormal();
            s1 += x; s2 += x*x; s4 += x*x*x*x;
        }
    }
    const scalar mean = s1/N, var = s2/N - mean*mean;
    EXPECT_LT(mag(mean), 4/sqrt(scalar(N)));
    EXPECT_LT(mag(var - 1), 4*sqrt(2.0/N));
    EXPECT_LT(mag(s4/N - 3), 4*sqrt(96.0/N));
}


// * * * * * * * * * * * * * * * * * Drag  * * * * * * * * * * * * * * * * * //

// S4: Stokes limit and a hand value; the tau_p of the channel particles
TEST(Drag, SchillerNaumann)
{
    EXPECT_DOUBLE_EQ(SchillerNaumannFactor(0), 1.0);
    EXPECT_NEAR(SchillerNaumannFactor(10), 1 + 0.15*4.8641, 1e-4);
    EXPECT_NEAR(SchillerNaumannFactor(2000), 0.44*2000/24.0, 1e-12);
    const scalar tauP = 2200*sqr(12e-6)/(18*1.845e-5);
    EXPECT_NEAR(tauP, 9.54e-4, 0.005e-4);
}


// * * * * * * * * * * * * * * * * * Lift  * * * * * * * * * * * * * * * * * //

// S6: small-Re limit (pi/8) rho d^3 Omega ^ u_s; zero without Omega
TEST(Lift, RotationLiftLimits)
{
    const scalar d = 12e-6, rho = 1.2, mu = 1.8e-5;
    const vector Us(1e-3, 0, 0), Omega(0, 0, 50);
    const vector RK = pi/8*rho*pow3(d)*(Omega ^ Us);
    EXPECT_LT
    (
        mag(rotationLift(Us, Omega, d, rho, mu, true) - RK),
        1e-14*mag(RK)
    );
    // Re_p = 8e-4, Re_R = 4.8e-7: C_RL -> Re_R/Re_p within 1e-3
    EXPECT_LT
    (
        mag(rotationLift(Us, Omega, d, rho, mu) - RK),
        1e-3*mag(RK)
    );
    EXPECT_EQ(mag(rotationLift(Us, vector::zero, d, rho, mu)), 0);

    // Large Re_R Re_p: C_RL -> 0.45, F = (pi/8) rho d^2 0.45|u_s| ...
    const scalar D = 1e-3;
    const vector Us2(10, 0, 0), Om2(0, 0, 1e4);
    const scalar Rep = rho*10*D/mu, ReR = rho*1e4*D*D/mu;
    const scalar CRL = 0.45 + (ReR/Rep - 0.45)
       *exp(-0.05684*pow(ReR, 0.4)*pow(Rep, 0.3));
    const vector F2 = pi/8*rho*D*D*CRL*10*(Om2 ^ Us2)/1e4;
    EXPECT_LT(mag(rotationLift(Us2, Om2, D, rho, mu) - F2), 1e-12*mag(F2));
}


// * * * * * * * * * * * * * * * * Rotation  * * * * * * * * * * * * * * * * //

namespace
{

// The fluid torque on a spinning sphere, (rho/2)(d/2)^5 C_R |Omega| Omega
// (AB16 Eqs. 11-12): the oracle of the spin update
vector fluidTorque
(
    const vector& Omega,
    const scalar d,
    const scalar rho,
    const scalar mu
)
{
    const scalar ReR = rotationalReynolds(Omega, d, rho, mu);
    if (ReR <= 0)
    {
        return Zero;
    }
    return 0.5*rho*pow5(0.5*d)*torqueCoefficient(ReR)*mag(Omega)*Omega;
}

} // End anonymous namespace

// S7: Stokes torque, branch jump at Re_R = 32 below 0.2 %
TEST(Rotation, TorqueBranches)
{
    const scalar d = 12e-6, rho = 1.2, mu = 1.8e-5;
    const vector Omega(0, 0, 300);
    const vector T = fluidTorque(Omega, d, rho, mu);
    EXPECT_LT(mag(T - pi*mu*pow3(d)*Omega), 1e-14*mag(T));

    const scalar below = torqueCoefficient(32);
    const scalar above = torqueCoefficient(32*(1 + 1e-12));
    EXPECT_NEAR(below, 2*pi, 1e-12);
    EXPECT_LT(mag(above/below - 1), 2e-3);
    EXPECT_GT(mag(above/below - 1), 1e-3);
    EXPECT_NEAR(torqueCoefficient(100), 12.9/10 + 1.284, 1e-12);
}

// S7: spin relaxes to w/2 with tau = rho_p d^2/(60 mu); the update is
// exact (two half steps = one step) and its initial rate is T/I
TEST(Rotation, SpinUpdateExact)
{
    const scalar d = 12e-6, rhoP = 2200, mu = 1.845e-5;
    const scalar tau = spinTimeScale(rhoP, d, mu, 0);
    EXPECT_NEAR(tau, rhoP*d*d/(60*mu), 1e-18);
    EXPECT_NEAR(tau, 0.3*rhoP*d*d/(18*mu), 1e-15);

    const vector w(0, 0, -2000), om0(100, 0, 400);
    const scalar dt = 1e-4;
    const vector one = spinUpdate(om0, w, dt, tau);
    const vector two = spinUpdate(spinUpdate(om0, w, dt/2, tau), w, dt/2, tau);
    EXPECT_LT(mag(one - two), 1e-12*mag(one));
    const vector expect = 0.5*w + (om0 - 0.5*w)*exp(-dt/tau);
    EXPECT_LT(mag(one - expect), 1e-12*mag(expect));

    // I domega/dt = T at t = 0
    const scalar h = 1e-10*tau;
    const vector rate = (spinUpdate(om0, w, h, tau) - om0)/h;
    const scalar I = rhoP*pi*pow(d, 5)/60;
    const vector T = fluidTorque(0.5*w - om0, d, 1.2, mu);
    EXPECT_LT(mag(I*rate - T), 1e-5*mag(T));
    // Above Re_R = 32 (Dennis, Singh & Ingham) the torque exceeds the
    // Stokes torque, so the spin relaxes faster: I domega/dt = T again
    const scalar dBig = 1e-3, rhoF = 1.2;
    const vector Om(0, 0, 2000);
    const scalar ReR = rotationalReynolds(Om, dBig, rhoF, mu);
    ASSERT_GT(ReR, 100);
    const scalar tauBig = spinTimeScale(rhoP, dBig, mu, ReR);
    EXPECT_LT(tauBig, rhoP*dBig*dBig/(60*mu));
    const vector om1(0.5*vector(0, 0, 1000) - Om);
    const scalar hBig = 1e-10*tauBig;
    const vector rateBig =
        (spinUpdate(om1, vector(0, 0, 1000), hBig, tauBig) - om1)/hBig;
    const vector TBig = fluidTorque(Om, dBig, rhoF, mu);
    EXPECT_LT
    (
        mag(rhoP*pi*pow(dBig, 5)/60*rateBig - TBig),
        1e-5*mag(TBig)
    );
}


// * * * * * * * * * * * * * * * SGS velocity  * * * * * * * * * * * * * * * //

// S8: stationary variance 1 per component (u_sgs = sigma w), correlation
// exp(-lag/tau_par) along the slip and exp(-lag/tau_perp) across
TEST(PozorskiApte, StationaryVarianceAndCorrelation)
{
    const label N = 20000;
    const scalar sigma = 0.2, tauL = 1e-3, betaC = 1;
    const vector Urs(0.3, 0, 0);
    scalar tauPar, tauPerp;
    PozorskiApteTimeScales(tauL, 0.3, sigma, betaC, tauPar, tauPerp);
    EXPECT_NEAR(tauPar, tauL/sqrt(1 + 2.25), 1e-15);
    EXPECT_NEAR(tauPerp, tauL/sqrt(1 + 9.0), 1e-15);

    const scalar dt = 0.1*tauPerp;
    const label nLag = 8;       // lag = 0.8 tauPerp
    scalar var[3] = {0, 0, 0}, cov[3] = {0, 0, 0};
    for (label k = 0; k < N; ++k)
    {
        // start away from equilibrium (w = 0), relax for 30 tau_par
        vector w(Zero);
        label step = 0;
        for (; step < 300; ++step)
        {
            keyedRandom r(3, 3, 0, k, step, 0.0);
            const vector xi(r.GaussNormal(), r.GaussNormal(), r.GaussNormal());
            w = PozorskiApteStep(w, Urs, sigma, tauL, betaC, dt, xi);
        }
        const vector w0(w);
        for (label i = 0; i < nLag; ++i, ++step)
        {
            keyedRandom r(3, 3, 0, k, step, 0.0);
            const vector xi(r.GaussNormal(), r.GaussNormal(), r.GaussNormal());
            w = PozorskiApteStep(w, Urs, sigma, tauL, betaC, dt, xi);
        }
        for (direction c = 0; c < 3; ++c)
        {
            var[c] += sqr(w0[c]);
            cov[c] += w0[c]*w[c];
        }
    }
    const scalar lag = nLag*dt;
    for (direction c = 0; c < 3; ++c)
    {
        EXPECT_NEAR(var[c]/N, 1.0, 0.04) << "component " << int(c);
        const scalar tau = (c == 0 ? tauPar : tauPerp);
        EXPECT_NEAR(cov[c]/var[c], exp(-lag/tau), 0.025)
            << "component " << int(c);
    }
}


} // End namespace Foam

// ************************************************************************* //
