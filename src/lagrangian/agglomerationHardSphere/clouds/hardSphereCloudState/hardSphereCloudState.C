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

\*---------------------------------------------------------------------------*/

#include "hardSphereCloudState.H"
#include "localIOdictionary.H"
#include "IOField.H"
#include "Time.H"
#include "cloud.H"
#include "OSspecific.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::word Foam::hardSphereCloudState::recordName
(
    "hardSphereCloudState"
);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::IOobject recordIO
(
    const Foam::polyMesh& mesh,
    const Foam::word& cloudName,
    const Foam::IOobject::readOption r
)
{
    return Foam::IOobject
    (
        Foam::hardSphereCloudState::recordName,
        mesh.time().timeName(),
        "uniform"/Foam::cloud::prefix/cloudName,
        mesh,
        r,
        Foam::IOobject::NO_WRITE,
        false
    );
}


Foam::IOobject fieldIO
(
    const Foam::polyMesh& mesh,
    const Foam::word& cloudName,
    const Foam::word& field
)
{
    return Foam::IOobject
    (
        field,
        mesh.time().timeName(),
        Foam::cloud::prefix/cloudName,
        mesh,
        Foam::IOobject::MUST_READ,
        Foam::IOobject::NO_WRITE,
        false
    );
}


//- True if the file of an IOobject is there (any field type)
bool present(const Foam::IOobject& io)
{
    return
        Foam::isFile(io.objectPath())
     || Foam::isFile(io.objectPath() + ".gz");
}


//- The record of the current time: writer, completeness, the clouds of
//  the case (sorted, so that every rank and run writes the same list)
Foam::localIOdictionary newRecord
(
    const Foam::polyMesh& mesh,
    const Foam::word& cloudName,
    const bool complete
)
{
    Foam::localIOdictionary record
    (
        recordIO(mesh, cloudName, Foam::IOobject::NO_READ)
    );
    const Foam::string app(Foam::getEnv("FOAM_EXECUTABLE"));
    record.add
    (
        "writer",
        Foam::word(app.empty() ? "OpenFOAM" : app.c_str())
    );
    record.add("complete", Foam::word(complete ? "true" : "false"));
    record.add("clouds", mesh.sortedNames<Foam::cloud>());
    return record;
}


void writeRecord(Foam::localIOdictionary& record, const Foam::Time& time)
{
    record.regIOobject::writeObject
    (
        Foam::IOstream::ASCII,
        Foam::IOstream::currentVersion,
        time.writeCompression(),
        true
    );
}


//- The first other cloud whose record of the current time names cloudName
//  (this rank's folder), or empty
Foam::word namedBy(const Foam::Time& time, const Foam::word& cloudName)
{
    const Foam::fileName dir
    (
        time.timePath()/"uniform"/Foam::cloud::prefix
    );
    for
    (
        const Foam::fileName& other
      : Foam::readDir(dir, Foam::fileName::DIRECTORY)
    )
    {
        const Foam::fileName f
        (
            dir/other/Foam::hardSphereCloudState::recordName
        );
        if (other == cloudName || !Foam::isFile(f))
        {
            continue;
        }
        const Foam::dictionary d((Foam::IFstream(f))());
        const Foam::wordList clouds
        (
            d.getOrDefault<Foam::wordList>("clouds", Foam::wordList())
        );
        if (clouds.found(cloudName))
        {
            return other;
        }
    }
    return Foam::word::null;
}

//- True if the current time is the earliest time folder of the case (or
//  of this processor folder): where initial particles are written
bool earliestTime(const Foam::Time& time)
{
    for (const Foam::instant& t : time.times())
    {
        if (t.name() != time.constant())
        {
            return t.equal(time.value());
        }
    }
    return true;
}


//- No rank has the record of the time: stop if particle fields of a
//  solver's write (not initial ones written by hand) are there, or if
//  another cloud's record names this cloud (this cloud's write was cut
//  off before it began)
void checkWithoutRecord
(
    const Foam::Time& time,
    const Foam::word& cloudName,
    const Foam::IOobject& io,
    const Foam::wordList& there,
    const bool initial,
    const Foam::word& namer
)
{
    using namespace Foam;
    if (there.size() && !initial)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the particle fields " << there << " are there but"
            << " the record " << io.objectPath() << " is missing: the"
            << " uniform folder of the time or of the cloud was lost,"
            << " or its write cut off. Restart from an earlier time, or"
            << " remove " << time.timePath()/cloud::prefix/cloudName
            << " to restart without particles (particles written by"
            << " hand at a later time than the case's first need the"
            << " record too: aggloTools.cloud.write_record)"
            << exit(FatalError);
    }
    if (!namer.empty())
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the record of cloud " << namer << " of this time"
            << " names this cloud, but its record " << io.objectPath()
            << " is missing: its write never began (cut off). Restart"
            << " from an earlier time" << exit(FatalError);
    }
}


//- The record's counts against the particles read: the whole cloud's
//  particles and primaries, and this rank's fields
void checkCounts
(
    const Foam::Time& time,
    const Foam::word& cloudName,
    const Foam::IOobject& io,
    const Foam::localIOdictionary& record,
    const Foam::label nParticles,
    const Foam::label nTotal,
    const Foam::label nPrimTotal,
    const Foam::wordList& missing,
    const Foam::wordList& there
)
{
    using namespace Foam;
    const label recTotal = record.get<label>("nParticlesTotal");
    const label recPrim = record.get<label>("nPrimariesTotal");

    if (nTotal != recTotal)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": " << nTotal << " particles read, but " << recTotal
            << " were written (" << io.objectPath() << "). A particle file"
            << " of this time is missing or cut off; restart from an"
            << " earlier time" << exit(FatalError);
    }
    if (nParticles > 0 && missing.size())
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the particle fields " << missing << " are missing in "
            << time.timePath()/cloud::prefix/cloudName << " (written: "
            << there << "); without them agglomerates would become"
            << " primaries. Restart from an earlier time"
            << exit(FatalError);
    }
    if (nPrimTotal != recPrim)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the particles read hold " << nPrimTotal << " primaries,"
            << " but " << recPrim << " were written ("
            << io.objectPath() << ")" << exit(FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hardSphereCloudState::begin
(
    const polyMesh& mesh,
    const word& cloudName
)
{
    localIOdictionary record(newRecord(mesh, cloudName, false));
    writeRecord(record, mesh.time());
}


void Foam::hardSphereCloudState::write
(
    const polyMesh& mesh,
    const word& cloudName,
    const label nParticles,
    const label nPrimaries,
    const label nFragmentIds
)
{
    localIOdictionary record(newRecord(mesh, cloudName, true));
    record.add("nProcs", Pstream::nProcs());
    record.add("nParticles", nParticles);
    record.add("nParticlesTotal", returnReduce(nParticles, sumOp<label>()));
    record.add("nPrimariesTotal", returnReduce(nPrimaries, sumOp<label>()));
    if (nFragmentIds >= 0)
    {
        record.add("nFragmentIds", nFragmentIds);
    }
    writeRecord(record, mesh.time());
}


Foam::label Foam::hardSphereCloudState::check
(
    const polyMesh& mesh,
    const word& cloudName,
    const label nParticles,
    const label nPrimaries,
    const wordList& fields
)
{
    const Time& time = mesh.time();
    const IOobject io(recordIO(mesh, cloudName, IOobject::MUST_READ));
    const bool here = present(io);

    wordList missing;
    wordList there;
    for (const word& f : fields)
    {
        (present(fieldIO(mesh, cloudName, f)) ? there : missing).append(f);
    }
    const word namer(here ? word::null : namedBy(time, cloudName));

    // The same reductions on every rank before any rank may stop
    const bool anywhere = returnReduce(here, orOp<bool>());
    const label nTotal = returnReduce(nParticles, sumOp<label>());
    const label nPrimTotal = returnReduce(nPrimaries, sumOp<label>());

    // Initial particles written by hand: at the case's earliest time,
    // which no solver wrote (no uniform/time)
    const bool initial =
        earliestTime(time) && !isFile(time.timePath()/"uniform"/"time");

    if (!anywhere)
    {
        checkWithoutRecord(time, cloudName, io, there, initial, namer);
        // (A rank without the fields or the naming record returns; the
        // one that has them stops the run)
        return 0;
    }
    if (!here)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the record " << io.objectPath() << " is missing on this"
            << " processor while others have it (a processor folder"
            << " incomplete?)" << exit(FatalError);
    }

    const localIOdictionary record(io);
    if (!record.getOrDefault<bool>("complete", true))
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the write of this time began but did not end (the record"
            << " " << io.objectPath() << " says complete false): it was"
            << " cut off. Restart from an earlier time" << exit(FatalError);
    }
    checkCounts
    (
        time, cloudName, io, record, nParticles, nTotal, nPrimTotal,
        missing, there
    );

    // Written by a run with break-up (absent: none handed out; the cloud
    // checks the particles' fragment ids against it)
    return record.getOrDefault<label>("nFragmentIds", 0);
}


// ************************************************************************* //
