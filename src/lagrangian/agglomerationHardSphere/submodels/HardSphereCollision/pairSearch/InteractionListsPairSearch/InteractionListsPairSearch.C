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

#include "InteractionListsPairSearch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class ParcelType>
void Foam::InteractionListsPairSearch<ParcelType>::checkLists
(
    const scalar distance
)
{
    if (il_.valid() && distance <= distance_)
    {
        return;
    }

    // Some headroom so that growing agglomerates do not rebuild every step
    distance_ = max(1.5*distance, minDistance_);

    Info<< "    Hard-sphere interaction lists, distance " << distance_
        << " m" << endl;

    il_.reset
    (
        new InteractionLists<ParcelType>
        (
            this->mesh_, distance_, false, UName_
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::InteractionListsPairSearch<ParcelType>::InteractionListsPairSearch
(
    const dictionary& dict,
    const polyMesh& mesh,
    const word& UName
)
:
    PairSearch<ParcelType>(mesh),
    UName_(UName),
    minDistance_(dict.getOrDefault<scalar>("interactionDistance", 0)),
    il_(nullptr),
    distance_(0),
    referred_(),
    referredX1_(),
    cellStart_(),
    cellParcels_(),
    occupancy_()
{
    if (minDistance_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "interactionDistance " << minDistance_ << " is not valid:"
            << " give a distance >= 0 [m]" << exit(FatalIOError);
    }
}


template<class ParcelType>
void Foam::InteractionListsPairSearch<ParcelType>::sortByCell
(
    const UList<ParcelType*>& parcels
)
{
    // Parcels per cell (counting sort)
    const label nCells = this->mesh_.nCells();
    cellStart_.setSize(nCells + 1);
    cellStart_ = 0;
    for (const ParcelType* p : parcels)
    {
        ++cellStart_[p->cell() + 1];
    }
    for (label celli = 0; celli < nCells; ++celli)
    {
        cellStart_[celli + 1] += cellStart_[celli];
    }
    cellParcels_.setSize(parcels.size());
    labelList fill(SubList<label>(cellStart_, nCells));
    forAll(parcels, i)
    {
        cellParcels_[fill[parcels[i]->cell()]++] = i;
    }

    // The occupancy that the interaction lists send
    occupancy_.setSize(nCells);
    for (label celli = 0; celli < nCells; ++celli)
    {
        DynamicList<ParcelType*>& cellList = occupancy_[celli];
        cellList.clear();
        for (label a = cellStart_[celli]; a < cellStart_[celli + 1]; ++a)
        {
            cellList.append(parcels[cellParcels_[a]]);
        }
    }
}


template<class ParcelType>
void Foam::InteractionListsPairSearch<ParcelType>::visitReal
(
    const labelListList& dil,
    const typename PairSearch<ParcelType>::visitor& visit
) const
{
    // Same cell and the direct interaction list
    forAll(dil, celli)
    {
        for (label a = cellStart_[celli]; a < cellStart_[celli + 1]; ++a)
        {
            const label i = cellParcels_[a];

            for (label b = a + 1; b < cellStart_[celli + 1]; ++b)
            {
                visit(i, cellParcels_[b]);
            }

            for (const label cellj : dil[celli])
            {
                for
                (
                    label b = cellStart_[cellj];
                    b < cellStart_[cellj + 1];
                    ++b
                )
                {
                    visit(i, cellParcels_[b]);
                }
            }
        }
    }
}


template<class ParcelType>
void Foam::InteractionListsPairSearch<ParcelType>::visitReferred
(
    const InteractionLists<ParcelType>& il,
    const label n,
    const typename PairSearch<ParcelType>::visitor& visit
)
{
    const labelListList& ril = il.ril();
    const List<IDLList<ParcelType>>& referred = il.referredParticles();

    referred_.clear();
    referredX1_.clear();

    forAll(ril, refCelli)
    {
        for (const ParcelType& pj : referred[refCelli])
        {
            const label k = referred_.size();
            referred_.append(&pj);
            referredX1_.append(pj.position());

            for (const label celli : ril[refCelli])
            {
                for
                (
                    label a = cellStart_[celli];
                    a < cellStart_[celli + 1];
                    ++a
                )
                {
                    visit(cellParcels_[a], n + k);
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::InteractionListsPairSearch<ParcelType>::search
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const scalar distance,
    const scalar,
    const typename PairSearch<ParcelType>::visitor& visit
)
{
    checkLists(distance);
    InteractionLists<ParcelType>& il = il_();
    sortByCell(parcels);

    // Referred parcels: send now, receive after the real-real search
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    const label startOfRequests = Pstream::nRequests();
    il.sendReferredData(occupancy_, pBufs);

    visitReal(il.dil(), visit);

    il.receiveReferredData(pBufs, startOfRequests);
    visitReferred(il, parcels.size(), visit);
}


// ************************************************************************* //
