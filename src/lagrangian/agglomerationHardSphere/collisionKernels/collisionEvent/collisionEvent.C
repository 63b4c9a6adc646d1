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
#include <cstring>
#include <cstdint>
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

template<class T>
void put(char* buf, std::size_t& pos, const T v)
{
    std::memcpy(buf + pos, &v, sizeof(T));
    pos += sizeof(T);
}

template<class T>
T get(const char* buf, std::size_t& pos)
{
    T v;
    std::memcpy(&v, buf + pos, sizeof(T));
    pos += sizeof(T);
    return v;
}

void putState(char* buf, std::size_t& pos, const Foam::hardSphereState& s)
{
    for (const Foam::vector* v : {&s.x, &s.U, &s.omega})
    {
        for (Foam::direction c = 0; c < 3; ++c)
        {
            put<double>(buf, pos, (*v)[c]);
        }
    }
    put<double>(buf, pos, s.d);
    put<double>(buf, pos, s.rho);
}

void getState(const char* buf, std::size_t& pos, Foam::hardSphereState& s)
{
    for (Foam::vector* v : {&s.x, &s.U, &s.omega})
    {
        for (Foam::direction c = 0; c < 3; ++c)
        {
            (*v)[c] = get<double>(buf, pos);
        }
    }
    s.d = get<double>(buf, pos);
    s.rho = get<double>(buf, pos);
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
} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const std::size_t Foam::collisionEvent::recordBytes;
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


Foam::label Foam::collisionEvent::agglomeratesByte(const char* buf)
{
    // After the time index (4 bytes), the category and the branch
    std::size_t pos = sizeof(int32_t) + 2;
    return get<uint8_t>(buf, pos);
}


// ************************************************************************* //
