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

#include "hardSphereStep.H"
#include "collisionOutcome.H"
#include "agglomerationModel.H"
#include "objectRegistry.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(hardSphereStep, 0);
}


const Foam::Enum<Foam::hardSphereStep::counterType>
Foam::hardSphereStep::commonCounterNames
({
    { counterType::COL, "nCol" },
    { counterType::COL_FIRST, "nColFirst" },
    { counterType::COL_REPEAT, "nColRepeat" },
    { counterType::COL_OVERLAP, "nColOverlapStart" },
    { counterType::AGG, "nAgg" },
    { counterType::AGG_FIRST, "nAggFirst" },
    { counterType::AGG_REPEAT, "nAggRepeat" },
    { counterType::AGG_OVERLAP, "nAggOverlapStart" },
    { counterType::SUPPRESSED, "nSuppressed" },
    { counterType::SKIP_SEPARATING, "nSkipSeparating" },
    { counterType::WALL, "nWall" },
    { counterType::WALL_CENTRE, "nWallCentre" },
    { counterType::STICKING, "nSticking" },
    { counterType::ENERGY_GAIN, "nEnergyGain" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardSphereStep::hardSphereStep(const objectRegistry& cloud)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            cloud.time().timeName(),
            cloud,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    counts(N_COUNTERS, Zero),
    sums(1, Zero),
    eventPoint(),
    eventCategory(),
    eventAgglomerates(),
    mass0(-1),
    nPrimaries0(-1),
    model_(nullptr),
    extraCounterNames_(),
    extraSumNames_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hardSphereStep::setModel(const agglomerationModel& model)
{
    model_ = &model;
    resize();
}


Foam::labelPair Foam::hardSphereStep::addColumns
(
    const wordList& counterNames,
    const wordList& sumNames
)
{
    const labelPair offsets(counts.size(), sums.size());
    extraCounterNames_.append(counterNames);
    extraSumNames_.append(sumNames);
    resize();
    return offsets;
}


void Foam::hardSphereStep::resize()
{
    counts.setSize(counterNames().size());
    sums.setSize(sumNames().size());
    reset();
}


Foam::wordList Foam::hardSphereStep::counterNames() const
{
    wordList names(commonCounterNames.names());
    if (model_)
    {
        names.append(model_->counterNames());
    }
    names.append(extraCounterNames_);
    return names;
}


Foam::wordList Foam::hardSphereStep::sumNames() const
{
    wordList names({"agglomerationEnergyGain"});
    if (model_)
    {
        names.append(model_->sumNames());
    }
    names.append(extraSumNames_);
    return names;
}


void Foam::hardSphereStep::reset()
{
    counts = 0;
    sums = 0;
    eventPoint.clear();
    eventCategory.clear();
    eventAgglomerates.clear();
    mass0 = -1;
    nPrimaries0 = -1;
}


void Foam::hardSphereStep::audit
(
    const scalar mass,
    const label nPrimaries
) const
{
    if
    (
        mass0 < 0
     || (
            nPrimaries == nPrimaries0
         && mag(mass - mass0) <= 1e-11*max(mass0, VSMALL)
        )
    )
    {
        return;
    }

    FatalErrorInFunction
        << "Particle mass or primaries not conserved by the"
        << " collision stage: mass " << mass0 << " -> " << mass
        << ", primaries " << nPrimaries0 << " -> " << nPrimaries
        << exit(FatalError);
}


void Foam::hardSphereStep::observe(const collisionEventRecord& event)
{
    const label category = event.category;
    const point xc(event.contactPoint());
    const collisionOutcome* outcome = event.outcomePtr();

    ++counts[COL];
    ++counts[COL_FIRST + category];

    const bool agglomerates = outcome && outcome->agglomerates;

    eventPoint.append(xc);
    eventCategory.append(category);
    eventAgglomerates.append(agglomerates);

    if (!outcome)
    {
        return;
    }

    const collisionOutcome& o = *outcome;

    if (agglomerates)
    {
        ++counts[AGG];
        ++counts[AGG_FIRST + category];

        if (o.dKEformation > 0)
        {
            ++counts[ENERGY_GAIN];
            sums[0] += o.dKEformation;
        }
    }
    if (o.isSticking())
    {
        ++counts[STICKING];
    }
    if (model_)
    {
        // The model's counters and sums follow the common ones
        SubList<label> modelCounts
        (
            counts,
            counts.size() - N_COUNTERS,
            N_COUNTERS
        );
        SubList<scalar> modelSums(sums, sums.size() - 1, 1);
        model_->count(o, modelCounts, modelSums);
    }
}


// ************************************************************************* //
