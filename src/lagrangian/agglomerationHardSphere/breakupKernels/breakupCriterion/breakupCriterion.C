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
    const structureModel& structure,
    const scalar en
)
:
    rho0_(material.rho0()),
    material_(material),
    en_(en),
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

Foam::scalar Foam::breakupCriterion::impactBonds(const label N) const
{
    // One primary freed: the bonds cut (doc/breakup.md 2) for small N, half
    // the coordination number of a surface primary otherwise [rec]
    return N <= 4 ? scalar(N - 1) : 0.5*strength_.coordination(N);
}


Foam::scalar Foam::breakupCriterion::impactBondEnergy
(
    const label N,
    const scalar dp,
    const scalar vn
) const
{
    return
        impactBonds(N)
       *material_.vanDerWaalsEnergy(en_, dp, rho0_, dp, rho0_, vn);
}


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
    if (stresses_.on(breakupStresses::WALL_IMPACT) && L.wallImpactSpeed > 0)
    {
        const scalar vn = L.wallImpactSpeed;
        const scalar M = s.mass();
        const scalar E =
            impactBondEnergy(s.nPrimary, s.primaryDiameter(rho0_), vn);
        const scalar r =
            E > 0 ? stresses_.Cw()*0.5*M*vn*vn/E : GREAT;
        if (v.mechanism < 0 || r > v.ratio)
        {
            v.mechanism = breakupStresses::WALL_IMPACT;
            v.ratio = r;
        }
    }
    return v;
}


// ************************************************************************* //
