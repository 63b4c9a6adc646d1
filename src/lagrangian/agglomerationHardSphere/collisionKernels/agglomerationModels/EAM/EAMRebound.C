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

\*---------------------------------------------------------------------------*/

#include "EAM.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::agglomerationModels::EAM::reboundWithCohesion
(
    const binaryCollision& pair,
    const cohesionEnergies& e,
    collisionOutcome& outcome
) const
{
    // The factors of the normal, tangential and spin velocities and the
    // branch (AB16 Eqs. 55-59; Alletto: Eqs. 60-64)
    scalar kn = 1;
    scalar kt = 1;
    scalar komega = 1;
    if (e.kn2 > 0)
    {
        outcome.branch = branchCode_[CASE_I];
        kn = std::sqrt(e.kn2);
    }
    else if (e.kt2 >= 0)
    {
        outcome.branch = branchCode_[CASE_II];
        kn = 0;
        kt = std::sqrt(e.kt2);
    }
    else
    {
        // Only reached by alletto2014
        outcome.branch = branchCode_[CASE_III_REBOUND];
        kn = 0;
        kt = 0;
        komega = spinFactor(e, outcome);
    }

    // AB16 Eq. 52
    const vector& n = pair.n();
    const scalar mHat = pair.mHat();
    const vector fAg = -(1 - kn)*e.wn*n - (1 - kt)*e.wt*e.tE;

    // AB16 Eqs. 47-48: centres only, spins scaled by k_omega
    outcome.p1.U -= (mHat/pair.m1())*fAg;
    outcome.p2.U += (mHat/pair.m2())*fAg;
    outcome.p1.omega *= komega;
    outcome.p2.omega *= komega;

    // doc/models.md 5.1, A6: orbital angular momentum change (non-zero
    // in case II)
    outcome.values[DELTA_L] = mag(mHat*pair.ell()*(n ^ fAg));
}


Foam::scalar Foam::agglomerationModels::EAM::spinFactor
(
    const cohesionEnergies& e,
    collisionOutcome& outcome
)
{
    // Alletto's case-III rebound: the energy the normal and tangential
    // motion cannot give is taken from the spins
    if (!(e.ErotPlus > 0))
    {
        return 0;
    }
    const scalar X = e.dE - e.En - e.Et;

    // AB16 Eq. 64; beta of Eq. 62 cancels
    const scalar komega2 = 1 - X/e.ErotPlus;
    outcome.values[KOMEGA2] = komega2;
    outcome.setFlag(SPIN_CLAMPED, komega2 < 0);
    if (komega2 < 0)
    {
        return 0;
    }
    return std::sqrt(komega2);
}


// ************************************************************************* //
