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

#include "fragmentIds.H"
#include "Pstream.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::fragmentIds::assign(const UList<labelPair>& parents)
{
    // Every rank's parents, on every rank
    List<List<labelPair>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = parents;
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    // The rank of each of this rank's parents in the global order of the
    // parents' ids (unique ids: a strict order)
    label nTotal = 0;
    forAll(all, proci)
    {
        nTotal += all[proci].size();
    }

    List<labelPair> flat(nTotal);
    labelList owner(nTotal);
    labelList local(nTotal);
    label k = 0;
    forAll(all, proci)
    {
        forAll(all[proci], i)
        {
            flat[k] = all[proci][i];
            owner[k] = proci;
            local[k] = i;
            ++k;
        }
    }

    const labelList order(sortedOrder(flat));

    labelList ids(parents.size(), -1);
    forAll(order, rank)
    {
        const label j = order[rank];
        if (owner[j] == Pstream::myProcNo())
        {
            ids[local[j]] = next_ + rank;
        }
    }

    next_ += nTotal;
    return ids;
}


// ************************************************************************* //
