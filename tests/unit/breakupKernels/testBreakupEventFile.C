/*---------------------------------------------------------------------------*\
Description
    The break-up log's file for the Python reader: one record of known,
    pairwise different values written with its header (mechanisms, model,
    fields) and read back exactly; where AGGLO_LAYOUT_DIR names a folder
    the file is left there for tests/aggloTools/test_eventLayouts.py,
    which reads every field with aggloTools.breakuplog.DTYPE.
\*---------------------------------------------------------------------------*/

#include "../testHelpers.H"
#include "breakupEvent.H"
#include "eventFile.H"
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

using namespace Foam;
using namespace aggloTest;

namespace
{

//- A record whose every field differs from the others (values also in
//  tests/aggloTools/test_eventLayouts.py)
breakupEvent layoutSample()
{
    breakupEvent e;
    e.timeIndex = 12;
    e.mechanism = 1;
    e.proc = 2;
    e.id = 31;
    e.newProc = -2;
    e.newId = 7;
    e.dt = 1e-5;
    e.parent = hardSphereState
    (
        point(1e-3, 2e-3, 3e-3), vector(0.1, -0.2, 0.3),
        vector(10, -20, 30), 4e-5, 1100, 9
    );
    e.load.epsilon = 5.5;
    e.load.nu = 1.5e-5;
    e.load.rhoF = 1.2;
    e.load.omega = e.parent.omega;
    e.load.dragForce = vector(1e-9, 2e-9, -3e-9);
    e.load.wallImpactSpeed = 0.25;
    e.S = symmTensor(11, 12, 13, 14, 15, 16);
    e.values = FixedList<scalar, breakupEvent::nValues>({0.5, 1.5, 2.5, 3.5});
    e.a = hardSphereState
    (
        point(4e-3, 5e-3, 6e-3), vector(0.4, 0.5, 0.6),
        vector(40, 50, 60), 1.2e-5, 2200, 1
    );
    e.b = hardSphereState
    (
        point(7e-3, 8e-3, 9e-3), vector(0.7, 0.8, 0.9),
        vector(70, 80, 90), 3.8e-5, 1150, 8
    );
    e.attempt = 3;
    return e;
}

} // End anonymous namespace


TEST(BreakupEventFile, WrittenForPython)
{
    const char* dir = ::getenv("AGGLO_LAYOUT_DIR");
    const fileName f
    (
        dir
      ? fileName(dir)/"breakupEvents.bin"
      : fileName("/tmp/aggloTestBreakup" + Foam::name(label(::getpid()))
          + ".bin")
    );
    std::remove(f.c_str());
    const List<wordList> names
    (
        {
            wordList({"turbulence", "drag", "rotation"}),
            wordList({"layoutSample"}),
            wordList({"v0", "v1", "v2", "v3"})
        }
    );
    const List<breakupEvent> one(1, layoutSample());
    eventFile<breakupEvent>::append(f, one, names);
    List<wordList> back;
    const List<breakupEvent> read(eventFile<breakupEvent>::read(f, back));
    ASSERT_EQ(read.size(), 1);
    EXPECT_EQ(back, names);
    EXPECT_EQ(read[0].newId, 7);
    EXPECT_EQ(read[0].S, one[0].S);
    EXPECT_EQ(read[0].b.x, one[0].b.x);
    EXPECT_EQ(read[0].attempt, 3);
    if (!dir)
    {
        std::remove(f.c_str());
    }
}

// ************************************************************************* //
