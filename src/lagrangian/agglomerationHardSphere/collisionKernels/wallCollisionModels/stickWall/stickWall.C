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

#include "stickWall.H"
#include "hardSphereInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(stickWall, 0);
    addToRunTimeSelectionTable(wallCollisionModel, stickWall, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stickWall::stickWall(const dictionary& dict)
:
    wallCollisionModel(dict, typeName, true)
{
    // No coefficients: an empty (or absent) stickCoeffs
    hardSphereInput::checkKeys(coeffDict_, wordList());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::stickWall::impact
(
    const vector& nw,
    const vector& Uw,
    const scalar d,
    vector& U,
    vector& omega,
    keyedRandom&
) const
{
    FatalErrorInFunction
        << "A particle deposits at a stick wall: no impact to resolve"
        << abort(FatalError);
    return false;
}


// ************************************************************************* //
