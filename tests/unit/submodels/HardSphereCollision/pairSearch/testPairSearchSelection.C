/*---------------------------------------------------------------------------*\
    Unit tests of the pair searches' run-time selection (PairSearch::New):
    no entry selects particleGrid, pairSearch names another, a misspelt
    name stops naming the valid searches, and interactionDistance (the
    interactionLists' own entry) with another search stops naming it.
\*---------------------------------------------------------------------------*/

#include "PairSearch.H"
#include "basicAgglomerateParcel.H"
#include "testMeshes.H"
#include "Time.H"
#include "polyMesh.H"
#include "IStringStream.H"
#include <gtest/gtest.h>
#include <string>

using namespace Foam;
using aggloTest::boxMesh;

namespace
{

typedef PairSearch<basicAgglomerateParcel> searchType;

std::string selectionError(const std::string& text)
{
    try
    {
        autoPtr<Time> runTime(Time::New());
        autoPtr<polyMesh> mesh(boxMesh(runTime(), true));
        IStringStream is(text);
        searchType::New(dictionary(is), mesh(), "U");
    }
    catch (const Foam::error& err)
    {
        return std::string(err.message());
    }
    return "";
}

} // End anonymous namespace


TEST(pairSearch, selection)
{
    autoPtr<Time> runTime(Time::New());
    autoPtr<polyMesh> mesh(boxMesh(runTime(), true));
    {
        IStringStream is("");
        EXPECT_EQ(searchType::New(dictionary(is), mesh(), "U")->type(),
                  "particleGrid");
    }
    {
        IStringStream is("pairSearch bruteForce;");
        EXPECT_EQ(searchType::New(dictionary(is), mesh(), "U")->type(),
                  "bruteForce");
    }

    const std::string bad(selectionError("pairSearch grid;"));
    EXPECT_NE(bad.find("grid"), std::string::npos) << bad;
    EXPECT_NE(bad.find("particleGrid"), std::string::npos) << bad;
    EXPECT_NE(bad.find("interactionLists"), std::string::npos) << bad;

    const std::string dist(selectionError("interactionDistance 1e-4;"));
    EXPECT_NE(dist.find("interactionDistance"), std::string::npos) << dist;
    EXPECT_NE(dist.find("particleGrid"), std::string::npos) << dist;
}
