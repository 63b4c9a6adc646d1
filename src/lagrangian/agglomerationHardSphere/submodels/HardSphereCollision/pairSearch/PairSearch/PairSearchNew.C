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

#include "PairSearch.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::autoPtr<Foam::PairSearch<ParcelType>>
Foam::PairSearch<ParcelType>::New
(
    const dictionary& dict,
    const polyMesh& mesh,
    const word& UName
)
{
    const word searchType
    (
        dict.getOrDefault<word>("pairSearch", "particleGrid")
    );
    if (searchType != "interactionLists" && dict.found("interactionDistance"))
    {
        FatalIOErrorInFunction(dict)
            << "interactionDistance is read by pairSearch interactionLists"
            << " only (pairSearch is " << searchType << ")"
            << exit(FatalIOError);
    }

    return New(searchType, dict, mesh, UName);
}


template<class ParcelType>
Foam::autoPtr<Foam::PairSearch<ParcelType>>
Foam::PairSearch<ParcelType>::New
(
    const word& searchType,
    const dictionary& dict,
    const polyMesh& mesh,
    const word& UName
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(searchType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "pairSearch " << searchType << " is not valid; valid"
            << " choices: " << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return autoPtr<PairSearch<ParcelType>>(cstrIter()(dict, mesh, UName));
}


// ************************************************************************* //
