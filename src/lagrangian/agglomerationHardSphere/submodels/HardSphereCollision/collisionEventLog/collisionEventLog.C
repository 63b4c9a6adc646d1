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

#include "collisionEventLog.H"
#include "meshWavePatchDistMethod.H"
#include "volFields.H"
#include "wallPolyPatch.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "IOdictionary.H"
#include "cloud.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Wall distance of the cell centres (meshWave with wall correction; no
//  fvSchemes entry needed)
Foam::scalarField wallDistance(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const labelHashSet walls
    (
        mesh.boundaryMesh().findPatchIDs<wallPolyPatch>()
    );
    volScalarField y
    (
        IOobject
        (
            "eventLogWallDistance", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedScalar("y", dimLength, GREAT),
        patchDistMethod::patchTypes<scalar>(mesh, walls)
    );
    if (walls.size())
    {
        patchDistMethods::meshWave(mesh, walls, true).correct(y);
    }
    return y.primitiveField();
}

//- The record of the log at a written time
Foam::IOobject recordIO
(
    const Foam::fvMesh& mesh,
    const Foam::word& cloudName,
    const Foam::IOobject::readOption r
)
{
    return Foam::IOobject
    (
        "collisionEventLog",
        mesh.time().timeName(),
        "uniform"/Foam::cloud::prefix/cloudName,
        mesh,
        r,
        Foam::IOobject::NO_WRITE,
        false
    );
}

} // End anonymous namespace

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionEventLog::collisionEventLog
(
    const fvMesh& mesh,
    const word& cloudName,
    const wordList& branches
)
:
    mesh_(mesh),
    file_
    (
        folder(mesh.time(), cloudName)
       /("events" + Foam::name(Pstream::myProcNo()) + ".bin")
    ),
    branches_(branches),
    buffer_(),
    nWritten_(0),
    cloudName_(cloudName),
    nInFile_(0),
    nOthers_(0),
    y_(wallDistance(mesh))
{
    const fileName dir(folder(mesh.time(), cloudName));
    const label start = mesh.time().timeIndex();
    label removed = 0;
    if (Pstream::master())
    {
        mkDir(dir);
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            if (f.hasExt("bin") && f.startsWith("events"))
            {
                removed += collisionEventFile::truncateAfter(dir/f, start);
            }
        }
    }
    // Every rank appends only after the master has cut the files back;
    // its file exists from the start (an empty log is a log)
    reduce(removed, sumOp<label>());
    mkDir(dir);
    collisionEventFile::append(file_, List<collisionEvent>(), branches_);
    nInFile_ = collisionEventFile::size(file_);
    if (Pstream::master())
    {
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            // events<rank>.bin of a rank this run does not have
            const std::string rank(f.nameLessExt().substr(6));
            label r = -1;
            if
            (
                f.hasExt("bin") && f.startsWith("events")
             && !(readLabel(rank, r) && r >= 0 && r < Pstream::nProcs())
            )
            {
                nOthers_ += collisionEventFile::size(dir/f);
            }
        }
    }

    // The log must hold what it held when the start time was written: a
    // run from an earlier time cuts it back, and time folders after that
    // run's end are from the older run
    IOobject io(recordIO(mesh, cloudName, IOobject::MUST_READ));
    const label nHeld = returnReduce(nInFile_ + nOthers_, sumOp<label>());
    const bool readable = io.typeHeaderOk<IOdictionary>(true);
    if (!readable && isFile(io.objectPath()))
    {
        // Written, but empty or cut off: the count cannot be checked
        FatalErrorInFunction
            << "The record " << io.objectPath() << " of the collision-event"
            << " log is empty or cut off: the events logged up to time "
            << mesh.time().timeName() << " cannot be checked. Restart from"
            << " an earlier time" << exit(FatalError);
    }
    if (readable)
    {
        const label nRecorded = IOdictionary(io).get<label>("nEvents");
        if (nHeld != nRecorded)
        {
            FatalErrorInFunction
                << "The collision-event log " << dir << " holds " << nHeld
                << " events up to time " << mesh.time().timeName()
                << ", but " << nRecorded << " were logged when this time"
                << " was written (" << io.objectPath() << "). A run from"
                << " an earlier time has cut the log back since: the time"
                << " folders after that run's end are from an older run."
                << " Remove them and start from the last time that run"
                << " wrote, or switch eventLog off" << exit(FatalError);
        }
    }

    Info<< "    eventLog: " << dir << " (time index " << start;
    if (removed)
    {
        Info<< "; " << removed << " events after it removed";
    }
    Info<< ")" << endl;
}


Foam::collisionEventLog::~collisionEventLog()
{
    flush();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::collisionEventLog::folder
(
    const Time& runTime,
    const word& cloudName
)
{
    return
        runTime.globalPath()/"postProcessing"
       /(cloudName + "CollisionEvents");
}


void Foam::collisionEventLog::observe(const collisionEventRecord& event)
{
    const Time& runTime = mesh_.time();
    collisionEvent e;
    e.timeIndex = runTime.timeIndex();
    e.category = event.category;
    e.setOutcome(event.outcomePtr());
    e.time = runTime.value() - (1 - event.s)*runTime.deltaTValue();
    e.proc[0] = event.id1.first();
    e.id[0] = event.id1.second();
    e.proc[1] = event.id2.first();
    e.id[1] = event.id2.second();
    e.p1 = event.s1;
    e.p2 = event.s2;
    e.wallDistance = y_[event.celli];
    buffer_.append(e);
}


void Foam::collisionEventLog::flush()
{
    if (buffer_.size())
    {
        collisionEventFile::append(file_, buffer_, branches_);
        nWritten_ += buffer_.size();
        nInFile_ += buffer_.size();
        buffer_.clear();
    }
}


void Foam::collisionEventLog::write()
{
    flush();
    IOdictionary record(recordIO(mesh_, cloudName_, IOobject::NO_READ));
    record.add
    (
        "nEvents", returnReduce(nInFile_ + nOthers_, sumOp<label>())
    );
    record.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
}


// ************************************************************************* //
