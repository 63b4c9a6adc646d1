/*---------------------------------------------------------------------------*\
Description
    The collision-event record and file (doc/eventLog.md): a record packs
    into recordBytes bytes and unpacks to the same numbers bit for bit;
    a file appends and reads back in order, rejects another layout, and
    is cut back exactly after a time index (a restart), a partial last
    record (a write cut off by a kill) included.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "collisionEventFile.H"
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <unistd.h>

using namespace Foam;
using namespace aggloTest;

namespace
{

//- The branches of the corrected EAM, as its model names them
const wordList eamBranches({"eq21", "eq65", "caseI", "caseII"});

//- A record of every field; extreme: values at the limits of a double
//  (the byte round trip keeps them exactly), else within the bounds of a
//  valid record that the file reader checks (a velocity of 1e300 is
//  refused there as corrupt)
collisionEvent sample(const label k, const bool extreme = false)
{
    collisionEvent e;
    e.timeIndex = 100 + k/3;
    e.category = k % 3;
    e.branch = (k % 2 ? 0 : 3);     // eq21, caseII
    e.agglomerates = k % 2;
    e.type = collisionOutcome::SLIDING;
    e.time = 0.1 + 1e-7*k + 1.0/3.0;
    e.proc = {k % 4, 3};
    e.id = {k, 2147483000 + k};
    e.p1 = hardSphereState
    (
        point(1.0/7.0, -2e-300, 5e-7*k), vector(1e-3, -0.5, 1.0/3.0),
        vector(1e5, 0, -std::numeric_limits<double>::denorm_min()),
        12e-6, 2200.0/3.0, 1
    );
    e.p2 = hardSphereState
    (
        point(0.25, 0.5, 0.75), vector(-1e-3, 0.5, extreme ? 1e300 : 1e3),
        vector(0, 1, 2), 24e-6*(1 + k), 2200, 8 + k
    );
    e.wallDistance = 3.5e-5;
    return e;
}

void expectSame(const collisionEvent& a, const collisionEvent& b)
{
    EXPECT_EQ(a.timeIndex, b.timeIndex);
    EXPECT_EQ(a.category, b.category);
    EXPECT_EQ(a.branch, b.branch);
    EXPECT_EQ(a.agglomerates, b.agglomerates);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.proc, b.proc);
    EXPECT_EQ(a.id, b.id);
    for (const auto& s : {std::make_pair(&a.p1, &b.p1),
                          std::make_pair(&a.p2, &b.p2)})
    {
        EXPECT_EQ(s.first->x, s.second->x);
        EXPECT_EQ(s.first->U, s.second->U);
        EXPECT_EQ(s.first->omega, s.second->omega);
        EXPECT_EQ(s.first->d, s.second->d);
        EXPECT_EQ(s.first->rho, s.second->rho);
        EXPECT_EQ(s.first->nPrimary, s.second->nPrimary);
    }
    EXPECT_EQ(float(a.wallDistance), float(b.wallDistance));
}

fileName tmpFile(const std::string& tag)
{
    const fileName f
    (
        "/tmp/aggloTestEvents" + tag + Foam::name(label(::getpid()))
      + ".bin"
    );
    std::remove(f.c_str());
    return f;
}

} // End anonymous namespace


TEST(CollisionEvent, PackUnpackExact)
{
    char buf[collisionEvent::recordBytes + 1];
    buf[collisionEvent::recordBytes] = 'z';
    for (label k = 0; k < 7; ++k)
    {
        const collisionEvent e(sample(k, true));
        e.pack(buf);
        collisionEvent f;
        f.unpack(buf);
        expectSame(e, f);
    }
    // the record is exactly recordBytes long
    EXPECT_EQ(buf[collisionEvent::recordBytes], 'z');
}

TEST(CollisionEvent, OutcomeOfGhostAndKernel)
{
    collisionEvent e;
    e.setOutcome(nullptr);
    EXPECT_EQ(e.branch, collisionEvent::ghostBranch);
    EXPECT_FALSE(e.agglomerates);
    collisionOutcome o;
    o.branch = 1;
    o.agglomerates = true;
    o.type = collisionOutcome::SLIDING;
    e.setOutcome(&o);
    EXPECT_EQ(e.branch, 1);
    EXPECT_TRUE(e.agglomerates);
    EXPECT_EQ(e.type, label(collisionOutcome::SLIDING));
}

TEST(CollisionEventFile, AppendReadTruncate)
{
    const fileName f(tmpFile("A"));
    List<collisionEvent> first(5), second(4);
    forAll(first, k) first[k] = sample(k);              // steps 100, 101
    forAll(second, k) second[k] = sample(5 + k);        // steps 101-104
    collisionEventFile::append(f, first, eamBranches);
    collisionEventFile::append(f, second, eamBranches);
    wordList branches;
    List<collisionEvent> all(collisionEventFile::read(f, branches));
    EXPECT_EQ(branches, eamBranches);
    ASSERT_EQ(all.size(), 9);
    forAll(all, k)
    {
        expectSame(all[k], sample(k));
    }

    // a write cut off by a kill: half a record more
    {
        std::ofstream os(f.c_str(), std::ios::binary | std::ios::app);
        os.write("partial", 7);
    }
    EXPECT_THROW(collisionEventFile::read(f, branches), Foam::error);

    // restart from step 102: the records of steps 103 and 104 go
    label kept = 0;
    for (label k = 0; k < 9; ++k)
    {
        kept += (sample(k).timeIndex <= 102);
    }
    EXPECT_EQ(collisionEventFile::truncateAfter(f, 102), 9 - kept);
    all = collisionEventFile::read(f, branches);
    ASSERT_EQ(all.size(), kept);
    forAll(all, k)
    {
        expectSame(all[k], sample(k));
    }
    // nothing after the last step: unchanged
    EXPECT_EQ(collisionEventFile::truncateAfter(f, 1000), 0);
    EXPECT_EQ(collisionEventFile::read(f, branches).size(), kept);

    // events of another model's branches are not appended to
    const wordList mamBranches({"rebound", "agglomerate"});
    List<collisionEvent> one(1, sample(0));
    one[0].timeIndex = 1000;
    EXPECT_THROW
    (
        collisionEventFile::append(f, one, mamBranches),
        Foam::error
    );
    EXPECT_EQ(collisionEventFile::read(f, branches).size(), kept);
    EXPECT_EQ(branches, eamBranches);

    // before every record: the header only, which then follows the model
    // of the run that appends
    EXPECT_EQ(collisionEventFile::truncateAfter(f, 0), kept);
    EXPECT_EQ(collisionEventFile::read(f, branches).size(), 0);
    one[0].branch = 1;
    collisionEventFile::append(f, one, mamBranches);
    all = collisionEventFile::read(f, branches);
    EXPECT_EQ(branches, mamBranches);
    ASSERT_EQ(all.size(), 1);
    expectSame(all[0], one[0]);

    // a branch code beyond the header's names is a corrupt record
    one[0].branch = 2;
    collisionEventFile::append(f, one, mamBranches);
    EXPECT_NE
    (
        errorMessage([&]{ collisionEventFile::read(f, branches); })
            .find("branch 2 (valid: 0-1, 255 ghost)"),
        std::string::npos
    );
    std::remove(f.c_str());
}

TEST(CollisionEventFile, HeaderNamesTheBranches)
{
    const std::string head(collisionEventFile::header(eamBranches));
    EXPECT_EQ
    (
        head,
        collisionEventFile::layout() + " branches eq21,eq65,caseI,caseII"
    );
    EXPECT_LT(head.size(), collisionEventFile::headerBytes);

    // names that do not fit the header, or none, are refused
    wordList many(20, word("aLongBranchName"));
    EXPECT_THROW(collisionEventFile::header(many), Foam::error);
    EXPECT_THROW(collisionEventFile::header(wordList()), Foam::error);
}

TEST(CollisionEventFile, RejectsAnotherLayout)
{
    const fileName f(tmpFile("B"));
    {
        std::ofstream os(f.c_str(), std::ios::binary);
        std::string head("aggloCollisionEvents 1 recordBytes 196 arch LSB");
        head.resize(collisionEventFile::headerBytes - 1, ' ');
        os << head << '\n';
    }
    wordList branches;
    EXPECT_THROW(collisionEventFile::read(f, branches), Foam::error);
    List<collisionEvent> one(1, sample(0));
    EXPECT_THROW
    (
        collisionEventFile::append(f, one, eamBranches),
        Foam::error
    );
    std::remove(f.c_str());
}

TEST(CollisionEventFile, WrittenForPython)
{
    // Records 5 and 6 of sample() in a log file: where AGGLO_LAYOUT_DIR
    // names a folder, left there for tests/aggloTools/test_eventLayouts.py
    // (the Python reader's layout against this one), else read back here
    const char* dir = ::getenv("AGGLO_LAYOUT_DIR");
    const fileName f
    (
        dir ? fileName(dir)/"collisionEvents.bin" : tmpFile("P")
    );
    std::remove(f.c_str());
    const List<collisionEvent> two({sample(5), sample(6)});
    collisionEventFile::append(f, two, eamBranches);
    wordList branches;
    const List<collisionEvent> back(collisionEventFile::read(f, branches));
    ASSERT_EQ(back.size(), 2);
    expectSame(back[0], two[0]);
    expectSame(back[1], two[1]);
    if (!dir)
    {
        std::remove(f.c_str());
    }
}

// ************************************************************************* //
