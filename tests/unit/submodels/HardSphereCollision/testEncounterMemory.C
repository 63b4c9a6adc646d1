/*---------------------------------------------------------------------------*\
    Unit tests of the encounter memory (encounterMemory, mesh-free): the
    contact categories against the rule written out by hand (overlap at
    step start first, then a repeat within the memory time with the last
    partner of either particle, else a first contact), the release
    distance (1 + eps)(r1 + r2) and its edge, and the checked input (a
    word, a number >= 0, else a fatal IO error naming the entry).
\*---------------------------------------------------------------------------*/

#include "encounterMemory.H"
#include "testHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;
using aggloTest::makeDict;

namespace
{

encounterMemory::memory particle
(
    const label proc,
    const label id,
    const label partnerProc,
    const label partnerId,
    const scalar tLast
)
{
    return {{proc, id}, {partnerProc, partnerId}, tLast};
}


std::string memoryError(const std::string& text)
{
    try
    {
        const dictionary dict(makeDict(text));
        encounterMemory m(dict);
    }
    catch (const Foam::error& err)
    {
        return std::string(err.message());
    }
    return "";
}

} // End anonymous namespace


TEST(encounterMemory, categories)
{
    const encounterMemory m(1e-3, 0.1);
    const auto a = particle(0, 1, 0, 2, 0.5);       // remembers b
    const auto b = particle(0, 2, -1, -1, -GREAT);  // remembers nobody
    const auto c = particle(1, 7, 0, 1, 0.5);       // remembers a

    // Overlap at step start wins over a repeat
    EXPECT_EQ(m.category(true, a, b, 0.5005), encounterMemory::OVERLAP_START);

    // The last partner of either side, within the memory time
    EXPECT_EQ(m.category(false, a, b, 0.5005), encounterMemory::REPEAT);
    EXPECT_EQ(m.category(false, b, a, 0.5005), encounterMemory::REPEAT);
    EXPECT_EQ(m.category(false, c, a, 0.5008), encounterMemory::REPEAT);

    // Beyond the memory time: a first contact again
    EXPECT_EQ(m.category(false, a, b, 0.5011), encounterMemory::FIRST);

    // Another particle (the processor counts: (1, 2) is not (0, 2))
    const auto d = particle(1, 2, -1, -1, -GREAT);
    EXPECT_EQ(m.category(false, a, d, 0.5005), encounterMemory::FIRST);
    EXPECT_EQ(m.category(false, b, d, 0.5005), encounterMemory::FIRST);
}


TEST(encounterMemory, unlimitedMemory)
{
    const encounterMemory m(makeDict("encounterMemory unlimited;"));
    const auto a = particle(0, 1, 0, 2, 0);
    const auto b = particle(0, 2, 0, 1, 0);
    EXPECT_EQ(m.category(false, a, b, 1e6), encounterMemory::REPEAT);
}


TEST(encounterMemory, releaseDistance)
{
    // Default eps 0.1: R = 2 releases beyond 2.2
    const encounterMemory m(makeDict(""));
    EXPECT_TRUE(m.releases());
    EXPECT_DOUBLE_EQ(m.reach(), 1.1);
    EXPECT_TRUE(m.near(sqr(2.19), 2));
    EXPECT_TRUE(m.near(sqr(1.1*2), 2));
    EXPECT_FALSE(m.near(sqr(2.21), 2));

    // none: never near, the search reaches the contact distance only
    const encounterMemory never(makeDict("encounterRelease none;"));
    EXPECT_FALSE(never.releases());
    EXPECT_DOUBLE_EQ(never.reach(), 1);
    EXPECT_FALSE(never.near(0, 2));

    const encounterMemory wide(makeDict("encounterRelease 0.5;"));
    EXPECT_DOUBLE_EQ(wide.reach(), 1.5);
    EXPECT_TRUE(wide.near(sqr(2.99), 2));
    EXPECT_FALSE(wide.near(sqr(3.01), 2));
}


TEST(encounterMemory, badInput)
{
    const std::string neg(memoryError("encounterMemory -1;"));
    EXPECT_NE(neg.find("encounterMemory"), std::string::npos) << neg;
    EXPECT_NE(neg.find("unlimited"), std::string::npos) << neg;

    const std::string word(memoryError("encounterRelease never;"));
    EXPECT_NE(word.find("encounterRelease"), std::string::npos) << word;
    EXPECT_NE(word.find("none"), std::string::npos) << word;
}
