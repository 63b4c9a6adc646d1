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

#include "eventLogFiles.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "IOdictionary.H"
#include "cloud.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Event>
Foam::IOobject Foam::eventLogFiles<Event>::recordIO
(
    const IOobject::readOption r
) const
{
    return IOobject
    (
        recordName_,
        mesh_.time().timeName(),
        "uniform"/cloud::prefix/cloudName_,
        mesh_,
        r,
        IOobject::NO_WRITE,
        false
    );
}


template<class Event>
std::string Foam::eventLogFiles<Event>::what()
{
    std::string s(Event::title());
    s[0] = tolower(s[0]);
    for (char& c : s)
    {
        c = (c == ' ' ? '-' : c);
    }
    return s + " log";
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Event>
Foam::eventLogFiles<Event>::eventLogFiles
(
    const fvMesh& mesh,
    const word& cloudName,
    const word& suffix,
    const word& recordName,
    const List<wordList>& names
)
:
    mesh_(mesh),
    dir_(folder(mesh.time(), cloudName, suffix)),
    file_(dir_/("events" + Foam::name(Pstream::myProcNo()) + ".bin")),
    recordName_(recordName),
    cloudName_(cloudName),
    names_(names),
    buffer_(),
    nInFile_(0),
    nOthers_(0)
{
    const label start = mesh.time().timeIndex();
    label nFound = 0;           // the events files there before this run
    const label removed = cutBack(start, nFound);

    // Every rank appends only after the master has cut the files back;
    // its file exists from the start (an empty log is a log)
    mkDir(dir_);
    eventFile<Event>::append(file_, List<Event>(), names_);
    nInFile_ = eventFile<Event>::size(file_);
    nOthers_ = countOthers();
    checkRecord(nFound);

    Info<< "    eventLog: " << dir_ << " (time index " << start;
    if (removed)
    {
        Info<< "; " << removed << " events after it removed";
    }
    Info<< ")" << endl;
}


template<class Event>
Foam::eventLogFiles<Event>::~eventLogFiles()
{
    flush();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Event>
Foam::label Foam::eventLogFiles<Event>::cutBack
(
    const label start,
    label& nFound
) const
{
    label removed = 0;
    nFound = 0;
    if (Pstream::master())
    {
        mkDir(dir_);
        for (const fileName& f : readDir(dir_, fileName::FILE))
        {
            if (f.hasExt("bin") && f.startsWith("events"))
            {
                ++nFound;
                removed += eventFile<Event>::truncateAfter(dir_/f, start);
            }
        }
    }
    reduce(removed, sumOp<label>());
    reduce(nFound, sumOp<label>());
    return removed;
}


template<class Event>
Foam::label Foam::eventLogFiles<Event>::countOthers() const
{
    label n = 0;
    if (Pstream::master())
    {
        for (const fileName& f : readDir(dir_, fileName::FILE))
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
                n += eventFile<Event>::size(dir_/f);
            }
        }
    }
    return n;
}


template<class Event>
void Foam::eventLogFiles<Event>::checkRecord(const label nFound) const
{
    // The log must hold what it held when the start time was written: a
    // run from an earlier time cuts it back, and time folders after that
    // run's end are from the older run
    IOobject io(recordIO(IOobject::MUST_READ));
    const label nHeld = returnReduce(nInFile_ + nOthers_, sumOp<label>());
    const bool readable = io.typeHeaderOk<IOdictionary>(true);
    if (!readable && isFile(io.objectPath()))
    {
        // Written, but empty or cut off: the count cannot be checked
        FatalErrorInFunction
            << "The record " << io.objectPath() << " of the " << what().c_str()
            << " is empty or cut off: the events logged up to time "
            << mesh_.time().timeName() << " cannot be checked. Restart from"
            << " an earlier time" << exit(FatalError);
    }
    if (!readable)
    {
        return;
    }
    const label nRecorded = IOdictionary(io).get<label>("nEvents");
    if (nRecorded && !nFound)
    {
        FatalErrorInFunction
            << "The " << what().c_str() << " " << dir_ << " has no"
            << " events file, but " << nRecorded << " events were"
            << " logged when time " << mesh_.time().timeName() << " was"
            << " written (" << io.objectPath() << "): the log was"
            << " deleted or moved. Put it back, start from a time"
            << " before its first event, or switch eventLog off"
            << exit(FatalError);
    }
    if (nHeld != nRecorded)
    {
        FatalErrorInFunction
            << "The " << what().c_str() << " " << dir_ << " holds "
            << nHeld
            << " events up to time " << mesh_.time().timeName()
            << ", but " << nRecorded << " were logged when this time"
            << " was written (" << io.objectPath() << "). A run from"
            << " an earlier time has cut the log back since: the time"
            << " folders after that run's end are from an older run."
            << " Remove them and start from the last time that run"
            << " wrote, or switch eventLog off" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Event>
Foam::fileName Foam::eventLogFiles<Event>::folder
(
    const Time& runTime,
    const word& cloudName,
    const word& suffix
)
{
    return runTime.globalPath()/"postProcessing"/(cloudName + suffix);
}


template<class Event>
void Foam::eventLogFiles<Event>::refuseLaterEvents
(
    const fvMesh& mesh,
    const word& cloudName,
    const word& suffix
)
{
    const fileName dir(folder(mesh.time(), cloudName, suffix));
    const label start = mesh.time().timeIndex();
    label later = 0;
    if (Pstream::master() && isDir(dir))
    {
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            if (f.hasExt("bin") && f.startsWith("events"))
            {
                List<wordList> names;
                for (const Event& e : eventFile<Event>::read(dir/f, names))
                {
                    later += (e.timeIndex > start);
                }
            }
        }
    }
    reduce(later, sumOp<label>());
    if (later)
    {
        FatalErrorInFunction
            << "The " << what().c_str() << " " << dir << " holds " << later
            << " events after time " << mesh.time().timeName() << " (time"
            << " index " << start << "), logged by an earlier run. With"
            << " eventLog off this run would leave them in the log beside"
            << " a history that no longer has them: switch eventLog on"
            << " (the log is then cut back to this time) or remove " << dir
            << exit(FatalError);
    }
}


template<class Event>
void Foam::eventLogFiles<Event>::flush()
{
    if (buffer_.size())
    {
        eventFile<Event>::append(file_, buffer_, names_);
        nInFile_ += buffer_.size();
        buffer_.clear();
    }
}


template<class Event>
void Foam::eventLogFiles<Event>::write()
{
    flush();
    IOdictionary record(recordIO(IOobject::NO_READ));
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
