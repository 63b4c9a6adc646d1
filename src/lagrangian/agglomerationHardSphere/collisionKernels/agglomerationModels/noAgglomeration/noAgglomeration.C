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

#include "noAgglomeration.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace agglomerationModels
{
    defineTypeNameAndDebug(noAgglomeration, 0);
    addToRunTimeSelectionTable
    (
        agglomerationModel,
        noAgglomeration,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerationModels::noAgglomeration::noAgglomeration
(
    const dictionary& dict,
    const hardSphereMaterial& material,
    const collisionCoefficients& coeffs
)
:
    agglomerationModel(typeName, dict, material, coeffs)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList&
Foam::agglomerationModels::noAgglomeration::branchNames() const
{
    static const wordList names({"rebound"});
    return names;
}


void Foam::agglomerationModels::noAgglomeration::collide
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    reboundWithoutCohesion(pair, p1, p2, outcome);
    outcome.branch = 0;
}


// ************************************************************************* //
