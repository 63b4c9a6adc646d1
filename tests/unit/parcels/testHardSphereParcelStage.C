/*---------------------------------------------------------------------------*\
    Unit tests of the collision stage's state that a parcel carries
    (hardSphereParcelStage), on a particle of a box mesh:
    - each flag is set by its own edit and read by its own predicate,
      the others untouched; a relocation ends with relocated();
    - a step starts from the known end position of the last one (not
      computed from the particle), else from the particle's position,
      and clears every flag;
    - a rotation rotates the position and reports itself once
      (takeRotated), a translation moves it;
    - the ASCII stream round trip keeps the position and the flags.
\*---------------------------------------------------------------------------*/

#include "hardSphereParcelStage.H"
#include "particle.H"
#include "testMeshes.H"
#include "Time.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "transform.H"
#include "testHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;


TEST(hardSphereParcelStage, flagsAndPositions)
{
    const point x(1, 2, 3);
    hardSphereParcelStage s(x);
    EXPECT_EQ(s.startPosition(), x);
    EXPECT_FALSE
    (
        s.collided() || s.relocating() || s.removed() || s.formed()
     || s.positionKnown()
    );

    s.markCollided();
    EXPECT_TRUE(s.collided());
    EXPECT_FALSE(s.removed() || s.formed() || s.relocating());
    s.markFormed();
    EXPECT_TRUE(s.formed() && s.collided());
    EXPECT_FALSE(s.removed());
    s.markRemoved();
    EXPECT_TRUE(s.removed());

    const point y(-4, 5, 0.5);
    s.relocateTo(y);
    EXPECT_TRUE(s.relocating());
    EXPECT_EQ(s.relocationTarget(), y);
    s.relocated();
    EXPECT_FALSE(s.relocating());
    // the wall contacts of the parcels made in the step read the target
    // after their relocation
    EXPECT_EQ(s.relocationTarget(), y);
    EXPECT_TRUE(s.collided() && s.formed() && s.removed());

    const point z(7, 8, 9);
    s.setKnownPosition(z);
    EXPECT_TRUE(s.positionKnown());
    EXPECT_EQ(s.knownPosition(), z);
    s.forgetPosition();
    EXPECT_FALSE(s.positionKnown());
    EXPECT_TRUE(s.collided());

    s.reset(x);
    EXPECT_EQ(s.startPosition(), x);
    EXPECT_FALSE(s.collided() || s.formed() || s.removed());
}


TEST(hardSphereParcelStage, startStep)
{
    autoPtr<Time> runTime(Time::New());
    autoPtr<polyMesh> mesh(aggloTest::boxMesh(runTime(), false));

    const point xp(0.31e-3, 0.42e-3, 0.53e-3);
    const particle p(mesh(), xp, mesh->findCell(xp));

    // A known end position is the next start, not the particle's position
    const point known(0.1e-3, 0.2e-3, 0.3e-3);
    hardSphereParcelStage s;
    s.markCollided();
    s.noteWallImpact(0.3);
    s.setKnownPosition(known);
    s.startStep(p);
    EXPECT_EQ(s.startPosition(), known);
    EXPECT_FALSE(s.collided() || s.positionKnown());
    EXPECT_EQ(s.wallImpactSpeed(), 0);

    // Without one (a restart, a relocation), the particle's position
    s.startStep(p);
    EXPECT_LT(mag(s.startPosition() - xp), 1e-15*mag(xp));
}


TEST(hardSphereParcelStage, transforms)
{
    const point x(1, 2, 3);
    hardSphereParcelStage s(x);

    s.translate(vector(0.5, 0, -1));
    EXPECT_EQ(s.startPosition(), point(1.5, 2, 2));
    EXPECT_FALSE(s.takeRotated());

    // A quarter turn about z: (x, y) -> (-y, x)
    const tensor T(rotationTensor(vector(1, 0, 0), vector(0, 1, 0)));
    s.transform(T);
    EXPECT_LT(mag(s.startPosition() - point(-2, 1.5, 2)), 1e-14);
    EXPECT_TRUE(s.takeRotated());
    EXPECT_FALSE(s.takeRotated());
}


TEST(hardSphereParcelStage, asciiStream)
{
    hardSphereParcelStage s;
    s.markCollided();
    s.setKnownPosition(point(0.25, -1e-7, 3e5));

    // the largest of the step's wall impacts is kept
    s.noteWallImpact(0.7);
    s.noteWallImpact(0.2);
    EXPECT_EQ(s.wallImpactSpeed(), 0.7);

    OStringStream os;
    os << s;
    IStringStream is(os.str());
    hardSphereParcelStage r;
    is >> r;

    EXPECT_EQ(r.knownPosition(), s.knownPosition());
    EXPECT_EQ(r.wallImpactSpeed(), 0.7);
    EXPECT_TRUE(r.positionKnown() && r.collided());
    EXPECT_FALSE(r.relocating() || r.removed() || r.formed());
}


// ************************************************************************* //
