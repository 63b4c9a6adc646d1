/*---------------------------------------------------------------------------*\
Description
    How soon an overloaded agglomerate breaks (doc/breakup.md 1.6): the
    deterministic rate breaks at once; the stochastic one with
    1 - exp(-dt/t_e), t_e the Kolmogorov time (nu/eps)^(1/2) or the eddy
    lifetime d_a^(2/3) eps^(-1/3), against hand values; no dissipation,
    no break; bad input names the entry.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "breakupRate.H"

using namespace Foam;
using namespace aggloTest;

namespace
{

std::string rateError(const std::string& text)
{
    try
    {
        breakupRate rate(makeDict(text));
    }
    catch (const Foam::error& err)
    {
        return std::string(err.message());
    }
    return "";
}

} // End anonymous namespace


TEST(BreakupRate, DeterministicBreaksAtOnce)
{
    const breakupRate none;
    EXPECT_FALSE(none.stochastic());
    EXPECT_EQ(none.probability(1e-9, 1, 1e-6, 1e-5), 1);

    const breakupRate det(makeDict("model deterministic;"));
    EXPECT_FALSE(det.stochastic());
    EXPECT_EQ(det.probability(1e-9, 0, 1e-6, 1e-5), 1);
}


TEST(BreakupRate, StochasticAgainstHandValues)
{
    // Kolmogorov: nu = 1e-6, eps = 100 -> t_e = 1e-4 s; dt = t_e
    const breakupRate k(makeDict("model stochastic; timeScale kolmogorov;"));
    EXPECT_TRUE(k.stochastic());
    EXPECT_NEAR(k.timeScale(100, 1e-6, 1e-5), 1e-4, 1e-16);
    EXPECT_NEAR(k.probability(1e-4, 100, 1e-6, 1e-5), 0.6321205588285577,
                1e-15);

    // Eddy: d_a = 1e-4 m, eps = 1 -> t_e = (1e-8)^(1/3) = 2.1544347e-3 s
    const breakupRate e(makeDict("model stochastic; timeScale eddy;"));
    EXPECT_NEAR(e.timeScale(1, 1e-6, 1e-4), 2.154434690031884e-3, 1e-17);
    EXPECT_NEAR
    (
        e.probability(1e-3, 1, 1e-6, 1e-4),
        1 - std::exp(-1e-3/2.154434690031884e-3),
        1e-15
    );

    // Small steps: P -> dt/t_e
    EXPECT_NEAR(k.probability(1e-10, 100, 1e-6, 1e-5), 1e-6, 1e-12);

    // Without dissipation there is no turbulent time scale: no break
    EXPECT_EQ(k.probability(1, 0, 1e-6, 1e-5), 0);
}


TEST(BreakupRate, BadInputNamesTheEntry)
{
    EXPECT_NE(rateError("model random;").find("random"), std::string::npos);
    EXPECT_NE
    (
        rateError("model stochastic; timeScale lagrangian;")
            .find("lagrangian"),
        std::string::npos
    );
    EXPECT_NE
    (
        rateError("model stochastic;").find("timeScale"), std::string::npos
    );
    EXPECT_NE
    (
        rateError("model deterministic; timeScale eddy;").find("timeScale"),
        std::string::npos
    );
}
