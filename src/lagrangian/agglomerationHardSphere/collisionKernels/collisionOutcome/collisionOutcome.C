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

#include "collisionOutcome.H"
#include <limits>

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::collisionOutcome::collisionType>
Foam::collisionOutcome::collisionTypeNames
({
    { collisionType::STICKING, "sticking" },
    { collisionType::SLIDING, "sliding" },
});


const Foam::Enum<Foam::collisionOutcome::branchType>
Foam::collisionOutcome::branchTypeNames
({
    { branchType::REBOUND, "rebound" },
    { branchType::AGGLOMERATE, "agglomerate" },
    { branchType::EQ21, "eq21" },
    { branchType::EQ65, "eq65" },
    { branchType::CASE_I, "caseI" },
    { branchType::CASE_II, "caseII" },
    { branchType::CASE_III_REBOUND, "caseIIIrebound" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionOutcome::collisionOutcome()
:
    type(STICKING),
    branch(REBOUND),
    agglomerates(false),
    p1(),
    p2(),
    agglomerate(),
    fna(std::numeric_limits<scalar>::quiet_NaN()),
    fnc(fna),
    fncStar(fna),
    tStar(fna),
    dEvdW(fna),
    EkinPlus(fna),
    ErotPlus(fna),
    ErotAg(fna),
    kn2(fna),
    kt2(fna),
    komega2(fna),
    deltaL(fna),
    critI(false),
    critII(false),
    spinClamped(false),
    dKEformation(fna),
    spinCapped(false)
{}


// ************************************************************************* //
