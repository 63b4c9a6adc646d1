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

#include "cloudMassBalance.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::cloudMassBalance::sums
(
    const CloudType& cloud,
    scalar& massInFlight,
    label& nPrimariesInFlight,
    scalar& massInjected,
    label& nInjected
)
{
    massInFlight = 0;
    nPrimariesInFlight = 0;
    for (const auto& p : cloud)
    {
        massInFlight += p.nParticle()*p.mass();
        nPrimariesInFlight += p.nPrimary();
    }
    reduce(massInFlight, sumOp<scalar>());
    reduce(nPrimariesInFlight, sumOp<label>());

    // The injectors' totals are global already
    massInjected = 0;
    nInjected = 0;
    forAll(cloud.injectors(), i)
    {
        massInjected += cloud.injectors()[i].massInjected();
        nInjected += cloud.injectors()[i].parcelsAddedTotal();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::cloudMassBalance::start(const CloudType& cloud)
{
    scalar mass, injected;
    label nPrimaries, nInjected;
    sums(cloud, mass, nPrimaries, injected, nInjected);

    if (restarted_)
    {
        check(mass, nPrimaries, injected, nInjected);
        return;
    }
    massStart_ = mass + lostMass() - injected;
    nPrimariesStart_ = nPrimaries + lostPrimaries() - nInjected;
}


template<class CloudType>
void Foam::cloudMassBalance::check(const CloudType& cloud) const
{
    scalar mass, injected;
    label nPrimaries, nInjected;
    sums(cloud, mass, nPrimaries, injected, nInjected);
    check(mass, nPrimaries, injected, nInjected);
}


// ************************************************************************* //
