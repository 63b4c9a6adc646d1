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

#include "breakupKernel.H"
#include "hardSphereCollisionKernel.H"
#include "keyedRandom.H"
#include "hardSphereInput.H"
#include "randomStreams.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::breakupKernel::breakupKernel
(
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision
)
:
    criterion_
    (
        coeffs, collision.material(), collision.structure(),
        collision.coeffs().en()
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
    ),
    randomSeed_(hardSphereInput::getSeed(coeffs))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::breakupKernel::keys()
{
    return {"randomSeed", "strength", "stresses", "fragmentation", "rate"};
}


bool Foam::breakupKernel::deferred
(
    const breakupCriterion::verdict& v,
    const breakupStresses::load& L,
    const scalar d,
    const scalar dt,
    const key& k
) const
{
    if
    (
        !v.breaks()
     || v.mechanism != breakupStresses::TURBULENCE
     || !rate_.stochastic()
    )
    {
        return false;
    }
    keyedRandom rnd
    (
        randomSeed_, randomStreams::breakupRate, k.origProc, k.origId,
        k.timeIndex, 0
    );
    return rnd.sample01() >= rate_.probability(dt, L.epsilon, L.nu, d);
}


Foam::agglomerateFragmentation::fragments Foam::breakupKernel::split
(
    const hardSphereState& parent,
    const breakupCriterion::verdict& v,
    const symmTensor& S,
    const key& k
) const
{
    keyedRandom rnd
    (
        randomSeed_, randomStreams::breakup, k.origProc, k.origId,
        k.timeIndex, 0
    );
    const label N1 = fragmentation_.fragmentSize(parent.nPrimary, rnd);
    const vector e =
        fragmentation_.direction
        (
            S, parent.omega, v.mechanism == breakupStresses::ROTATION, rnd
        );
    return fragmentation_.split(parent, N1, e);
}


// ************************************************************************* //
