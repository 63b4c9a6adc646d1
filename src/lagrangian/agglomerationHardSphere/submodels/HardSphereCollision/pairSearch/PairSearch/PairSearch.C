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
#include "periodicLattice.H"

// * * * * * * * * * * * * * * Private Classes * * * * * * * * * * * * * * //

template<class ParcelType>
bool Foam::PairSearch<ParcelType>::searchKey::operator<
(
    const searchKey& b
) const
{
    if (i != b.i) return i < b.i;
    if (proc != b.proc) return proc < b.proc;
    if (id != b.id) return id < b.id;
    for (direction c = 0; c < 3; ++c)
    {
        if (x[c] != b.x[c]) return x[c] < b.x[c];
    }
    return false;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class ParcelType>
void Foam::PairSearch<ParcelType>::candidateKeys
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const scalar distance,
    const scalar inflate,
    DynamicList<searchKey>& keys
)
{
    const label n = parcels.size();
    keys.clear();
    auto collect = [&](const label i, const label j)
    {
        const ParcelType& pj = j < n ? *parcels[j] : referred(j - n);
        const point& xj = j < n ? x1[j] : referredPosition(j - n);
        searchKey k;
        k.i = i;
        k.proc = pj.origProc();
        k.id = pj.origId();
        k.x = xj;
        keys.append(k);
    };
    search(parcels, x1, distance, inflate, collect);
    std::sort(keys.begin(), keys.end());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::PairSearch<ParcelType>::PairSearch(const polyMesh& mesh)
:
    period_
    (
        periodicLattice
        (
            mesh, "pairSearch", periodicLattice::ROTATIONAL_SKIP
        ).axisPeriods()
    ),
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
Foam::wordList Foam::PairSearch<ParcelType>::keys()
{
    return wordList({"pairSearch", "pairSearchCheck", "interactionDistance"});
}


template<class ParcelType>
Foam::scalar Foam::PairSearch<ParcelType>::checkedDistance
(
    const scalar dMax,
    const scalar dxMag,
    const vector& dxMax,
    const scalar dReach,
    const word& cloudName
) const
{
    const scalar distance = max(dMax + 2*dxMag, dReach);
    const bool iso = isotropic();

    // The reach of the search along each axis against half the period
    for (direction c = 0; c < vector::nComponents; ++c)
    {
        const scalar reach =
            iso ? distance : max(dMax + 2*dxMax[c], dReach);
        if (reach > 0.5*period_[c])
        {
            FatalErrorInFunction
                << "Cloud " << cloudName << ": the collision search"
                << " reaches " << reach << " m along "
                << vector::componentNames[c] << " (d_max " << dMax
                << " m, largest displacement in the step "
                << (iso ? dxMag : dxMax[c]) << " m"
                << (iso ? ", isotropic search" : "")
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


template<class ParcelType>
void Foam::PairSearch<ParcelType>::check
(
    PairSearch<ParcelType>& oracle,
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const scalar distance,
    const scalar inflate,
    const word& cloudName
)
{
    DynamicList<searchKey> expected;
    DynamicList<searchKey> found;
    oracle.candidateKeys(parcels, x1, distance, inflate, expected);
    candidateKeys(parcels, x1, distance, inflate, found);

    label nDiff = (expected.size() != found.size());
    for (label k = 0; !nDiff && k < found.size(); ++k)
    {
        nDiff += !(found[k] == expected[k]);
    }
    reduce(nDiff, sumOp<label>());
    const label nPairs = returnReduce(found.size(), sumOp<label>());
    if (nDiff)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << ": pairSearchCheck: the "
            << type() << " search found " << found.size()
            << " candidates on processor " << Pstream::myProcNo()
            << ", the " << oracle.type() << " oracle " << expected.size()
            << exit(FatalError);
    }
    Info<< "    pairSearchCheck: " << nPairs << " candidate pairs,"
        << " identical to the " << oracle.type() << " oracle" << endl;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

#include "PairSearchNew.C"

// ************************************************************************* //
