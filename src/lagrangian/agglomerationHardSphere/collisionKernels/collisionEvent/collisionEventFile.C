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

#include "collisionEventFile.H"
#include "error.H"
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <sys/stat.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The size of a file in bytes (-1 if it does not exist)
long long fileBytes(const Foam::fileName& file)
{
    struct stat st;
    if (::stat(file.c_str(), &st) != 0)
    {
        return -1;
    }
    return st.st_size;
}


//- Check the layout of the header and return the branches it names
Foam::wordList checkHeader(std::istream& is, const Foam::fileName& file)
{
    std::string head(Foam::collisionEventFile::headerBytes, ' ');
    is.read(&head[0], head.size());
    const std::string want
    (
        Foam::collisionEventFile::layout() + " branches "
    );
    if (!is || head.compare(0, want.size(), want) != 0)
    {
        FatalErrorInFunction
            << "Collision event file " << file << " does not start with"
            << " the header of this build:" << Foam::nl << "    " << want
            << "<names>" << Foam::nl << "(another layout or machine, or"
            << " not an event file)" << Foam::exit(Foam::FatalError);
    }

    std::istringstream names(head.substr(want.size()));
    std::string list;
    names >> list;
    Foam::wordList branches;
    std::istringstream items(list);
    std::string name;
    while (std::getline(items, name, ','))
    {
        branches.append(Foam::word(name));
    }
    if (branches.empty())
    {
        FatalErrorInFunction
            << "Collision event file " << file << ": the header names no"
            << " branch" << Foam::exit(Foam::FatalError);
    }
    return branches;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const std::size_t Foam::collisionEventFile::headerBytes;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::string Foam::collisionEventFile::layout()
{
    const int one = 1;
    const bool lsb = *reinterpret_cast<const char*>(&one) == 1;
    std::ostringstream os;
    os  << "aggloCollisionEvents 2 recordBytes "
        << collisionEvent::recordBytes << " arch "
        << (lsb ? "LSB" : "MSB") << ";label=32;scalar=64";
    return os.str();
}


std::string Foam::collisionEventFile::header(const wordList& branches)
{
    std::string head(layout() + " branches ");
    forAll(branches, b)
    {
        head += (b ? "," : "") + std::string(branches[b]);
    }
    if (branches.empty() || head.size() >= headerBytes)
    {
        FatalErrorInFunction
            << "The branch names " << branches << " do not fit the "
            << label(headerBytes) << "-byte header of the collision event"
            << " log (at least one, " << label(headerBytes - 1)
            << " characters in all with the layout)" << exit(FatalError);
    }
    return head;
}


void Foam::collisionEventFile::append
(
    const fileName& file,
    const UList<collisionEvent>& events,
    const wordList& branches
)
{
    long long size = fileBytes(file);
    if (size > 0)
    {
        std::ifstream is(file.c_str(), std::ios::binary);
        const wordList inFile(checkHeader(is, file));
        if (inFile != branches)
        {
            if (size > static_cast<long long>(headerBytes))
            {
                FatalErrorInFunction
                    << "Collision event file " << file << " holds events"
                    << " of an agglomeration model with the branches "
                    << inFile << "; this run's model has " << branches
                    << ": move the folder away to start a new log"
                    << exit(FatalError);
            }
            // No event yet: the header follows this run's model
            size = 0;
        }
    }

    std::ofstream os
    (
        file.c_str(),
        std::ios::binary | (size > 0 ? std::ios::app : std::ios::trunc)
    );
    if (size <= 0)
    {
        std::string head(header(branches));
        head.resize(headerBytes - 1, ' ');
        head += '\n';
        os.write(head.data(), head.size());
    }

    char buf[collisionEvent::recordBytes];
    for (const collisionEvent& e : events)
    {
        e.pack(buf);
        os.write(buf, collisionEvent::recordBytes);
    }
    os.flush();
    if (!os)
    {
        FatalErrorInFunction
            << "Cannot append to the collision event file " << file
            << exit(FatalError);
    }
}


Foam::List<Foam::collisionEvent>
Foam::collisionEventFile::read(const fileName& file, wordList& branches)
{
    const long long size = fileBytes(file);
    if (size < 0)
    {
        FatalErrorInFunction
            << "No collision event file " << file << exit(FatalError);
    }
    const long long body = size - headerBytes;
    if (body < 0 || body % collisionEvent::recordBytes)
    {
        FatalErrorInFunction
            << "Collision event file " << file << " has " << label(size)
            << " bytes: not the header plus whole records of "
            << label(collisionEvent::recordBytes) << " bytes (a write"
            << " cut off? a restart of the run cuts it back)"
            << exit(FatalError);
    }

    std::ifstream is(file.c_str(), std::ios::binary);
    branches = checkHeader(is, file);

    List<collisionEvent> events(body/collisionEvent::recordBytes);
    char buf[collisionEvent::recordBytes];
    forAll(events, k)
    {
        collisionEvent& e = events[k];
        is.read(buf, collisionEvent::recordBytes);
        e.unpack(buf);

        // A corrupt record would be replayed as a collision
        const std::string why(e.invalid(buf, branches.size()));
        if (!why.empty())
        {
            FatalErrorInFunction
                << "Collision event file " << file << ", record " << k
                << ": " << why.c_str() << "; the file is corrupt"
                << exit(FatalError);
        }
    }
    return events;
}


Foam::label Foam::collisionEventFile::size(const fileName& file)
{
    const long long bytes = fileBytes(file);
    return
        bytes > static_cast<long long>(headerBytes)
      ? label((bytes - headerBytes)/collisionEvent::recordBytes)
      : 0;
}


Foam::label Foam::collisionEventFile::truncateAfter
(
    const fileName& file,
    const label timeIndex
)
{
    const long long size = fileBytes(file);
    if (size < 0)
    {
        return 0;
    }
    const std::size_t R = collisionEvent::recordBytes;
    long long keep = 0;
    label removed = 0;
    if (size >= static_cast<long long>(headerBytes))
    {
        std::ifstream is(file.c_str(), std::ios::binary);
        checkHeader(is, file);
        keep = headerBytes;
        char buf[R];
        collisionEvent e;
        while (is.read(buf, R))
        {
            e.unpack(buf);
            if (e.timeIndex > timeIndex)
            {
                ++removed;
                while (is.read(buf, R))
                {
                    ++removed;
                }
                break;
            }
            keep += R;
        }
    }
    if (keep != size && ::truncate(file.c_str(), keep) != 0)
    {
        FatalErrorInFunction
            << "Cannot cut back the collision event file " << file
            << exit(FatalError);
    }
    return removed;
}


// ************************************************************************* //
