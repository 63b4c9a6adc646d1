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

#include "CollisionResolver.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class ParcelType>
const Foam::Enum
<
    typename Foam::CollisionResolver<ParcelType>::overlapTreatmentType
>
Foam::CollisionResolver<ParcelType>::overlapTreatmentNames
({
    { overlapTreatmentType::OVERLAP_NONE, "none" },
    { overlapTreatmentType::OVERLAP_SEPARATE, "separate" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::CollisionResolver<ParcelType>::CollisionResolver
(
    const dictionary& dict,
    const hardSphereCollisionKernel& kernel
)
:
    kernel_(kernel),
    overlapTreatment_
    (
        overlapTreatmentNames.getOrDefault
        (
            "overlapTreatment", dict, OVERLAP_NONE
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
Foam::wordList Foam::CollisionResolver<ParcelType>::keys()
{
    return wordList({"collisionResponse", "overlapTreatment"});
}


template<class ParcelType>
void Foam::CollisionResolver<ParcelType>::write(Ostream& os) const
{
    os  << "collisionResponse " << this->type() << ", overlapTreatment "
        << overlapTreatmentNames[overlapTreatment_];
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

#include "CollisionResolverNew.C"

// ************************************************************************* //
