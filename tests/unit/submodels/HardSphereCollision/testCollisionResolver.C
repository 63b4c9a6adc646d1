/*---------------------------------------------------------------------------*\
    Unit tests of the response to an accepted event (CollisionResolver,
    mesh-free, on a stand-in parcel with the parcel interface the resolvers
    use):
    - selection: collisionResponse physical | ghost, a misspelt name is a
      fatal IO error naming the choices; ghost needs agglomerationModel
      none;
    - physical rebound: the parcels get the kernel's post-collision states
      (the kernel called directly is the oracle) whichever side resolves,
      both remember each other at the contact time, the momentum of the
      pair is conserved; a second copy of the pair is a duplicate;
    - physical agglomeration: the lower-id partner becomes the agglomerate
      at the mass-weighted centre of the end positions (Eq. 81), mass
      conserved, the other is removed;
    - overlapTreatment separate: the partners end at least at contact
      distance, moved apart along their centre line with the mass ratio;
    - ghost: no parcel state changes but the memory, every copy of another
      pair counted, a second image of the same pair a duplicate.
\*---------------------------------------------------------------------------*/

#include "PhysicalCollisionResolver.H"
#include "GhostCollisionResolver.H"
#include "hardSphereParcelStage.H"
#include "testHelpers.H"
#include <gtest/gtest.h>

using namespace Foam;
using namespace aggloTest;

namespace Foam
{

//- The parcel interface the resolvers use, without a mesh
class testParcel
{
public:

    vector U_ = Zero, omega_ = Zero;
    scalar d_ = 12e-6, rho_ = 2200;
    label nPrimary_ = 1;
    label lastProc_ = -1, lastId_ = -1;
    scalar lastTime_ = -GREAT;
    hardSphereParcelStage stage_;

    vector& U() { return U_; }
    vector& omega() { return omega_; }
    scalar& d() { return d_; }
    scalar& rho() { return rho_; }
    label& nPrimary() { return nPrimary_; }
    label& lastPartnerProc() { return lastProc_; }
    label& lastPartnerId() { return lastId_; }
    scalar& lastContactTime() { return lastTime_; }

    hardSphereParcelStage& stage() { return stage_; }
    const hardSphereParcelStage& stage() const { return stage_; }

    hardSphereState state(const point& x) const
    {
        return hardSphereState(x, U_, omega_, d_, rho_, nPrimary_);
    }
};

} // End namespace Foam

makeCollisionResolver(testParcel);
makeCollisionResolverType(PhysicalCollisionResolver, testParcel);
makeCollisionResolverType(GhostCollisionResolver, testParcel);


namespace
{

typedef CollisionResolver<testParcel> resolverType;

//- A head-on-ish pair at contact: a at the origin, b one diameter along
//  x, approaching at v with an offset angle
void pair(testParcel& a, testParcel& b, const scalar v, const scalar theta)
{
    hardSphereState s1, s2;
    referencePair(v, theta, 1e3, -2e3, s1, s2);
    a.U_ = s1.U;
    a.omega_ = s1.omega;
    b.U_ = s2.U;
    b.omega_ = s2.omega;
}

//- The kernel input without agglomeration, with extra entries
std::string kernelString(const std::string& extra)
{
    return
        quartzInput() + " agglomerationModel none; structureModel CSM; "
      + extra;
}

std::string selectionError(const std::string& text)
{
    try
    {
        const dictionary dict(makeDict(text));
        hardSphereCollisionKernel kernel(dict);
        resolverType::New(dict, kernel);
    }
    catch (const Foam::error& err)
    {
        return std::string(err.message());
    }
    return "";
}

} // End anonymous namespace


TEST(collisionResolver, selection)
{
    const dictionary dict(kernelDict("none"));
    hardSphereCollisionKernel kernel(dict);
    EXPECT_EQ(resolverType::New(dict, kernel)->type(), "physical");
    EXPECT_TRUE(resolverType::New(dict, kernel)->onePerParticle());

    const std::string bad
    (
        selectionError(kernelString("collisionResponse ghosted;"))
    );
    EXPECT_NE(bad.find("ghosted"), std::string::npos) << bad;
    EXPECT_NE(bad.find("physical"), std::string::npos) << bad;

    const std::string agg
    (
        selectionError
        (
            quartzInput() + " agglomerationModel MAM; structureModel CSM;"
            " collisionResponse ghost;"
        )
    );
    EXPECT_NE(agg.find("agglomerationModel none"), std::string::npos) << agg;

    const std::string ovl
    (
        selectionError(kernelString("overlapTreatment apart;"))
    );
    EXPECT_NE(ovl.find("apart"), std::string::npos) << ovl;
}


TEST(collisionResolver, physicalRebound)
{
    const dictionary dict(kernelDict("none"));
    hardSphereCollisionKernel kernel(dict);
    autoPtr<resolverType> r(resolverType::New(dict, kernel));

    // Either side resolves: i is the higher id in the second case
    for (const bool iLow : {true, false})
    {
        testParcel a, b;
        pair(a, b, 0.3, 30);
        a.U_ += vector(0.1, 0.2, 0);     // the pair drifts: P != 0
        b.U_ += vector(0.1, 0.2, 0);
        const point xa(0, 0, 0), xb(12e-6, 0, 0);
        const labelPair ida(0, 3), idb(1, 5);   // a has the lower id
        const collisionOutcome expected
        (
            kernel.collide(a.state(xa), b.state(xb))
        );
        const vector P0(a.state(xa).momentum() + b.state(xb).momentum());
        const scalar Pscale =
            mag(a.state(xa).momentum()) + mag(b.state(xb).momentum());

        testParcel& pi = iLow ? a : b;
        testParcel& pj = iLow ? b : a;
        collisionEventRecord ev;
        ev.set
        (
            iLow ? ida : idb, pi.state(iLow ? xa : xb),
            iLow ? idb : ida, pj.state(iLow ? xb : xa),
            iLow, 0, 0.5, 2.5, 0
        );
        r->startStep();
        EXPECT_FALSE(r->duplicate(pi, ida, idb));
        r->resolve(ev, pi, &pj, iLow, xa, xb, 1e-5);

        EXPECT_TRUE(ev.applied);
        EXPECT_FALSE(ev.outcome.agglomerates);
        EXPECT_EQ(a.U_, expected.p1.U);
        EXPECT_EQ(b.U_, expected.p2.U);
        EXPECT_EQ(a.omega_, expected.p1.omega);
        EXPECT_EQ(b.omega_, expected.p2.omega);
        const vector P1(a.state(xa).momentum() + b.state(xb).momentum());
        EXPECT_LE(mag(P1 - P0), 1e-12*Pscale);

        EXPECT_EQ(labelPair(a.lastProc_, a.lastId_), idb);
        EXPECT_EQ(labelPair(b.lastProc_, b.lastId_), ida);
        EXPECT_EQ(a.lastTime_, 2.5);
        EXPECT_FALSE(a.stage().relocating() || b.stage().relocating());
        EXPECT_TRUE(r->duplicate(pi, ida, idb));
    }
}


TEST(collisionResolver, physicalAgglomeration)
{
    const dictionary dict(kernelDict("MAM"));
    hardSphereCollisionKernel kernel(dict);
    autoPtr<resolverType> r(resolverType::New(dict, kernel));

    testParcel a, b;
    b.d_ = 6e-6;
    pair(a, b, 1e-3, 0);
    const point xa(0, 0, 0), xb(9e-6, 0, 0);
    const point xa1(1e-6, 2e-6, 0), xb1(11e-6, -1e-6, 3e-6);
    const scalar ma = a.state(xa).mass(), mb = b.state(xb).mass();

    // b resolves (it has the higher id): a keeps the storage
    collisionEventRecord ev;
    ev.set({0, 9}, b.state(xb), {0, 2}, a.state(xa), false, 0, 0.1, 1, 0);
    r->resolve(ev, b, &a, false, xb1, xa1, 1e-5);

    ASSERT_TRUE(ev.outcome.agglomerates);
    EXPECT_TRUE(b.stage().removed());
    EXPECT_FALSE(a.stage().removed());
    EXPECT_TRUE(a.stage().formed() && a.stage().relocating());
    const point& xAg = a.stage().relocationTarget();
    EXPECT_LT(mag(xAg - (ma*xa1 + mb*xb1)/(ma + mb)), 1e-18);
    EXPECT_EQ(a.nPrimary_, 2);
    EXPECT_TRUE(near(a.state(xa).mass(), ma + mb, 1e-12));
    EXPECT_EQ(a.lastId_, -1);
}


TEST(collisionResolver, overlapSeparate)
{
    const dictionary dict
    (
        makeDict(kernelString("overlapTreatment separate;"))
    );
    hardSphereCollisionKernel kernel(dict);
    autoPtr<resolverType> r(resolverType::New(dict, kernel));

    // Contact at s = 0.5 of a step of 1e-5 s; the end positions overlap
    testParcel a, b;
    pair(a, b, 0.3, 0);
    const point xa(0, 0, 0), xb(12e-6, 0, 0);
    collisionEventRecord ev;
    ev.set({0, 1}, a.state(xa), {0, 2}, b.state(xb), true, 0, 0.5, 0, 0);
    r->resolve(ev, a, &b, true, xa, xa, 1e-5);

    ASSERT_TRUE(a.stage().relocating() && b.stage().relocating());
    // After the contact the partners separate: from contact, with the new
    // velocities over the rest of the step
    const scalar rest = 0.5e-5;
    const point& xa2 = a.stage().relocationTarget();
    const point& xb2 = b.stage().relocationTarget();
    EXPECT_LT(mag(xa2 - (xa + rest*a.U_)), 1e-18);
    EXPECT_LT(mag(xb2 - (xb + rest*b.U_)), 1e-18);
    EXPECT_GE(mag(xb2 - xa2), 12e-6*(1 - 1e-12));
}


TEST(collisionResolver, ghost)
{
    const dictionary dict
    (
        makeDict(kernelString("collisionResponse ghost;"))
    );
    hardSphereCollisionKernel kernel(dict);
    autoPtr<resolverType> r(resolverType::New(dict, kernel));
    EXPECT_EQ(r->type(), "ghost");
    EXPECT_FALSE(r->onePerParticle());

    testParcel a, b, c;
    pair(a, b, 0.3, 30);
    c = b;
    const vector Ua(a.U_), Ub(b.U_);
    const labelPair ida(0, 1), idb(0, 2), idc(0, 3);

    r->startStep();
    EXPECT_FALSE(r->duplicate(a, ida, idb));
    collisionEventRecord ev;
    ev.set(ida, a.state(Zero), idb, b.state(Zero), true, 0, 0.2, 7, 0);
    r->resolve(ev, a, &b, true, Zero, Zero, 1e-5);
    EXPECT_FALSE(ev.applied);
    EXPECT_EQ(ev.outcomePtr(), nullptr);
    EXPECT_EQ(a.U_, Ua);
    EXPECT_EQ(b.U_, Ub);
    EXPECT_FALSE(a.stage().collided() || b.stage().collided());
    EXPECT_EQ(labelPair(a.lastProc_, a.lastId_), idb);
    EXPECT_EQ(labelPair(b.lastProc_, b.lastId_), ida);
    EXPECT_EQ(b.lastTime_, 7);

    // The same pair through another image: a duplicate; a with another
    // partner in the same step: counted too (every event)
    EXPECT_TRUE(r->duplicate(a, ida, idb));
    EXPECT_FALSE(r->duplicate(a, ida, idc));

    // The next step forgets the pairs
    r->startStep();
    EXPECT_FALSE(r->duplicate(a, ida, idb));
}
