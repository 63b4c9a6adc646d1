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

#include "agglomerateStrength.H"
#include "hardSphereInput.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::agglomerateStrength::nSmall;

const Foam::Enum<Foam::agglomerateStrength::coordinationType>
Foam::agglomerateStrength::coordinationTypeNames
({
    { coordinationType::EXACT_SMALL_RUMPF, "exactSmallRumpf" },
    { coordinationType::RUMPF, "rumpf" },
    { coordinationType::POROSITY_POWER, "porosityPower" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerateStrength::agglomerateStrength
(
    const dictionary& dict,
    const hardSphereMaterial& material,
    const structureModel& structure
)
:
    material_(material),
    structure_(structure),
    cR_
    (
        hardSphereInput::getInRange
        (
            dict,
            "rumpfPrefactor",
            hardSphereInput::closed(1),
            hardSphereInput::closed(1.125)
        )
    ),
    coordination_(coordinationTypeNames.get("coordination", dict))
{
    hardSphereInput::checkKeys(dict, {"rumpfPrefactor", "coordination"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::agglomerateStrength::coordination
(
    const label nPrimary
) const
{
    const scalar eps = structure_.porosity(nPrimary);
    if (coordination_ == coordinationType::POROSITY_POWER)
    {
        // [paper: S5]
        return 15*std::pow(1 - eps, 1.2);
    }
    // Rumpf's k eps = pi [paper: S4]
    return constant::mathematical::pi/eps;
}


Foam::scalar Foam::agglomerateStrength::tensileStrength
(
    const label nPrimary,
    const scalar dp
) const
{
    using constant::mathematical::pi;

    const scalar F = bondForce(dp);
    if
    (
        coordination_ == coordinationType::EXACT_SMALL_RUMPF
     && nPrimary <= nSmall
    )
    {
        // Weakest plane [rec]: n_b = N - 1 bonds hold one primary
        const scalar da = structure_.diameter(nPrimary, dp);
        return (nPrimary - 1)*F/(0.25*pi*da*da);
    }

    // Rumpf [paper: S4], prefactor c_R [paper: S5]
    const scalar eps = structure_.porosity(nPrimary);
    return cR_*(1 - eps)*coordination(nPrimary)*F/(pi*dp*dp);
}


void Foam::agglomerateStrength::write(Ostream& os) const
{
    os  << "strength: rumpfPrefactor " << cR_ << ", coordination "
        << coordinationTypeNames[coordination_];
}


// ************************************************************************* //
