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
    Replays the break-up event log of a run (<model>Coeffs: eventLog
    true; doc/eventLog.md) through the break-up model of the run (any
    model of the family breakupKernel: the log's header names it, its
    mechanisms and its values) and of variants: the same parents under the
    same loads, any of the model's coefficients, without running the flow
    again. Prints a table and writes JSON: per configuration the logged
    break-ups that still break, by mechanism, those deferred by a
    stochastic rate, those whose mechanism changes, and those whose
    fragments are the logged ones bit for bit.

    The run's own configuration (the cloud's <model>Coeffs and the
    material and structure of its hardSphereCoeffs) must reproduce every
    logged break-up (-check: exit 1 on any difference). A variants
    dictionary (-variants) names configurations that change the run's
    coefficients, each merged into them:
    \verbatim
    weaker   { strength { rumpfPrefactor 0.5; } }
    binary   { fragmentation { mode binary; } }
    noDrag   { stresses { mechanisms (turbulence rotation); }
               remove (stresses.Cd); }
    \endverbatim
    (remove: the run's entries to drop first, so that a mode or a
    mechanism whose entries are accepted only while it is on can be
    switched off, e.g. remove (fragmentation.betaAlpha); for beta to
    binary).

    The log holds the agglomerates that broke: a replay tells which of
    them a variant would also break, not which of the others it would
    break, nor what its fragments would have done afterwards. It knows
    no neighbours: the fragments are placed along the direction of the
    logged try (doc/breakup.md 3.2); a variant with fewer tries than a
    logged break-up needed does not reproduce it.

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
#include "breakupReplayReport.H"
#include "readBreakupEvents.H"

namespace
{

//- True if the states are equal bit for bit
bool same(const hardSphereState& a, const hardSphereState& b)
{
    return
        a.x == b.x && a.U == b.U && a.omega == b.omega && a.d == b.d
     && a.rho == b.rho && a.nPrimary == b.nPrimary;
}


//- Replay the events through the model of the coefficients
breakupReplayResult replay
(
    const word& name,
    const word& model,
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision,
    const UList<breakupEvent>& events,
    const List<wordList>& logged
)
{
    const autoPtr<breakupKernel> kernel
    (
        breakupKernel::New(model, coeffs, collision)
    );
    if (kernel->mechanisms() != logged[0] || kernel->fields() != logged[2])
    {
        FatalIOErrorInFunction(coeffs)
            << "Configuration " << name << ": the break-up model " << model
            << " of this build has the mechanisms " << kernel->mechanisms()
            << " and the values " << kernel->fields() << "; the log names "
            << logged[0] << " and " << logged[2] << exit(FatalIOError);
    }
    breakupReplayResult r;
    r.name = name;
    r.byMechanism.setSize(logged[0].size(), 0);
    for (const breakupEvent& e : events)
    {
        const breakupKernel::key k{e.proc, e.id, e.timeIndex};
        const breakupKernel::verdict v =
            kernel->check(e.parent, e.replayLoad(), e.dt, k);
        if (v.mechanism < 0)
        {
            continue;
        }
        if (v.deferred)
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
        // The try that placed the fragments in the run (the replay knows
        // no neighbours): beyond a variant's tries it cannot be made
        if (e.attempt >= kernel->fragmentation().tries())
        {
            continue;
        }
        const agglomerateFragmentation::fragments f =
            kernel->split(e.parent, v, e.S, k, e.attempt);
        if (v.values == e.values && same(f.a, e.a) && same(f.b, e.b))
        {
            ++r.reproduced;
        }
    }
    return r;
}

//- The collision kernel's entries of the run's cloud (its material and
//  structure)
dictionary runKernelDict(const dictionary& subModels)
{
    const dictionary& hsCoeffs = subModels.subDict("hardSphereCoeffs");
    dictionary kernelDict;
    for (const word& key : hardSphereCollisionKernel::keys(hsCoeffs))
    {
        if (hsCoeffs.found(key))
        {
            kernelDict.add(hsCoeffs.lookupEntry(key, keyType::LITERAL));
        }
    }
    return kernelDict;
}


//- The replays of the run's coefficients and of each variant of the file
//  variantsFile (none if empty), each merged into the run's
List<breakupReplayResult> replayConfigurations
(
    const word& model,
    const dictionary& runCoeffs,
    const hardSphereCollisionKernel& collision,
    const UList<breakupEvent>& events,
    const List<wordList>& names,
    const fileName& variantsFile
)
{
    List<breakupReplayResult> results;
    results.append
    (
        replay("run", model, runCoeffs, collision, events, names)
    );
    if (variantsFile.empty())
    {
        return results;
    }
    const dictionary variants(readVariants(variantsFile));
    for (const entry& v : variants)
    {
        if (!v.isDict() || v.keyword() == "run")
        {
            FatalIOErrorInFunction(variants)
                << "Variant " << v.keyword() << " must be a dictionary"
                << " of " << model << "Coeffs entries, not named run"
                << exit(FatalIOError);
        }
        const dictionary coeffs
        (
            applyVariant(runCoeffs, v.dict(), variants.name()/v.keyword())
        );
        results.append
        (
            replay(v.keyword(), model, coeffs, collision, events, names)
        );
    }
    return results;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- The utility's options
void addOptions()
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
        " <model>Coeffs"
    );
}


//- The replays of the run's configuration (its break-up coefficients, the
//  material and structure of its collision kernel) and of the variants
List<breakupReplayResult> replays
(
    const Time& runTime,
    const argList& args,
    const word& cloudName,
    const word& model,
    const UList<breakupEvent>& events,
    const List<wordList>& names
)
{
    const IOdictionary props
    (
        IOobject
        (
            cloudName + "Properties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    const dictionary& subModels = props.subDict("subModels");
    const hardSphereCollisionKernel collision(runKernelDict(subModels));
    return
        replayConfigurations
        (
            model, subModels.subDict(model + "Coeffs"), collision, events,
            names,
            args.found("variants")
          ? fileName(args.get<fileName>("variants").expand())
          : fileName::null
        );
}


int main(int argc, char *argv[])
{
    addOptions();

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

    // The logs, in a deterministic order; the output checked before any
    // work; the events
    const fileNameList logs(breakupLogFiles(dir));
    checkTarget("json", jsonOut, dir, logs);
    List<wordList> names;
    word model;
    const DynamicList<breakupEvent> events
    (
        readBreakupEvents(runTime, cloudName, dir, logs, names, model)
    );
    const wordList& mechanisms = names[0];

    const List<breakupReplayResult> results
    (
        replays(runTime, args, cloudName, model, events, names)
    );

    // Table and JSON
    const std::string js
    (
        replayReport
        (
            args.path(), cloudName, dir, logs.size(), events, model,
            mechanisms, results
        )
    );
    writeAtomically(jsonOut, js);
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
