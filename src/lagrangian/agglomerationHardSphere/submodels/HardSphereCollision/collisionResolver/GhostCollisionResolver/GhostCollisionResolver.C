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

#include "GhostCollisionResolver.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::GhostCollisionResolver<ParcelType>::GhostCollisionResolver
(
    const dictionary& dict,
    const hardSphereCollisionKernel& kernel
)
:
    CollisionResolver<ParcelType>(dict, kernel),
    done_()
{
    if (kernel.agglomeration().type() != "none")
    {
        FatalIOErrorInFunction(dict)
            << "collisionResponse ghost counts contacts without"
            << " applying them: set agglomerationModel none (it is "
            << kernel.agglomeration().type() << ")"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::GhostCollisionResolver<ParcelType>::resolve
(
    collisionEventRecord& event,
    ParcelType& pi,
    ParcelType* pjReal,
    const bool iLow,
    const point&,
    const point&,
    const scalar
)
{
    event.applied = false;
    this->remember(pi, iLow ? event.id2() : event.id1(), event.time);
    if (pjReal)
    {
        this->remember(*pjReal, iLow ? event.id1() : event.id2(), event.time);
    }
}


// ************************************************************************* //
