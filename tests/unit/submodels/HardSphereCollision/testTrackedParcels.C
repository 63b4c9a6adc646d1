/*---------------------------------------------------------------------------*\
    Unit tests of the tracked parcels of a step (TrackedParcels, mesh-free,
    on a stand-in parcel and cloud with the interface it uses) and of the
    step record's mass audit (hardSphereStep):
    - check: every parcel of the cloud tracked here (fatal otherwise,
      naming both numbers), one particle per parcel (fatal otherwise); the
      largest diameter, displacement and displacement per axis, the
      particle mass and primaries (gathered as each track ends) against
      hand values and against the sums over the cloud;
    - checkPositions: an end position off by more than 1e-12 of the
      bounding box is fatal, round-off is not;
    - finish: the end positions become the known positions except for the
      parcels to be moved or removed; the lists are empty after;
    - audit: the mass and primaries after the stage against those before
      (auditBefore keeps the tracked sums): silent within 1e-11 relative,
      fatal beyond, nothing if the stage did not run; auditAfter sums the
      cloud after the stage plus what left it (a deposited parcel) and
      stops on a parcel that lost mass or one that left uncounted.
\*---------------------------------------------------------------------------*/

#include "TrackedParcels.H"
#include "hardSphereStep.H"
#include "hardSphereParcelStage.H"
#include "Time.H"
#include "testHelpers.H"
#include <gtest/gtest.h>
#include <functional>
#include <list>

using namespace Foam;
using aggloTest::errorMessage;

namespace
{

//- The parcel interface TrackedParcels and the audit use
struct testParcel
{
    point x = Zero;             // the particle's position
    scalar d_ = 10e-6;
    scalar n_ = 1;
    scalar mass_ = 1e-12;
    label nPrimary_ = 1;
    hardSphereParcelStage stage_;

    scalar d() const { return d_; }
    scalar nParticle() const { return n_; }
    scalar mass() const { return mass_; }
    label nPrimary() const { return nPrimary_; }
    point position() const { return x; }
    hardSphereParcelStage& stage() { return stage_; }
    const hardSphereParcelStage& stage() const { return stage_; }
};

//- The cloud interface: a name, a size and its parcels
struct testCloud
{
    std::list<testParcel> parcels;
    word name() const { return "testCloud"; }
    label size() const { return parcels.size(); }
    std::list<testParcel>::const_iterator begin() const
    {
        return parcels.begin();
    }
    std::list<testParcel>::const_iterator end() const
    {
        return parcels.end();
    }
};

} // End anonymous namespace


TEST(trackedParcels, checkAndExtent)
{
    testCloud cloud;
    cloud.parcels.resize(3);
    auto it = cloud.parcels.begin();
    testParcel& a = *it++;
    testParcel& b = *it++;
    testParcel& c = *it;
    b.d_ = 30e-6;
    c.d_ = 20e-6;
    b.mass_ = 2e-12;
    b.nPrimary_ = 4;
    c.mass_ = 3e-12;
    b.stage_.reset(point(1, 1, 1));
    c.stage_.reset(point(0, 0, 1));

    TrackedParcels<testParcel> tracked;
    tracked.reset(3);
    tracked.append(a, point(0.3, -0.4, 0));      // |dx| 0.5
    tracked.append(b, point(1, 1.6, 1));         // |dx| 0.6 along y
    tracked.append(c, point(-0.2, 0, 1.1));

    scalar dMax = -1, dxMag = -1, mass = -1;
    vector dxMax(-1, -1, -1);
    label nPrimaries = -1;
    tracked.check(cloud, dMax, dxMag, dxMax, mass, nPrimaries);
    EXPECT_EQ(dMax, 30e-6);
    EXPECT_NEAR(dxMag, 0.6, 1e-15);
    EXPECT_NEAR(dxMax.x(), 0.3, 1e-15);
    EXPECT_NEAR(dxMax.y(), 0.6, 1e-15);
    EXPECT_NEAR(dxMax.z(), 0.1, 1e-15);
    EXPECT_NEAR(mass, 6e-12, 1e-27);
    EXPECT_EQ(nPrimaries, 6);
    scalar cloudMass;
    label cloudPrimaries;
    hardSphereStep::globalSums(cloud, cloudMass, cloudPrimaries);
    EXPECT_NEAR(mass, cloudMass, 1e-27);
    EXPECT_EQ(nPrimaries, cloudPrimaries);

    // A fourth parcel that was not tracked here
    cloud.parcels.emplace_back();
    auto check = [&]
    {
        tracked.check(cloud, dMax, dxMag, dxMax, mass, nPrimaries);
    };
    const std::string missing(errorMessage(check));
    EXPECT_NE(missing.find("3 tracks"), std::string::npos) << missing;
    EXPECT_NE(missing.find("4 parcels"), std::string::npos) << missing;
    cloud.parcels.pop_back();

    // A parcel of two particles (as its track ended)
    b.n_ = 2;
    tracked.reset(3);
    tracked.append(a, point(0.3, -0.4, 0));
    tracked.append(b, point(1, 1.6, 1));
    tracked.append(c, point(-0.2, 0, 1.1));
    const std::string two(errorMessage(check));
    EXPECT_NE(two.find("nParticle = 2"), std::string::npos) << two;

    // reset forgets the sums of the step before
    b.n_ = 1;
    tracked.reset(3);
    tracked.append(a, point(0, 0, 0));
    tracked.append(b, point(1, 1, 1));
    tracked.append(c, point(0, 0, 1));
    check();
    EXPECT_EQ(dxMag, 0);
    EXPECT_NEAR(mass, 6e-12, 1e-27);
    EXPECT_EQ(nPrimaries, 6);
}


TEST(trackedParcels, positionsAndFinish)
{
    testParcel a, b, c;
    a.x = point(1e-3, 0, 0);
    b.x = point(0, 2e-3, 0);
    c.x = point(0, 0, 3e-3);
    b.stage_.relocateTo(point(-1, -1, -1));
    c.stage_.markRemoved();

    TrackedParcels<testParcel> tracked;
    tracked.reset(3);
    const scalar L = 1e-2;
    tracked.append(a, a.x + vector(1e-15, 0, 0));      // round-off
    tracked.append(b, b.x);
    tracked.append(c, c.x);
    EXPECT_EQ(errorMessage([&]{ tracked.checkPositions(L, "c"); }), "");

    tracked.reset(3);
    tracked.append(a, a.x + vector(0, 2e-12*L, 0));     // beyond
    tracked.append(b, b.x);
    const std::string off(errorMessage([&]{ tracked.checkPositions(L, "c"); }));
    EXPECT_NE(off.find("round-off"), std::string::npos) << off;

    tracked.reset(3);
    tracked.append(a, point(4, 5, 6));
    tracked.append(b, point(7, 8, 9));
    tracked.append(c, point(1, 2, 3));
    tracked.finish();
    EXPECT_TRUE(a.stage_.positionKnown());
    EXPECT_EQ(a.stage_.knownPosition(), point(4, 5, 6));
    EXPECT_FALSE(b.stage_.positionKnown());
    EXPECT_EQ(b.stage_.relocationTarget(), point(-1, -1, -1));
    EXPECT_FALSE(c.stage_.positionKnown());
    EXPECT_EQ(tracked.parcels().size(), 0);
    EXPECT_EQ(tracked.x1().size(), 0);
}


TEST(hardSphereStep, massAudit)
{
    autoPtr<Time> runTime(Time::New());
    hardSphereStep step(runTime());

    // The stage did not run: nothing to audit
    EXPECT_EQ(errorMessage([&]{ step.audit(1, 1); }), "");

    testCloud cloud;
    cloud.parcels.resize(3);
    auto it = cloud.parcels.begin();
    it->mass_ = 1e-12;
    (++it)->mass_ = 2e-12;
    it->nPrimary_ = 4;
    (++it)->mass_ = 3e-12;
    step.auditBefore(6e-12, 6);
    EXPECT_EQ(step.mass0, 6e-12);
    EXPECT_EQ(step.nPrimaries0, 6);

    EXPECT_EQ(errorMessage([&]{ step.audit(6e-12*(1 + 5e-12), 6); }), "");

    const std::string mass
    (
        errorMessage([&]{ step.audit(6e-12*(1 + 2e-11), 6); })
    );
    EXPECT_NE(mass.find("not conserved"), std::string::npos) << mass;

    const std::string primaries
    (
        errorMessage([&]{ step.audit(6e-12, 5); })
    );
    EXPECT_NE(primaries.find("primaries 6 -> 5"), std::string::npos)
        << primaries;

    // The cloud's sums after the stage: unchanged passes, a parcel that
    // lost mass stops the run
    EXPECT_EQ(errorMessage([&]{ step.auditAfter(cloud, 0, 0); }), "");

    // A parcel that left the cloud (deposited) in the stage: kept by
    // what left, lost without it
    cloud.parcels.pop_back();
    EXPECT_EQ(errorMessage([&]{ step.auditAfter(cloud, 3e-12, 1); }), "");
    EXPECT_NE
    (
        errorMessage([&]{ step.auditAfter(cloud, 0, 0); })
       .find("not conserved"),
        std::string::npos
    );
    EXPECT_NE
    (
        errorMessage([&]{ step.auditAfter(cloud, 3e-12, 0); })
       .find("primaries 6 -> 5"),
        std::string::npos
    );

    cloud.parcels.begin()->mass_ *= 0.999;
    EXPECT_NE
    (
        errorMessage([&]{ step.auditAfter(cloud, 3e-12, 1); })
       .find("not conserved"),
        std::string::npos
    );

    // The record is in the registry under its type name
    EXPECT_TRUE(runTime().foundObject<hardSphereStep>("hardSphereStep"));
}


// ************************************************************************* //
