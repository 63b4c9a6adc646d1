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


void Foam::hardSphereStatisticsAccumulator::readCounters()
{
    if (!state_.found("counters"))
    {
        return;
    }

    // A counter or sum that the state lacks started with this run (another
    // agglomeration model before the restart)
    const dictionary& cd = state_.subDict("counters");
    forAll(counters_, i)
    {
        counters_[i] = cd.getOrDefault<label>(counterNames_[i], 0);
    }
    forAll(sums_, i)
    {
        sums_[i] = state_.getOrDefault<scalar>(sumNames_[i], 0);
    }
}


void Foam::hardSphereStatisticsAccumulator::updateState()
{
    dictionary cd;
    forAll(counters_, i)
    {
        cd.add(counterNames_[i], counters_[i]);
    }
    state_.set("counters", cd);
    forAll(sums_, i)
    {
        state_.set(sumNames_[i], sums_[i]);
    }

    if (profiles_.valid())
    {
        state_.set("profiles", profiles_->state());
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
    startTime_(mesh.time().timeName()),
    counterNames_(),
    sumNames_(),
    counters_(),
    sums_(),
    profiles_
    (
        dict.getOrDefault<bool>("profiles", false)
      ? new hardSphereProfiles(mesh, dict)
      : nullptr
    )
{
    if (profiles_.valid() && state_.found("profiles"))
    {
        profiles_->read(state_.subDict("profiles"));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hardSphereStatisticsAccumulator::start
(
    const wordList& counterNames,
    const wordList& sumNames
)
{
    counterNames_ = counterNames;
    sumNames_ = sumNames;
    counters_.setSize(counterNames.size(), Zero);
    sums_.setSize(sumNames.size(), Zero);
    readCounters();

    if (Pstream::master())
    {
        const fileName dir(baseDir()/startTime_);
        mkDir(dir);
        statsFilePtr_.reset(new OFstream(dir/"stats.dat"));

        OFstream& os = statsFilePtr_();
        os.precision(IOstream::defaultPrecision());
        os  << "# Hard-sphere statistics of cloud " << cloudName_ << nl
            << "# Counters are cumulative since the start of the run"
            << " (restart state)" << nl
            << "# Time nParticles nPrimaries nAgglomerates"
            << " nPrimariesInAgglomerates maxPrimaries";
        for (const word& name : counterNames_)
        {
            os  << ' ' << name;
        }
        os  << " aggRate D10 Dmax mass" << endl;
    }
}


void Foam::hardSphereStatisticsAccumulator::addCounts
(
    const List<label>& increments,
    const List<scalar>& sums
)
{
    forAll(counters_, i)
    {
        counters_[i] += increments[i];
    }
    forAll(sums_, i)
    {
        sums_[i] += sums[i];
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

    if (profiles_.valid())
    {
        profiles_->write(dir/"profiles.dat", cloudName_);
    }
}


// ************************************************************************* //
