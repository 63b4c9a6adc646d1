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

#include "collisionSchedule.H"
#include "HashSet.H"
#include "Pstream.H"
#include "IOstreams.H"

#include <algorithm>

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::collisionSchedule::eventLess(const event& a, const event& b)
{
    if (a.s != b.s) return a.s < b.s;
    if (a.lo() != b.lo()) return lessId(a.lo(), b.lo());
    return lessId(a.hi(), b.hi());
}


bool Foam::collisionSchedule::pairLess(const event& a, const event& b)
{
    if (a.lo() != b.lo()) return lessId(a.lo(), b.lo());
    if (a.hi() != b.hi()) return lessId(a.hi(), b.hi());
    if (a.s != b.s) return a.s < b.s;
    return a.separating < b.separating;
}


void Foam::collisionSchedule::select
(
    List<event>& all,
    const bool onePerParticle,
    const label rank,
    labelList& accepted,
    scalarList& acceptedS,
    label& nSuppressed,
    label& nSeparating
)
{
    nSuppressed = 0;
    nSeparating = 0;

    // Group the copies of each pair, the earliest first
    std::sort(all.begin(), all.end(), pairLess);

    labelList groupStart(all.size() + 1);
    label nGroups = 0;
    forAll(all, k)
    {
        if (k == 0 || !all[k].samePair(all[k - 1]))
        {
            groupStart[nGroups++] = k;
        }
    }
    groupStart[nGroups] = all.size();

    // The groups in event order (unique pairs: a strict total order)
    labelList order(nGroups);
    forAll(order, g)
    {
        order[g] = g;
    }
    std::sort
    (
        order.begin(),
        order.end(),
        [&](const label a, const label b)
        {
            return eventLess(all[groupStart[a]], all[groupStart[b]]);
        }
    );

    // Greedy, at most one event per particle
    typedef HashSet<globalId, globalId::Hash<>> idSet;
    idSet taken(2*nGroups + 1);
    DynamicList<labelPair> mine;    // (candidate index, group start)

    for (const label g : order)
    {
        const event& e = all[groupStart[g]];

        if (e.separating)
        {
            ++nSeparating;
            continue;
        }
        if (onePerParticle && (taken.found(e.lo()) || taken.found(e.hi())))
        {
            ++nSuppressed;
            continue;
        }
        taken.insert(e.lo());
        taken.insert(e.hi());

        for (label k = groupStart[g]; k < groupStart[g + 1]; ++k)
        {
            if (all[k].rank == rank && !all[k].separating)
            {
                mine.append(labelPair(all[k].index, groupStart[g]));
            }
        }
    }

    std::sort
    (
        mine.begin(),
        mine.end(),
        [](const labelPair& a, const labelPair& b) { return a[0] < b[0]; }
    );
    accepted.setSize(mine.size());
    acceptedS.setSize(mine.size());
    forAll(mine, m)
    {
        accepted[m] = mine[m][0];
        acceptedS[m] = all[mine[m][1]].s;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionSchedule::collisionSchedule()
:
    candidates_(),
    accepted_(),
    acceptedS_(),
    nSuppressed_(0),
    nSeparating_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionSchedule::clear()
{
    candidates_.clear();
    accepted_.clear();
    acceptedS_.clear();
    nSuppressed_ = 0;
    nSeparating_ = 0;
}


Foam::label Foam::collisionSchedule::append
(
    const scalar s,
    const globalId& a,
    const globalId& b,
    const bool separating
)
{
    const bool aLow = lessId(a, b);
    const globalId& lo = aLow ? a : b;
    const globalId& hi = aLow ? b : a;

    event e;
    e.s = s;
    e.loProc = lo[0];
    e.loId = lo[1];
    e.hiProc = hi[0];
    e.hiId = hi[1];
    e.rank = Pstream::myProcNo();
    e.index = candidates_.size();
    e.separating = separating;

    candidates_.append(e);
    return e.index;
}


void Foam::collisionSchedule::select(const bool onePerParticle)
{
    List<List<event>> perRank(Pstream::nProcs());
    perRank[Pstream::myProcNo()] = candidates_;
    Pstream::gatherList(perRank);
    Pstream::scatterList(perRank);

    label n = 0;
    for (const List<event>& evs : perRank)
    {
        n += evs.size();
    }
    List<event> all(n);
    n = 0;
    for (const List<event>& evs : perRank)
    {
        for (const event& e : evs)
        {
            all[n++] = e;
        }
    }

    select
    (
        all,
        onePerParticle,
        Pstream::myProcNo(),
        accepted_,
        acceptedS_,
        nSuppressed_,
        nSeparating_
    );
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Istream& Foam::operator>>(Istream& is, collisionSchedule::event& e)
{
    is.readBegin("collisionSchedule::event");
    is  >> e.s >> e.loProc >> e.loId >> e.hiProc >> e.hiId
        >> e.rank >> e.index >> e.separating;
    is.readEnd("collisionSchedule::event");
    is.check(FUNCTION_NAME);
    return is;
}


Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const collisionSchedule::event& e
)
{
    os  << token::BEGIN_LIST << e.s << token::SPACE
        << e.loProc << token::SPACE << e.loId << token::SPACE
        << e.hiProc << token::SPACE << e.hiId << token::SPACE
        << e.rank << token::SPACE << e.index << token::SPACE
        << e.separating << token::END_LIST;
    return os;
}


// ************************************************************************* //
