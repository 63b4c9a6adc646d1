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

#include "CollisionCandidates.H"
#include "pairContact.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class ParcelType>
inline void Foam::CollisionCandidates<ParcelType>::markNearPartners
(
    const label i,
    const label j,
    const bool jReal,
    const encounterMemory::memory& mi,
    const encounterMemory::memory& mj,
    const vector& xij1,
    const scalar R,
    const encounterMemory& memory
)
{
    if
    (
        (mi.lastPartner[1] >= 0 || (jReal && mj.lastPartner[1] >= 0))
     && memory.near(magSqr(xij1), R)
    )
    {
        if (mi.lastPartner == mj.id)
        {
            partnerNear_[i] = true;
        }
        if (jReal && mj.lastPartner == mi.id)
        {
            partnerNear_[j] = true;
        }
    }
}


template<class ParcelType>
void Foam::CollisionCandidates<ParcelType>::forgetFarPartners
(
    const UList<ParcelType*>& parcels
)
{
    forAll(parcels, i)
    {
        if (!partnerNear_[i] && parcels[i]->lastPartnerId() >= 0)
        {
            parcels[i]->lastPartnerProc() = -1;
            parcels[i]->lastPartnerId() = -1;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::CollisionCandidates<ParcelType>::find
(
    const UList<ParcelType*>& parcels,
    const UList<point>& x1,
    PairSearch<ParcelType>& search,
    const scalar distance,
    const encounterMemory& memory,
    const scalar tStart,
    const scalar dt
)
{
    typedef collisionSchedule::globalId globalId;

    const label n = parcels.size();

    schedule_.clear();
    candidates_.clear();
    partnerNear_.setSize(n);
    partnerNear_ = false;
    pairContact pc;

    auto evaluate = [&](const label i, const label j)
    {
        const ParcelType& pi = *parcels[i];
        const bool jReal = j < n;
        const ParcelType& pj = jReal ? *parcels[j] : search.referred(j - n);
        const point& xj1 = jReal ? x1[j] : search.referredPosition(j - n);

        const point& xi0 = pi.stage().startPosition();
        const point& xj0 = pj.stage().startPosition();
        const vector dxi(x1[i] - xi0);
        const vector dxj(xj1 - xj0);
        const scalar R = 0.5*(pi.d() + pj.d());

        const encounterMemory::memory mi
            {{pi.origProc(), pi.origId()}, pi.lastPartner(),
             pi.lastContactTime()};
        const encounterMemory::memory mj
            {{pj.origProc(), pj.origId()}, pj.lastPartner(),
             pj.lastContactTime()};

        markNearPartners(i, j, jReal, mi, mj, xj1 - x1[i], R, memory);

        if (!pc.find(xi0, dxi, xj0, dxj, R))
        {
            return;
        }

        const globalId idI({mi.id.first(), mi.id.second()});
        const globalId idJ({mj.id.first(), mj.id.second()});

        candidate c;
        c.i = i;
        c.j = j;
        c.iLow = collisionSchedule::lessId(idI, idJ);
        c.category =
            memory.category(pc.overlapStart, mi, mj, tStart + pc.s*dt);

        const vector xij
        (
            (xj0 + pc.s*dxj) - (xi0 + pc.s*dxi)
        );
        const scalar mxij = mag(xij);
        const bool separating =
            mxij < VSMALL || ((pj.U() - pi.U()) & (xij/mxij)) >= 0;

        schedule_.append(pc.s, idI, idJ, separating);
        candidates_.append(c);
    };

    search.search(parcels, x1, distance, memory.reach(), evaluate);

    // Forget the last partners that moved beyond the release distance
    // (the categories of this step's events are already set)
    if (memory.releases())
    {
        forgetFarPartners(parcels);
    }
}


// ************************************************************************* //
