/*---------------------------------------------------------------------------*\
Description
    The steps that are a multiple of several intervals (stepPeriod, the
    cloud's stop interval and the solver's write-now step): against a
    brute-force search for the smallest step every interval divides; the
    intervals of zero or less left out; a period beyond the largest label
    refused, not wrapped round.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "stepPeriod.H"
#include <gtest/gtest.h>
#include <limits>

using namespace Foam;

namespace
{

//- The smallest positive step every positive interval divides
label bruteForce(const std::vector<label>& intervals)
{
    for (label step = 1; ; ++step)
    {
        bool all = true;
        for (const label n : intervals)
        {
            if (n > 0 && step % n != 0)
            {
                all = false;
            }
        }
        if (all)
        {
            return step;
        }
    }
}

} // End anonymous namespace


TEST(stepPeriod, noIntervalIsAnyStep)
{
    stepPeriod period;
    EXPECT_EQ(period.steps(), 1);
    period.include(0);
    period.include(-4);
    EXPECT_EQ(period.steps(), 1);
}


TEST(stepPeriod, theClockSchedules)
{
    // The cloud's start positions (20 steps) with its cell order
    for (const label order : {0, 1, 7, 8, 12, 20, 50, 100})
    {
        stepPeriod period;
        period.include(20);
        period.include(order);
        EXPECT_EQ(period.steps(), bruteForce({20, order})) << order;
    }
}


TEST(stepPeriod, leastCommonMultipleAgainstSearch)
{
    // Every set of up to three intervals in -1..24, in any order
    for (label a = -1; a <= 24; ++a)
    {
        for (label b = -1; b <= 24; ++b)
        {
            for (const label c : {-1, 0, 6, 9, 16, 21})
            {
                stepPeriod period;
                period.include(a);
                period.include(b);
                period.include(c);
                ASSERT_EQ(period.steps(), bruteForce({a, b, c}))
                    << a << " " << b << " " << c;

                stepPeriod reversed;
                reversed.include(c);
                reversed.include(b);
                reversed.include(a);
                ASSERT_EQ(reversed.steps(), period.steps());
            }
        }
    }
}


TEST(stepPeriod, greatestCommonDivisor)
{
    EXPECT_EQ(stepPeriod::greatestCommonDivisor(140, 20), 20);
    EXPECT_EQ(stepPeriod::greatestCommonDivisor(20, 140), 20);
    EXPECT_EQ(stepPeriod::greatestCommonDivisor(40, 60), 20);
    EXPECT_EQ(stepPeriod::greatestCommonDivisor(17, 20), 1);
}


TEST(stepPeriod, overflowRefused)
{
    // 2^30 - 1 = 3 x 357913941 takes a factor 3, not a factor 5
    const label big = std::numeric_limits<label>::max()/2 + 1;
    stepPeriod period;
    period.include(big - 1);
    period.include(3);
    EXPECT_EQ(period.steps(), big - 1);
    const std::string msg =
        aggloTest::errorMessage([&]() { period.include(5); });
    EXPECT_NE(msg.find("exceeds the largest label"), std::string::npos)
        << msg;
    EXPECT_EQ(period.steps(), big - 1);
}


// ************************************************************************* //
