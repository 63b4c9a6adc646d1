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
#include "hardSphereWallInteraction.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::BruteForcePairSearch<ParcelType>::BruteForcePairSearch
(
    const dictionary& dict,
    const polyMesh& mesh,
    const word&
)
:
    PairSearch<ParcelType>(mesh),
    lattice_(mesh, "pairSearch bruteForce"),
    wallFaces_(hardSphereWallInteraction::wallFaces(mesh)),
    received_(),
    partner_(),
    partnerX1_(),
    partnerLocal_(),
    referred_(),
    referredX1_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::BruteForcePairSearch<ParcelType>::gatherPartners
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1
)
{
    const label n = parcels.size();

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
    partner_.clear();
    partnerX1_.clear();
    partnerLocal_.clear();
    forAll(parcels, i)
    {
        partner_.append(parcels[i]);
        partnerX1_.append(x1[i]);
        partnerLocal_.append(i);
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
            new IDLList<ParcelType>(is, typename ParcelType::iNew(this->mesh_))
        );
        label k = 0;
        for (const ParcelType& p : received_[proci])
        {
            partner_.append(&p);
            partnerX1_.append(theirX1[k++]);
            partnerLocal_.append(-1);
        }
    }
}


template<class ParcelType>
Foam::List<Foam::vector>
Foam::BruteForcePairSearch<ParcelType>::partnerBoxes
(
    const scalar inflate,
    List<sweptBoxGrid::box>& box
) const
{
    // Boxes of all partners, and the image shifts that can matter: boxes
    // that overlap have end positions within D_i + D_j <= 2 D_max
    // (tested as the grid keeps them: rounded outward to single precision)
    box.setSize(partner_.size());
    scalar diagMax = 0;
    forAll(partner_, k)
    {
        const ParcelType& pk = *partner_[k];
        const boundBox bk
        (
            sweptBoxGrid::sweptBox
            (
                pk.stage().startPosition(), partnerX1_[k], 0.5*inflate*pk.d()
            )
        );
        box[k] = sweptBoxGrid::rounded(bk);
        diagMax = max(diagMax, mag(bk.span()));
    }
    return lattice_.shifts(2*diagMax);
}


template<class ParcelType>
bool Foam::BruteForcePairSearch<ParcelType>::refer
(
    const ParcelType& pk,
    const point& xk,
    const vector& s,
    const scalar inflate,
    const sweptBoxGrid::box& boxI
)
{
    // An image: a copy moved by the shift (its start position with it)
    autoPtr<ParcelType> copy(new ParcelType(pk));
    copy->transformProperties(s);
    const sweptBoxGrid::box bk
    (
        sweptBoxGrid::rounded
        (
            sweptBoxGrid::sweptBox
            (
                copy->stage().startPosition(),
                xk,
                0.5*inflate*copy->d()
            )
        )
    );
    if (!sweptBoxGrid::overlap(boxI, bk))
    {
        return false;
    }
    referred_.append(copy.ptr());
    referredX1_.append(xk);
    return true;
}


template<class ParcelType>
void Foam::BruteForcePairSearch<ParcelType>::search
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const scalar,
    const scalar inflate,
    const typename PairSearch<ParcelType>::visitor& visit
)
{
    const label n = parcels.size();
    gatherPartners(parcels, x1);
    List<sweptBoxGrid::box> box;
    const List<vector> shifts(partnerBoxes(inflate, box));

    referred_.clear();
    referredX1_.clear();

    forAll(parcels, i)
    {
        const ParcelType& pi = *parcels[i];

        forAll(partner_, k)
        {
            const ParcelType& pk = *partner_[k];
            const label j = partnerLocal_[k];

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

                if (identity && j >= 0)
                {
                    if (sweptBoxGrid::overlap(box[i], box[k]))
                    {
                        visit(i, j);
                    }
                }
                else if (refer(pk, partnerX1_[k] + s, s, inflate, box[i]))
                {
                    visit(i, n + referred_.size() - 1);
                }
            }
        }
    }
}


// ************************************************************************* //
