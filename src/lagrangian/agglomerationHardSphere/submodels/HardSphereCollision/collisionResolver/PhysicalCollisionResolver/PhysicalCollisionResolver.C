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

#include "PhysicalCollisionResolver.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class ParcelType>
void Foam::PhysicalCollisionResolver<ParcelType>::makeAgglomerate
(
    ParcelType& p,
    const hardSphereState& ag,
    const point& xAg
)
{
    p.U() = ag.U;
    p.omega() = ag.omega;
    p.d() = ag.d;
    p.rho() = ag.rho;
    p.nPrimary() = ag.nPrimary;
    p.lastPartnerProc() = -1;
    p.lastPartnerId() = -1;
    p.lastContactTime() = -GREAT;
    p.stage().markCollided();
    p.stage().markFormed();
    p.stage().relocateTo(xAg);
}


template<class ParcelType>
void Foam::PhysicalCollisionResolver<ParcelType>::remove(ParcelType& p)
{
    p.stage().markCollided();
    p.stage().markRemoved();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::PhysicalCollisionResolver<ParcelType>::PhysicalCollisionResolver
(
    const dictionary& dict,
    const hardSphereCollisionKernel& kernel
)
:
    CollisionResolver<ParcelType>(dict, kernel)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::PhysicalCollisionResolver<ParcelType>::resolve
(
    collisionEventRecord& event,
    ParcelType& pi,
    ParcelType* pjReal,
    const bool iLow,
    const point& xi1,
    const point& xj1,
    const scalar dt
)
{
    collisionOutcome& outcome = event.outcome;
    this->kernel_.collide(event.p1, event.p2, outcome);
    event.applied = true;

    const hardSphereState& si = iLow ? event.p1 : event.p2;
    const hardSphereState& sj = iLow ? event.p2 : event.p1;

    if (outcome.agglomerates)
    {
        // The lower-id partner becomes the agglomerate at the centre of
        // mass of the end-of-step positions (Eq. 81); the other goes
        const scalar mi = si.mass();
        const scalar mj = sj.mass();
        const point xAg((mi*xi1 + mj*xj1)/(mi + mj));

        if (iLow)
        {
            makeAgglomerate(pi, outcome.agglomerate, xAg);
            if (pjReal) remove(*pjReal);
        }
        else
        {
            remove(pi);
            if (pjReal) makeAgglomerate(*pjReal, outcome.agglomerate, xAg);
        }
        return;
    }

    // Rebound
    const hardSphereState& newI = iLow ? outcome.p1 : outcome.p2;
    const hardSphereState& newJ = iLow ? outcome.p2 : outcome.p1;
    const bool separate =
        this->overlapTreatment_ == CollisionResolver<ParcelType>::
            OVERLAP_SEPARATE;

    point xiNew(xi1);
    point xjNew(xj1);
    if (separate)
    {
        const scalar rest = (1 - event.s)*dt;
        xiNew = si.x + rest*newI.U;
        xjNew = sj.x + rest*newJ.U;

        const scalar R = 0.5*(si.d + sj.d);
        const vector e(xjNew - xiNew);
        const scalar me = mag(e);
        if (me < R && me > VSMALL)
        {
            const scalar delta = R - me;
            const scalar mi = si.mass();
            const scalar mj = sj.mass();
            xiNew -= (mj/(mi + mj))*delta*e/me;
            xjNew += (mi/(mi + mj))*delta*e/me;
        }
    }

    auto rebound = [&]
    (
        ParcelType& p,
        const hardSphereState& st,
        const labelPair& partner,
        const point& xNew
    )
    {
        p.U() = st.U;
        p.omega() = st.omega;
        this->remember(p, partner, event.time);
        p.stage().markCollided();
        if (separate)
        {
            p.stage().relocateTo(xNew);
        }
    };

    const labelPair idI = iLow ? event.id1() : event.id2();
    const labelPair idJ = iLow ? event.id2() : event.id1();
    rebound(pi, newI, idJ, xiNew);
    if (pjReal)
    {
        rebound(*pjReal, newJ, idI, xjNew);
    }
}


// ************************************************************************* //
