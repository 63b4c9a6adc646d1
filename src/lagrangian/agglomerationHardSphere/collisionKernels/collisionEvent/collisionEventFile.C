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
#include <cmath>
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


//- The bounds of a record's values (doc/eventLog.md, "Valid records";
//  aggloTools.eventlog checks the same): wide enough for any particle of
//  a flow, narrow enough that the kernels' products (masses, energies,
//  moments of inertia) stay finite, so that a corrupt record is refused
//  instead of stopping the replay with a floating-point exception
const Foam::scalar dMin = 1e-9, dMax = 1;           // m
const Foam::scalar rhoMin = 1e-3, rhoMax = 1e6;     // kg/m3
const Foam::scalar xMax = 1e6;                      // m, per component
const Foam::scalar UMax = 1e4;                      // m/s, per component
const Foam::scalar omegaMax = 1e12;                 // rad/s, per component


//- A vector as text, (x y z)
std::string text(const Foam::vector& v)
{
    std::ostringstream os;
    os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
    return os.str();
}


//- True if every component of v is finite and within +-bound
bool bounded(const Foam::vector& v, const Foam::scalar bound)
{
    for (const Foam::scalar c : {v.x(), v.y(), v.z()})
    {
        if (!(std::isfinite(c) && std::abs(c) <= bound))
        {
            return false;
        }
    }
    return true;
}


//- The reason why a record read from a log cannot be a logged collision
//  (empty if it can be one); buf: the record as read
std::string invalidRecord(const Foam::collisionEvent& e, const char* buf)
{
    const int nBranches = Foam::collisionOutcome::branchTypeNames.size();
    const Foam::label agglomerates =
        Foam::collisionEvent::agglomeratesByte(buf);

    std::ostringstream os;
    if (e.timeIndex < 0)
    {
        os << "time index " << e.timeIndex << " (valid: >= 0)";
    }
    else if (e.category < 0 || e.category > 2)
    {
        os << "category " << e.category << " (valid: 0 first, 1 repeat,"
           << " 2 overlap at the start of the step)";
    }
    else if
    (
        e.branch != Foam::collisionEvent::ghostBranch
     && (e.branch < 0 || e.branch >= nBranches)
    )
    {
        os << "branch " << e.branch << " (valid: 0-"
           << nBranches - 1 << ", "
           << Foam::collisionEvent::ghostBranch << " ghost)";
    }
    else if (agglomerates < 0 || agglomerates > 1)
    {
        os << "agglomerates " << agglomerates << " (valid: 0, 1)";
    }
    else if (e.type < 0 || e.type > 1)
    {
        os << "collision type " << e.type << " (valid: 0 sticking,"
           << " 1 sliding)";
    }
    else if (!std::isfinite(e.time))
    {
        os << "contact time " << e.time << " (valid: finite)";
    }
    for (const Foam::hardSphereState* p : {&e.p1, &e.p2})
    {
        if (!os.str().empty())
        {
            break;
        }
        const int k = p == &e.p1 ? 1 : 2;
        if (!(std::isfinite(p->d) && p->d >= dMin && p->d <= dMax))
        {
            os << "partner " << k << ": d " << p->d << " (valid: "
               << dMin << " - " << dMax << " m)";
        }
        else if
        (
            !(std::isfinite(p->rho) && p->rho >= rhoMin && p->rho <= rhoMax)
        )
        {
            os << "partner " << k << ": rho " << p->rho << " (valid: "
               << rhoMin << " - " << rhoMax << " kg/m3)";
        }
        else if (p->nPrimary < 1)
        {
            os << "partner " << k << ": nPrimary " << p->nPrimary
               << " (valid: >= 1)";
        }
        else if (!bounded(p->x, xMax))
        {
            os << "partner " << k << ": position " << text(p->x) << " (valid:"
               << " finite, each component within +-" << xMax << " m)";
        }
        else if (!bounded(p->U, UMax))
        {
            os << "partner " << k << ": velocity " << text(p->U) << " (valid:"
               << " finite, each component within +-" << UMax << " m/s)";
        }
        else if (!bounded(p->omega, omegaMax))
        {
            os << "partner " << k << ": spin " << text(p->omega) << " (valid:"
               << " finite, each component within +-" << omegaMax
               << " rad/s)";
        }
    }
    return os.str();
}


void checkHeader(std::istream& is, const Foam::fileName& file)
{
    std::string head(Foam::collisionEventFile::headerBytes, ' ');
    is.read(&head[0], head.size());
    const std::string want(Foam::collisionEventFile::header());
    if (!is || head.compare(0, want.size(), want) != 0)
    {
        FatalErrorInFunction
            << "Collision event file " << file << " does not start with"
            << " the header of this build:" << Foam::nl << "    " << want
            << Foam::nl << "(another layout or machine, or not an event"
            << " file)" << Foam::exit(Foam::FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const std::size_t Foam::collisionEventFile::headerBytes;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::string Foam::collisionEventFile::header()
{
    const int one = 1;
    const bool lsb = *reinterpret_cast<const char*>(&one) == 1;
    std::ostringstream os;
    os  << "aggloCollisionEvents 1 recordBytes "
        << collisionEvent::recordBytes << " arch "
        << (lsb ? "LSB" : "MSB") << ";label=32;scalar=64";
    return os.str();
}


void Foam::collisionEventFile::append
(
    const fileName& file,
    const UList<collisionEvent>& events
)
{
    const long long size = fileBytes(file);
    if (size > 0)
    {
        std::ifstream is(file.c_str(), std::ios::binary);
        checkHeader(is, file);
    }

    std::ofstream os(file.c_str(), std::ios::binary | std::ios::app);
    if (size <= 0)
    {
        std::string head(header());
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
Foam::collisionEventFile::read(const fileName& file)
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
    checkHeader(is, file);

    List<collisionEvent> events(body/collisionEvent::recordBytes);
    char buf[collisionEvent::recordBytes];
    forAll(events, k)
    {
        collisionEvent& e = events[k];
        is.read(buf, collisionEvent::recordBytes);
        e.unpack(buf);

        // A corrupt record would be replayed as a collision
        const std::string why(invalidRecord(e, buf));
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
