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

#include "collisionEventRecord.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionEventRecord::collisionEventRecord()
:
    collisionEvent(),
    s(0),
    celli(-1),
    applied(false),
    outcome()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionEventRecord::set
(
    const labelPair& idA,
    const hardSphereState& sA,
    const labelPair& idB,
    const hardSphereState& sB,
    const bool aLow,
    const label cat,
    const scalar sc,
    const scalar t,
    const label cell
)
{
    const labelPair& lo = aLow ? idA : idB;
    const labelPair& hi = aLow ? idB : idA;
    proc[0] = lo.first();
    id[0] = lo.second();
    proc[1] = hi.first();
    id[1] = hi.second();
    p1 = aLow ? sA : sB;
    p2 = aLow ? sB : sA;
    category = cat;
    s = sc;
    time = t;
    celli = cell;
    applied = false;
}


Foam::point Foam::collisionEventRecord::contactPoint() const
{
    const vector d(p2.x - p1.x);
    const scalar l = mag(d);
    if (l < VSMALL)
    {
        return p1.x;
    }
    const vector n12(d/l);
    return point(p1.x + 0.5*p1.d*n12);
}


// ************************************************************************* //
