/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           | www.openfoam.com
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2026 agglomerationHardSphere project contributors
-------------------------------------------------------------------------------
License
    This file is part of the agglomerationHardSphere extension of OpenFOAM.

    It is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.
Application
    hardSphereReplay

Group
    grpLagrangianUtilities

Description
    Replays the collision-event log of a run (hardSphereCoeffs: eventLog
    true; doc/eventLog.md) through one or several collision kernels: the
    same pre-collision states, any agglomeration model, restitution
    coefficient or option, without running the flow again. Prints a table
    and writes JSON: per configuration the events, agglomerations, alpha
    with its 95 % Wilson interval and the branch counts; for every other
    configuration the paired comparison with the first (or -base NAME):
    events agglomerating under one and not the other, the ratio of the
    alphas with its paired 95 % interval.

    Without kernel dictionaries the run's own kernel (the cloud's
    hardSphereCoeffs) is replayed, and every event's branch, collision type
    and agglomeration are compared with what the run logged (-check: exit
    1 on any difference). A kernel dictionary holds the kernel entries of
    hardSphereCollide's input (material, particleCollision,
    agglomerationModel, structureModel, their Coeffs, capAgglomerateSpin);
    its file name names the configuration. A variants dictionary
    (-variants) names configurations that change the run's kernel, each
    merged into it:
    \verbatim
    EAM080 { agglomerationModel EAM; particleCollision { en 0.80; } }
    MAM080 { agglomerationModel MAM; particleCollision { en 0.80; } }
    \endverbatim

    The replay freezes the collision ensemble: what a changed outcome
    would do to later collisions and to the flow is not included.

Usage
    hardSphereReplay [-case DIR] [-cloud NAME] [-events all|first]
        [-json FILE] [-check] [-variants FILE] [-base NAME]
        [-eventsOut FILE] [kernelDict ...]

    -check ends with a fatal error (exit status 1) unless the run's kernel
    reproduces every logged outcome. An output must be a regular file or
    new (not a folder, a special file or a log read); it is written to a
    verified temporary file and renamed, so a failed call leaves an
    earlier result intact.

    The logs are read from postProcessing/<cloud>CollisionEvents of the
    case (events<rank>.bin: serial and decomposed runs alike).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "hardSphereCollisionKernel.H"
#include "hardSphereInput.H"
#include "binaryCollision.H"
#include "collisionEventFile.H"
#include "collisionEventLog.H"
#include <algorithm>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

#include "replayConfiguration.H"
#include "replayOutput.H"
#include "replayLogCount.H"
#include "replayVariants.H"
#include "writeEvents.H"
#include "writeReplay.H"
#include "readEvents.H"
#include "replayConfigurations.H"


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- The utility's options
void addOptions()
{
    argList::addNote
    (
        "Replay a run's collision-event log through collision kernels"
    );
    argList::noParallel();
    argList::noMandatoryArgs();
    argList::addArgument("kernelDict ...");
    argList::addOption("cloud", "name", "the cloud (kinematicCloud)");
    argList::addOption
    (
        "events", "all|first", "the events replayed (all)"
    );
    argList::addOption("json", "file", "JSON output (replay.json in the"
        " log folder)");
    argList::addBoolOption
    (
        "check", "exit 1 unless the run's kernel reproduces every event"
    );
    argList::addOption
    (
        "variants", "file", "configurations that change the run's kernel"
    );
    argList::addOption
    (
        "base", "name", "the configuration the others are paired with"
        " (the first)"
    );
    argList::addOption
    (
        "eventsOut", "file", "CSV: every replayed event, its pair state"
        " (u_n, tangential speeds, spins) and each configuration's branch,"
        " agglomeration and intermediates"
    );
}


//- Print each configuration's reproduced outcomes; true if every compared
//  configuration reproduced all
bool reportMatches(const UList<replayResult>& results)
{
    bool ok = true;
    for (const replayResult& r : results)
    {
        if (r.compared)
        {
            Info<< nl << r.name << ": " << r.matches << " of " << r.compared
                << " logged outcomes reproduced (branch, collision type,"
                << " agglomeration)" << nl;
            ok = ok && r.matches == r.compared;
        }
    }
    return ok;
}


int main(int argc, char *argv[])
{
    addOptions();

    #include "setRootCase.H"
    #include "createTime.H"

    // Every output is checked first and written last, through a verified
    // temporary file (replayOutput.H): a failure leaves an earlier result
    // as it was
    const bool keepEvents = args.found("eventsOut");

    const word cloudName(args.getOrDefault<word>("cloud", "kinematicCloud"));
    const fileName jsonOut
    (
        args.getOrDefault<fileName>
        (
            "json", collisionEventLog::folder(runTime, cloudName)
            /"replay.json"
        )
    );
    const word which(args.getOrDefault<word>("events", "all"));
    if (which != "all" && which != "first")
    {
        FatalErrorInFunction
            << "-events " << which << " is not valid; valid choices:"
            << " (all first)" << exit(FatalError);
    }

    // The logs, in a deterministic order; the outputs checked before any
    // work (replayOutput.H)
    const fileName dir(collisionEventLog::folder(runTime, cloudName));
    const fileNameList logs(logFiles(dir));
    checkTarget("json", jsonOut, dir, logs);
    if (keepEvents)
    {
        checkTarget("eventsOut", args.get<fileName>("eventsOut"), dir, logs);
    }
    const label nFiles = logs.size();
    wordList loggedBranches;
    const DynamicList<collisionEvent> events
    (
        readEvents(runTime, cloudName, dir, logs, which, loggedBranches)
    );

    // The configurations: the run's kernel (and its variants) unless
    // kernel dictionaries are given
    const List<replayResult> results
    (
        replayConfigurations
        (
            args, runTime, cloudName, events, loggedBranches, keepEvents
        )
    );
    const label base = baseConfiguration(args, results);

    writeReplay
    (
        events, loggedBranches, results, base, which, nFiles, dir,
        runTime.globalPath(), cloudName, jsonOut
    );

    if (keepEvents)
    {
        writeEvents(args.get<fileName>("eventsOut"), events, results);
    }

    const bool ok = reportMatches(results);
    Info<< nl << "JSON: " << jsonOut << nl;

    // The exit status through FatalError: a plain return would be
    // overridden by the argList's exit status 0
    if (args.found("check") && !ok)
    {
        FatalErrorInFunction
            << "-check: the run's kernel does not reproduce every logged"
            << " outcome (see the counts above)" << exit(FatalError);
    }
    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
