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

const uint64_t Foam::sweptBoxGrid::EMPTY = ~uint64_t(0);

const Foam::label Foam::sweptBoxGrid::maxBins = (1 << 21) - 2;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sweptBoxGrid::sweptBoxGrid()
:
    boxes_(),
    nReal_(0),
    origin_(Zero),
    spacing_(1),
    invSpacing_(1),
    slotKey_(),
    binStart_(1, Zero),
    binItems_(),
    binKey_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sweptBoxGrid::build
(
    List<boundBox>&& boxes,
    const label nReal,
    scalar spacing
)
{
    boxes_.transfer(boxes);
    nReal_ = nReal;

    const label n = boxes_.size();
    if (n == 0)
    {
        binStart_ = labelList(1, Zero);
        binItems_.clear();
        binKey_.clear();
        return;
    }

    // Origin, extent and spacing
    point lo(boxes_[0].min());
    point hi(boxes_[0].max());
    scalar meanExtent = 0;
    for (const boundBox& b : boxes_)
    {
        lo = min(lo, b.min());
        hi = max(hi, b.max());
        meanExtent += cmptMax(b.span());
    }
    meanExtent /= n;

    if (spacing <= 0)
    {
        spacing = 2*meanExtent;
    }
    const scalar extent = cmptMax(hi - lo);
    if (spacing <= 0 || extent/spacing > maxBins)
    {
        // Degenerate boxes, or too many bins for the key: coarser
        spacing = max(extent/maxBins, VSMALL);
    }
    origin_ = lo;
    spacing_ = spacing;
    invSpacing_ = 1/spacing;

    // Bin ranges and number of insertions
    label nInsert = 0;
    List<FixedList<label, 6>> range(n);
    forAll(boxes_, i)
    {
        FixedList<label, 6>& r = range[i];
        label m = 1;
        for (direction c = 0; c < 3; ++c)
        {
            r[c] = index(boxes_[i].min()[c], c);
            r[c + 3] = index(boxes_[i].max()[c], c);
            m *= r[c + 3] - r[c] + 1;
        }
        nInsert += m;
    }

    // Open-addressing hash table of the bins, at most half full
    label bits = 4;
    while ((label(1) << bits) < 2*nInsert)
    {
        ++bits;
    }
    const uint64_t mask = (uint64_t(1) << bits) - 1;
    slotKey_.setSize(label(1) << bits);
    slotKey_ = EMPTY;
    labelList slotCount(slotKey_.size(), Zero);
    labelList insertSlot(nInsert);

    label ins = 0;
    forAll(boxes_, i)
    {
        const FixedList<label, 6>& r = range[i];
        for (label bi = r[0]; bi <= r[3]; ++bi)
        {
            for (label bj = r[1]; bj <= r[4]; ++bj)
            {
                for (label bk = r[2]; bk <= r[5]; ++bk)
                {
                    const uint64_t k = key(bi, bj, bk);
                    uint64_t s = ((k*0x9E3779B97F4A7C15ull) >> 20) & mask;
                    while (slotKey_[s] != EMPTY && slotKey_[s] != k)
                    {
                        s = (s + 1) & mask;
                    }
                    slotKey_[s] = k;
                    ++slotCount[s];
                    insertSlot[ins++] = s;
                }
            }
        }
    }

    // Compact bins (in slot order) and their starts
    labelList slotBin(slotKey_.size(), -1);
    label nBins = 0;
    forAll(slotKey_, s)
    {
        if (slotKey_[s] != EMPTY)
        {
            slotBin[s] = nBins++;
        }
    }
    binKey_.setSize(nBins);
    binStart_.setSize(nBins + 1);
    binStart_[0] = 0;
    forAll(slotKey_, s)
    {
        const label b = slotBin[s];
        if (b >= 0)
        {
            binKey_[b] = slotKey_[s];
            binStart_[b + 1] = binStart_[b] + slotCount[s];
        }
    }

    // Items, ascending within each bin
    labelList fill(SubList<label>(binStart_, nBins));
    binItems_.setSize(nInsert);
    ins = 0;
    forAll(boxes_, i)
    {
        const FixedList<label, 6>& r = range[i];
        const label m =
            (r[3] - r[0] + 1)*(r[4] - r[1] + 1)*(r[5] - r[2] + 1);
        for (label q = 0; q < m; ++q)
        {
            binItems_[fill[slotBin[insertSlot[ins++]]]++] = i;
        }
    }
}


// ************************************************************************* //
