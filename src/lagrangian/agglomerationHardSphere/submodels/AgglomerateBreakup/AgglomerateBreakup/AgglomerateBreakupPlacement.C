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
Foam::scalar Foam::AgglomerateBreakup<CloudType>::reachOf
(
    const hardSphereState& parent,
    const agglomerateFragmentation::fragments& f
)
{
    const point& X = parent.x;
    return max
    (
        0.5*parent.d,
        max(mag(f.a.x - X) + 0.5*f.a.d, mag(f.b.x - X) + 0.5*f.b.d)
    );
}


template<class CloudType>
typename Foam::AgglomerateBreakup<CloudType>::parentTable
Foam::AgglomerateBreakup<CloudType>::allParents
(
    const UList<labelPair>& ids,
    const scalarList& reach
)
{
    List<List<labelPair>> allIds(Pstream::nProcs());
    List<scalarList> allReach(Pstream::nProcs());
    allIds[Pstream::myProcNo()] = ids;
    allReach[Pstream::myProcNo()] = reach;
    Pstream::gatherList(allIds);
    Pstream::scatterList(allIds);
    Pstream::gatherList(allReach);
    Pstream::scatterList(allReach);
    parentTable parents;
    forAll(allIds, proci)
    {
        forAll(allIds[proci], k)
        {
            parents.insert(allIds[proci][k], allReach[proci][k]);
        }
    }
    return parents;
}


template<class CloudType>
bool Foam::AgglomerateBreakup<CloudType>::yields
(
    const labelPair& id,
    const point& X,
    const scalar reach,
    const UList<neighbour>& near,
    const parentTable& parents
)
{
    for (const neighbour& nb : near)
    {
        const auto r = parents.cfind(nb.id);
        if
        (
            r.found() && nb.id != id
         && collisionSchedule::lessId
            (
                {nb.id.first(), nb.id.second()}, {id.first(), id.second()}
            )
         && mag(nb.x - X) < reach + r.val()
        )
        {
            return true;
        }
    }
    return false;
}


template<class CloudType>
Foam::label Foam::AgglomerateBreakup<CloudType>::firstClearTry
(
    const breakupEvent& e,
    const labelPair& id,
    const UList<neighbour>& near,
    agglomerateFragmentation::fragments& f
) const
{
    const label tries = kernel_->fragmentation().tries();
    for (label t = 0; t < tries; ++t)
    {
        const agglomerateFragmentation::fragments g =
            t ? splitOf(e, t) : f;
        if (clear(g, near, id))
        {
            f = g;
            return t;
        }
    }
    return -1;
}


template<class CloudType>
void Foam::AgglomerateBreakup<CloudType>::place(stepSurvey& s)
{
    const label nParents = s.parents.size();
    if (!returnReduce(nParents > 0, orOp<bool>()))
    {
        return;
    }

    // The first try of each parent and the reach of its fragments; the
    // search's boxes (half width inflate d/2) must meet where a fragment
    // may touch a neighbour or another parent's fragment
    List<agglomerateFragmentation::fragments> f(nParents);
    scalarList reach(nParents);
    scalar inflate = 1;
    forAll(s.events, k)
    {
        f[k] = splitOf(s.events[k], 0);
        reach[k] = reachOf(s.events[k].parent, f[k]);
        inflate = max(inflate, 2*reach[k]/s.events[k].parent.d);
    }
    reduce(inflate, maxOp<scalar>());
    const parentTable parents(allParents(s.ids, reach));

    List<DynamicList<neighbour>> near;
    neighbours(s, inflate, near);

    // Of two parents whose fragments may meet, the one of the higher id
    // waits a step; the others take the first direction that leaves every
    // neighbour untouched, or wait (doc/breakup.md 3.2)
    label kept = 0;
    forAll(s.parents, k)
    {
        const breakupEvent& e = s.events[k];
        const bool first =
            !yields(s.ids[k], e.parent.x, reach[k], near[k], parents);
        const label attempt =
            first ? firstClearTry(e, s.ids[k], near[k], f[k]) : -1;
        if (debug)
        {
            Pout<< "    placement of (" << e.proc << ' ' << e.id << "): "
                << (first ? "" : "a neighbour's break-up first, ")
                << "try " << attempt << ", reach " << reach[k] << ", "
                << near[k].size() << " neighbours" << endl;
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
        s.fragments.append(f[k]);
        ++kept;
    }
    s.parents.setSize(kept);
    s.events.setSize(kept);
    s.ids.setSize(kept);
}


// ************************************************************************* //
