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

#include "agglomerationModel.H"
#include "hardSphereInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(agglomerationModel, 0);
    defineRunTimeSelectionTable(agglomerationModel, dictionary);
}


const Foam::Enum<Foam::agglomerationModel::impactVelocityType>
Foam::agglomerationModel::impactVelocityTypeNames
({
    { impactVelocityType::NORMAL, "normal" },
    { impactVelocityType::FULL, "full" },
});


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::agglomerationModel::checkCoeffs(const wordList& valid) const
{
    if (hasCoeffs_)
    {
        hardSphereInput::checkKeys(coeffDict_, valid);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerationModel::agglomerationModel
(
    const word& type,
    const dictionary& dict,
    const hardSphereMaterial& material,
    const collisionCoefficients& coeffs
)
:
    coeffDict_(dict.optionalSubDict(type + "Coeffs")),
    hasCoeffs_(dict.isDict(type + "Coeffs")),
    material_(material),
    coeffs_(coeffs)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::agglomerationModel::reboundWithoutCohesion
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    const scalar fna = pair.fna(coeffs_.en());

    bool isSticking = true;
    const vector fHat = pair.impulse(coeffs_, fna, fna, isSticking);

    outcome.type =
        isSticking ? collisionOutcome::STICKING : collisionOutcome::SLIDING;
    outcome.agglomerates = false;
    outcome.fna = fna;
    outcome.p1 = p1;
    outcome.p2 = p2;
    pair.apply(fHat, outcome.p1, outcome.p2);
}


Foam::agglomerationModel::impactVelocityType
Foam::agglomerationModel::readImpactVelocity() const
{
    return impactVelocityTypeNames.getOrDefault
    (
        "impactVelocity",
        coeffDict_,
        impactVelocityType::NORMAL
    );
}


Foam::scalar Foam::agglomerationModel::impactSpeed
(
    const impactVelocityType option,
    const binaryCollision& pair
)
{
    // doc/models.md 2.2, A1: v = |u_n| (head-on assumption) or |u_r|
    return
        option == impactVelocityType::NORMAL
      ? -pair.un()
      : mag(pair.ur());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::agglomerationModel::noNames()
{
    static const wordList none;
    return none;
}


const Foam::wordList& Foam::agglomerationModel::valueNames() const
{
    return noNames();
}


const Foam::wordList& Foam::agglomerationModel::counterNames() const
{
    return noNames();
}


const Foam::wordList& Foam::agglomerationModel::sumNames() const
{
    return noNames();
}


void Foam::agglomerationModel::count
(
    const collisionOutcome&,
    UList<label>&,
    UList<scalar>&
) const
{}


Foam::label Foam::agglomerationModel::branchCode(const word& name) const
{
    const label code = branchNames().find(name);
    if (code < 0)
    {
        FatalErrorInFunction
            << "Agglomeration model " << type() << " has no branch "
            << name << "; its branches: " << branchNames()
            << exit(FatalError);
    }
    return code;
}


void Foam::agglomerationModel::writeOptions(Ostream& os) const
{
    os.writeEntry("agglomerationModel", type());
}


// ************************************************************************* //
