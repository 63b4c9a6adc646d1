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

#include "hardSphereStatisticsAccumulator.H"
#include "cloud.H"
#include "volFields.H"
#include "OSspecific.H"


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::hardSphereStatisticsAccumulator::baseDir() const
{
    return
        mesh_.time().globalPath()/"postProcessing"
       /(cloudName_ + "HardSphere");
}


void Foam::hardSphereStatisticsAccumulator::readState()
{
    if (!state_.found("counters"))
    {
        return;
    }

    const dictionary& cd = state_.subDict("counters");
    forAll(counters_, i)
    {
        counters_[i] =
            cd.getOrDefault<label>
            (
                hardSphereStep::counterNames[counterType(i)],
                0
            );
    }
    sumDeltaL_ = state_.getOrDefault<scalar>("sumDeltaL", 0);
    energyGain_ = state_.getOrDefault<scalar>("agglomerationEnergyGain", 0);

    if (profiles_ && state_.found("profiles"))
    {
        const dictionary& pd = state_.subDict("profiles");

        const label n = pd.get<label>("nBins");
        if (n != nBins_)
        {
            FatalIOErrorInFunction(state_)
                << "The restart state has " << n << " profile bins but "
                << "statistics.nBins is " << nBins_
                << "; keep nBins when restarting" << exit(FatalIOError);
        }

        pd.readEntry("nSteps", nSteps_);
        pd.readEntry("colBin", colBin_);
        pd.readEntry("colFirstBin", colFirstBin_);
        pd.readEntry("aggBin", aggBin_);
        pd.readEntry("alphaSum", alphaSum_);
        pd.readEntry("visits", visits_);
        pd.readEntry("meanD", meanD_);
        pd.readEntry("meanU", meanU_);
        pd.readEntry("M2U", M2U_);
    }
}


void Foam::hardSphereStatisticsAccumulator::updateState()
{
    dictionary cd;
    forAll(counters_, i)
    {
        cd.add(hardSphereStep::counterNames[counterType(i)], counters_[i]);
    }
    state_.set("counters", cd);
    state_.set("sumDeltaL", sumDeltaL_);
    state_.set("agglomerationEnergyGain", energyGain_);

    if (profiles_)
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
        state_.set("profiles", pd);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardSphereStatisticsAccumulator::hardSphereStatisticsAccumulator
(
    const fvMesh& mesh,
    const word& cloudName,
    const dictionary& dict
)
:
    mesh_(mesh),
    cloudName_(cloudName),
    state_
    (
        IOobject
        (
            cloudName + "HardSphereStatistics",
            mesh.time().timeName(),
            "uniform"/cloud::prefix/cloudName,
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    ),
    counters_(hardSphereStep::N_COUNTERS, Zero),
    sumDeltaL_(0),
    energyGain_(0),
    profiles_(dict.getOrDefault<bool>("profiles", false)),
    direction_(Zero),
    nBins_(0),
    xMin_(0),
    binWidth_(1),
    nSteps_(0)
{
    if (profiles_)
    {
        direction_ = dict.get<vector>("direction");
        if (mag(direction_) < SMALL)
        {
            FatalIOErrorInFunction(dict)
                << "statistics.direction must be a non-zero vector"
                << exit(FatalIOError);
        }
        direction_ /= mag(direction_);

        nBins_ = dict.get<label>("nBins");
        if (nBins_ < 1)
        {
            FatalIOErrorInFunction(dict)
                << "statistics.nBins = " << nBins_
                << " is out of range [1, inf)" << exit(FatalIOError);
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
            const scalar V = mesh.V()[celli];
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

    readState();

    if (Pstream::master())
    {
        const fileName dir(baseDir()/mesh.time().timeName());
        mkDir(dir);
        statsFilePtr_.reset(new OFstream(dir/"stats.dat"));

        OFstream& os = statsFilePtr_();
        os.precision(IOstream::defaultPrecision());
        os  << "# Hard-sphere statistics of cloud " << cloudName_ << nl
            << "# Counters are cumulative since the start of the run"
            << " (restart state)" << nl
            << "# Time nParticles nPrimaries nAgglomerates"
            << " nPrimariesInAgglomerates maxPrimaries";
        forAll(counters_, i)
        {
            os  << ' ' << hardSphereStep::counterNames[counterType(i)];
        }
        os  << " aggRate D10 Dmax mass" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::hardSphereStatisticsAccumulator::bin(const point& x) const
{
    if (!profiles_)
    {
        return -1;
    }

    const label b = floor(((x & direction_) - xMin_)/binWidth_);

    if (b < 0 || b > nBins_)
    {
        return -1;
    }

    return min(b, nBins_ - 1);
}


void Foam::hardSphereStatisticsAccumulator::addCounts
(
    const List<label>& increments,
    const scalar sumDeltaL,
    const scalar energyGain
)
{
    forAll(counters_, i)
    {
        counters_[i] += increments[i];
    }
    sumDeltaL_ += sumDeltaL;
    energyGain_ += energyGain;
}


void Foam::hardSphereStatisticsAccumulator::addEventProfiles
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


void Foam::hardSphereStatisticsAccumulator::addParticleProfiles
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


void Foam::hardSphereStatisticsAccumulator::writeStep
(
    const scalar time,
    const label nParticles,
    const label nPrimaries,
    const label nAgglomerates,
    const label nPrimariesInAgglomerates,
    const label maxPrimaries,
    const scalar D10,
    const scalar Dmax,
    const scalar mass
)
{
    if (!Pstream::master())
    {
        return;
    }

    OFstream& os = statsFilePtr_();

    os  << time << ' ' << nParticles << ' ' << nPrimaries << ' '
        << nAgglomerates << ' ' << nPrimariesInAgglomerates << ' '
        << maxPrimaries;
    forAll(counters_, i)
    {
        os  << ' ' << counters_[i];
    }

    const label nCol = counters_[hardSphereStep::COL];
    const scalar aggRate =
        nCol > 0 ? scalar(counters_[hardSphereStep::AGG])/nCol : 0;

    os  << ' ' << aggRate << ' ' << D10 << ' ' << Dmax << ' ' << mass
        << endl;
}


void Foam::hardSphereStatisticsAccumulator::writeTime
(
    const Map<label>& sizeHistogram
)
{
    updateState();

    state_.instance() = mesh_.time().timeName();
    state_.regIOobject::write();

    if (!Pstream::master())
    {
        return;
    }

    const fileName dir(baseDir()/mesh_.time().timeName());
    mkDir(dir);

    {
        OFstream os(dir/"agglomerateSizes.dat");
        os  << "# Agglomerates per number of primaries k (k >= 2) of cloud "
            << cloudName_ << nl
            << "# k count" << nl;

        const List<label> sizes(sizeHistogram.sortedToc());
        for (const label k : sizes)
        {
            os  << k << ' ' << sizeHistogram[k] << nl;
        }
    }

    if (profiles_)
    {
        OFstream os(dir/"profiles.dat");
        os.precision(IOstream::defaultPrecision());
        os  << "# Profiles of cloud " << cloudName_ << " along "
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
}


// ************************************************************************* //
