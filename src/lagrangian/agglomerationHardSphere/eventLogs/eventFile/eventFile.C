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

#include "eventFile.H"
#include "error.H"
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <sys/stat.h>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Event>
long long Foam::eventFile<Event>::fileBytes(const fileName& file)
{
    struct stat st;
    if (::stat(file.c_str(), &st) != 0)
    {
        return -1;
    }
    return st.st_size;
}


template<class Event>
Foam::List<Foam::wordList> Foam::eventFile<Event>::checkHeader
(
    std::istream& is,
    const fileName& file
)
{
    std::string head(headerBytes, ' ');
    is.read(&head[0], head.size());
    const wordList keys(Event::namesKeys());
    const std::string want(layout() + " " + keys[0] + " ");
    if (!is || head.compare(0, want.size(), want) != 0)
    {
        FatalErrorInFunction
            << Event::title() << " file " << file << " does not start with"
            << " the header of this build:" << nl << "    " << want
            << "<names>" << nl << "(another layout or machine, or not an"
            << " event file)" << exit(FatalError);
    }

    // key list key list ...: the lists comma-separated, "-" if empty
    std::istringstream items(head.substr(layout().size()));
    List<wordList> result(keys.size());
    forAll(keys, i)
    {
        std::string key, list;
        items >> key >> list;
        if (key != keys[i] || list.empty())
        {
            FatalErrorInFunction
                << Event::title() << " file " << file << ": the header"
                << " names no " << keys[i] << " (it gives the keys "
                << keys << " in this order)" << exit(FatalError);
        }
        std::istringstream names(list == "-" ? std::string() : list);
        std::string name;
        while (std::getline(names, name, ','))
        {
            result[i].append(word(name));
        }
    }
    if (result[0].empty())
    {
        FatalErrorInFunction
            << Event::title() << " file " << file << ": the header names no"
            << " " << keys[0] << exit(FatalError);
    }
    return result;
}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class Event>
const std::size_t Foam::eventFile<Event>::headerBytes;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Event>
std::string Foam::eventFile<Event>::layout()
{
    const int one = 1;
    const bool lsb = *reinterpret_cast<const char*>(&one) == 1;
    std::ostringstream os;
    os  << Event::fileTag() << " recordBytes " << Event::recordBytes
        << " arch " << (lsb ? "LSB" : "MSB") << ";label=32;scalar=64";
    return os.str();
}


template<class Event>
std::string Foam::eventFile<Event>::header(const List<wordList>& names)
{
    const wordList keys(Event::namesKeys());
    std::string head(layout());
    forAll(keys, i)
    {
        head += " " + keys[i] + " ";
        const wordList none;
        const wordList& list = i < names.size() ? names[i] : none;
        forAll(list, b)
        {
            head += (b ? "," : "") + std::string(list[b]);
        }
        head += list.empty() ? "-" : "";
    }
    if
    (
        names.size() != keys.size() || names[0].empty()
     || head.size() >= headerBytes
    )
    {
        FatalErrorInFunction
            << "The names " << names << " do not fit the "
            << label(headerBytes) << "-byte header of the "
            << Event::title() << " log (" << keys << ", at least one "
            << keys[0] << ", " << label(headerBytes - 1)
            << " characters in all with the layout)" << exit(FatalError);
    }
    return head;
}


template<class Event>
void Foam::eventFile<Event>::append
(
    const fileName& file,
    const UList<Event>& events,
    const List<wordList>& names
)
{
    long long size = fileBytes(file);
    if (size > 0)
    {
        std::ifstream is(file.c_str(), std::ios::binary);
        const List<wordList> inFile(checkHeader(is, file));
        if (inFile != names)
        {
            if (size > static_cast<long long>(headerBytes))
            {
                FatalErrorInFunction
                    << Event::title() << " file " << file << " holds events"
                    << " of " << Event::namesOwner() << " with the "
                    << Event::namesKeys() << " " << inFile << "; this run's"
                    << " model has " << names << ": move the folder away"
                    << " to start a new log" << exit(FatalError);
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
        std::string head(header(names));
        head.resize(headerBytes - 1, ' ');
        head += '\n';
        os.write(head.data(), head.size());
    }

    char buf[Event::recordBytes];
    for (const Event& e : events)
    {
        e.pack(buf);
        os.write(buf, Event::recordBytes);
    }
    os.flush();
    if (!os)
    {
        FatalErrorInFunction
            << "Cannot append to the " << Event::title() << " file "
            << file << exit(FatalError);
    }
}


template<class Event>
Foam::List<Event> Foam::eventFile<Event>::read
(
    const fileName& file,
    List<wordList>& names
)
{
    const long long size = fileBytes(file);
    if (size < 0)
    {
        FatalErrorInFunction
            << "No " << Event::title() << " file " << file
            << exit(FatalError);
    }
    const long long body = size - headerBytes;
    if (body < 0 || body % Event::recordBytes)
    {
        FatalErrorInFunction
            << Event::title() << " file " << file << " has " << label(size)
            << " bytes: not the header plus whole records of "
            << label(Event::recordBytes) << " bytes (a write cut off? a"
            << " restart of the run cuts it back)" << exit(FatalError);
    }

    std::ifstream is(file.c_str(), std::ios::binary);
    names = checkHeader(is, file);

    List<Event> events(body/Event::recordBytes);
    char buf[Event::recordBytes];
    forAll(events, k)
    {
        Event& e = events[k];
        is.read(buf, Event::recordBytes);
        e.unpack(buf);

        // A corrupt record would be replayed as an event
        const std::string why(e.invalid(buf, names));
        if (!why.empty())
        {
            FatalErrorInFunction
                << Event::title() << " file " << file << ", record " << k
                << ": " << why.c_str() << "; the file is corrupt"
                << exit(FatalError);
        }
    }
    return events;
}


template<class Event>
Foam::label Foam::eventFile<Event>::size(const fileName& file)
{
    const long long bytes = fileBytes(file);
    return
        bytes > static_cast<long long>(headerBytes)
      ? label((bytes - headerBytes)/Event::recordBytes)
      : 0;
}


template<class Event>
Foam::label Foam::eventFile<Event>::truncateAfter
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
    const std::size_t R = Event::recordBytes;
    long long keep = 0;
    label removed = 0;
    if (size >= static_cast<long long>(headerBytes))
    {
        std::ifstream is(file.c_str(), std::ios::binary);
        checkHeader(is, file);
        keep = headerBytes;
        char buf[R];
        Event e;
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
            << "Cannot cut back the " << Event::title() << " file " << file
            << exit(FatalError);
    }
    return removed;
}


// ************************************************************************* //
