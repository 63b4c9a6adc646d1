/*---------------------------------------------------------------------------*\
    Unit tests of the statistics' profiles (hardSphereProfiles) on a 1 mm
    box of 5^3 cells with walls built in the test (testMeshes.H):
    - slabs: a position's slab along the direction (the upper bound in the
      last slab, outside -1); slab volumes sum to the box and, with slabs
      thinner than the cells, each cell is split by overlap (every slab
      1/nBins of the box);
    - running averages (Eq. 88): two batches merged by the pairwise update
      give the mean and the covariance of all samples computed directly;
      the volume fraction is averaged over the sampled steps;
    - restart state: the accumulators written and read back give the same
      profiles file; a state with another number of slabs is fatal;
    - bad input: a zero direction or nBins < 1 is a fatal IO error naming
      the entry.
\*---------------------------------------------------------------------------*/

#include "hardSphereProfiles.H"
#include "testMeshes.H"
#include "Time.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "testHelpers.H"
#include <gtest/gtest.h>
#include <fstream>
#include <functional>
#include <sstream>

using namespace Foam;
using aggloTest::errorMessage;

namespace
{

dictionary settings(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

//- The rows of a profiles file (comments skipped)
std::vector<std::vector<double>> rows(const fileName& file)
{
    std::vector<std::vector<double>> out;
    std::ifstream is(file);
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        std::vector<double> r;
        double v;
        while (ls >> v)
        {
            r.push_back(v);
        }
        out.push_back(r);
    }
    return out;
}

//- A scratch file name for this process
fileName scratch(const word& name)
{
    return fileName("/tmp")/("aggloUnitTests-" + Foam::name(pid()) + name);
}

} // End anonymous namespace


TEST(hardSphereProfiles, slabs)
{
    autoPtr<Time> runTime(Time::New());
    autoPtr<polyMesh> mesh(aggloTest::boxMesh(runTime(), false));

    hardSphereProfiles p
    (
        mesh(), settings("direction (0 2 0); nBins 5;")
    );
    EXPECT_EQ(p.bin(point(0.5e-3, 0.1e-3, 0.5e-3)), 0);
    EXPECT_EQ(p.bin(point(0.5e-3, 0.5e-3, 0.5e-3)), 2);
    EXPECT_EQ(p.bin(point(0.5e-3, 0.99e-3, 0.5e-3)), 4);
    EXPECT_EQ(p.bin(point(0.5e-3, 1e-3, 0.5e-3)), 4);
    EXPECT_EQ(p.bin(point(0.5e-3, -0.01e-3, 0.5e-3)), -1);
    EXPECT_EQ(p.bin(point(0.5e-3, 1.3e-3, 0.5e-3)), -1);
    EXPECT_NEAR(sum(p.slabVolume()), 1e-9, 1e-22);

    // Slabs thinner than the cells: each cell split by overlap
    hardSphereProfiles thin
    (
        mesh(), settings("direction (0 1 0); nBins 20;")
    );
    for (const scalar V : thin.slabVolume())
    {
        EXPECT_NEAR(V, 1e-9/20, 1e-22);
    }
}


TEST(hardSphereProfiles, runningAverages)
{
    autoPtr<Time> runTime(Time::New());
    autoPtr<polyMesh> mesh(aggloTest::boxMesh(runTime(), false));
    hardSphereProfiles p(mesh(), settings("direction (0 1 0); nBins 2;"));

    // Velocity samples in slab 0 (slab 1 stays empty), two batches
    const List<vector> batch1({{1, 2, 0}, {3, -1, 1}, {2, 0, 4}});
    const List<vector> batch2({{-1, 1, 2}, {5, 3, -2}});
    const List<scalar> d1({1e-5, 2e-5, 3e-5});
    const List<scalar> d2({4e-5, 6e-5});

    for (const auto& b : {std::make_pair(&batch1, &d1),
                          std::make_pair(&batch2, &d2)})
    {
        const List<vector>& U = *b.first;
        const List<scalar>& d = *b.second;
        const vector K(p.meanU()[0]);
        scalarField n(2, Zero), volume(2, Zero), sumD(2, Zero);
        vectorField sumU(2, Zero);
        symmTensorField sumUU(2, Zero);
        forAll(U, i)
        {
            n[0] += 1;
            volume[0] += 1e-11;
            sumD[0] += d[i];
            sumU[0] += U[i];
            sumUU[0] += sqr(U[i] - K);
        }
        p.addParticles(n, volume, sumD, sumU, sumUU);
    }
    p.addEvents
    (
        scalarField(List<scalar>({3, 1})),
        scalarField(List<scalar>({2, 0})),
        scalarField(List<scalar>({1, 1}))
    );

    // Direct mean and (population) covariance of all five samples
    List<vector> all(batch1);
    all.append(batch2);
    vector mean(Zero);
    for (const vector& u : all) mean += u/all.size();
    symmTensor R(Zero);
    for (const vector& u : all) R += sqr(u - mean)/all.size();

    const fileName file(scratch("test.dat"));
    p.write(file, "c");
    const auto r = rows(file);
    rm(file);
    ASSERT_EQ(r.size(), 2u);
    ASSERT_EQ(r[0].size(), 17u);
    const scalar V = 0.5e-9;
    EXPECT_NEAR(r[0][0], 0.25e-3, 1e-15);           // slab centre
    EXPECT_NEAR(r[0][1], 3/V, 1e-6*3/V);            // collisions
    EXPECT_NEAR(r[0][2], 2/V, 1e-6*2/V);            // first contacts
    EXPECT_NEAR(r[0][4], 1.0/3, 1e-6);              // aggRate
    EXPECT_NEAR(r[0][5], (3e-11/V + 2e-11/V)/2, 1e-9);   // alpha
    EXPECT_NEAR(r[0][6], 3.2e-5, 1e-15);            // mean d
    for (direction c = 0; c < 3; ++c)
    {
        EXPECT_NEAR(r[0][7 + c], mean[c], 1e-9);
    }
    const scalar Rc[6] = {R.xx(), R.xy(), R.xz(), R.yy(), R.yz(), R.zz()};
    for (label c = 0; c < 6; ++c)
    {
        EXPECT_NEAR(r[0][10 + c], Rc[c], 1e-9*(1 + mag(Rc[c])));
    }
    EXPECT_EQ(r[0][16], 5);
    EXPECT_EQ(r[1][16], 0);

    // Restart: the state read back writes the same file
    hardSphereProfiles q(mesh(), settings("direction (0 1 0); nBins 2;"));
    q.read(p.state());
    const fileName f1(scratch("A.dat"));
    const fileName f2(scratch("B.dat"));
    p.write(f1, "c");
    q.write(f2, "c");
    EXPECT_EQ(rows(f1), rows(f2));
    rm(f1);
    rm(f2);

    hardSphereProfiles other
    (
        mesh(), settings("direction (0 1 0); nBins 3;")
    );
    const std::string bins(errorMessage([&]{ other.read(p.state()); }));
    EXPECT_NE(bins.find("keep nBins"), std::string::npos) << bins;
}


TEST(hardSphereProfiles, badInput)
{
    autoPtr<Time> runTime(Time::New());
    autoPtr<polyMesh> mesh(aggloTest::boxMesh(runTime(), false));
    const std::string zero
    (
        errorMessage
        ([&]{
            hardSphereProfiles bad
            (
                mesh(), settings("direction (0 0 0); nBins 4;")
            );
        })
    );
    EXPECT_NE(zero.find("direction"), std::string::npos) << zero;
    const std::string bins
    (
        errorMessage
        ([&]{
            hardSphereProfiles bad
            (
                mesh(), settings("direction (0 1 0); nBins 0;")
            );
        })
    );
    EXPECT_NE(bins.find("nBins = 0"), std::string::npos) << bins;
}


// ************************************************************************* //
