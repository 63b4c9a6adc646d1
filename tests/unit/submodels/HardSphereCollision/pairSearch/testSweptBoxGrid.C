/*---------------------------------------------------------------------------*\
    Unit tests of the broad phase of the pair search (sweptBoxGrid): the
    grid keeps each box in single precision rounded outward (each bound
    the float next to it outward: it holds the exact box), and the
    overlapping pairs of those boxes found through the hashed grid are
    exactly those of the O(N^2) oracle (every pair, once, real-real and
    real-image, never image-image) on random clouds: uniform, clustered at
    a wall, polydisperse, with images, with a particle moving many bins in
    a step, with bins much smaller and much larger than the boxes; touching
    boxes count (closed boxes); every pair of the exact boxes is among
    them, and boxes a rounding apart are paired.
\*---------------------------------------------------------------------------*/

#include "sweptBoxGrid.H"
#include <gtest/gtest.h>
#include <random>
#include <set>
#include <utility>

using namespace Foam;

namespace
{

typedef std::set<std::pair<label, label>> pairSet;

//- A random cloud of swept boxes in the unit cube: radius r (times a
//  factor up to 'poly'), displacement up to 'move' in each component,
//  y-positions scaled by 'ySpan' (clustering at the wall y = 0)
List<boundBox> cloud
(
    const label n,
    const scalar r,
    const scalar poly,
    const scalar move,
    const scalar ySpan,
    const unsigned seed
)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    List<boundBox> boxes(n);
    forAll(boxes, i)
    {
        const point x0(u(gen), ySpan*u(gen), u(gen));
        const vector dx
        (
            move*(2*u(gen) - 1), move*(2*u(gen) - 1), move*(2*u(gen) - 1)
        );
        const scalar h = r*(1 + (poly - 1)*u(gen));
        boxes[i] = sweptBoxGrid::sweptBox(x0, x0 + dx, h);
    }
    return boxes;
}


//- Every overlapping pair of the boxes (double precision, or the grid's
//  rounded ones) with a real first member
template<class Box>
pairSet overlapping(const List<Box>& boxes, const label nReal)
{
    pairSet s;
    for (label a = 0; a < nReal; ++a)
    {
        for (label b = a + 1; b < boxes.size(); ++b)
        {
            if (sweptBoxGrid::overlap(boxes[a], boxes[b]))
            {
                s.insert({a, b});
            }
        }
    }
    return s;
}


//- The boxes as the grid keeps them
List<sweptBoxGrid::box> rounded(const List<boundBox>& boxes)
{
    List<sweptBoxGrid::box> r(boxes.size());
    forAll(boxes, i)
    {
        r[i] = sweptBoxGrid::rounded(boxes[i]);
    }
    return r;
}


//- The exact pairs: those of the double-precision boxes
pairSet exactPairs(const List<boundBox>& boxes, const label nReal)
{
    return overlapping(boxes, nReal);
}


//- The oracle: the pairs of the rounded boxes
pairSet bruteForce(const List<boundBox>& boxes, const label nReal)
{
    return overlapping(rounded(boxes), nReal);
}


//- The grid's pairs; duplicates and bad orders are counted
pairSet gridPairs
(
    const List<boundBox>& boxes,
    const label nReal,
    const scalar spacing,
    label& nVisits,
    label& nBad
)
{
    sweptBoxGrid grid;
    grid.build(rounded(boxes), nReal, spacing);
    pairSet s;
    nVisits = 0;
    nBad = 0;
    auto visit = [&](const label a, const label b)
    {
        ++nVisits;
        if (a >= nReal || b <= a)
        {
            ++nBad;
        }
        s.insert({a, b});
    };
    grid.pairs(visit);
    return s;
}


void expectOracle
(
    const List<boundBox>& boxes,
    const label nReal,
    const scalar spacing = 0
)
{
    const pairSet expected = bruteForce(boxes, nReal);
    label nVisits = 0, nBad = 0;
    const pairSet found = gridPairs(boxes, nReal, spacing, nVisits, nBad);
    EXPECT_EQ(nBad, 0);
    EXPECT_EQ(nVisits, label(found.size())) << "duplicate pairs";
    EXPECT_EQ(found, expected);

    // Every exact pair is found
    for (const auto& p : exactPairs(boxes, nReal))
    {
        EXPECT_EQ(found.count(p), 1u) << p.first << ' ' << p.second;
    }
}

} // End anonymous namespace


TEST(SweptBoxGrid, UniformCloudMatchesOracle)
{
    const List<boundBox> boxes = cloud(3000, 0.006, 1, 0.004, 1, 1);
    const pairSet expected = bruteForce(boxes, boxes.size());
    // Enough pairs for the test to mean something
    EXPECT_GT(expected.size(), 50u);
    expectOracle(boxes, boxes.size());
}


TEST(SweptBoxGrid, ClusteredAtAWallMatchesOracle)
{
    // Packed into y < 0.02: many boxes per bin
    const List<boundBox> boxes = cloud(2000, 0.005, 1, 0.002, 0.02, 2);
    EXPECT_GT(bruteForce(boxes, boxes.size()).size(), 500u);
    expectOracle(boxes, boxes.size());
}


TEST(SweptBoxGrid, PolydisperseMatchesOracle)
{
    // Radii up to 5 times the smallest (agglomerates up to 5 d)
    const List<boundBox> boxes = cloud(2000, 0.003, 5, 0.003, 1, 3);
    expectOracle(boxes, boxes.size());
}


TEST(SweptBoxGrid, ImagesArePairedWithRealsOnly)
{
    // The last 500 boxes are images: real-image pairs once, image-image
    // pairs never
    const List<boundBox> boxes = cloud(2000, 0.008, 2, 0.004, 1, 4);
    const label nReal = 1500;
    expectOracle(boxes, nReal);

    label nVisits = 0, nBad = 0;
    const pairSet found = gridPairs(boxes, nReal, 0, nVisits, nBad);
    label nRealImage = 0;
    for (const auto& p : found)
    {
        nRealImage += (p.second >= nReal);
    }
    EXPECT_GT(nRealImage, 10);
}


TEST(SweptBoxGrid, FastParticleAcrossManyBins)
{
    // One particle sweeps across the whole cube diagonally in a step
    List<boundBox> boxes = cloud(1000, 0.004, 1, 0.001, 1, 5);
    boxes[17] = sweptBoxGrid::sweptBox
    (
        point(0.01, 0.02, 0.03), point(0.97, 0.95, 0.9), 0.004
    );
    const pairSet expected = bruteForce(boxes, boxes.size());
    label n17 = 0;
    for (const auto& p : expected)
    {
        n17 += (p.first == 17 || p.second == 17);
    }
    EXPECT_GT(n17, 100);
    expectOracle(boxes, boxes.size());
}


TEST(SweptBoxGrid, AnySpacingGivesTheSamePairs)
{
    const List<boundBox> boxes = cloud(800, 0.01, 3, 0.01, 1, 6);
    // Bins much smaller than the boxes, and one bin for all
    expectOracle(boxes, boxes.size(), 0.004);
    expectOracle(boxes, boxes.size(), 0.05);
    expectOracle(boxes, boxes.size(), 10);
}


TEST(SweptBoxGrid, ShearFlowBoxesGetLongBins)
{
    // A shear flow with a large step: streamwise displacements up to 40
    // radii (u = y), spanwise and wall-normal ones of a tenth of a radius
    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u(0, 1);
    const scalar r = 0.002;
    List<boundBox> boxes(3000);
    forAll(boxes, i)
    {
        const point x0(u(gen), u(gen), 0.1*u(gen));
        const vector dx
        (
            40*r*(2*x0.y() - 1), 0.1*r*(2*u(gen) - 1), 0.1*r*(2*u(gen) - 1)
        );
        boxes[i] = sweptBoxGrid::sweptBox(x0, x0 + dx, r);
    }
    EXPECT_GT(bruteForce(boxes, boxes.size()).size(), 100u);
    expectOracle(boxes, boxes.size());

    // Twice the mean extent along each axis: long bins along the flow
    sweptBoxGrid grid;
    grid.build(rounded(boxes), boxes.size(), 0);
    vector mean(Zero);
    for (const boundBox& b : boxes)
    {
        mean += b.span()/boxes.size();
    }
    for (direction c = 0; c < 3; ++c)
    {
        // Each rounded bound moves by at most a float's step, 2^-23 at
        // the coordinates here (below 2): spans up to 2^-22 wider
        EXPECT_NEAR(grid.spacing()[c], 2*mean[c], 2*std::ldexp(1.0, -22));
        EXPECT_GE(grid.spacing()[c], 2*mean[c]);
    }
    EXPECT_GT(grid.spacing().x(), 5*grid.spacing().y());
}


TEST(SweptBoxGrid, TouchingAndDegenerateBoxes)
{
    // Boxes touching on a face, at a corner, points on a bin edge, and
    // two identical points
    List<boundBox> boxes(6);
    boxes[0] = boundBox(point(0, 0, 0), point(0.25, 0.25, 0.25));
    boxes[1] = boundBox(point(0.25, 0, 0), point(0.5, 0.25, 0.25));
    boxes[2] = boundBox(point(0.5, 0.25, 0.25), point(0.75, 0.5, 0.5));
    boxes[3] = boundBox(point(0.5, 0.5, 0.5), point(0.5, 0.5, 0.5));
    boxes[4] = boundBox(point(0.5, 0.5, 0.5), point(0.5, 0.5, 0.5));
    boxes[5] = boundBox(point(0.9, 0.9, 0.9), point(1, 1, 1));
    const pairSet expected
    ({
        {0, 1}, {1, 2}, {2, 3}, {2, 4}, {3, 4}
    });
    EXPECT_EQ(bruteForce(boxes, 6), expected);
    for (const scalar h : {0.0, 0.25, 0.1, 1.0})
    {
        expectOracle(boxes, 6, h);
    }
}


TEST(SweptBoxGrid, EmptyAndSingle)
{
    label nVisits = 0, nBad = 0;
    EXPECT_TRUE(gridPairs(List<boundBox>(), 0, 0, nVisits, nBad).empty());
    List<boundBox> one(1, boundBox(point::zero, point::one));
    EXPECT_TRUE(gridPairs(one, 1, 0, nVisits, nBad).empty());
}


TEST(SweptBoxGrid, RoundedBoxHoldsTheExactOneWithinAFloat)
{
    std::mt19937 gen(8);
    std::uniform_real_distribution<double> u(-1, 1);
    for (label n = 0; n < 10000; ++n)
    {
        const point x(u(gen), 0.1*u(gen), 1e-3*u(gen));
        const boundBox b(x, x + vector(1e-5, 2e-6, 1e-7)*(1 + u(gen)));
        const sweptBoxGrid::box r(sweptBoxGrid::rounded(b));
        for (direction c = 0; c < 3; ++c)
        {
            // Outward, and the next float inward would not hold it
            EXPECT_LE(double(r.min[c]), b.min()[c]);
            EXPECT_GE(double(r.max[c]), b.max()[c]);
            const float inMin = std::nextafter(r.min[c], HUGE_VALF);
            const float inMax = std::nextafter(r.max[c], -HUGE_VALF);
            EXPECT_GT(double(inMin), b.min()[c]);
            EXPECT_LT(double(inMax), b.max()[c]);
        }
    }

    // A bound that is a float stays as it is
    const boundBox exact(point(0.5, -0.25, 0), point(0.75, 1, 2));
    const sweptBoxGrid::box r(sweptBoxGrid::rounded(exact));
    EXPECT_EQ(r.min[0], 0.5f);
    EXPECT_EQ(r.min[1], -0.25f);
    EXPECT_EQ(r.max[2], 2.0f);
}


TEST(SweptBoxGrid, BoxesARoundingApartArePaired)
{
    // A gap of 1e-12 at 0.3 (a float's step there is 3e-8): apart in
    // double precision, touching once rounded
    List<boundBox> boxes(2);
    boxes[0] = boundBox(point(0.1, 0.1, 0.1), point(0.3, 0.2, 0.2));
    boxes[1] = boundBox(point(0.3 + 1e-12, 0.1, 0.1), point(0.5, 0.2, 0.2));
    EXPECT_TRUE(exactPairs(boxes, 2).empty());
    const pairSet expected({{0, 1}});
    EXPECT_EQ(bruteForce(boxes, 2), expected);
    expectOracle(boxes, 2);

    // A gap of 1e-6 stays a gap
    boxes[1] = boundBox(point(0.3 + 1e-6, 0.1, 0.1), point(0.5, 0.2, 0.2));
    EXPECT_TRUE(bruteForce(boxes, 2).empty());
    expectOracle(boxes, 2);
}


TEST(SweptBoxGrid, LargeBoxesInManyBinsOfABucket)
{
    // Three boxes of 20^3 bins each: 24,000 insertions in 32,768 buckets,
    // so that many bins of one box share a bucket (with each other and
    // with the other boxes' bins); each overlapping pair is still
    // reported once
    List<boundBox> boxes(3);
    boxes[0] = boundBox(point(0, 0, 0), point(0.2, 0.2, 0.2));
    boxes[1] = boundBox(point(0.1, 0.1, 0.1), point(0.3, 0.3, 0.3));
    boxes[2] = boundBox(point(0.25, 0, 0), point(0.45, 0.2, 0.2));
    const pairSet expected({{0, 1}, {1, 2}});
    EXPECT_EQ(bruteForce(boxes, 3), expected);
    expectOracle(boxes, 3, 0.01);
    expectOracle(boxes, 2, 0.01);
}


// ************************************************************************* //
