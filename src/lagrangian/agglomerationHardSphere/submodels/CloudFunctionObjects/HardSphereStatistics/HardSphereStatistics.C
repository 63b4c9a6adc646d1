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

#include "HardSphereStatistics.H"
#include "hardSphereInput.H"
#include "encounterMemory.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::HardSphereStatistics<CloudType>::HardSphereStatistics
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    stats_(nullptr)
{
    hardSphereInput::checkKeys
    (
        dict,
        {"type", "profiles", "direction", "nBins"}
    );
    stats_.reset
    (
        new hardSphereStatisticsAccumulator(owner.mesh(), owner.name(), dict)
    );
}


template<class CloudType>
Foam::HardSphereStatistics<CloudType>::HardSphereStatistics
(
    const HardSphereStatistics<CloudType>& hs
)
:
    CloudFunctionObject<CloudType>(hs),
    stats_(nullptr)
{
    // A second accumulator would start stats.dat again
    FatalErrorInFunction
        << "The hardSphereStatistics of cloud " << hs.owner().name()
        << " cannot be copied (the hard-sphere cloud is transient and is"
        << " never copied)" << exit(FatalError);
}


// * * * * * * * * * * * * * * * Private Classes * * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereStatistics<CloudType>::particleSums::reduce()
{
    Foam::reduce(nParticles, sumOp<label>());
    Foam::reduce(nPrimaries, sumOp<label>());
    Foam::reduce(nAgglomerates, sumOp<label>());
    Foam::reduce(nPrimariesInAgglomerates, sumOp<label>());
    Foam::reduce(maxPrimaries, maxOp<label>());
    Foam::reduce(sumD, sumOp<scalar>());
    Foam::reduce(Dmax, maxOp<scalar>());
    Foam::reduce(mass, sumOp<scalar>());
}


template<class CloudType>
Foam::HardSphereStatistics<CloudType>::slabSums::slabSums(const label n)
:
    colBin(n, Zero),
    colFirstBin(n, Zero),
    aggBin(n, Zero),
    visits(n, Zero),
    volume(n, Zero),
    sumDBin(n, Zero),
    sumU(n, Zero),
    sumUU(n, Zero)
{}


template<class CloudType>
void Foam::HardSphereStatistics<CloudType>::slabSums::reduce()
{
    Foam::reduce(colBin, sumOp<scalarField>());
    Foam::reduce(colFirstBin, sumOp<scalarField>());
    Foam::reduce(aggBin, sumOp<scalarField>());
    Foam::reduce(visits, sumOp<scalarField>());
    Foam::reduce(volume, sumOp<scalarField>());
    Foam::reduce(sumDBin, sumOp<scalarField>());
    Foam::reduce(sumU, sumOp<vectorField>());
    Foam::reduce(sumUU, sumOp<symmTensorField>());
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::hardSphereStep&
Foam::HardSphereStatistics<CloudType>::stepRecord() const
{
    const CloudType& cloud = this->owner();
    if (!cloud.template foundObject<hardSphereStep>(hardSphereStep::typeName))
    {
        FatalErrorInFunction
            << "The function object hardSphereStatistics needs a"
            << " hard-sphere cloud; " << cloud.name()
            << " is not one" << exit(FatalError);
    }
    return cloud.template lookupObject<hardSphereStep>
    (
        hardSphereStep::typeName
    );
}


template<class CloudType>
void Foam::HardSphereStatistics<CloudType>::sumParticles
(
    const hardSphereProfiles* profiles,
    particleSums& s,
    slabSums& b,
    Map<label>& histogram,
    const bool writeTime
) const
{
    const vectorField& K =
        profiles ? profiles->meanU() : vectorField::null();

    for (const parcelType& p : this->owner())
    {
        ++s.nParticles;
        s.nPrimaries += p.nPrimary();
        if (p.nPrimary() > 1)
        {
            ++s.nAgglomerates;
            s.nPrimariesInAgglomerates += p.nPrimary();
            if (writeTime)
            {
                ++histogram(p.nPrimary(), 0);
            }
        }
        s.maxPrimaries = max(s.maxPrimaries, p.nPrimary());
        s.sumD += p.d();
        s.Dmax = max(s.Dmax, p.d());
        s.mass += p.nParticle()*p.mass();

        if (profiles)
        {
            // The position of the collision stage where known
            const label k = profiles->bin
            (
                p.stage().positionKnown()
              ? p.stage().knownPosition() : p.position()
            );
            if (k >= 0)
            {
                b.visits[k] += 1;
                b.volume[k] += p.nParticle()*p.volume();
                b.sumDBin[k] += p.d();
                b.sumU[k] += p.U();
                b.sumUU[k] += sqr(p.U() - K[k]);
            }
        }
    }
}


template<class CloudType>
void Foam::HardSphereStatistics<CloudType>::binEvents
(
    const hardSphereStep& step,
    const hardSphereProfiles& profiles,
    slabSums& b
)
{
    forAll(step.eventPoint, e)
    {
        const label k = profiles.bin(step.eventPoint[e]);
        if (k >= 0)
        {
            b.colBin[k] += 1;
            if (step.eventCategory[e] == encounterMemory::FIRST)
            {
                b.colFirstBin[k] += 1;
            }
            if (step.eventAgglomerates[e])
            {
                b.aggBin[k] += 1;
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereStatistics<CloudType>::postEvolve()
{
    typedef hardSphereStep hs;
    const hardSphereStep& step = stepRecord();
    hardSphereStatisticsAccumulator& st = stats_();

    // Counters (named by the collision stage and its agglomeration model)
    if (!st.started())
    {
        st.start(step.counterNames(), step.sumNames());
    }
    labelField globalCounts(step.counts);
    reduce(globalCounts, sumOp<labelField>());
    scalarField globalSums(step.sums);
    reduce(globalSums, sumOp<scalarField>());
    st.addCounts(globalCounts, globalSums);

    // Particles, and the profiles' slabs
    const Time& runTime = this->owner().db().time();
    const bool writeTime = runTime.writeTime();
    hardSphereProfiles* profiles = st.profiles();
    particleSums s;
    slabSums b(profiles ? profiles->nBins() : 0);
    Map<label> histogram;
    sumParticles(profiles, s, b, histogram, writeTime);
    s.reduce();
    if (profiles)
    {
        binEvents(step, *profiles, b);
        b.reduce();
        profiles->addEvents(b.colBin, b.colFirstBin, b.aggBin);
        profiles->addParticles(b.visits, b.volume, b.sumDBin, b.sumU, b.sumUU);
    }

    st.writeStep
    (
        runTime.value(),
        s.nParticles,
        s.nPrimaries,
        s.nAgglomerates,
        s.nPrimariesInAgglomerates,
        s.maxPrimaries,
        s.nParticles ? s.sumD/s.nParticles : 0,
        s.Dmax,
        s.mass
    );

    if (writeTime)
    {
        Pstream::mapCombineGather(histogram, plusEqOp<label>());
        Pstream::mapCombineScatter(histogram);
        st.writeTime(histogram);
    }

    const label* c = st.counters().cdata();
    Info<< "    Hard-sphere: nCol " << c[hs::COL]
        << " (step " << globalCounts[hs::COL]
        << "), nAgg " << c[hs::AGG]
        << " (step " << globalCounts[hs::AGG]
        << "), nWall " << c[hs::WALL]
        << ", suppressed " << c[hs::SUPPRESSED]
        << ", particles " << s.nParticles
        << ", agglomerates " << s.nAgglomerates << endl;
}


// ************************************************************************* //
