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

Description
    AgglomerateParcel's storage: every parcel of one type in one
    parcelPool (operator new and delete of the class).

\*---------------------------------------------------------------------------*/

#include "AgglomerateParcel.H"

// * * * * * * * * * * * * * * * * * Storage  * * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::parcelPool& Foam::AgglomerateParcel<ParcelType>::pool()
{
    // Never destroyed: a parcel may be deleted during static destruction
    static parcelPool* p =
        new parcelPool(sizeof(AgglomerateParcel), alignof(AgglomerateParcel));
    return *p;
}


template<class ParcelType>
void* Foam::AgglomerateParcel<ParcelType>::operator new(std::size_t size)
{
    if (size != sizeof(AgglomerateParcel))
    {
        return ::operator new(size);
    }
    return pool().allocate();
}


template<class ParcelType>
void Foam::AgglomerateParcel<ParcelType>::operator delete
(
    void* p,
    std::size_t size
)
{
    if (size != sizeof(AgglomerateParcel))
    {
        ::operator delete(p);
        return;
    }
    pool().deallocate(p);
}


// ************************************************************************* //
