/*---------------------------------------------------------------------------*\
    Unit tests of the pair searches (PairSearch) on meshes built in the
    test (blockMesh from a dictionary string; no case on disk): on a box
    periodic in x and z with walls in y, and on a box without cyclics,
    particleGrid and the bruteForce oracle give exactly the candidate
    pairs found here independently, by a hand-written O(N^2) loop over
    every periodic image: the pairs whose swept boxes (inflated by
    1.1 d/2) overlap; interactionLists, whose cells are the bins, visits
    a superset of those pairs at the search distance of the stage (d_max
    + 2 max|dx| per axis, inflated as the boxes are). Their run-time
    selection: testPairSearchSelection.C.
\*---------------------------------------------------------------------------*/

#include "ParticleGridPairSearch.H"
#include "BruteForcePairSearch.H"
#include "basicAgglomerateParcel.H"
#include "testMeshes.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "IStringStream.H"
#include "HashTable.H"
#include <gtest/gtest.h>
#include <random>
#include <set>
#include <tuple>

using namespace Foam;
using aggloTest::boxMesh;

namespace
{

typedef PairSearch<basicAgglomerateParcel> searchType;

//- (lower index, higher index, the higher one's end position rounded to
//  1e-12 m: an image's is shifted); a pair with an image is keyed from
//  the real particle: (real index, image's particle index, position)
typedef std::tuple<label, label, long, long, long> pairKey;

pairKey key(const label i, const label j, const point& xj)
{
    return pairKey
    (
        i, j, std::lround(xj.x()*1e12), std::lround(xj.y()*1e12),
        std::lround(xj.z()*1e12)
    );
}

//- The box as an fvMesh with a velocity field U (the interactionLists
//  search refers wall data with it)
struct fvBox
{
    autoPtr<fvMesh> mesh;
    autoPtr<volVectorField> U;

    fvBox(const Time& runTime, const bool periodic)
    {
        autoPtr<polyMesh> pm(boxMesh(runTime, periodic));
        mesh.reset
        (
            new fvMesh
            (
                IOobject
                (
                    polyMesh::defaultRegion, runTime.constant(), runTime,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                pointField(pm().points()),
                faceList(pm().faces()),
                labelList(pm().faceOwner()),
                labelList(pm().faceNeighbour())
            )
        );
        List<polyPatch*> patches(pm().boundaryMesh().size());
        forAll(patches, i)
        {
            patches[i] =
                pm().boundaryMesh()[i].clone(mesh().boundaryMesh()).ptr();
        }
        mesh().addFvPatches(patches);
        U.reset
        (
            new volVectorField
            (
                IOobject("U", runTime.timeName(), mesh()),
                mesh(),
                dimensionedVector(dimVelocity, Zero)
            )
        );
    }
};


//- A random cloud: n particles of 20-60 um in the box (away from the walls
//  by a radius), displaced by up to 'move' per component over the step;
//  the parcels sit at their start positions, or (atEnd) at their end
//  positions x1 as the collision stage sees them, the start positions
//  then outside the box after a cyclic crossing; the parcels own
//  themselves (deleted by the caller)
void randomCloud
(
    const polyMesh& mesh,
    const label n,
    const scalar move,
    const unsigned seed,
    List<basicAgglomerateParcel*>& parcels,
    List<point>& x1,
    const bool atEnd = false
)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    parcels.setSize(n);
    x1.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar d = 20e-6 + 40e-6*u(gen);
        const point x
        (
            1e-3*u(gen), 0.5*d + (1e-3 - d)*u(gen), 1e-3*u(gen)
        );
        basicAgglomerateParcel* p =
            new basicAgglomerateParcel(mesh, x, mesh.findCell(x));
        p->d() = d;
        parcels[i] = p;
        const vector dx
        (
            move*vector(2*u(gen) - 1, 2*u(gen) - 1, 2*u(gen) - 1)
        );
        if (atEnd)
        {
            x1[i] = x;
            p->stage().setKnownPosition(x - dx);
        }
        else
        {
            x1[i] = x + dx;
        }
    }
}


std::set<pairKey> candidates
(
    searchType& search,
    const UList<basicAgglomerateParcel*>& parcels,
    const UList<point>& x1,
    const scalar distance
)
{
    std::set<pairKey> keys;
    const label n = parcels.size();
    Map<label> index;
    forAll(parcels, k)
    {
        index.insert(parcels[k]->origId(), k);
    }
    auto collect = [&](const label i, const label j)
    {
        if (j < n)
        {
            keys.insert(key(min(i, j), max(i, j), x1[max(i, j)]));
        }
        else
        {
            const basicAgglomerateParcel& pj = search.referred(j - n);
            keys.insert
            (
                key(i, index[pj.origId()], search.referredPosition(j - n))
            );
        }
    };
    search.search(parcels, x1, distance, 1.1, collect);
    return keys;
}


//- The oracle written out here: every pair of a real particle i with a
//  real particle j > i or an image of any particle (shift by the periods
//  -1, 0, 1 along x and z) whose swept boxes, inflated by 1.1 d/2,
//  overlap
std::set<pairKey> handOracle
(
    const UList<basicAgglomerateParcel*>& parcels,
    const UList<point>& x1,
    const bool periodic
)
{
    std::set<pairKey> keys;
    const label n = parcels.size();
    auto box = [&](const label i, const vector& s)
    {
        const point& a = parcels[i]->stage().startPosition();
        const scalar h = 0.55*parcels[i]->d();
        const vector hv(h, h, h);
        return boundBox(min(a, x1[i]) - hv + s, max(a, x1[i]) + hv + s);
    };
    const label m = periodic ? 1 : 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            for (label a = -m; a <= m; ++a)
            {
                for (label c = -m; c <= m; ++c)
                {
                    const vector s(1e-3*a, 0, 1e-3*c);
                    const bool image = (a != 0 || c != 0);
                    if (!image && j <= i)
                    {
                        continue;
                    }
                    if (box(i, Zero).overlaps(box(j, s)))
                    {
                        keys.insert(key(i, j, x1[j] + s));
                    }
                }
            }
        }
    }
    return keys;
}


struct meshFixture
{
    autoPtr<Time> runTime;
    autoPtr<polyMesh> mesh;
    List<basicAgglomerateParcel*> parcels;
    List<point> x1;

    meshFixture(const bool periodic, const label n, const scalar move)
    :
        runTime(Time::New()),
        mesh(boxMesh(runTime(), periodic))
    {
        randomCloud(mesh(), n, move, 7u + n, parcels, x1);
    }

    ~meshFixture()
    {
        for (basicAgglomerateParcel* p : parcels)
        {
            delete p;
        }
    }
};

const dictionary noEntries;

} // End anonymous namespace


TEST(pairSearch, particleGridEqualsOracleWithImages)
{
    meshFixture f(true, 400, 40e-6);
    BruteForcePairSearch<basicAgglomerateParcel> oracle
    (
        noEntries, f.mesh(), "U"
    );
    ParticleGridPairSearch<basicAgglomerateParcel> grid
    (
        noEntries, f.mesh(), "U"
    );

    const std::set<pairKey> expected(handOracle(f.parcels, f.x1, true));
    const std::set<pairKey> bf(candidates(oracle, f.parcels, f.x1, 0));
    const std::set<pairKey> pg(candidates(grid, f.parcels, f.x1, 0));

    // Dense enough to have pairs, across the cyclics too
    ASSERT_GT(expected.size(), 100u);
    EXPECT_GT(grid.nReferred(), 0);
    EXPECT_EQ(bf, expected);
    EXPECT_EQ(pg, expected);
}


TEST(pairSearch, particleGridEqualsOracleWithoutCyclics)
{
    meshFixture f(false, 300, 80e-6);
    BruteForcePairSearch<basicAgglomerateParcel> oracle
    (
        noEntries, f.mesh(), "U"
    );
    ParticleGridPairSearch<basicAgglomerateParcel> grid
    (
        noEntries, f.mesh(), "U"
    );
    const std::set<pairKey> expected(handOracle(f.parcels, f.x1, false));
    ASSERT_GT(expected.size(), 50u);
    EXPECT_EQ(candidates(oracle, f.parcels, f.x1, 0), expected);
    EXPECT_EQ(candidates(grid, f.parcels, f.x1, 0), expected);
    EXPECT_EQ(grid.nReferred(), 0);
}


TEST(pairSearch, interactionListsCoversOracle)
{
    for (const bool periodic : {true, false})
    {
        const scalar move = periodic ? 40e-6 : 80e-6;
        autoPtr<Time> runTime(Time::New());
        fvBox box(runTime(), periodic);
        struct
        {
            List<basicAgglomerateParcel*> parcels;
            List<point> x1;
            const polyMesh& mesh() const { return *meshPtr; }
            const polyMesh* meshPtr;
        } f;
        f.meshPtr = &box.mesh();
        randomCloud
        (
            box.mesh(), periodic ? 400 : 300, move,
            7u + (periodic ? 400 : 300), f.parcels, f.x1, true
        );
        // Selected at run time: the library's instantiation
        IStringStream is("pairSearch interactionLists;");
        autoPtr<searchType> listsPtr
        (
            searchType::New(dictionary(is), f.mesh(), "U")
        );
        searchType& lists = listsPtr();

        // The stage's search distance: largest diameter (inflated as the
        // boxes are) and twice the largest displacement
        scalar dMax = 0;
        scalar dxMax = 0;
        forAll(f.parcels, i)
        {
            dMax = max(dMax, f.parcels[i]->d());
            const point& x0 = f.parcels[i]->stage().startPosition();
            dxMax = max(dxMax, mag(f.x1[i] - x0));
        }
        const scalar distance = 1.1*dMax + 2*dxMax;

        const std::set<pairKey> expected
        (
            handOracle(f.parcels, f.x1, periodic)
        );
        std::set<pairKey> got;
        try
        {
            got = candidates(lists, f.parcels, f.x1, distance);
        }
        catch (const Foam::error& err)
        {
            FAIL() << err.message();
        }
        ASSERT_GT(expected.size(), 50u);
        label missing = 0;
        for (const pairKey& k : expected)
        {
            missing += !got.count(k);
        }
        EXPECT_EQ(missing, 0) << "periodic " << periodic;
        EXPECT_GE(got.size(), expected.size());
        EXPECT_EQ(lists.nReferred() > 0, periodic);
        for (basicAgglomerateParcel* p : f.parcels)
        {
            delete p;
        }
    }
}

