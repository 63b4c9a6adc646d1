/*---------------------------------------------------------------------------*\
Description
    Material and coefficient input: yield pressure factor c(nu) of AB16
    App. A against doc/models.md 2.2, and the errors on out-of-range or
    missing material and coefficient entries.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "agglomerationModel.H"

using namespace Foam;
using namespace aggloTest;

namespace
{

const std::string base =
    quartzInput() + " agglomerationModel EAM; structureModel CSM;";

} // End anonymous namespace


TEST(Material, YieldPressureFactorQuartz)
{
    // doc/models.md 2.2 table: nu = 0.17 -> zeta 0.438, c 1.46635
    EXPECT_TRUE(near(hardSphereMaterial::yieldPressureFactor(0.17),
        1.46635, 1e-5));
    EXPECT_TRUE(near(hardSphereMaterial::yieldDepth(0.17), 0.438, 2e-3));
}

TEST(Material, YieldPressureFactorPolystyrene)
{
    // nu = 0.34 -> zeta 0.494, c 1.66161
    EXPECT_TRUE(near(hardSphereMaterial::yieldPressureFactor(0.34),
        1.66161, 1e-5));
    EXPECT_TRUE(near(hardSphereMaterial::yieldDepth(0.34), 0.494, 2e-3));
}

TEST(Material, PMaxFromSigmaY)
{
    const dictionary dict(makeDict
    (
        "H 6.3e-20; E 7.2e10; nu 0.17; sigmaY 1.1e9; delta0 2e-10;"
        " rho0 2200;"
    ));
    const hardSphereMaterial mat(dict);
    // doc/models.md 0.6: p = 1.612985e9 Pa
    EXPECT_TRUE(near(mat.pMax(), 1.612985e9, 1e-5));
    // EHat = E/(2(1 - nu^2)) = 3.70714e10 Pa
    EXPECT_TRUE(near(mat.EHat(), 3.70714e10, 1e-5));
}

TEST(BadInput, RestitutionAboveOne)
{
    const std::string msg =
        kernelError(replaced(base, "en 0.97", "en 1.2"));
    EXPECT_NE(msg.find("'en'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(0, 1]"), std::string::npos) << msg;
}

TEST(BadInput, RestitutionZero)
{
    const std::string msg = kernelError(replaced(base, "en 0.97", "en 0"));
    EXPECT_NE(msg.find("'en'"), std::string::npos) << msg;
}

TEST(BadInput, NegativeHamaker)
{
    const std::string msg =
        kernelError(replaced(base, "H 6.3e-20", "H -6.3e-20"));
    EXPECT_NE(msg.find("'H'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(0, inf)"), std::string::npos) << msg;
}

TEST(BadInput, PoissonRatioOutOfRange)
{
    const std::string msg = kernelError(replaced(base, "nu 0.17", "nu 0.5"));
    EXPECT_NE(msg.find("'nu'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[0, 0.5)"), std::string::npos) << msg;
}

TEST(BadInput, MissingEntry)
{
    const std::string msg =
        kernelError(replaced(base, "delta0 2e-10;", ""));
    EXPECT_NE(msg.find("'delta0' not found"), std::string::npos) << msg;
}

TEST(BadInput, NeitherPressureNorYield)
{
    const std::string msg =
        kernelError(replaced(base, "pMax 1.612985e9;", ""));
    EXPECT_NE(msg.find("pMax"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sigmaY"), std::string::npos) << msg;
}

TEST(BadInput, NegativeFriction)
{
    const std::string msg =
        kernelError(replaced(base, "muKin 0.092", "muKin -0.1"));
    EXPECT_NE(msg.find("'muKin'"), std::string::npos) << msg;
}

TEST(BadInput, PackingFractionsDecreasingDiameter)
{
    const std::string msg = kernelError
    (
        base + " CSMCoeffs { packingFractions ((2 0.26683) (3 0.9)); }"
    );
    EXPECT_NE(msg.find("decreasing"), std::string::npos) << msg;
}
