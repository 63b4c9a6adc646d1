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

#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::hardSphereStep::globalSums
(
    const CloudType& cloud,
    scalar& mass,
    label& nPrimaries
)
{
    mass = 0;
    nPrimaries = 0;
    for (const auto& p : cloud)
    {
        mass += p.nParticle()*p.mass();
        nPrimaries += p.nPrimary();
    }
    reduce(mass, sumOp<scalar>());
    reduce(nPrimaries, sumOp<label>());
}


template<class CloudType>
void Foam::hardSphereStep::auditAfter
(
    const CloudType& cloud,
    const scalar lostMass,
    const label lostPrimaries
) const
{
    scalar mass;
    label nPrimaries;
    globalSums(cloud, mass, nPrimaries);
    audit(mass + lostMass, nPrimaries + lostPrimaries);
}


// ************************************************************************* //
