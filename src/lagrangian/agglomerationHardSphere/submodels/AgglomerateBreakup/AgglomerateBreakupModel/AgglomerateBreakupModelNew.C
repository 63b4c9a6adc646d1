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

#include "AgglomerateBreakupModel.H"
#include "breakupKernel.H"

// The driver of the family: declared here, since the parcel's headers
// include this file; complete where the cloud (HardSphereCloud.C) and its
// submodels instantiate the selector
namespace Foam
{
    template<class CloudType> class AgglomerateBreakup;
}

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::AgglomerateBreakupModel<CloudType>>
Foam::AgglomerateBreakupModel<CloudType>::New
(
    const dictionary& dict,
    CloudType& owner
)
{
    // Absent: none, the paper's model (no break-up)
    const word modelType(dict.getOrDefault<word>("breakupModel", "none"));

    // A model of the family: the one driver runs its kernel
    const wordList models(breakupKernel::types());
    if (models.found(modelType))
    {
        return autoPtr<AgglomerateBreakupModel<CloudType>>
        (
            new AgglomerateBreakup<CloudType>(dict, owner, modelType)
        );
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        wordList valid(dictionaryConstructorTablePtr_->sortedToc());
        valid.append(models);
        FatalIOErrorInFunction(dict)
            << "Unknown breakupModel " << modelType << nl << nl
            << "Valid breakupModel types: " << valid
            << exit(FatalIOError);
    }

    return autoPtr<AgglomerateBreakupModel<CloudType>>
    (
        cstrIter()(dict, owner)
    );
}


// ************************************************************************* //
