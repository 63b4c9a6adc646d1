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

#include "collisionEvent.H"
#include "particleIds.H"
#include "eventRecord.H"
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using Foam::eventRecord::put;
    using Foam::eventRecord::get;
    using Foam::eventRecord::putState;
    using Foam::eventRecord::getState;
}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const std::size_t Foam::collisionEvent::recordBytes;
const std::size_t Foam::collisionEvent::headerBytes;
const Foam::label Foam::collisionEvent::ghostBranch;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionEvent::collisionEvent()
:
    timeIndex(0),
    category(0),
    branch(ghostBranch),
    agglomerates(false),
    type(collisionOutcome::STICKING),
    time(0),
    proc(-1),
    id(-1),
    p1(),
    p2(),
    wallDistance(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionEvent::setOutcome(const collisionOutcome* outcome)
{
    if (outcome)
    {
        branch = outcome->branch;
        agglomerates = outcome->agglomerates;
        type = outcome->type;
    }
    else
    {
        branch = ghostBranch;
        agglomerates = false;
        type = collisionOutcome::STICKING;
    }
}


void Foam::collisionEvent::pack(char* buf) const
{
    std::size_t pos = 0;
    put<int32_t>(buf, pos, timeIndex);
    put<uint8_t>(buf, pos, category);
    put<uint8_t>(buf, pos, branch);
    put<uint8_t>(buf, pos, agglomerates);
    put<uint8_t>(buf, pos, type);
    put<double>(buf, pos, time);
    put<int32_t>(buf, pos, proc[0]);
    put<int32_t>(buf, pos, id[0]);
    put<int32_t>(buf, pos, proc[1]);
    put<int32_t>(buf, pos, id[1]);
    putState(buf, pos, p1);
    putState(buf, pos, p2);
    put<int32_t>(buf, pos, p1.nPrimary);
    put<int32_t>(buf, pos, p2.nPrimary);
    put<float>(buf, pos, wallDistance);
}


void Foam::collisionEvent::unpack(const char* buf)
{
    std::size_t pos = 0;
    timeIndex = get<int32_t>(buf, pos);
    category = get<uint8_t>(buf, pos);
    branch = get<uint8_t>(buf, pos);
    agglomerates = get<uint8_t>(buf, pos);
    type = get<uint8_t>(buf, pos);
    time = get<double>(buf, pos);
    proc[0] = get<int32_t>(buf, pos);
    id[0] = get<int32_t>(buf, pos);
    proc[1] = get<int32_t>(buf, pos);
    id[1] = get<int32_t>(buf, pos);
    getState(buf, pos, p1);
    getState(buf, pos, p2);
    p1.nPrimary = get<int32_t>(buf, pos);
    p2.nPrimary = get<int32_t>(buf, pos);
    wallDistance = get<float>(buf, pos);
}


std::string Foam::collisionEvent::invalid
(
    const char* buf,
    const label nBranches
) const
{
    const collisionEvent& e = *this;
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
    else if
    (
        !(std::isfinite(e.wallDistance) && e.wallDistance >= 0)
    )
    {
        os << "wall distance " << e.wallDistance << " (valid: finite,"
           << " >= 0)";
    }
    for (label k = 0; k < 2 && os.str().empty(); ++k)
    {
        // A rank's number, or the fragments' or injected parcels'
        if (!Foam::particleIds::valid(e.proc[k]) || e.id[k] < 0)
        {
            os << "partner " << k + 1 << ": origProc " << e.proc[k]
               << ", origId " << e.id[k] << " (valid: origProc a rank >= 0,"
               << " -2 (a fragment) or -3 (injected), origId >= 0)";
        }
    }
    for (const Foam::hardSphereState* p : {&e.p1, &e.p2})
    {
        if (!os.str().empty())
        {
            break;
        }
        os << Foam::eventRecord::invalidState
        (
            *p, p == &e.p1 ? "partner 1" : "partner 2"
        );
    }
    return os.str();
}


Foam::label Foam::collisionEvent::agglomeratesByte(const char* buf)
{
    // After the time index (4 bytes), the category and the branch
    std::size_t pos = sizeof(int32_t) + 2;
    return get<uint8_t>(buf, pos);
}


// ************************************************************************* //
