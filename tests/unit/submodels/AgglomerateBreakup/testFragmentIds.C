/*---------------------------------------------------------------------------*\
Description
    The global ids of the fragments (fragmentIds): handed out in the order
    of the parents' global ids whatever order the parents come in, after
    the ids handed out before, one per parent; against a brute-force
    oracle (the rank of each parent among all by counting). The 2-rank
    path is the case test of tests/unit/submodels/AgglomerateBreakup.
\*---------------------------------------------------------------------------*/

#include "../../testHelpers.H"
#include "fragmentIds.H"
#include "Random.H"

using namespace Foam;

TEST(fragmentIds, HandValues)
{
    fragmentIds ids(10);
    const List<labelPair> parents
    ({
        labelPair(1, 5), labelPair(0, 7), labelPair(-2, 3), labelPair(0, 2)
    });
    const labelList got(ids.assign(parents));
    // order: (-2 3) < (0 2) < (0 7) < (1 5)
    EXPECT_EQ(got, labelList({13, 12, 10, 11}));
    EXPECT_EQ(ids.next(), 14);

    EXPECT_TRUE(ids.assign(List<labelPair>()).empty());
    EXPECT_EQ(ids.next(), 14);
}


TEST(fragmentIds, AgainstCountingOracle)
{
    Random rnd(5);
    fragmentIds ids;
    label next = 0;
    for (label round = 0; round < 20; ++round)
    {
        // Distinct ids in a random order
        const label n = rnd.position<label>(0, 50);
        List<labelPair> parents(n);
        forAll(parents, i)
        {
            parents[i] = labelPair(rnd.position<label>(-2, 3), 1000*round + i);
        }
        for (label i = n - 1; i > 0; --i)
        {
            Swap(parents[i], parents[rnd.position<label>(0, i)]);
        }

        const labelList got(ids.assign(parents));
        forAll(parents, i)
        {
            label below = 0;
            for (const labelPair& q : parents)
            {
                below += (q < parents[i]);
            }
            EXPECT_EQ(got[i], next + below);
        }
        next += n;
        EXPECT_EQ(ids.next(), next);
    }
}
