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

#include "stepPeriod.H"
#include "error.H"
#include <limits>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::stepPeriod::greatestCommonDivisor(label a, label b)
{
    while (b != 0)
    {
        const label r = a % b;
        a = b;
        b = r;
    }
    return a;
}


void Foam::stepPeriod::include(const label interval)
{
    if (interval <= 0)
    {
        return;
    }
    const label factor = steps_/greatestCommonDivisor(steps_, interval);
    if (factor > std::numeric_limits<label>::max()/interval)
    {
        FatalErrorInFunction
            << "The least common multiple of " << steps_ << " and "
            << interval << " steps exceeds the largest label" << nl
            << exit(FatalError);
    }
    steps_ = factor*interval;
}


// ************************************************************************* //
