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

#include "breakupCriterion.H"
#include "hardSphereInput.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::breakupCriterion::breakupCriterion
(
    const dictionary& dict,
    const hardSphereMaterial& material,
    const structureModel& structure
)
:
    rho0_(material.rho0()),
    strength_(dict.subDict("strength"), material, structure),
    stresses_(dict.subDict("stresses"))
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::breakupCriterion::dissipation
(
    const scalar nu,
    const scalar nut,
    const symmTensor& S
)
{
    // doc/breakup.md 1.1 [rec]: 2 nu S:S + nu_t |S|^2 = (nu + nu_t) 2 S:S
    return (nu + nut)*2*(S && S);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::breakupCriterion::verdict Foam::breakupCriterion::check
(
    const hardSphereState& s,
    const breakupStresses::load& L
) const
{
    verdict v{-1, 0, 0};
    if (s.nPrimary < 2)
    {
        return v;
    }

    v.sigmaT =
        strength_.tensileStrength(s.nPrimary, s.primaryDiameter(rho0_));
    const FixedList<scalar, 3> sigma(stresses_.stresses(L, s.d, s.rho));
    forAll(sigma, m)
    {
        if (stresses_.on(breakupStresses::mechanismType(m)))
        {
            const scalar r = sigma[m]/v.sigmaT;
            if (v.mechanism < 0 || r > v.ratio)
            {
                v.mechanism = m;
                v.ratio = r;
            }
        }
    }
    return v;
}


// ************************************************************************* //
