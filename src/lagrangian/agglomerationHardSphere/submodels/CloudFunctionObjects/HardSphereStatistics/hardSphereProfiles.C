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

#include "hardSphereProfiles.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardSphereProfiles::hardSphereProfiles
(
    const polyMesh& mesh,
    const dictionary& dict
)
:
    direction_(Zero),
    nBins_(0),
    xMin_(0),
    binWidth_(1),
    nSteps_(0)
{
    direction_ = dict.get<vector>("direction");
    if (mag(direction_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "statistics.direction must be a non-zero vector"
            << exit(FatalIOError);
    }
    direction_ /= mag(direction_);

    // The bound keeps the profiles' memory (about 200 bytes a bin in
    // the profiles and as much again in each step's sums) and each
    // write's profiles.dat (a row a bin) small: 1e5 bins are about
    // 40 MB, far finer than any mesh the profiles average over
    nBins_ = dict.get<label>("nBins");
    if (nBins_ < 1 || nBins_ > maxBins)
    {
        FatalIOErrorInFunction(dict)
            << "statistics.nBins = " << nBins_
            << " is out of range [1, " << maxBins << "]"
            << exit(FatalIOError);
    }

    const scalarField xp(mesh.points() & direction_);
    xMin_ = gMin(xp);
    binWidth_ = (gMax(xp) - xMin_)/nBins_;

    // Slab volumes: each cell's volume is split over the slabs in
    // proportion to the overlap of its extent along the direction
    // (exact for cells aligned with it), so that slabs thinner than
    // the cells (e.g. the centre of a wall-graded channel) get their
    // share instead of nothing
    slabVolume_.setSize(nBins_, Zero);
    const pointField& pts = mesh.points();
    const labelListList& cellPts = mesh.cellPoints();
    forAll(cellPts, celli)
    {
        scalar lo = GREAT;
        scalar hi = -GREAT;
        for (const label pointi : cellPts[celli])
        {
            const scalar s = pts[pointi] & direction_;
            lo = min(lo, s);
            hi = max(hi, s);
        }
        const scalar V = mesh.cellVolumes()[celli];
        const label b0 = max(label(floor((lo - xMin_)/binWidth_)), 0);
        const label b1 =
            min(label(floor((hi - xMin_)/binWidth_)), nBins_ - 1);
        if (hi - lo <= SMALL*binWidth_ || b0 >= b1)
        {
            slabVolume_[min(max(b0, 0), nBins_ - 1)] += V;
            continue;
        }
        for (label b = b0; b <= b1; ++b)
        {
            const scalar overlap =
                min(hi, xMin_ + (b + 1)*binWidth_)
              - max(lo, xMin_ + b*binWidth_);
            if (overlap > 0)
            {
                slabVolume_[b] += V*overlap/(hi - lo);
            }
        }
    }
    reduce(slabVolume_, sumOp<scalarField>());

    colBin_.setSize(nBins_, Zero);
    colFirstBin_.setSize(nBins_, Zero);
    aggBin_.setSize(nBins_, Zero);
    alphaSum_.setSize(nBins_, Zero);
    visits_.setSize(nBins_, Zero);
    meanD_.setSize(nBins_, Zero);
    meanU_.setSize(nBins_, Zero);
    M2U_.setSize(nBins_, Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::hardSphereProfiles::bin(const point& x) const
{
    const label b = floor(((x & direction_) - xMin_)/binWidth_);

    if (b < 0 || b > nBins_)
    {
        return -1;
    }

    return min(b, nBins_ - 1);
}


void Foam::hardSphereProfiles::addEvents
(
    const scalarField& col,
    const scalarField& colFirst,
    const scalarField& agg
)
{
    colBin_ += col;
    colFirstBin_ += colFirst;
    aggBin_ += agg;
}


void Foam::hardSphereProfiles::addParticles
(
    const scalarField& n,
    const scalarField& volume,
    const scalarField& sumD,
    const vectorField& sumU,
    const symmTensorField& sumUUshifted
)
{
    ++nSteps_;

    forAll(n, b)
    {
        if (slabVolume_[b] > 0)
        {
            alphaSum_[b] += volume[b]/slabVolume_[b];
        }

        if (n[b] <= 0)
        {
            continue;
        }

        // Merge the step batch into the running averages (Eq. 88, the
        // pairwise update of Chan et al. with the old mean as shift)
        const scalar na = visits_[b];
        const scalar nb = n[b];
        const scalar nab = na + nb;

        const vector delta(sumU[b]/nb - meanU_[b]);

        M2U_[b] += sumUUshifted[b] - (nb*nb/nab)*sqr(delta);
        meanU_[b] += (nb/nab)*delta;
        meanD_[b] += (sumD[b] - nb*meanD_[b])/nab;
        visits_[b] = nab;
    }
}


void Foam::hardSphereProfiles::read(const dictionary& dict)
{
    const label n = dict.get<label>("nBins");
    if (n != nBins_)
    {
        FatalIOErrorInFunction(dict)
            << "The restart state has " << n << " profile bins but "
            << "statistics.nBins is " << nBins_
            << "; keep nBins when restarting" << exit(FatalIOError);
    }

    dict.readEntry("nSteps", nSteps_);
    dict.readEntry("colBin", colBin_);
    dict.readEntry("colFirstBin", colFirstBin_);
    dict.readEntry("aggBin", aggBin_);
    dict.readEntry("alphaSum", alphaSum_);
    dict.readEntry("visits", visits_);
    dict.readEntry("meanD", meanD_);
    dict.readEntry("meanU", meanU_);
    dict.readEntry("M2U", M2U_);
}


Foam::dictionary Foam::hardSphereProfiles::state() const
{
    dictionary pd;
    pd.add("nBins", nBins_);
    pd.add("nSteps", nSteps_);
    pd.add("colBin", colBin_);
    pd.add("colFirstBin", colFirstBin_);
    pd.add("aggBin", aggBin_);
    pd.add("alphaSum", alphaSum_);
    pd.add("visits", visits_);
    pd.add("meanD", meanD_);
    pd.add("meanU", meanU_);
    pd.add("M2U", M2U_);
    return pd;
}


void Foam::hardSphereProfiles::write
(
    const fileName& file,
    const word& cloudName
) const
{
    OFstream os(file);
    os.precision(IOstream::defaultPrecision());
    os  << "# Profiles of cloud " << cloudName << " along "
        << direction_ << ", " << nSteps_ << " steps sampled" << nl
        << "# slab volumes: cell volumes split by overlap" << nl
        << "# x nColPerVolume nColFirstPerVolume nAggPerVolume aggRate"
        << " alpha meanD Ux Uy Uz uu uv uw vv vw ww visits" << nl;

    forAll(colBin_, b)
    {
        const scalar V = max(slabVolume_[b], VSMALL);
        const scalar nv = max(visits_[b], scalar(1));
        const symmTensor R(M2U_[b]/nv);

        os  << xMin_ + (b + 0.5)*binWidth_ << ' '
            << colBin_[b]/V << ' ' << colFirstBin_[b]/V << ' '
            << aggBin_[b]/V << ' '
            << (colBin_[b] > 0 ? aggBin_[b]/colBin_[b] : 0) << ' '
            << (nSteps_ > 0 ? alphaSum_[b]/nSteps_ : 0) << ' '
            << meanD_[b] << ' '
            << meanU_[b].x() << ' ' << meanU_[b].y() << ' '
            << meanU_[b].z() << ' '
            << R.xx() << ' ' << R.xy() << ' ' << R.xz() << ' '
            << R.yy() << ' ' << R.yz() << ' ' << R.zz() << ' '
            << visits_[b] << nl;
    }
}


// ************************************************************************* //
