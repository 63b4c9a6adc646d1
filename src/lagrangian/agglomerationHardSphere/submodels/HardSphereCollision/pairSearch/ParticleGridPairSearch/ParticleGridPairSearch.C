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

#include "ParticleGridPairSearch.H"
#include "hardSphereWallInteraction.H"
#include "PstreamBuffers.H"
#include "treeBoundBox.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class ParcelType>
Foam::boundBox Foam::ParticleGridPairSearch<ParcelType>::sweptBox
(
    const ParcelType& p,
    const point& x1,
    const scalar inflate
)
{
    return sweptBoxGrid::sweptBox
    (
        p.stage().startPosition(), x1, 0.5*inflate*p.d()
    );
}


template<class ParcelType>
bool Foam::ParticleGridPairSearch<ParcelType>::targets
(
    const vector& spanMax,
    const boundBox& interior,
    DynamicList<label>& targetProc,
    DynamicList<label>& targetShift
) const
{
    // A box reaches at most spanMax from its end position, the partner's
    // too
    const label me = Pstream::myProcNo();
    const boundBox& own = procBb_[me];
    const vector r3(2*spanMax);
    bool interiorFree = true;

    forAll(procBb_, k)
    {
        if (!procBb_[k].valid())
        {
            continue;
        }
        forAll(shifts_, si)
        {
            if (k == me && si == 0)
            {
                continue;
            }
            const boundBox b
            (
                procBb_[k].min() - shifts_[si], procBb_[k].max() - shifts_[si]
            );
            const boundBox grown(b.min() - r3, b.max() + r3);
            if (!sweptBoxGrid::overlap(own, grown))
            {
                continue;
            }
            targetProc.append(k);
            targetShift.append(si);

            // Does the target reach into the interior? (then no particle
            // may skip the tests)
            if (interior.valid() && sweptBoxGrid::overlap(interior, grown))
            {
                interiorFree = false;
            }
        }
    }
    return interiorFree;
}


template<class ParcelType>
void Foam::ParticleGridPairSearch<ParcelType>::exchange
(
    List<IDLList<ParcelType>>& sendParcels,
    const List<DynamicList<point>>& sendX1
)
{
    const label me = Pstream::myProcNo();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(sendParcels, k)
    {
        if (k != me && sendParcels[k].size())
        {
            UOPstream os(k, pBufs);
            os << sendX1[k] << sendParcels[k];
        }
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    forAll(received_, k)
    {
        if (k == me || !recvSizes[k])
        {
            continue;
        }
        UIPstream is(k, pBufs);
        const List<point> theirX1(is);
        received_.set
        (
            k,
            new IDLList<ParcelType>
            (
                is, typename ParcelType::iNew(this->mesh_)
            )
        );
        label q = 0;
        for (const ParcelType& p : received_[k])
        {
            referred_.append(&p);
            referredX1_.append(theirX1[q++]);
        }
    }
}


template<class ParcelType>
void Foam::ParticleGridPairSearch<ParcelType>::refer
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const scalar inflate,
    const vector& spanMax
)
{
    const label me = Pstream::myProcNo();
    const boundBox& own = procBb_[me];

    images_.clear();
    received_.clear();
    received_.setSize(Pstream::nProcs());
    referred_.clear();
    referredX1_.clear();

    // The (processor, shift) targets within reach of this box, and the
    // interior whose particles reach none of them (if none reaches in)
    const vector r3(2*spanMax);
    const vector i3(1.01*r3 + 1e-9*own.span());
    const boundBox interior(own.min() + i3, own.max() - i3);
    DynamicList<label> targetProc;
    DynamicList<label> targetShift;
    const bool interiorFree =
        targets(spanMax, interior, targetProc, targetShift);

    // Per processor: the copies and their end positions
    List<IDLList<ParcelType>> sendParcels(Pstream::nProcs());
    List<DynamicList<point>> sendX1(Pstream::nProcs());

    forAll(parcels, i)
    {
        const point& x = x1[i];
        if (interiorFree && interior.valid() && interior.contains(x))
        {
            continue;
        }
        forAll(targetProc, t)
        {
            const label k = targetProc[t];
            const vector& s = shifts_[targetShift[t]];
            const boundBox reachK
            (
                procBb_[k].min() - spanMax, procBb_[k].max() + spanMax
            );
            const boundBox box(sweptBox(*parcels[i], x, inflate));
            if
            (
                !sweptBoxGrid::overlap
                (
                    reachK, boundBox(box.min() + s, box.max() + s)
                )
            )
            {
                continue;
            }
            const point xs(x + s);

            ParcelType* copy = new ParcelType(*parcels[i]);
            copy->transformProperties(s);
            if (k == me)
            {
                images_.append(copy);
                referred_.append(copy);
                referredX1_.append(xs);
            }
            else
            {
                sendParcels[k].append(copy);
                sendX1[k].append(xs);
            }
        }
    }

    if (Pstream::parRun())
    {
        exchange(sendParcels, sendX1);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::ParticleGridPairSearch<ParcelType>::ParticleGridPairSearch
(
    const dictionary& dict,
    const polyMesh& mesh,
    const word&
)
:
    PairSearch<ParcelType>(mesh),
    lattice_(mesh, "pairSearch particleGrid"),
    shifts_(lattice_.shifts(0.5*lattice_.minPeriod())),
    procBb_(Pstream::nProcs()),
    images_(),
    received_(),
    referred_(),
    referredX1_(),
    wallTree_(nullptr),
    cellWallFaces_(),
    cellWallDone_(),
    wallDistance_(-1)
{
    // Every processor's bounding box (an empty one is invalid)
    procBb_[Pstream::myProcNo()] =
        mesh.nCells() ? boundBox(mesh.points(), false) : boundBox();
    Pstream::gatherList(procBb_);
    Pstream::scatterList(procBb_);

    // The wall faces of this processor
    const labelList wallFaces(hardSphereWallInteraction::wallFaces(mesh));
    if (wallFaces.size())
    {
        treeBoundBox bb(mesh.points());
        bb.inflate(1e-4);
        wallTree_.reset
        (
            new indexedOctree<treeDataFace>
            (
                treeDataFace(true, mesh, wallFaces),
                bb,
                8,          // maxLevel
                10,         // leafSize
                100.0       // duplicity
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::ParticleGridPairSearch<ParcelType>::search
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    const scalar,
    const scalar inflate,
    const typename PairSearch<ParcelType>::visitor& visit
)
{
    const label n = parcels.size();

    // The largest span of the real particles' swept boxes
    vector spanMax(Zero);
    forAll(parcels, i)
    {
        spanMax = max(spanMax, sweptBox(*parcels[i], x1[i], inflate).span());
    }
    reduce(spanMax, maxOp<vector>());

    refer(parcels, x1, inflate, spanMax);

    // The boxes of the real particles, then of the referred partners
    // (their start positions are shifted with them), in single precision
    // rounded outward: one list, allocated once at its final size
    const label m = referred_.size();
    List<sweptBoxGrid::box> boxes(n + m);
    forAll(parcels, i)
    {
        boxes[i] =
            sweptBoxGrid::rounded(sweptBox(*parcels[i], x1[i], inflate));
    }
    forAll(referred_, k)
    {
        boxes[n + k] = sweptBoxGrid::rounded
        (
            sweptBox(*referred_[k], referredX1_[k], inflate)
        );
    }

    // The grid lives for this search only: its arrays (about 45 B per
    // particle with the boxes) are not held between steps
    sweptBoxGrid grid;
    grid.build(std::move(boxes), n, 0);
    grid.pairs(visit);
}


template<class ParcelType>
const Foam::labelList& Foam::ParticleGridPairSearch<ParcelType>::wallFaces
(
    const label celli,
    const scalar r
) const
{
    static const labelList none;
    if (!wallTree_.valid())
    {
        return none;
    }

    if (r > wallDistance_)
    {
        // (Re)build the cache for a larger reach
        wallDistance_ = 1.5*r;
        cellWallFaces_.clear();
        cellWallFaces_.setSize(this->mesh_.nCells());
        cellWallDone_.clear();
        cellWallDone_.resize(this->mesh_.nCells());
    }

    if (!cellWallDone_.test(celli))
    {
        const vector w(wallDistance_, wallDistance_, wallDistance_);
        const boundBox cellBb
        (
            this->mesh_.cells()[celli].points
            (
                this->mesh_.faces(), this->mesh_.points()
            ),
            false
        );
        const labelList elems
        (
            wallTree_->findBox
            (
                treeBoundBox(cellBb.min() - w, cellBb.max() + w)
            )
        );
        labelList& faces = cellWallFaces_[celli];
        faces.setSize(elems.size());
        forAll(elems, e)
        {
            faces[e] = wallTree_->shapes().faceLabels()[elems[e]];
        }
        cellWallDone_.set(celli);
    }

    return cellWallFaces_[celli];
}


// ************************************************************************* //
