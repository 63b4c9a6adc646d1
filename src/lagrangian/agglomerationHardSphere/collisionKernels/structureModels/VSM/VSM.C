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

#include "VSM.H"
#include "CSM.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace structureModels
{
    defineTypeNameAndDebug(VSM, 0);
    addToRunTimeSelectionTable(structureModel, VSM, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModels::VSM::VSM
(
    const dictionary& dict,
    const hardSphereMaterial& material
)
:
    structureModel(typeName, dict, material)
{
    checkCoeffs(wordList());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::structureModels::VSM::porosity(const label nPrimary) const
{
    return 1 - structureModels::CSM::defaultPackingFraction(nPrimary);
}


// ************************************************************************* //
