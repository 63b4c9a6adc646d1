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
    breakupReplay

Group
    grpLagrangianUtilities

Description
    Replays the break-up event log of a run (stressThresholdCoeffs:
    eventLog true; doc/eventLog.md) through the break-up kernel of the run
    and of variants: the same parents under the same loads, any strength,
    stresses, fragmentation or rate coefficients, without running the flow
    again. Prints a table and writes JSON: per configuration the logged
    break-ups that still break, by mechanism, those deferred by a
    stochastic rate, those whose mechanism changes, and those whose
    fragments are the logged ones bit for bit.

    The run's own configuration (the cloud's stressThresholdCoeffs and the
    material and structure of its hardSphereCoeffs) must reproduce every
    logged break-up (-check: exit 1 on any difference). A variants
    dictionary (-variants) names configurations that change the run's
    coefficients, each merged into them:
    \verbatim
    weaker   { strength { rumpfPrefactor 0.5; } }
    binary   { fragmentation { mode binary; } }
    \endverbatim

    The log holds the agglomerates that broke: a replay tells which of
    them a variant would also break, not which of the others it would
    break, nor what its fragments would have done afterwards.

Usage
    breakupReplay [-case DIR] [-cloud NAME] [-json FILE] [-check]
        [-variants FILE]

    The logs are read from postProcessing/<cloud>BreakupEvents of the
    case (events<rank>.bin: serial and decomposed runs alike). The JSON
    goes to breakupReplay.json there unless -json names a file.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OStringStream.H"
#include "IFstream.H"
#include "hardSphereCollisionKernel.H"
#include "hardSphereInput.H"
#include "breakupKernel.H"
#include "breakupEvent.H"
#include "eventLogFiles.H"
#include <algorithm>
#include <iomanip>
#include <sstream>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

#include "replayOutput.H"
#include "replayLogCount.H"
#include "replayVariants.H"

namespace
{

//- What one configuration does with the logged break-ups
struct breakupReplayResult
{
    word name;
    label breaks = 0, deferred = 0, mechanismChanged = 0, reproduced = 0;
    labelList byMechanism;
};


//- The labels as a JSON list
std::string json(const labelUList& l)
{
    std::ostringstream os;
    os  << '[';
    forAll(l, i)
    {
        os  << (i ? ", " : "") << l[i];
    }
    os  << ']';
    return os.str();
}


//- True if the states are equal bit for bit
bool same(const hardSphereState& a, const hardSphereState& b)
{
    return
        a.x == b.x && a.U == b.U && a.omega == b.omega && a.d == b.d
     && a.rho == b.rho && a.nPrimary == b.nPrimary;
}


//- Replay the events through the kernel of the coefficients
breakupReplayResult replay
(
    const word& name,
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision,
    const UList<breakupEvent>& events
)
{
    const breakupKernel kernel(coeffs, collision);
    breakupReplayResult r;
    r.name = name;
    r.byMechanism.setSize(breakupStresses::mechanismTypeNames.size(), 0);
    for (const breakupEvent& e : events)
    {
        const breakupCriterion::verdict v = kernel.check(e.parent, e.load);
        const breakupKernel::key k{e.proc, e.id, e.timeIndex};
        if (!v.breaks())
        {
            continue;
        }
        if (kernel.deferred(v, e.load, e.parent.d, e.dt, k))
        {
            ++r.deferred;
            continue;
        }
        ++r.breaks;
        ++r.byMechanism[v.mechanism];
        if (v.mechanism != e.mechanism)
        {
            ++r.mechanismChanged;
            continue;
        }
        const agglomerateFragmentation::fragments f =
            kernel.split(e.parent, v, e.S, k);
        if (v.ratio == e.ratio && same(f.a, e.a) && same(f.b, e.b))
        {
            ++r.reproduced;
        }
    }
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Replay a run's break-up event log through break-up kernels"
    );
    argList::noParallel();
    argList::addOption("cloud", "name", "the cloud (kinematicCloud)");
    argList::addOption
    (
        "json", "file", "JSON output (breakupReplay.json in the log folder)"
    );
    argList::addBoolOption
    (
        "check", "exit 1 unless the run's kernel reproduces every event"
    );
    argList::addOption
    (
        "variants", "file", "configurations that change the run's"
        " stressThresholdCoeffs"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    const word cloudName(args.getOrDefault<word>("cloud", "kinematicCloud"));
    const fileName dir
    (
        eventLogFiles<breakupEvent>::folder
        (
            runTime, cloudName, "BreakupEvents"
        )
    );
    const fileName jsonOut
    (
        args.getOrDefault<fileName>("json", dir/"breakupReplay.json")
    );

    // The logs, in a deterministic order
    fileNameList files(readDir(dir, fileName::FILE));
    Foam::sort(files);
    fileNameList logs;
    for (const fileName& f : files)
    {
        if (f.hasExt("bin") && f.startsWith("events"))
        {
            logs.append(f);
        }
    }
    if (logs.empty())
    {
        FatalErrorInFunction
            << "No break-up event log in " << dir << nl << "(run the case"
            << " with eventLog true; in stressThresholdCoeffs)"
            << exit(FatalError);
    }
    checkTarget("json", jsonOut, dir, logs);

    const wordList mechanisms(breakupStresses::mechanismTypeNames.names());
    DynamicList<breakupEvent> events;
    for (const fileName& f : logs)
    {
        wordList names;
        events.append(eventFile<breakupEvent>::read(dir/f, names));
        if (names != mechanisms)
        {
            FatalErrorInFunction
                << "The log " << dir/f << " names the mechanisms " << names
                << "; this build has " << mechanisms << exit(FatalError);
        }
    }
    checkLogCount(runTime, cloudName, "breakupEventLog", dir, events.size());
    std::stable_sort
    (
        events.begin(), events.end(),
        [](const breakupEvent& a, const breakupEvent& b)
        {
            if (a.timeIndex != b.timeIndex) return a.timeIndex < b.timeIndex;
            if (a.proc != b.proc) return a.proc < b.proc;
            return a.id < b.id;
        }
    );

    // The run's configuration: its break-up coefficients, the material and
    // structure of its collision kernel
    const IOdictionary props
    (
        IOobject
        (
            cloudName + "Properties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const dictionary& subModels = props.subDict("subModels");
    const dictionary& hsCoeffs = subModels.subDict("hardSphereCoeffs");
    dictionary kernelDict;
    for (const word& key : hardSphereCollisionKernel::keys(hsCoeffs))
    {
        if (hsCoeffs.found(key))
        {
            kernelDict.add(hsCoeffs.lookupEntry(key, keyType::LITERAL));
        }
    }
    const hardSphereCollisionKernel collision(kernelDict);
    const dictionary& runCoeffs = subModels.subDict("stressThresholdCoeffs");

    List<breakupReplayResult> results;
    results.append(replay("run", runCoeffs, collision, events));
    if (args.found("variants"))
    {
        const dictionary variants
        (
            readVariants(args.get<fileName>("variants").expand())
        );
        wordList valid(breakupKernel::keys());
        valid.append("eventLog");
        for (const entry& v : variants)
        {
            if (!v.isDict() || v.keyword() == "run")
            {
                FatalIOErrorInFunction(variants)
                    << "Variant " << v.keyword() << " must be a dictionary"
                    << " of stressThresholdCoeffs entries, not named run"
                    << exit(FatalIOError);
            }
            hardSphereInput::checkKeys(v.dict(), valid);
            dictionary coeffs(runCoeffs);
            coeffs.merge(v.dict());
            nameAfterVariant(coeffs, variants.name()/v.keyword());
            results.append(replay(v.keyword(), coeffs, collision, events));
        }
    }

    // Table
    labelList logged(mechanisms.size(), Zero);
    for (const breakupEvent& e : events)
    {
        ++logged[e.mechanism];
    }
    Info<< nl << "breakupReplay: " << events.size() << " break-ups of "
        << logs.size() << " log file(s) in " << dir << nl << "logged:";
    forAll(mechanisms, m)
    {
        Info<< ' ' << mechanisms[m] << ' ' << logged[m];
    }
    Info<< nl << nl;
    {
        std::ostringstream os;
        os  << std::setw(16) << "configuration" << std::setw(9) << "breaks";
        for (const word& m : mechanisms)
        {
            os  << std::setw(12) << m;
        }
        os  << std::setw(10) << "deferred" << std::setw(18)
            << "other mechanism" << std::setw(12) << "reproduced";
        Info<< os.str().c_str() << nl;
    }
    OStringStream js;
    js  << "{\n  \"case\": \"" << args.path().c_str() << "\",\n"
        << "  \"cloud\": \"" << cloudName.c_str() << "\",\n"
        << "  \"logFiles\": " << logs.size() << ",\n"
        << "  \"events\": " << events.size() << ",\n"
        << "  \"mechanisms\": [";
    forAll(mechanisms, m)
    {
        js  << (m ? ", " : "") << '"' << mechanisms[m].c_str() << '"';
    }
    js  << "],\n  \"logged\": " << json(logged).c_str()
        << ",\n  \"configurations\": [";
    forAll(results, i)
    {
        const breakupReplayResult& r = results[i];
        std::ostringstream os;
        os  << std::setw(16) << r.name << std::setw(9) << r.breaks;
        for (const label n : r.byMechanism)
        {
            os  << std::setw(12) << n;
        }
        os  << std::setw(10) << r.deferred << std::setw(18)
            << r.mechanismChanged << std::setw(12) << r.reproduced;
        Info<< os.str().c_str() << nl;

        js  << (i ? "," : "") << "\n    {\"name\": \"" << r.name.c_str()
            << "\", \"breaks\": " << r.breaks << ", \"byMechanism\": "
            << json(r.byMechanism).c_str()
            << ", \"deferred\": " << r.deferred
            << ", \"mechanismChanged\": " << r.mechanismChanged
            << ", \"reproduced\": " << r.reproduced << "}";
    }
    js  << "\n  ]\n}\n";
    writeAtomically(jsonOut, js.str());
    Info<< nl << "Written " << jsonOut << nl;

    const label bad = events.size() - results[0].reproduced;
    if (bad)
    {
        Info<< nl << "The run's kernel does not reproduce " << bad << " of "
            << events.size() << " logged break-ups" << nl;
        if (args.found("check"))
        {
            FatalErrorInFunction
                << "-check: " << bad << " logged break-ups not reproduced"
                << exit(FatalError);
        }
    }
    else
    {
        Info<< nl << "The run's kernel reproduces every logged break-up"
            << nl;
    }

    Info<< nl << "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
