/*---------------------------------------------------------------------------*\
Description
    Run-time selection of the kernel's models: an unknown agglomeration
    model, structure model or option value stops with an error naming the
    entry and listing the valid choices.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"

using namespace Foam;
using namespace aggloTest;

namespace
{

const std::string base =
    quartzInput() + " agglomerationModel EAM; structureModel CSM;";

} // End anonymous namespace


TEST(ModelSelection, UnknownAgglomerationModel)
{
    const std::string msg =
        kernelError
        (
            replaced(base, "agglomerationModel EAM", "agglomerationModel EMA")
        );
    EXPECT_NE(msg.find("EMA"), std::string::npos) << msg;
    EXPECT_NE(msg.find("MAM"), std::string::npos) << msg;
    EXPECT_NE(msg.find("EAMAlletto2014"), std::string::npos) << msg;
}

TEST(ModelSelection, UnknownStructureModel)
{
    const std::string msg =
        kernelError(replaced(base, "structureModel CSM", "structureModel XSM"));
    EXPECT_NE(msg.find("XSM"), std::string::npos) << msg;
    EXPECT_NE(msg.find("VSM"), std::string::npos) << msg;
}

TEST(ModelSelection, UnknownOptionValue)
{
    const std::string msg =
        kernelError(base + " EAMCoeffs { impactVelocity diagonal; }");
    EXPECT_NE(msg.find("diagonal"), std::string::npos) << msg;
    EXPECT_NE(msg.find("normal"), std::string::npos) << msg;
    EXPECT_NE(msg.find("full"), std::string::npos) << msg;
}


// ************************************************************************* //
