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

Description
    HardSphereCollision: applying the accepted events, the wall contacts
    at one radius and the centre-hit fallback (included by
    HardSphereCollision.C).

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCollision<CloudType>::applyEvents
(
    const UList<parcelType*>& parcels,
    const UList<point>& x1
)
{
    typedef collisionSchedule::globalId globalId;
    typedef FixedList<label, 4> pairKey;

    hardSphereStep& step = this->step_;
    const label n = parcels.size();
    const scalar dt = this->owner().db().time().deltaTValue();
    const scalar tStart = this->owner().db().time().value() - dt;
    const bool ghost = collisionResponse_ == RESPONSE_GHOST;

    auto key = [](const globalId& a, const globalId& b)
    {
        return pairKey({a[0], a[1], b[0], b[1]});
    };

    // Contact point of an event, seen from partner 1
    auto contactPoint = []
    (
        const point& xc1,
        const scalar d1,
        const point& xc2
    )
    {
        const scalar l = mag(xc2 - xc1);
        if (l < VSMALL)
        {
            return xc1;
        }
        const vector n12((xc2 - xc1)/l);
        return point(xc1 + 0.5*d1*n12);
    };

    collisionOutcome outcome;

    // Ghost mode: (pair, real side) already counted, against a second
    // periodic image of the same pair
    HashSet<pairKey, pairKey::Hash<>> ghostDone;

    forAll(schedule_.accepted(), a)
    {
        const candidate& c = candidates_[schedule_.accepted()[a]];

        // Every copy of the pair (from the other processor, through another
        // image) at the event's contact time: one geometry for both
        const scalar s = schedule_.acceptedS()[a];

        parcelType& pi = *parcels[c.i];
        parcelType* pjRealPtr = c.j < n ? parcels[c.j] : nullptr;
        const parcelType& pj =
            pjRealPtr ? *pjRealPtr : referred(c.j - n);
        const point& xj1 =
            pjRealPtr ? x1[c.j] : referredPosition(c.j - n);

        const globalId idI({pi.origProc(), pi.origId()});
        const globalId idJ({pj.origProc(), pj.origId()});
        const scalar tc = tStart + s*dt;

        if (ghost)
        {
            // Count once per pair where the lower-id partner is real;
            // both real partners remember each other
            if (!ghostDone.insert(key(idI, idJ)))
            {
                continue;
            }

            if (c.iLow || pjRealPtr)
            {
                const point xci
                (
                    pi.position0() + s*(x1[c.i] - pi.position0())
                );
                const point xcj(pj.position0() + s*(xj1 - pj.position0()));
                step.count
                (
                    c.category, contactPoint(xci, pi.d(), xcj), nullptr
                );
                if (log_.valid())
                {
                    const hardSphereState si
                    (
                        xci, pi.U(), pi.omega(), pi.d(), pi.rho(),
                        pi.nPrimary()
                    );
                    const hardSphereState sj
                    (
                        xcj, pj.U(), pj.omega(), pj.d(), pj.rho(),
                        pj.nPrimary()
                    );
                    log_->record
                    (
                        c.iLow ? si : sj, c.iLow ? sj : si,
                        c.iLow ? labelPair(idI[0], idI[1])
                               : labelPair(idJ[0], idJ[1]),
                        c.iLow ? labelPair(idJ[0], idJ[1])
                               : labelPair(idI[0], idI[1]),
                        c.category, s, pi.cell(), nullptr
                    );
                }
            }

            pi.lastPartnerProc() = idJ[0];
            pi.lastPartnerId() = idJ[1];
            pi.lastContactTime() = tc;
            if (pjRealPtr)
            {
                pjRealPtr->lastPartnerProc() = idI[0];
                pjRealPtr->lastPartnerId() = idI[1];
                pjRealPtr->lastContactTime() = tc;
            }
            continue;
        }

        if (pi.hasStatus(parcelType::COLLIDED))
        {
            // The same pair through a second periodic image
            continue;
        }

        const vector dxi(x1[c.i] - pi.position0());
        const vector dxj(xj1 - pj.position0());
        const point xic(pi.position0() + s*dxi);
        const point xjc(pj.position0() + s*dxj);

        const hardSphereState si
        (
            xic, pi.U(), pi.omega(), pi.d(), pi.rho(), pi.nPrimary()
        );
        const hardSphereState sj
        (
            xjc, pj.U(), pj.omega(), pj.d(), pj.rho(), pj.nPrimary()
        );

        const hardSphereState& s1 = c.iLow ? si : sj;
        const hardSphereState& s2 = c.iLow ? sj : si;

        kernel_.collide(s1, s2, outcome);

        // Counted (and logged) once: where the lower-id partner is real
        if (c.iLow || pjRealPtr)
        {
            step.count
            (
                c.category, contactPoint(s1.x, s1.d, s2.x), &outcome
            );
            if (log_.valid())
            {
                const globalId& id1 = c.iLow ? idI : idJ;
                const globalId& id2 = c.iLow ? idJ : idI;
                log_->record
                (
                    s1, s2, labelPair(id1[0], id1[1]),
                    labelPair(id2[0], id2[1]), c.category, s, pi.cell(),
                    &outcome
                );
            }
        }

        if (outcome.agglomerates)
        {
            // The lower-id partner becomes the agglomerate at the centre of
            // mass of the end-of-step positions (Eq. 81); the other goes
            const scalar mi = si.mass();
            const scalar mj = sj.mass();
            const point xAg((mi*x1[c.i] + mj*xj1)/(mi + mj));

            auto makeAgglomerate = [&](parcelType& p)
            {
                const hardSphereState& ag = outcome.agglomerate;
                p.U() = ag.U;
                p.omega() = ag.omega;
                p.d() = ag.d;
                p.rho() = ag.rho;
                p.nPrimary() = ag.nPrimary;
                p.lastPartnerProc() = -1;
                p.lastPartnerId() = -1;
                p.lastContactTime() = -GREAT;
                p.position0() = xAg;
                p.setStatus(parcelType::COLLIDED);
                p.setStatus(parcelType::RELOCATE);
                p.setStatus(parcelType::FORMED);
            };

            auto remove = [](parcelType& p)
            {
                p.setStatus(parcelType::COLLIDED);
                p.setStatus(parcelType::REMOVE);
            };

            if (c.iLow)
            {
                makeAgglomerate(pi);
                if (pjRealPtr) remove(*pjRealPtr);
            }
            else
            {
                remove(pi);
                if (pjRealPtr) makeAgglomerate(*pjRealPtr);
            }
            continue;
        }

        // Rebound
        const hardSphereState& newI = c.iLow ? outcome.p1 : outcome.p2;
        const hardSphereState& newJ = c.iLow ? outcome.p2 : outcome.p1;
        const bool separate = (overlapTreatment_ == OVERLAP_SEPARATE);

        point xiNew(x1[c.i]);
        point xjNew(xj1);
        if (separate)
        {
            const scalar rest = (1 - s)*dt;
            xiNew = xic + rest*newI.U;
            xjNew = xjc + rest*newJ.U;

            const scalar R = 0.5*(pi.d() + pj.d());
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
            parcelType& p,
            const hardSphereState& st,
            const globalId& partner,
            const point& xNew
        )
        {
            p.U() = st.U;
            p.omega() = st.omega;
            p.lastPartnerProc() = partner[0];
            p.lastPartnerId() = partner[1];
            p.lastContactTime() = tc;
            p.setStatus(parcelType::COLLIDED);
            if (separate)
            {
                p.position0() = xNew;
                p.setStatus(parcelType::RELOCATE);
            }
        };

        rebound(pi, newI, idJ, xiNew);
        if (pjRealPtr)
        {
            rebound(*pjRealPtr, newJ, idI, xjNew);
        }
    }
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::wallContact
(
    parcelType& p,
    const point& x
)
{
    const scalar dt = this->owner().db().time().deltaTValue();

    hardSphereWallInteraction::particle wp
    {
        p.origProc(), p.origId(), p.d(), p.U(), p.omega(), &p.UTurb()
    };
    bool moved = false;
    point xNew;

    const hardSphereWallInteraction::resultType result =
        walls_.contactAtRadius
        (
            x, wallFaces(p.cell(), 0.5*p.d()), dt, wp, moved, xNew
        );

    if (result == hardSphereWallInteraction::IMPACT)
    {
        ++this->step_.counts[hardSphereStep::WALL];
    }
    if (moved)
    {
        p.position0() = xNew;
        p.setStatus(parcelType::RELOCATE);
    }
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::wallContacts
(
    const UList<parcelType*>& parcels,
    UList<point>& x1
)
{
    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];

        if (p.hasStatus(parcelType::REMOVE) || p.hasStatus(parcelType::FORMED))
        {
            continue;
        }

        // Relocated by an event: from the relocation target
        if (p.hasStatus(parcelType::RELOCATE))
        {
            x1[i] = p.position0();
        }

        wallContact(p, x1[i]);
    }
}


template<class CloudType>
bool Foam::HardSphereCollision<CloudType>::hitWall
(
    parcelType& p,
    const polyPatch& pp
)
{
    if (!walls_.handles(pp.index()))
    {
        return false;
    }

    hardSphereWallInteraction::particle wp
    {
        p.origProc(), p.origId(), p.d(), p.U(), p.omega(), &p.UTurb()
    };

    if (walls_.hitCentre(p.face(), wp, p.stepFraction()))
    {
        ++this->step_.counts[hardSphereStep::WALL_CENTRE];
    }

    return true;
}


template<class CloudType>
bool Foam::HardSphereCollision<CloudType>::afterRelocation()
{
    bool relocate = false;

    if (walls_.atRadius())
    {
        for (parcelType& p : this->owner())
        {
            if (p.hasStatus(parcelType::FORMED))
            {
                // At the relocation target: position0 (exact)
                wallContact(p, p.position0());
                relocate = relocate || p.hasStatus(parcelType::RELOCATE);
            }
        }
    }

    return returnReduce(relocate, orOp<bool>());
}


// ************************************************************************* //
