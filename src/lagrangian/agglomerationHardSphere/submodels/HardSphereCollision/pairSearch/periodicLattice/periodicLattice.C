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

#include "periodicLattice.H"
#include "cyclicPolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::periodicLattice::periodicLattice
(
    const polyMesh& mesh,
    const word& who,
    const rotationalType rotational
)
:
    vectors_()
{
    DynamicList<vector> lattice;

    // One vector per pair of opposite patches
    auto addUnique = [&lattice](const vector& s)
    {
        for (const vector& e : lattice)
        {
            if (mag(e - s) < SMALL*mag(s) || mag(e + s) < SMALL*mag(s))
            {
                return;
            }
        }
        lattice.append(s);
    };

    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const cyclicPolyPatch* cycPtr = isA<cyclicPolyPatch>(pp);
        if (!cycPtr)
        {
            continue;
        }
        if
        (
            !cycPtr->parallel() && !cycPtr->separated()
         && rotational == ROTATIONAL_REJECT
        )
        {
            FatalErrorInFunction
                << who << ": the cyclic patch " << pp.name()
                << " is rotational; only translational cyclics are"
                << " supported (pairSearch interactionLists handles"
                << " rotational ones)" << exit(FatalError);
        }
        if (cycPtr->separated())
        {
            addUnique(cycPtr->separation()[0]);
        }
    }

    // The same lattice on every processor (a processor may hold no face
    // of a cyclic)
    List<List<vector>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = lattice;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    lattice.clear();
    for (const List<vector>& l : all)
    {
        for (const vector& s : l)
        {
            addUnique(s);
        }
    }

    vectors_.transfer(lattice);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::periodicLattice::minPeriod() const
{
    scalar p = GREAT;
    for (const vector& e : vectors_)
    {
        p = min(p, mag(e));
    }
    return p;
}


Foam::vector Foam::periodicLattice::axisPeriods() const
{
    vector period(GREAT, GREAT, GREAT);
    for (const vector& s : vectors_)
    {
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
                period[c] = min(period[c], L);
            }
        }
    }
    return period;
}


Foam::List<Foam::vector> Foam::periodicLattice::shifts
(
    const scalar reach
) const
{
    labelList m(vectors_.size());
    label nShifts = 1;
    forAll(vectors_, k)
    {
        m[k] = label(std::ceil(reach/mag(vectors_[k])));
        nShifts *= 2*m[k] + 1;
    }

    List<vector> result(nShifts);
    label n = 1;
    result[0] = Zero;
    for (label c = 0; c < nShifts; ++c)
    {
        vector s(Zero);
        label code = c;
        bool zero = true;
        forAll(vectors_, k)
        {
            const label w = 2*m[k] + 1;
            const label ck = code % w - m[k];
            s += scalar(ck)*vectors_[k];
            zero = zero && (ck == 0);
            code /= w;
        }
        if (!zero)
        {
            result[n++] = s;
        }
    }
    return result;
}


// ************************************************************************* //
