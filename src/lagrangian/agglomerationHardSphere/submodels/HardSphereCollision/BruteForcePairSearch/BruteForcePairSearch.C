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

#include "BruteForcePairSearch.H"
#include "cyclicPolyPatch.H"
#include "wallPolyPatch.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::BruteForcePairSearch<ParcelType>::BruteForcePairSearch
(
    const polyMesh& mesh
)
:
    mesh_(mesh),
    lattice_(),
    wallFaces_(),
    received_(),
    referred_(),
    referredX1_()
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    DynamicList<vector> lattice;
    DynamicList<label> wallFaces;

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

    for (const polyPatch& pp : pbm)
    {
        if (isA<wallPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                wallFaces.append(pp.start() + i);
            }
        }

        const cyclicPolyPatch* cycPtr = isA<cyclicPolyPatch>(pp);
        if (!cycPtr)
        {
            continue;
        }
        if (!cycPtr->parallel() && !cycPtr->separated())
        {
            FatalErrorInFunction
                << "pairSearch bruteForce: the cyclic patch " << pp.name()
                << " is rotational; only translational cyclics are"
                << " supported" << exit(FatalError);
        }
        if (!cycPtr->separated())
        {
            continue;
        }

        addUnique(cycPtr->separation()[0]);
    }

    // The same lattice on every processor (cyclics may be on some only)
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

    lattice_.transfer(lattice);
    wallFaces_.transfer(wallFaces);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class Visitor>
void Foam::BruteForcePairSearch<ParcelType>::search
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const List<DynamicList<ParcelType*>>&,
    const scalar distance,
    Visitor& visit
)
{
    const label n = parcels.size();
    const scalar d2 = sqr(distance);

    // Image shifts: all combinations of the lattice vectors e_k with the
    // coefficients -m_k..m_k, m_k = ceil(distance/|e_k|)
    DynamicList<vector> shifts;
    {
        labelList m(lattice_.size());
        label nShifts = 1;
        forAll(lattice_, k)
        {
            m[k] = ceil(distance/mag(lattice_[k]));
            nShifts *= 2*m[k] + 1;
        }
        for (label c = 0; c < nShifts; ++c)
        {
            vector s(Zero);
            label code = c;
            forAll(lattice_, k)
            {
                const label w = 2*m[k] + 1;
                s += scalar(code % w - m[k])*lattice_[k];
                code /= w;
            }
            shifts.append(s);
        }
    }

    // Every particle of this processor to every other processor
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    if (Pstream::parRun())
    {
        IDLList<ParcelType> mine;
        List<point> mineX1(n);
        forAll(parcels, i)
        {
            mine.append(new ParcelType(*parcels[i]));
            mineX1[i] = x1[i];
        }
        for (label proci = 0; proci < Pstream::nProcs(); ++proci)
        {
            if (proci != Pstream::myProcNo())
            {
                UOPstream os(proci, pBufs);
                os << mineX1 << mine;
            }
        }
    }
    pBufs.finishedSends();

    // All partners: own particles (index, x1) and received copies
    DynamicList<const ParcelType*> partner(parcels.size());
    DynamicList<point> partnerX1(parcels.size());
    DynamicList<label> partnerLocal(parcels.size());
    forAll(parcels, i)
    {
        partner.append(parcels[i]);
        partnerX1.append(x1[i]);
        partnerLocal.append(i);
    }

    received_.clear();
    received_.setSize(Pstream::nProcs());
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo() || !Pstream::parRun())
        {
            continue;
        }
        UIPstream is(proci, pBufs);
        List<point> theirX1(is);
        received_.set
        (
            proci,
            new IDLList<ParcelType>(is, typename ParcelType::iNew(mesh_))
        );
        label k = 0;
        for (const ParcelType& p : received_[proci])
        {
            partner.append(&p);
            partnerX1.append(theirX1[k++]);
            partnerLocal.append(-1);
        }
    }

    referred_.clear();
    referredX1_.clear();

    forAll(parcels, i)
    {
        const ParcelType& pi = *parcels[i];

        forAll(partner, k)
        {
            const ParcelType& pk = *partner[k];
            const label j = partnerLocal[k];

            for (const vector& s : shifts)
            {
                const bool identity = (s == vector::zero);

                // Real pairs once; never a particle with itself
                if (identity && j >= 0 && j <= i)
                {
                    continue;
                }
                if
                (
                    pk.origProc() == pi.origProc()
                 && pk.origId() == pi.origId()
                )
                {
                    continue;
                }

                const point xk(partnerX1[k] + s);
                if (magSqr(xk - x1[i]) > d2)
                {
                    continue;
                }

                if (identity && j >= 0)
                {
                    visit(i, j);
                    continue;
                }

                // A referred copy, moved by the image shift
                ParcelType* copy = new ParcelType(pk);
                copy->transformProperties(s);
                referred_.append(copy);
                referredX1_.append(xk);
                visit(i, n + referred_.size() - 1);
            }
        }
    }
}


// ************************************************************************* //
