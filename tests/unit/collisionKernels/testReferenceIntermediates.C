/*---------------------------------------------------------------------------*\
Description
    The intermediate magnitudes of the reference collisions of
    doc/models.md 12.3 (quartz, 12 um, Tab. 1): the EAM's energies and kn2
    of rows 3, 5 and 11, the head-on collision at 1 mm/s of section 12.4
    for MAM and EAM at 12 and 4 um, the case-III rebound of row 14
    (Alletto 2014, 12.1) and the angular momentum defect of row 15 (EAM
    case II, 5.1). Relative tolerances 1e-5 to 2e-4, by the digits the
    document prints.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include <tuple>
#include <vector>

using namespace Foam;
using namespace aggloTest;


TEST(ReferenceIntermediates, EAMRows3_5_11)
{
    const dictionary dict(kernelDict("EAM"));
    const hardSphereCollisionKernel kernel(dict);
    hardSphereState p1, p2;

    referencePair(1e-3, 0, 0, 0, p1, p2);
    collisionOutcome out(kernel.collide(p1, p2));
    EXPECT_TRUE(near(value(kernel, out, "dEvdW"), 1.0953e-18, 1e-4));
    EXPECT_TRUE(near(value(kernel, out, "EkinPlus"), 4.6822e-19, 1e-4));
    EXPECT_TRUE(near(value(kernel, out, "kn2"), -1.3394, 1e-4));

    referencePair(3e-3, 0, 0, 0, p1, p2);
    out = kernel.collide(p1, p2);
    EXPECT_TRUE(near(value(kernel, out, "kn2"), 0.2202, 2e-4));

    referencePair(3e-3, 60, 0, 0, p1, p2);
    out = kernel.collide(p1, p2);
    EXPECT_TRUE(near(value(kernel, out, "EkinPlus"), 2.2171e-18, 1e-4));
    EXPECT_TRUE(near(value(kernel, out, "ErotPlus"), 1.4215e-18, 1e-4));
    EXPECT_TRUE(near(value(kernel, out, "ErotAg"), 2.3993e-18, 1e-4));
    EXPECT_TRUE(near(value(kernel, out, "dEvdW"), 1.6430e-18, 1e-4));
}


namespace
{

//- Expect the named intermediate values of the collision of p1 and p2
//  under the kernel of dict, each within its relative tolerance
void expectValues
(
    const dictionary& dict,
    const hardSphereState& p1,
    const hardSphereState& p2,
    const std::vector<std::tuple<std::string, scalar, scalar>>& expected
)
{
    const hardSphereCollisionKernel kernel(dict);
    const collisionOutcome out(kernel.collide(p1, p2));
    for (const auto& e : expected)
    {
        EXPECT_TRUE
        (
            near(value(kernel, out, word(std::get<0>(e))), std::get<1>(e),
                 std::get<2>(e))
        ) << std::get<0>(e);
    }
}

} // End anonymous namespace


TEST(ReferenceIntermediates, Section12_4HeadOn1mmps)
{
    hardSphereState p1, p2;
    referencePair(1e-3, 0, 0, 0, p1, p2);

    const binaryCollision pair(p1, p2);
    EXPECT_TRUE(near(pair.m1(), 1.99051e-12, 1e-5));
    EXPECT_TRUE(near(pair.mHat(), 9.95257e-13, 1e-5));
    EXPECT_TRUE(near(pair.fna(0.97), 1.97e-3, 1e-12));

    expectValues
    (
        kernelDict("MAM"), p1, p2,
        {{"tStar", 4.74389e-8, 1e-5}, {"fnc", 0.10847, 1e-4},
         {"fncStar", 8.0701e-4, 1e-4}}
    );
    expectValues
    (
        kernelDict("MAM", "CSM", "MAMCoeffs { closure hertzRebound; }"),
        p1, p2,
        {{"fnc", 0.10799, 1e-4}, {"fncStar", 3.2894e-4, 1e-4}}
    );
    expectValues(kernelDict("EAM"), p1, p2, {{"dEvdW", 1.09533e-18, 1e-5}});

    // d = 4 um
    referencePair(1e-3, 0, 0, 0, p1, p2, 4e-6);
    expectValues
    (
        kernelDict("MAM"), p1, p2,
        {{"tStar", 1.5813e-8, 1e-4}, {"fnc", 0.32541, 1e-4},
         {"fncStar", 2.42104e-3, 1e-5}}
    );
    expectValues
    (
        kernelDict("EAM"), p1, p2,
        {{"dEvdW", 1.21704e-19, 1e-5}, {"EkinPlus", 1.73414e-20, 1e-5}}
    );
}


TEST(ReferenceIntermediates, Alletto2014Row14CaseIIIRebound)
{
    // doc/models.md 12.1: row 14 takes the case-III rebound branch;
    // in-plane relative velocity vanishes, spins scale by the same factor
    // in [0, 1], and KE(no cohesion) - KE = dE_vdW
    const dictionary dict(kernelDict("EAMAlletto2014"));
    const hardSphereCollisionKernel kernel(dict);
    const dictionary dictNone(kernelDict("none"));
    const hardSphereCollisionKernel none(dictNone);

    hardSphereState p1, p2;
    referencePair(2e-3, 45, 300, -300, p1, p2);
    const collisionOutcome out(kernel.collide(p1, p2));
    const collisionOutcome ref(none.collide(p1, p2));

    ASSERT_EQ(branchName(kernel, out), "caseIIIrebound");
    EXPECT_FALSE(out.agglomerates);
    const vector du = out.p2.U - out.p1.U;
    EXPECT_TRUE(near(du.x(), 0, 0, 1e-15));
    EXPECT_TRUE(near(du.y(), 0, 0, 1e-15));

    const scalar k1 = out.p1.omega.z()/ref.p1.omega.z();
    const scalar k2 = out.p2.omega.z()/ref.p2.omega.z();
    EXPECT_TRUE(near(k1, k2, 1e-12));
    EXPECT_GE(k1, 0);
    EXPECT_LE(k1, 1);

    const scalar KEnone = ref.p1.kineticEnergy() + ref.p2.kineticEnergy();
    const scalar KE = out.p1.kineticEnergy() + out.p2.kineticEnergy();
    EXPECT_TRUE(near(KEnone - KE, value(kernel, out, "dEvdW"), 1e-9));
}


TEST(ReferenceIntermediates, A6CaseIIAngularMomentumDefect)
{
    // doc/models.md 5.1: row 15 (EAM case II) changes the pair
    // angular momentum by m^ ell (1 - k_t)(w.t_E) (n x t_E), non-zero; the
    // spins are those of the collision without cohesion
    const dictionary dict(kernelDict("EAM"));
    const hardSphereCollisionKernel kernel(dict);
    hardSphereState p1, p2;
    referencePair(1e-2, 85, 0, 0, p1, p2);
    const binaryCollision pair(p1, p2);
    const collisionOutcome o(kernel.collide(p1, p2));
    ASSERT_EQ(branchName(kernel, o), "caseII");

    const vector L0 = pair.angularMomentum(p1, p2);
    const vector L1 = binaryCollision(o.p1, o.p2).angularMomentum(o.p1, o.p2);
    const scalar dL = mag(L1 - L0);
    EXPECT_GT(dL, 1e-3*mag(L0));
    EXPECT_TRUE(near(dL, value(kernel, o, "deltaL"), 1e-10));

    // |dL| = m^ ell (1 - k_t)|w.t| with w from the no-cohesion rebound
    const dictionary dictNone(kernelDict("none"));
    const hardSphereCollisionKernel none(dictNone);
    const collisionOutcome r(none.collide(p1, p2));
    const vector w = r.p2.U - r.p1.U;
    const scalar kt = std::sqrt(value(kernel, o, "kt2"));
    EXPECT_TRUE(near(dL, pair.mHat()*pair.ell()*(1 - kt)*std::abs(w & pair.t()),
        1e-10));
}
