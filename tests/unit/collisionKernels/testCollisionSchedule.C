/*---------------------------------------------------------------------------*\
    Unit tests of the event schedule (collisionSchedule): the global order
    (t_c, lower id, higher id), one event per pair seen from two ranks,
    greedy one-event-per-particle selection, the suppressed and separating
    counts; ties, duplicates, chains, and an input-order independent
    selection checked against a brute-force oracle.
\*---------------------------------------------------------------------------*/

#include "collisionSchedule.H"
#include "Random.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <set>
#include <utility>

using namespace Foam;

namespace
{

typedef collisionSchedule::globalId gid;
typedef std::pair<std::pair<label, label>, std::pair<label, label>> pairKey;

gid id(const label proc, const label i)
{
    return gid({proc, i});
}

//- An event as a processor would append it
collisionSchedule::event makeEvent
(
    const scalar s,
    const gid& a,
    const gid& b,
    const label rank,
    const label index,
    const bool separating = false
)
{
    const bool aLow = collisionSchedule::lessId(a, b);
    const gid& lo = aLow ? a : b;
    const gid& hi = aLow ? b : a;
    collisionSchedule::event e;
    e.s = s;
    e.loProc = lo[0];
    e.loId = lo[1];
    e.hiProc = hi[0];
    e.hiId = hi[1];
    e.rank = rank;
    e.index = index;
    e.separating = separating;
    return e;
}

pairKey keyOf(const collisionSchedule::event& e)
{
    return {{e.loProc, e.loId}, {e.hiProc, e.hiId}};
}

//- Select on a copy; the accepted pairs of rank 0
std::set<pairKey> acceptedPairs
(
    const List<collisionSchedule::event>& events,
    const bool onePerParticle,
    label& nSuppressed,
    label& nSeparating
)
{
    List<collisionSchedule::event> all(events);
    labelList accepted;
    scalarList acceptedS;
    collisionSchedule::select
    (
        all, onePerParticle, 0, accepted, acceptedS, nSuppressed, nSeparating
    );
    std::set<pairKey> pairs;
    for (const label k : accepted)
    {
        for (const collisionSchedule::event& e : events)
        {
            if (e.rank == 0 && e.index == k)
            {
                pairs.insert(keyOf(e));
            }
        }
    }
    return pairs;
}

} // End anonymous namespace


// Equal contact times: the lower id of the pair decides
TEST(CollisionSchedule, TieBrokenByLowerId)
{
    List<collisionSchedule::event> evs
    ({
        makeEvent(0.5, id(0, 1), id(0, 2), 0, 0),
        makeEvent(0.5, id(0, 2), id(0, 0), 0, 1)
    });
    label nSup = -1, nSep = -1;
    const std::set<pairKey> acc = acceptedPairs(evs, true, nSup, nSep);
    ASSERT_EQ(acc.size(), 1u);
    EXPECT_EQ(acc.count({{0, 0}, {0, 2}}), 1u);
    EXPECT_EQ(nSup, 1);
    EXPECT_EQ(nSep, 0);

    // Equal time and lower id: the higher id decides
    List<collisionSchedule::event> evs2
    ({
        makeEvent(0.5, id(0, 0), id(1, 3), 0, 0),
        makeEvent(0.5, id(0, 0), id(0, 7), 0, 1)
    });
    const std::set<pairKey> acc2 = acceptedPairs(evs2, true, nSup, nSep);
    ASSERT_EQ(acc2.size(), 1u);
    EXPECT_EQ(acc2.count({{0, 0}, {0, 7}}), 1u);
}


// A pair across a processor patch is found on both ranks (with different
// contact times from different images): one event, both copies applied
TEST(CollisionSchedule, PairSeenFromTwoRanks)
{
    List<collisionSchedule::event> all
    ({
        makeEvent(0.40, id(0, 5), id(1, 2), 0, 3),
        makeEvent(0.30, id(1, 2), id(0, 5), 1, 0),
        makeEvent(0.35, id(0, 5), id(0, 9), 0, 4)
    });

    for (const label rank : {0, 1})
    {
        List<collisionSchedule::event> copy(all);
        labelList accepted;
        scalarList acceptedS;
        label nSup = -1, nSep = -1;
        collisionSchedule::select
        (
            copy, true, rank, accepted, acceptedS, nSup, nSep
        );

        // The pair (0,5)-(1,2) is the earliest (0.30); (0,5)-(0,9) loses
        EXPECT_EQ(nSup, 1);
        EXPECT_EQ(nSep, 0);
        ASSERT_EQ(accepted.size(), 1);
        EXPECT_EQ(accepted[0], rank == 0 ? 3 : 0);
        // Both ranks apply the event's contact time, the earliest copy's
        EXPECT_EQ(acceptedS[0], 0.30);
    }
}


// a-b, b-c, c-d in time order: a-b and c-d; b-c first: only b-c
TEST(CollisionSchedule, Chains)
{
    const gid a = id(0, 0), b = id(0, 1), c = id(0, 2), d = id(0, 3);
    label nSup = -1, nSep = -1;

    List<collisionSchedule::event> chain
    ({
        makeEvent(0.1, a, b, 0, 0),
        makeEvent(0.2, b, c, 0, 1),
        makeEvent(0.3, c, d, 0, 2)
    });
    std::set<pairKey> acc = acceptedPairs(chain, true, nSup, nSep);
    EXPECT_EQ(acc.size(), 2u);
    EXPECT_EQ(acc.count({{0, 0}, {0, 1}}), 1u);
    EXPECT_EQ(acc.count({{0, 2}, {0, 3}}), 1u);
    EXPECT_EQ(nSup, 1);

    List<collisionSchedule::event> middle
    ({
        makeEvent(0.3, a, b, 0, 0),
        makeEvent(0.1, b, c, 0, 1),
        makeEvent(0.2, c, d, 0, 2)
    });
    acc = acceptedPairs(middle, true, nSup, nSep);
    EXPECT_EQ(acc.size(), 1u);
    EXPECT_EQ(acc.count({{0, 1}, {0, 2}}), 1u);
    EXPECT_EQ(nSup, 2);

    // Without the one-event rule every approaching pair is accepted
    acc = acceptedPairs(middle, false, nSup, nSep);
    EXPECT_EQ(acc.size(), 3u);
    EXPECT_EQ(nSup, 0);
}


// Separating pairs are counted, never accepted, and take no particle
TEST(CollisionSchedule, SeparatingSkipped)
{
    const gid a = id(0, 0), b = id(0, 1), c = id(0, 2);
    List<collisionSchedule::event> evs
    ({
        makeEvent(0.0, a, b, 0, 0, true),
        makeEvent(0.5, a, c, 0, 1)
    });
    label nSup = -1, nSep = -1;
    const std::set<pairKey> acc = acceptedPairs(evs, true, nSup, nSep);
    ASSERT_EQ(acc.size(), 1u);
    EXPECT_EQ(acc.count({{0, 0}, {0, 2}}), 1u);
    EXPECT_EQ(nSep, 1);
    EXPECT_EQ(nSup, 0);
}


// Duplicates of one pair on one rank (two periodic images): every copy
// is returned, in append order
TEST(CollisionSchedule, DuplicatesOnOneRank)
{
    List<collisionSchedule::event> evs
    ({
        makeEvent(0.7, id(0, 4), id(0, 1), 0, 0),
        makeEvent(0.2, id(0, 1), id(0, 4), 0, 1)
    });
    labelList accepted;
    scalarList acceptedS;
    label nSup = -1, nSep = -1;
    collisionSchedule::select(evs, true, 0, accepted, acceptedS, nSup, nSep);
    ASSERT_EQ(accepted.size(), 2);
    EXPECT_EQ(accepted[0], 0);
    EXPECT_EQ(accepted[1], 1);
    // Both copies at the contact time of the earliest
    EXPECT_EQ(acceptedS[0], 0.2);
    EXPECT_EQ(acceptedS[1], 0.2);
    EXPECT_EQ(nSup, 0);
}


// Random events: the selection does not depend on the input order and
// equals a brute-force greedy (repeatedly the earliest event, by the
// total order, of two free particles)
TEST(CollisionSchedule, OrderIndependentAndBruteForce)
{
    Random rnd(1234);
    const label nParticles = 40;

    for (label trial = 0; trial < 20; ++trial)
    {
        List<collisionSchedule::event> evs(150);
        forAll(evs, k)
        {
            label a = rnd.position<label>(0, nParticles - 1);
            label b = rnd.position<label>(0, nParticles - 2);
            if (b >= a) ++b;
            // Coarse times so that ties occur
            const scalar s = 0.1*rnd.position<label>(0, 9);
            evs[k] = makeEvent
            (
                s, id(a % 2, a), id(b % 2, b), 0, k, rnd.sample01<scalar>()
              < 0.1
            );
        }

        label nSup = -1, nSep = -1;
        const std::set<pairKey> acc = acceptedPairs(evs, true, nSup, nSep);

        // Shuffled input
        List<collisionSchedule::event> shuffled(evs);
        for (label k = shuffled.size() - 1; k > 0; --k)
        {
            std::swap(shuffled[k], shuffled[rnd.position<label>(0, k)]);
        }
        label nSup2 = -1, nSep2 = -1;
        EXPECT_EQ(acceptedPairs(shuffled, true, nSup2, nSep2), acc);
        EXPECT_EQ(nSup2, nSup);
        EXPECT_EQ(nSep2, nSep);

        // Brute force: the earliest copy of each pair decides, an
        // approaching one on a tie
        std::vector<collisionSchedule::event> unique;
        for (const collisionSchedule::event& e : evs)
        {
            bool found = false;
            for (collisionSchedule::event& u : unique)
            {
                if (u.samePair(e))
                {
                    found = true;
                    if
                    (
                        e.s < u.s
                     || (e.s == u.s && e.separating < u.separating)
                    )
                    {
                        u = e;
                    }
                }
            }
            if (!found) unique.push_back(e);
        }
        std::set<pairKey> oracle;
        std::set<std::pair<label, label>> busy;
        label nSepOracle = 0;
        std::vector<bool> done(unique.size(), false);
        for (size_t round = 0; round < unique.size(); ++round)
        {
            label best = -1;
            for (size_t k = 0; k < unique.size(); ++k)
            {
                if (done[k]) continue;
                if
                (
                    best < 0
                 || collisionSchedule::eventLess(unique[k], unique[best])
                )
                {
                    best = k;
                }
            }
            done[best] = true;
            const collisionSchedule::event& e = unique[best];
            if (e.separating)
            {
                ++nSepOracle;
                continue;
            }
            const std::pair<label, label> lo(e.loProc, e.loId);
            const std::pair<label, label> hi(e.hiProc, e.hiId);
            if (busy.count(lo) || busy.count(hi)) continue;
            busy.insert(lo);
            busy.insert(hi);
            oracle.insert(keyOf(e));
        }
        EXPECT_EQ(acc, oracle);
        EXPECT_EQ(nSep, nSepOracle);
        EXPECT_EQ
        (
            nSup,
            label(unique.size()) - nSepOracle - label(oracle.size())
        );
    }
}


// The serial member interface: append, select, accepted
TEST(CollisionSchedule, AppendAndSelect)
{
    collisionSchedule schedule;
    EXPECT_EQ(schedule.append(0.6, id(0, 3), id(0, 1), false), 0);
    EXPECT_EQ(schedule.append(0.2, id(0, 1), id(0, 2), false), 1);
    EXPECT_EQ(schedule.append(0.1, id(0, 5), id(0, 6), true), 2);
    schedule.select(true);
    ASSERT_EQ(schedule.accepted().size(), 1);
    EXPECT_EQ(schedule.accepted()[0], 1);
    EXPECT_EQ(schedule.nSuppressed(), 1);
    EXPECT_EQ(schedule.nSeparating(), 1);

    schedule.clear();
    EXPECT_EQ(schedule.size(), 0);
}


// ************************************************************************* //
