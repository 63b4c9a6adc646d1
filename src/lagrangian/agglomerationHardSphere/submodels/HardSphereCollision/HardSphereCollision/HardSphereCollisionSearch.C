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


Description
    HardSphereCollision: the pair search of the step and its optional
    check against the O(N^2) oracle (included by HardSphereCollision.C).

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCollision<CloudType>::setPeriods()
{
    period_ = vector(GREAT, GREAT, GREAT);
    for (const polyPatch& pp : this->owner().mesh().boundaryMesh())
    {
        const cyclicPolyPatch* cycPtr = isA<cyclicPolyPatch>(pp);
        if (cycPtr && cycPtr->separated())
        {
            const vector& s = cycPtr->separation()[0];
            const scalar L = mag(s);
            label nAxes = 0;
            direction axis = 0;
            for (direction c = 0; c < vector::nComponents; ++c)
            {
                if (mag(s[c]) > 1e-6*L)
                {
                    ++nAxes;
                    axis = c;
                }
            }
            for (direction c = 0; c < vector::nComponents; ++c)
            {
                if (nAxes > 1 || c == axis)
                {
                    period_[c] = min(period_[c], L);
                }
            }
        }
    }
    reduce(period_, minOp<vector>());
}


template<class CloudType>
Foam::scalar Foam::HardSphereCollision<CloudType>::checkedDistance
(
    const scalar dMax,
    const scalar dxMag,
    const vector& dxMax,
    const scalar dReach
) const
{
    const scalar distance = max(dMax + 2*dxMag, dReach);

    // The reach of the search along each axis against half the period:
    // the swept boxes (particleGrid, bruteForce) reach d_max + 2 max|dx_c|
    // along axis c; InteractionLists' search distance is isotropic
    for (direction c = 0; c < vector::nComponents; ++c)
    {
        const scalar reach =
            ilSearch_.valid() ? distance : max(dMax + 2*dxMax[c], dReach);
        if (reach > 0.5*period_[c])
        {
            FatalErrorInFunction
                << "Cloud " << this->owner().name() << ": the collision search"
                << " reaches " << reach << " m along "
                << vector::componentNames[c] << " (d_max " << dMax
                << " m, largest displacement in the step "
                << (ilSearch_.valid() ? dxMag : dxMax[c]) << " m"
                << (ilSearch_.valid() ? ", isotropic search" : "")
                << "), more than half the periodic length along "
                << vector::componentNames[c] << ", " << 0.5*period_[c]
                << " m: the pair search would miss partners through a"
                << " second periodic image beyond it (found by the O(N^2)"
                << " oracle). Reduce the time step (or enlarge the"
                << " periodic domain)" << exit(FatalError);
        }
    }

    return distance;
}


template<class CloudType>
template<class Search>
void Foam::HardSphereCollision<CloudType>::candidateKeys
(
    Search& search,
    const UList<parcelType*>& parcels,
    const UList<point>& x1,
    const scalar distance,
    const scalar inflate,
    DynamicList<searchKey>& keys
) const
{
    const label n = parcels.size();
    keys.clear();
    auto collect = [&](const label i, const label j)
    {
        const parcelType& pj =
            j < n ? *parcels[j] : search.referred(j - n);
        const point& xj = j < n ? x1[j] : search.referredPosition(j - n);
        searchKey k;
        k.i = i;
        k.proc = pj.origProc();
        k.id = pj.origId();
        k.x = xj;
        keys.append(k);
    };
    search.search(parcels, x1, noOccupancy_, distance, inflate, collect);
    std::sort(keys.begin(), keys.end());
}


template<class CloudType>
template<class Visitor>
void Foam::HardSphereCollision<CloudType>::search
(
    const UList<parcelType*>& parcels,
    const UList<point>& x1,
    const scalar distance,
    const scalar inflate,
    Visitor& visit
)
{
    CloudType& cloud = this->owner();

    if (bfCheck_.valid())
    {
        // The oracle's candidate set first (its referred copies are its
        // own), then the search's; they must be the same
        DynamicList<searchKey> oracle;
        DynamicList<searchKey> found;
        candidateKeys(bfCheck_(), parcels, x1, distance, inflate, oracle);
        candidateKeys(gridSearch_(), parcels, x1, distance, inflate, found);

        label nDiff = (oracle.size() != found.size());
        for (label k = 0; !nDiff && k < found.size(); ++k)
        {
            nDiff += !(found[k] == oracle[k]);
        }
        reduce(nDiff, sumOp<label>());
        const label nPairs = returnReduce(found.size(), sumOp<label>());
        if (nDiff)
        {
            FatalErrorInFunction
                << "Cloud " << cloud.name() << ": pairSearchCheck: the"
                << " particleGrid search found " << found.size()
                << " candidates on processor " << Pstream::myProcNo()
                << ", the O(N^2) oracle " << oracle.size()
                << exit(FatalError);
        }
        Info<< "    pairSearchCheck: " << nPairs
            << " candidate pairs, identical to the O(N^2) oracle" << endl;
    }

    // The cloud's cell occupancy is built only for the search that uses
    // it (once asked for, the cloud updates it every step)
    if (gridSearch_.valid())
    {
        gridSearch_->search
        (
            parcels, x1, noOccupancy_, distance, inflate, visit
        );
    }
    else if (ilSearch_.valid())
    {
        ilSearch_->search
        (
            parcels, x1, cloud.cellOccupancy(), distance, inflate, visit
        );
    }
    else
    {
        bfSearch_->search
        (
            parcels, x1, noOccupancy_, distance, inflate, visit
        );
    }
}


// ************************************************************************* //
