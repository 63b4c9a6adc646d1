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

#include "structureModel.H"
#include "hardSphereInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(structureModel, 0);
    defineRunTimeSelectionTable(structureModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::structureModel::checkCoeffs(const wordList& valid) const
{
    if (hasCoeffs_)
    {
        hardSphereInput::checkKeys(coeffDict_, valid);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModel::structureModel
(
    const word& type,
    const dictionary& dict,
    const hardSphereMaterial& material
)
:
    coeffDict_(dict.optionalSubDict(type + "Coeffs")),
    hasCoeffs_(dict.isDict(type + "Coeffs")),
    rho0_(material.rho0())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::structureModel::diameter
(
    const label nPrimary,
    const scalar d0
) const
{
    return d0*std::cbrt(nPrimary*rho0_/density(nPrimary));
}


void Foam::structureModel::form
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    const bool capSpin,
    collisionOutcome& outcome
) const
{
    const scalar m1 = pair.m1();
    const scalar m2 = pair.m2();
    const scalar mAg = m1 + m2;

    hardSphereState& ag = outcome.agglomerate;

    // AB16 Eqs. 80-81
    ag.U = (m1*p1.U + m2*p2.U)/mAg;
    ag.x = (m1*p1.x + m2*p2.x)/mAg;

    // doc/models.md 4.1, A11: integer bookkeeping of primaries
    ag.nPrimary = p1.nPrimary + p2.nPrimary;

    // AB16 Eqs. 82-84: effective density, diameter from mass conservation
    ag.rho = density(ag.nPrimary);
    ag.d =
        std::cbrt(6*mAg/(constant::mathematical::pi*ag.rho));

    // AB16 Eqs. 41, 85
    const vector L = pair.angularMomentum(p1, p2);
    const scalar Iag = 0.1*mAg*ag.d*ag.d;
    ag.omega = L/Iag;

    // doc/models.md 5.2, A7: kinetic energy change at formation
    const scalar KEbefore = p1.kineticEnergy() + p2.kineticEnergy();
    const scalar KEtrans = 0.5*mAg*magSqr(ag.U);
    scalar KErot = 0.5*Iag*magSqr(ag.omega);

    if (capSpin && KEtrans + KErot > KEbefore && KErot > 0)
    {
        const scalar allowed = max(KEbefore - KEtrans, scalar(0));
        ag.omega *= std::sqrt(allowed/KErot);
        KErot = 0.5*Iag*magSqr(ag.omega);
        outcome.spinCapped = true;
    }

    outcome.dKEformation = KEtrans + KErot - KEbefore;
}


// ************************************************************************* //
