/*---------------------------------------------------------------------------*\
    Unit tests of the record of an accepted event (collisionEventRecord,
    mesh-free): the partners are put in global-id order whichever side
    resolved the event, and the contact point is partner 1's centre plus
    its radius towards partner 2 (at contact distance, the same point
    seen from either side; for coincident centres, the centre).
\*---------------------------------------------------------------------------*/

#include "collisionEventRecord.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

hardSphereState state(const point& x, const scalar d)
{
    return hardSphereState(x, vector(1, 0, 0), Zero, d, 2200, 1);
}

} // End anonymous namespace


TEST(collisionEventRecord, idOrder)
{
    collisionEventRecord ev;
    const hardSphereState sa(state(point(0, 0, 0), 2e-6));
    const hardSphereState sb(state(point(3e-6, 0, 0), 4e-6));

    // a has the higher id: the record puts b first
    ev.set({0, 9}, sa, {0, 4}, sb, false, 1, 0.25, 1.5, 7);
    EXPECT_EQ(ev.id1(), labelPair(0, 4));
    EXPECT_EQ(ev.id2(), labelPair(0, 9));
    EXPECT_EQ(ev.p1.d, 4e-6);
    EXPECT_EQ(ev.p2.d, 2e-6);
    EXPECT_EQ(ev.category, 1);
    EXPECT_EQ(ev.s, 0.25);
    EXPECT_EQ(ev.time, 1.5);
    EXPECT_EQ(ev.celli, 7);
    EXPECT_FALSE(ev.applied);
    EXPECT_EQ(ev.outcomePtr(), nullptr);

    ev.set({0, 4}, sb, {0, 9}, sa, true, 1, 0.25, 1.5, 7);
    EXPECT_EQ(ev.id1(), labelPair(0, 4));
    EXPECT_EQ(ev.p1.d, 4e-6);
}


TEST(collisionEventRecord, contactPoint)
{
    collisionEventRecord ev;

    // Touching partners of radii 1 and 2 um, centres 3 um apart along
    // (1, 1, 0)/sqrt(2): the contact point is 1 um from partner 1
    const vector e(vector(1, 1, 0)/std::sqrt(2.0));
    const point x1(1e-3, 2e-3, 0);
    const point x2(x1 + 3e-6*e);
    ev.set({0, 1}, state(x1, 2e-6), {0, 2}, state(x2, 4e-6), true, 0, 0, 0, 0);
    const point c(ev.contactPoint());
    EXPECT_NEAR(mag(c - (x1 + 1e-6*e)), 0, 1e-18);

    // Seen from the other partner it is the same point
    const point c2(x2 - 2e-6*e);
    EXPECT_NEAR(mag(c - c2), 0, 1e-18);

    // Coincident centres: partner 1's centre
    ev.set({0, 1}, state(x1, 2e-6), {0, 2}, state(x1, 2e-6), true, 0, 0, 0, 0);
    EXPECT_EQ(ev.contactPoint(), x1);
}
