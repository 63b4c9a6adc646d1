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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereStatistics<CloudType>::postEvolve()
{
    typedef hardSphereStep hs;

    // The collision model's record of the stage, in the cloud's registry
    const CloudType& cloud = this->owner();
    if (!cloud.template foundObject<hardSphereStep>(hs::typeName))
    {
        FatalErrorInFunction
            << "The function object hardSphereStatistics needs a"
            << " hard-sphere cloud; " << cloud.name()
            << " is not one" << exit(FatalError);
    }
    const hardSphereStep& step =
        cloud.template lookupObject<hardSphereStep>(hs::typeName);
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

    // Particles
    label nParticles = 0;
    label nPrimaries = 0;
    label nAgglomerates = 0;
    label nPrimariesInAgglomerates = 0;
    label maxPrimaries = 0;
    scalar sumD = 0;
    scalar Dmax = 0;
    scalar mass = 0;

    hardSphereProfiles* profiles = st.profiles();
    const label nBins = profiles ? profiles->nBins() : 0;
    scalarField colBin(nBins, Zero);
    scalarField colFirstBin(nBins, Zero);
    scalarField aggBin(nBins, Zero);
    scalarField visits(nBins, Zero);
    scalarField volume(nBins, Zero);
    scalarField sumDBin(nBins, Zero);
    vectorField sumU(nBins, Zero);
    symmTensorField sumUU(nBins, Zero);
    const vectorField& K =
        profiles ? profiles->meanU() : vectorField::null();

    const bool writeTime = cloud.db().time().writeTime();
    Map<label> histogram;

    for (const parcelType& p : cloud)
    {
        ++nParticles;
        nPrimaries += p.nPrimary();
        if (p.nPrimary() > 1)
        {
            ++nAgglomerates;
            nPrimariesInAgglomerates += p.nPrimary();
            if (writeTime)
            {
                ++histogram(p.nPrimary(), 0);
            }
        }
        maxPrimaries = max(maxPrimaries, p.nPrimary());
        sumD += p.d();
        Dmax = max(Dmax, p.d());
        mass += p.nParticle()*p.mass();

        if (profiles)
        {
            // The position of the collision stage where known
            const label b = profiles->bin
            (
                p.stage().positionKnown()
              ? p.stage().knownPosition() : p.position()
            );
            if (b >= 0)
            {
                visits[b] += 1;
                volume[b] += p.nParticle()*p.volume();
                sumDBin[b] += p.d();
                sumU[b] += p.U();
                sumUU[b] += sqr(p.U() - K[b]);
            }
        }
    }

    reduce(nParticles, sumOp<label>());
    reduce(nPrimaries, sumOp<label>());
    reduce(nAgglomerates, sumOp<label>());
    reduce(nPrimariesInAgglomerates, sumOp<label>());
    reduce(maxPrimaries, maxOp<label>());
    reduce(sumD, sumOp<scalar>());
    reduce(Dmax, maxOp<scalar>());
    reduce(mass, sumOp<scalar>());

    if (profiles)
    {
        // Events at their contact points
        forAll(step.eventPoint, k)
        {
            const label b = profiles->bin(step.eventPoint[k]);
            if (b >= 0)
            {
                colBin[b] += 1;
                if (step.eventCategory[k] == encounterMemory::FIRST)
                {
                    colFirstBin[b] += 1;
                }
                if (step.eventAgglomerates[k])
                {
                    aggBin[b] += 1;
                }
            }
        }

        reduce(colBin, sumOp<scalarField>());
        reduce(colFirstBin, sumOp<scalarField>());
        reduce(aggBin, sumOp<scalarField>());
        reduce(visits, sumOp<scalarField>());
        reduce(volume, sumOp<scalarField>());
        reduce(sumDBin, sumOp<scalarField>());
        reduce(sumU, sumOp<vectorField>());
        reduce(sumUU, sumOp<symmTensorField>());

        profiles->addEvents(colBin, colFirstBin, aggBin);
        profiles->addParticles(visits, volume, sumDBin, sumU, sumUU);
    }

    st.writeStep
    (
        cloud.db().time().value(),
        nParticles,
        nPrimaries,
        nAgglomerates,
        nPrimariesInAgglomerates,
        maxPrimaries,
        nParticles ? sumD/nParticles : 0,
        Dmax,
        mass
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
        << ", particles " << nParticles
        << ", agglomerates " << nAgglomerates << endl;
}


// ************************************************************************* //
