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

#include "CloudCellOrder.H"
#include <algorithm>
#include <functional>
#include <new>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::label Foam::CloudCellOrder<CloudType>::defaultInterval = 20;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CloudCellOrder<CloudType>::CloudCellOrder
(
    const dictionary& solutionDict,
    const word& cloudName
)
:
    interval_
    (
        solutionDict.getOrDefault<label>("cellOrderInterval", defaultInterval)
    ),
    started_(false)
{
    if (interval_ < 0)
    {
        FatalIOErrorInFunction(solutionDict)
            << "cellOrderInterval = " << interval_ << " in cloud "
            << cloudName << ": it must be >= 0 (the number of time steps"
            << " between two sorts of the parcels into cell order; 0: off)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::CloudCellOrder<CloudType>::permutation
(
    const UList<parcelType*>& parcels,
    List<parcelType*>& slots,
    labelList& from
)
{
    const label n = parcels.size();

    // The new list order: by cell, the list order within a cell
    labelList cells(n);
    forAll(parcels, i)
    {
        cells[i] = parcels[i]->cell();
    }
    labelList order(identity(n));
    std::stable_sort
    (
        order.begin(), order.end(),
        [&cells](const label a, const label b) { return cells[a] < cells[b]; }
    );
    cells.clear();

    // The slots in address order: slot k receives the contents of
    // parcel order[k], which sits in slot from[k]
    labelList byAddress(identity(n));
    std::sort
    (
        byAddress.begin(), byAddress.end(),
        [&parcels](const label a, const label b)
        {
            return std::less<const parcelType*>()(parcels[a], parcels[b]);
        }
    );
    labelList slotOf(n);
    forAll(byAddress, k)
    {
        slotOf[byAddress[k]] = k;
    }
    from.setSize(n);
    forAll(order, k)
    {
        from[k] = slotOf[order[k]];
    }

    slots.setSize(n);
    forAll(byAddress, k)
    {
        slots[k] = parcels[byAddress[k]];
    }
}


template<class CloudType>
void Foam::CloudCellOrder<CloudType>::moveContents
(
    const UList<parcelType*>& slots,
    labelList& from
)
{
    // Along the cycles of the permutation, through one parcel-sized
    // buffer: a parcel is copied into its new slot, the old contents
    // destroyed in place
    typename std::aligned_storage
    <
        sizeof(parcelType), alignof(parcelType)
    >::type buffer;

    forAll(from, k)
    {
        if (from[k] < 0 || from[k] == k)
        {
            continue;
        }

        parcelType* saved = ::new (&buffer) parcelType(*slots[k]);

        label j = k;
        while (true)
        {
            const label src = from[j];
            from[j] = -1;
            slots[j]->~parcelType();
            if (src == k)
            {
                ::new (slots[j]) parcelType(*saved);
                break;
            }
            ::new (slots[j]) parcelType(*slots[src]);
            j = src;
        }

        saved->~parcelType();
    }
}


template<class CloudType>
void Foam::CloudCellOrder<CloudType>::sort(CloudType& cloud)
{
    const label n = cloud.size();
    if (n < 2)
    {
        return;
    }

    // The parcels in list order
    List<parcelType*> parcels(n);
    {
        label i = 0;
        for (parcelType& p : cloud)
        {
            parcels[i++] = &p;
        }
    }

    List<parcelType*> slots;
    labelList from;
    permutation(parcels, slots, from);

    // Unlink every parcel (nothing is freed), move the contents, re-link
    // in the new order
    for (parcelType* p : parcels)
    {
        cloud.remove(p);
    }
    parcels.clear();
    moveContents(slots, from);
    for (parcelType* p : slots)
    {
        cloud.append(p);
    }
}


// ************************************************************************* //
