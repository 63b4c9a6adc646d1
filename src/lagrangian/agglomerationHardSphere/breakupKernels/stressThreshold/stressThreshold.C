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

#include "stressThreshold.H"
#include "hardSphereCollisionKernel.H"
#include "keyedRandom.H"
#include "randomStreams.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(stressThreshold, 0);
    addToRunTimeSelectionTable(breakupKernel, stressThreshold, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::stressThreshold::keys()
{
    return {"randomSeed", "strength", "stresses", "fragmentation", "rate"};
}


const Foam::hardSphereCollisionKernel& Foam::stressThreshold::checked
(
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision
)
{
    if (!collision.hasStructure() || !collision.agglomeration().cohesive())
    {
        FatalIOErrorInFunction(coeffs)
            << "breakupModel stressThreshold needs collisionModel hardSphere"
            << " with an agglomeration model (EAM, EAMAlletto2014 or MAM)"
            << " and a structureModel: the bond force and the fragments'"
            << " sizes are theirs" << exit(FatalIOError);
    }
    return collision;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stressThreshold::stressThreshold
(
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision
)
:
    breakupKernel(coeffs, keys()),
    criterion_
    (
        coeffs, checked(coeffs, collision).material(),
        collision.structure(), collision.coeffs().en()
    ),
    fragmentation_
    (
        coeffs.subDict("fragmentation"),
        collision.structure(),
        collision.material().rho0()
    ),
    rate_
    (
        coeffs.found("rate")
      ? breakupRate(coeffs.subDict("rate"))
      : breakupRate()
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::stressThreshold::mechanisms() const
{
    static const wordList names
    (
        breakupStresses::mechanismTypeNames.names()
    );
    return names;
}


Foam::wordList Foam::stressThreshold::fields() const
{
    return {"ratio", "sigmaT"};
}


bool Foam::stressThreshold::needsDrag() const
{
    return criterion_.stresses().on(breakupStresses::DRAG);
}


Foam::breakupKernel::verdict Foam::stressThreshold::check
(
    const hardSphereState& s,
    const breakupStresses::load& L,
    const scalar dt,
    const key& k
) const
{
    const breakupCriterion::verdict c = criterion_.check(s, L);
    verdict v;
    v.values[0] = c.ratio;
    v.values[1] = c.sigmaT;
    if (!c.breaks())
    {
        return v;
    }
    v.mechanism = c.mechanism;
    if (c.mechanism == breakupStresses::TURBULENCE && rate_.stochastic())
    {
        keyedRandom rnd
        (
            randomSeed_, randomStreams::breakupRate, k.origProc, k.origId,
            k.timeIndex, 0
        );
        v.deferred =
            rnd.sample01() >= rate_.probability(dt, L.epsilon, L.nu, s.d);
    }
    return v;
}


Foam::agglomerateFragmentation::fragments Foam::stressThreshold::split
(
    const hardSphereState& parent,
    const verdict& v,
    const symmTensor& S,
    const key& k,
    const label attempt
) const
{
    keyedRandom rnd
    (
        randomSeed_, randomStreams::breakup, k.origProc, k.origId,
        k.timeIndex, 0
    );
    const label N1 = fragmentation_.fragmentSize(parent.nPrimary, rnd);
    const bool byRotation = v.mechanism == breakupStresses::ROTATION;
    vector e = fragmentation_.direction(S, parent.omega, byRotation, rnd);
    if (attempt)
    {
        // A further try's own draws (the first try's are keyed by 0)
        keyedRandom rndTry
        (
            randomSeed_, randomStreams::breakup, k.origProc, k.origId,
            k.timeIndex, attempt
        );
        e = fragmentation_.retryDirection
        (
            e, S, parent.omega, byRotation, attempt, rndTry
        );
    }
    return fragmentation_.split(parent, N1, e);
}


void Foam::stressThreshold::write(Ostream& os) const
{
    rate_.write(os);
}


// ************************************************************************* //
