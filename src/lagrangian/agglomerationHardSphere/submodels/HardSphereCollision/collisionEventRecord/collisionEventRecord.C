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
    id1(-1, -1),
    id2(-1, -1),
    category(0),
    s(0),
    tc(0),
    celli(-1),
    s1(),
    s2(),
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
    id1 = aLow ? idA : idB;
    id2 = aLow ? idB : idA;
    s1 = aLow ? sA : sB;
    s2 = aLow ? sB : sA;
    category = cat;
    s = sc;
    tc = t;
    celli = cell;
    applied = false;
}


Foam::point Foam::collisionEventRecord::contactPoint() const
{
    const vector d(s2.x - s1.x);
    const scalar l = mag(d);
    if (l < VSMALL)
    {
        return s1.x;
    }
    const vector n12(d/l);
    return point(s1.x + 0.5*s1.d*n12);
}


// ************************************************************************* //
