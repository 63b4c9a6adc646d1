/*---------------------------------------------------------------------------*\
Description
    Invariants of the kernels over random collisions (doc/models.md
    12.1): T1 momentum, T2 angular momentum, T3 kinetic energy, T10 EAM
    rebound energy, T11 Eq. 21 right-hand side, T12 dumbbell energy, T15
    MAM rebound velocity, T16 MAM sliding, T17 symmetries. The Hiller
    limit, monotonicity, scaling and critical velocities are in
    testCriticalVelocities.C.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "tensor.H"
#include <random>
#include <vector>

using namespace Foam;
using namespace aggloTest;

namespace
{

//- Random collision set-up of section 12.1: random orientation,
//  d1 = 12 um, d2 in {4, 12, 20} um, relative speed 3e-5..0.1 m/s,
//  spins 10..1e4 rad/s (log-uniform), quartz
class randomCollisions
{
    std::mt19937 gen_;
    std::uniform_real_distribution<scalar> uni_;
    scalar vMin_, vMax_;

    vector direction()
    {
        vector v;
        do
        {
            v = vector(uni_(gen_), uni_(gen_), uni_(gen_));
        } while (mag(v) < 1e-3 || mag(v) > 1);
        return v/mag(v);
    }

    scalar logUniform(const scalar a, const scalar b)
    {
        const scalar r = 0.5*(uni_(gen_) + 1);
        return a*std::pow(b/a, r);
    }

public:

    explicit randomCollisions
    (
        const unsigned seed,
        const scalar vMin = 3e-5,
        const scalar vMax = 0.1
    )
    :
        gen_(seed),
        uni_(-1, 1),
        vMin_(vMin),
        vMax_(vMax)
    {}

    void next(hardSphereState& p1, hardSphereState& p2, const label i)
    {
        const scalar d2s[3] = {4e-6, 12e-6, 20e-6};
        const scalar d2 = d2s[i % 3];
        const vector n = direction();
        vector ur = logUniform(vMin_, vMax_)*direction();
        if ((ur & n) > 0)
        {
            ur -= 2*(ur & n)*n;
        }
        p1 = hardSphereState(point(1e-3, 2e-3, -1e-3), vector(0.1, 0, 0),
            logUniform(10, 1e4)*direction(), 12e-6, 2200);
        p2 = hardSphereState(p1.x + 0.5*(12e-6 + d2)*n, p1.U + ur,
            logUniform(10, 1e4)*direction(), d2, 2200);
    }
};


vector totalMomentum(const collisionOutcome& o)
{
    return o.agglomerates
        ? o.agglomerate.momentum()
        : o.p1.momentum() + o.p2.momentum();
}


scalar totalKE(const collisionOutcome& o)
{
    return o.agglomerates
        ? o.agglomerate.kineticEnergy()
        : o.p1.kineticEnergy() + o.p2.kineticEnergy();
}


//- Angular momentum about the pair centre of mass after the collision
vector pairL(const collisionOutcome& o, const hardSphereState& p1)
{
    if (o.agglomerates)
    {
        return o.agglomerate.inertia()*o.agglomerate.omega;
    }
    // Post states at the same positions: same n and ell
    hardSphereState a(o.p1), b(o.p2);
    a.x = p1.x;
    return binaryCollision(a, b).angularMomentum(a, b);
}


void checkInvariants(const std::string& model, const std::string& structure)
{
    const dictionary dict(kernelDict(model, structure));
    const hardSphereCollisionKernel kernel(dict);
    randomCollisions rnd(2024);

    label nAgg = 0, nReb = 0;
    for (label i = 0; i < 3000; ++i)
    {
        hardSphereState p1, p2;
        rnd.next(p1, p2, i);
        const binaryCollision pair(p1, p2);
        const collisionOutcome o(kernel.collide(p1, p2));
        o.agglomerates ? ++nAgg : ++nReb;

        // T1 momentum
        const vector P0 = p1.momentum() + p2.momentum();
        const scalar scaleP =
            p1.mass()*mag(p1.U) + p2.mass()*mag(p2.U);
        EXPECT_LE(mag(totalMomentum(o) - P0), 1e-12*scaleP)
            << model << " collision " << i;

        // T2 angular momentum (not EAM case II, not Alletto case III)
        if
        (
            branchName(kernel, o) != "caseII"
         && branchName(kernel, o) != "caseIIIrebound"
        )
        {
            const vector L0 = pair.angularMomentum(p1, p2);
            const scalar scaleL =
                p1.inertia()*mag(p1.omega) + p2.inertia()*mag(p2.omega)
              + pair.mHat()*pair.ell()*mag(pair.ur());
            EXPECT_LE(mag(pairL(o, p1) - L0), 1e-12*scaleL)
                << model << " collision " << i << " branch "
                << branchName(kernel, o);
        }

        // T3 kinetic energy: rebounds of all models; agglomeration only
        // for CSM of two equal primaries (A7: VSM and unequal partners
        // can gain, section 5.2)
        const scalar KE0 = p1.kineticEnergy() + p2.kineticEnergy();
        if (!o.agglomerates || (structure == "CSM" && p1.d == p2.d))
        {
            EXPECT_LE(totalKE(o) - KE0, 1e-12*KE0)
                << model << " collision " << i;
        }

        // Mass and primaries
        if (o.agglomerates)
        {
            EXPECT_TRUE(near(o.agglomerate.mass(), p1.mass() + p2.mass(),
                1e-13));
            EXPECT_EQ(o.agglomerate.nPrimary, 2);
        }
    }
    if (model != "none")
    {
        EXPECT_GT(nAgg, 50) << model;
    }
    EXPECT_GT(nReb, 50) << model;
}

} // End anonymous namespace


TEST(Invariants, T1T2T3None)           { checkInvariants("none", "CSM"); }
TEST(Invariants, T1T2T3EAM_CSM)        { checkInvariants("EAM", "CSM"); }
TEST(Invariants, T1T2T3EAM_VSM)        { checkInvariants("EAM", "VSM"); }
TEST(Invariants, T1T2T3EAMAlletto2014)
{
    checkInvariants("EAMAlletto2014", "CSM");
}
TEST(Invariants, T1T2T3MAM_CSM)        { checkInvariants("MAM", "CSM"); }
TEST(Invariants, T1T2T3MAM_VSM)        { checkInvariants("MAM", "VSM"); }


TEST(Invariants, T10T11T12EAMEnergyBookkeeping)
{
    const dictionary dict(kernelDict("EAM"));
    const hardSphereCollisionKernel eam(dict);
    const dictionary dictNone(kernelDict("none"));
    const hardSphereCollisionKernel none(dictNone);
    randomCollisions rnd(7);

    label nCaseI = 0, nCaseII = 0;
    for (label i = 0; i < 3000; ++i)
    {
        hardSphereState p1, p2;
        rnd.next(p1, p2, i);

        // Centre-of-mass frame: the energy differences are ~1e-8 of the
        // bulk kinetic energy otherwise (round-off)
        const vector Ucm =
            (p1.momentum() + p2.momentum())/(p1.mass() + p2.mass());
        p1.U -= Ucm;
        p2.U -= Ucm;

        const binaryCollision pair(p1, p2);
        const collisionOutcome o(eam.collide(p1, p2));

        // T11: right-hand side of Eq. 21 is never negative
        EXPECT_GE
        (
            value(eam, o, "EkinPlus") + value(eam, o, "ErotPlus")
          - value(eam, o, "ErotAg"),
            0
        );

        // T12: closed form = 3x3 solve
        const vector L = pair.angularMomentum(p1, p2);
        const scalar Ec = agglomerationModels::EAM::dumbbellRotationalEnergy
            (L, pair.n(), p1.inertia(), p2.inertia(), pair.mHat(),
             pair.ell());
        const scalar Es =
            agglomerationModels::EAM::dumbbellRotationalEnergySolve
            (L, pair.n(), p1.inertia(), p2.inertia(), pair.mHat(),
             pair.ell());
        EXPECT_TRUE(near(Ec, Es, 1e-12));

        // T10: KE(no cohesion) - KE(EAM) = dE_vdW in both rebound cases
        if (!o.agglomerates)
        {
            branchName(eam, o) == "caseI" ? ++nCaseI : ++nCaseII;
            const collisionOutcome r(none.collide(p1, p2));
            const scalar dE = value(eam, o, "dEvdW");
            EXPECT_TRUE(near(totalKE(r) - totalKE(o), dE, 1e-9))
                << "branch " << branchName(eam, o);
        }
    }
    EXPECT_GT(nCaseI, 10);
    EXPECT_GT(nCaseII, 10);
}



TEST(Invariants, T15T16MAMReboundAndSliding)
{
    const dictionary dict(kernelDict("MAM"));
    const hardSphereCollisionKernel mam(dict);

    // Faster impacts than section 12.1 so that sliding MAM collisions
    // occur (f_nc >> f_na makes almost all of them sticking)
    randomCollisions rnd(99, 1e-3, 1);

    label nSliding = 0, nSlidingCritII = 0;
    for (label i = 0; i < 3000; ++i)
    {
        hardSphereState p1, p2;
        rnd.next(p1, p2, i);
        const binaryCollision pair(p1, p2);
        const collisionOutcome o(mam.collide(p1, p2));

        if (!o.isSticking())
        {
            ++nSliding;
            if (value(mam, o, "critII") == 1) ++nSlidingCritII;
        }
        if (!o.agglomerates)
        {
            // T15
            const scalar wn = (o.p2.U - o.p1.U) & pair.n();
            const scalar fncStar = value(mam, o, "fncStar");
            EXPECT_TRUE(near(wn, -0.97*pair.un() - fncStar, 1e-12, 1e-18))
                << i;
        }
    }
    // T16 (A13): with Tab. 1, criterion (ii) never holds when sliding
    EXPECT_GT(nSliding, 50);
    EXPECT_EQ(nSlidingCritII, 0);
}


TEST(Invariants, T17SwapShiftRotate)
{
    const char* models[4] = {"none", "EAM", "EAMAlletto2014", "MAM"};
    const tensor R
    (
        0.36, 0.48, -0.8,
        -0.8, 0.6, 0,
        0.48, 0.64, 0.6
    );
    for (const char* model : models)
    {
        const dictionary dict(kernelDict(model));
        const hardSphereCollisionKernel k(dict);
        randomCollisions rnd(5);
        for (label i = 0; i < 300; ++i)
        {
            hardSphereState p1, p2;
            rnd.next(p1, p2, i);
            const collisionOutcome o(k.collide(p1, p2));
            const scalar uScale = mag(p1.U) + mag(p2.U);
            const scalar wScale = mag(p1.omega) + mag(p2.omega)
              + mag(p2.U - p1.U)/p1.d;

            // Label swap
            const collisionOutcome s(k.collide(p2, p1));
            ASSERT_EQ(s.agglomerates, o.agglomerates) << model << i;
            EXPECT_EQ(s.branch, o.branch);
            if (!o.agglomerates)
            {
                EXPECT_LE(mag(s.p1.U - o.p2.U), 1e-12*uScale);
                EXPECT_LE(mag(s.p2.omega - o.p1.omega), 1e-12*wScale);
            }
            else
            {
                EXPECT_LE(mag(s.agglomerate.omega - o.agglomerate.omega),
                    1e-12*wScale);
            }

            // Galilean shift
            const vector shift(0.3, -0.2, 0.1);
            hardSphereState g1(p1), g2(p2);
            g1.U += shift;
            g2.U += shift;
            g1.x += vector(1, 2, 3);
            g2.x += vector(1, 2, 3);
            const collisionOutcome g(k.collide(g1, g2));
            ASSERT_EQ(g.agglomerates, o.agglomerates);
            if (!o.agglomerates)
            {
                EXPECT_LE(mag((g.p2.U - g.p1.U) - (o.p2.U - o.p1.U)),
                    1e-9*mag(p2.U - p1.U) + 1e-15);
            }

            // Rigid rotation
            hardSphereState r1(p1), r2(p2);
            r1.x = R & p1.x; r2.x = R & p2.x;
            r1.U = R & p1.U; r2.U = R & p2.U;
            r1.omega = R & p1.omega; r2.omega = R & p2.omega;
            const collisionOutcome r(k.collide(r1, r2));
            ASSERT_EQ(r.agglomerates, o.agglomerates);
            if (!o.agglomerates)
            {
                EXPECT_LE(mag(r.p2.U - (R & o.p2.U)), 1e-12*uScale);
                EXPECT_LE(mag(r.p1.omega - (R & o.p1.omega)), 1e-12*wScale);
            }
        }
    }
}

