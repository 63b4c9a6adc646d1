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
    The placement of the fragments among their neighbours (doc/breakup.md
    3.2): no fragment overlaps another particle, on any rank or through
    any cyclic patch.

\*---------------------------------------------------------------------------*/

#include "AgglomerateBreakup.H"
#include "PairSearch.H"
#include "collisionSchedule.H"
#include "hardSphereParcelStage.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::point Foam::AgglomerateBreakup<CloudType>::placeOf(const parcelType& p)
{
    const hardSphereParcelStage& st = p.stage();
    if (st.relocating())
    {
        return st.relocationTarget();
    }
    return st.positionKnown() ? st.knownPosition() : p.position();
}


template<class CloudType>
bool Foam::AgglomerateBreakup<CloudType>::clear
(
    const agglomerateFragmentation::fragments& f,
    const UList<neighbour>& near,
    const labelPair& id
)
{
    for (const neighbour& nb : near)
    {
        if (nb.id == id)
        {
            continue;
        }
        for (const hardSphereState* q : {&f.a, &f.b})
        {
            if (magSqr(q->x - nb.x) < sqr(0.5*(q->d + nb.d)))
            {
                return false;
            }
        }
    }
    return true;
}


template<class CloudType>
void Foam::AgglomerateBreakup<CloudType>::neighbours
(
    const stepSurvey& s,
    const scalar inflate,
    List<DynamicList<neighbour>>& near
)
{
    CloudType& cloud = this->owner();
    PairSearch<parcelType>& search = *cloud.collision().pairSearch();

    // The parents' indices by global id
    HashTable<label, labelPair, Hash<labelPair>> parentIndex;
    forAll(s.ids, k)
    {
        parentIndex.insert(s.ids[k], k);
    }

    // Every particle at its place after the collision stage; the span of
    // the search as the stage's (the boxes sweep from the step's start)
    const label n = cloud.size();
    List<parcelType*> parcels(n);
    List<point> x(n);
    labelList parentOf(n, -1);
    scalar dMax = 0, dxMag = 0;
    vector dxMax(Zero);
    label i = 0;
    for (parcelType& p : cloud)
    {
        parcels[i] = &p;
        x[i] = placeOf(p);
        parentOf[i] =
            parentIndex.lookup(labelPair(p.origProc(), p.origId()), -1);
        const vector dx(x[i] - p.stage().startPosition());
        dMax = max(dMax, p.d());
        dxMag = max(dxMag, mag(dx));
        dxMax = max(dxMax, cmptMag(dx));
        ++i;
    }
    reduce(dMax, maxOp<scalar>());
    reduce(dxMag, maxOp<scalar>());
    reduce(dxMax, maxOp<vector>());
    const scalar distance =
        search.checkedDistance
        (
            dMax, dxMag, dxMax, inflate*dMax, cloud.name()
        );

    near.setSize(s.parents.size());
    search.search
    (
        parcels, x, distance, inflate,
        [&](const label i, const label j)
        {
            const bool jReal = j < n;
            const parcelType& pj =
                jReal ? *parcels[j] : search.referred(j - n);
            if (parentOf[i] >= 0)
            {
                near[parentOf[i]].append
                (
                    {
                        jReal ? x[j] : search.referredPosition(j - n),
                        pj.d(), labelPair(pj.origProc(), pj.origId())
                    }
                );
            }
            if (jReal && parentOf[j] >= 0)
            {
                const parcelType& pi = *parcels[i];
                near[parentOf[j]].append
                (
                    {x[i], pi.d(), labelPair(pi.origProc(), pi.origId())}
                );
            }
        }
    );
}


template<class CloudType>
void Foam::AgglomerateBreakup<CloudType>::place(stepSurvey& s)
{
    const label nParents = s.parents.size();
    if (!returnReduce(nParents > 0, orOp<bool>()))
    {
        return;
    }

    // The first try of each parent and the reach of its fragments from its
    // centre (the same for every direction: a try turns the line)
    List<agglomerateFragmentation::fragments> first(nParents);
    scalarList reach(nParents);
    scalar inflate = 1;
    forAll(s.events, k)
    {
        const breakupEvent& e = s.events[k];
        first[k] = splitOf(e, 0);
        const point& X = e.parent.x;
        reach[k] = max
        (
            0.5*e.parent.d,
            max
            (
                mag(first[k].a.x - X) + 0.5*first[k].a.d,
                mag(first[k].b.x - X) + 0.5*first[k].b.d
            )
        );
        // The search's boxes (half width inflate d/2) must meet where a
        // fragment may touch a neighbour or another parent's fragment
        inflate = max(inflate, 2*reach[k]/e.parent.d);
    }
    reduce(inflate, maxOp<scalar>());

    // The parents of every rank with their reach
    List<List<labelPair>> allIds(Pstream::nProcs());
    List<scalarList> allReach(Pstream::nProcs());
    allIds[Pstream::myProcNo()] = s.ids;
    allReach[Pstream::myProcNo()] = reach;
    Pstream::gatherList(allIds);
    Pstream::scatterList(allIds);
    Pstream::gatherList(allReach);
    Pstream::scatterList(allReach);
    HashTable<scalar, labelPair, Hash<labelPair>> reachOf;
    forAll(allIds, proci)
    {
        forAll(allIds[proci], k)
        {
            reachOf.insert(allIds[proci][k], allReach[proci][k]);
        }
    }

    List<DynamicList<neighbour>> near;
    neighbours(s, inflate, near);

    // Of two parents whose fragments may meet, the one of the higher id
    // waits a step; the others take the first direction that leaves every
    // neighbour untouched, or wait (doc/breakup.md 3.2)
    const label tries = kernel_->fragmentation().tries();
    label kept = 0;
    forAll(s.parents, k)
    {
        const breakupEvent& e = s.events[k];
        bool room = true;
        for (const neighbour& nb : near[k])
        {
            const auto r = reachOf.cfind(nb.id);
            if
            (
                r.found() && nb.id != s.ids[k]
             && collisionSchedule::lessId
                (
                    {nb.id.first(), nb.id.second()},
                    {s.ids[k].first(), s.ids[k].second()}
                )
             && mag(nb.x - e.parent.x) < reach[k] + r.val()
            )
            {
                room = false;
                break;
            }
        }
        label attempt = -1;
        for (label t = 0; room && t < tries; ++t)
        {
            const agglomerateFragmentation::fragments f =
                t ? splitOf(e, t) : first[k];
            if (clear(f, near[k], s.ids[k]))
            {
                attempt = t;
                first[k] = f;
                break;
            }
        }
        if (debug)
        {
            Pout<< "    placement of (" << e.proc << ' ' << e.id << "): "
                << (room ? "" : "a neighbour's break-up first, ")
                << "try " << attempt << ", reach " << reach[k] << ", "
                << near[k].size() << " neighbours:";
            for (const neighbour& nb : near[k])
            {
                Pout<< " (" << nb.id << ' ' << mag(nb.x - e.parent.x)
                    << ' ' << nb.d << ')';
            }
            Pout<< endl;
        }
        if (attempt < 0)
        {
            ++s.nNoRoom;
            continue;
        }
        s.parents[kept] = s.parents[k];
        s.events[kept] = e;
        s.events[kept].attempt = attempt;
        s.ids[kept] = s.ids[k];
        s.fragments.append(first[k]);
        ++kept;
    }
    s.parents.setSize(kept);
    s.events.setSize(kept);
    s.ids.setSize(kept);
}


// ************************************************************************* //
