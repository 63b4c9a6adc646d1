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

#include "sweptBoxGrid.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::sweptBoxGrid::maxBins = (1 << 21) - 2;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sweptBoxGrid::sweptBoxGrid()
:
    boxes_(),
    nReal_(0),
    origin_(Zero),
    spacing_(1, 1, 1),
    invSpacing_(1, 1, 1),
    mask_(0),
    start_(1, Zero),
    items_(),
    tags_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sweptBoxGrid::build
(
    List<box>&& boxes,
    const label nReal,
    const scalar spacing
)
{
    boxes_.transfer(boxes);
    nReal_ = nReal;

    const label n = boxes_.size();
    if (n == 0)
    {
        start_ = labelList(1, Zero);
        items_.clear();
        tags_.clear();
        return;
    }

    setSpacing(spacing);
    sortIntoBuckets(countInsertions());
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::sweptBoxGrid::setSpacing(const scalar spacing)
{
    // Origin, extent and spacing
    const label n = boxes_.size();
    point lo(boxes_[0].min[0], boxes_[0].min[1], boxes_[0].min[2]);
    point hi(boxes_[0].max[0], boxes_[0].max[1], boxes_[0].max[2]);
    vector meanExtent(Zero);
    for (const box& b : boxes_)
    {
        for (direction c = 0; c < 3; ++c)
        {
            lo[c] = min(lo[c], scalar(b.min[c]));
            hi[c] = max(hi[c], scalar(b.max[c]));
            meanExtent[c] += scalar(b.max[c]) - scalar(b.min[c]);
        }
    }
    meanExtent /= n;

    const vector extent(hi - lo);
    for (direction c = 0; c < 3; ++c)
    {
        scalar h = spacing > 0 ? spacing : 2*meanExtent[c];
        if (h <= 0 || extent[c]/h > maxBins)
        {
            // Degenerate boxes, or too many bins for the key: coarser
            h = max(extent[c]/maxBins, VSMALL);
        }
        spacing_[c] = h;
        invSpacing_[c] = 1/h;
    }
    origin_ = lo;
}


Foam::label Foam::sweptBoxGrid::countInsertions() const
{
    label nInsert = 0;
    forAll(boxes_, i)
    {
        const FixedList<label, 6> r(binRange(i));
        nInsert += (r[3] - r[0] + 1)*(r[4] - r[1] + 1)*(r[5] - r[2] + 1);
    }
    return nInsert;
}


void Foam::sweptBoxGrid::sortIntoBuckets(const label nInsert)
{
    // Buckets: a power of 2 >= the number of insertions
    label bits = 4;
    while ((label(1) << bits) < nInsert)
    {
        ++bits;
    }
    mask_ = (uint64_t(1) << bits) - 1;
    const label nBuckets = label(1) << bits;

    // Counting sort of the insertions by bucket: count (start_[b] = the
    // end of bucket b after the running sum), then place backwards from
    // the ends, so that the items ascend within a bucket and start_[b]
    // ends at the start of bucket b
    start_.setSize(nBuckets + 1);
    start_ = 0;
    forAll(boxes_, i)
    {
        const FixedList<label, 6> r(binRange(i));
        for (label bi = r[0]; bi <= r[3]; ++bi)
        {
            for (label bj = r[1]; bj <= r[4]; ++bj)
            {
                for (label bk = r[2]; bk <= r[5]; ++bk)
                {
                    ++start_[bucket(bi, bj, bk)];
                }
            }
        }
    }
    for (label b = 1; b < nBuckets; ++b)
    {
        start_[b] += start_[b - 1];
    }
    start_[nBuckets] = nInsert;

    items_.setSize(nInsert);
    tags_.setSize(nInsert);
    for (label i = boxes_.size() - 1; i >= 0; --i)
    {
        const FixedList<label, 6> r(binRange(i));
        for (label bi = r[0]; bi <= r[3]; ++bi)
        {
            for (label bj = r[1]; bj <= r[4]; ++bj)
            {
                for (label bk = r[2]; bk <= r[5]; ++bk)
                {
                    const label pos = --start_[bucket(bi, bj, bk)];
                    items_[pos] = i;
                    tags_[pos] = tag(bi, bj, bk);
                }
            }
        }
    }
}


// ************************************************************************* //
