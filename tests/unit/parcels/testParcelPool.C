/*---------------------------------------------------------------------------*\
    Unit tests of the parcels' storage (parcelPool, AgglomerateParcel's
    operator new and delete):
    - a slot is the object's size rounded up to its alignment, at least a
      pointer;
    - the slots of a chunk are handed out contiguous and in address
      order, new chunks as needed, every slot aligned, distinct and
      writable without touching another (each filled with its own bytes);
    - a slot given back is handed out next (last in, first out), and the
      counts follow;
    - basicAgglomerateParcel takes its storage from its pool and gives it
      back; a type derived from it (another size) takes the heap.
\*---------------------------------------------------------------------------*/

#include "parcelPool.H"
#include "basicAgglomerateParcel.H"
#include "testMeshes.H"
#include "Time.H"
#include <gtest/gtest.h>
#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

using namespace Foam;

namespace
{

std::uintptr_t address(const void* p)
{
    return reinterpret_cast<std::uintptr_t>(p);
}

//- A parcel of another size: its storage comes from the heap
class largerParcel
:
    public basicAgglomerateParcel
{
    double extra_[3];

public:

    largerParcel(const polyMesh& mesh, const point& x, const label celli)
    :
        basicAgglomerateParcel(mesh, x, celli),
        extra_{1, 2, 3}
    {}
};

} // End anonymous namespace


TEST(parcelPool, slotSize)
{
    EXPECT_EQ(parcelPool(20, 8).slotSize(), 24u);
    EXPECT_EQ(parcelPool(24, 8).slotSize(), 24u);
    EXPECT_EQ(parcelPool(3, 4).slotSize(), sizeof(void*));
    EXPECT_EQ(parcelPool(40, 16).slotSize(), 48u);
    EXPECT_EQ(parcelPool(288, 8).slotSize(), 288u);
}


TEST(parcelPool, chunksContiguousAndDistinct)
{
    const std::size_t size = 40, perChunk = 4, n = 10;
    parcelPool pool(size, 8, perChunk);
    EXPECT_EQ(pool.nSlots(), 0u);

    std::vector<unsigned char*> slots;
    for (std::size_t i = 0; i < n; ++i)
    {
        slots.push_back(static_cast<unsigned char*>(pool.allocate()));
        std::memset(slots.back(), int(i + 1), size);
    }
    EXPECT_EQ(pool.nUsed(), n);
    EXPECT_EQ(pool.nSlots(), 12u);          // 3 chunks of 4

    std::set<const void*> distinct(slots.begin(), slots.end());
    EXPECT_EQ(distinct.size(), n);
    for (std::size_t i = 0; i < n; ++i)
    {
        EXPECT_EQ(address(slots[i]) % 8, 0u);
        EXPECT_TRUE(pool.holds(slots[i]));
        EXPECT_FALSE(pool.holds(slots[i] + 1));
        if (i % perChunk)
        {
            EXPECT_EQ(address(slots[i]) - address(slots[i - 1]), size);
        }
        for (std::size_t b = 0; b < size; ++b)
        {
            ASSERT_EQ(slots[i][b], i + 1) << "slot " << i << " byte " << b;
        }
    }
    int elsewhere = 0;
    EXPECT_FALSE(pool.holds(&elsewhere));
}


TEST(parcelPool, lastInFirstOut)
{
    parcelPool pool(32, 8, 8);
    void* a = pool.allocate();
    void* b = pool.allocate();
    void* c = pool.allocate();
    EXPECT_EQ(pool.nUsed(), 3u);

    pool.deallocate(a);
    pool.deallocate(c);
    pool.deallocate(nullptr);
    EXPECT_EQ(pool.nUsed(), 1u);
    EXPECT_EQ(pool.allocate(), c);
    EXPECT_EQ(pool.allocate(), a);
    EXPECT_EQ(pool.nUsed(), 3u);
    EXPECT_EQ(pool.nSlots(), 8u);
    pool.deallocate(b);
    EXPECT_EQ(pool.allocate(), b);
}


TEST(parcelPool, parcelsTakeTheirPool)
{
    autoPtr<Time> runTime(Time::New());
    autoPtr<polyMesh> mesh(aggloTest::boxMesh(runTime(), true));
    const point x(5e-4, 5e-4, 5e-4);
    const label celli = mesh().findCell(x);

    parcelPool& pool = basicAgglomerateParcel::pool();
    EXPECT_EQ(pool.slotSize(), sizeof(basicAgglomerateParcel));
    const std::size_t used = pool.nUsed();

    particle* p = new basicAgglomerateParcel(mesh(), x, celli);
    EXPECT_TRUE(pool.holds(p));
    EXPECT_EQ(pool.nUsed(), used + 1);

    // A copy (as the cloud clones and transfers them) as well
    autoPtr<particle> q(p->clone());
    EXPECT_TRUE(pool.holds(q.get()));
    EXPECT_EQ(pool.nUsed(), used + 2);

    // Deleted through the base class: back to the pool
    delete p;
    q.clear();
    EXPECT_EQ(pool.nUsed(), used);

    particle* r = new largerParcel(mesh(), x, celli);
    EXPECT_FALSE(pool.holds(r));
    EXPECT_EQ(pool.nUsed(), used);
    delete r;
    EXPECT_EQ(pool.nUsed(), used);
}


// ************************************************************************* //
