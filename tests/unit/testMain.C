/*---------------------------------------------------------------------------*\
Description
    GoogleTest main of the agglomerationHardSphere unit tests. OpenFOAM
    fatal errors throw (so bad input can be tested) and Info is silenced.
\*---------------------------------------------------------------------------*/

#include "error.H"
#include "messageStream.H"
#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);

    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    Foam::messageStream::level = 0;

    return RUN_ALL_TESTS();
}
