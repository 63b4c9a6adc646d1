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

#include "breakupEvent.H"
#include "eventRecord.H"
#include "agglomerateFragmentation.H"
#include "breakupCriterion.H"
#include "SHA1.H"
#include <cmath>
#include <cstdlib>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam::eventRecord;

    // The bounds of a record's step and load (doc/eventLog.md): wide
    // enough for any flow, narrow enough that the kernels' products
    // (eps/nu, S:S, nu/eps, rho u^2) stay finite, so that a corrupt
    // record is refused by name instead of a floating-point exception
    const Foam::scalar dtMax = 1e3;         // s
    const Foam::scalar epsilonMax = 1e12;   // m2/s3
    const Foam::scalar nuMin = 1e-9, nuMax = 1;     // m2/s
    // the fluid's density: the particles' bounds (eventRecord)
    const Foam::scalar impactMax = 1e4;     // m/s
    const Foam::scalar strainMax = 1e12;    // 1/s
    const Foam::scalar valueMax = 1e100;    // the model's values

    bool within(const Foam::scalar v, const Foam::scalar lo,
                const Foam::scalar hi)
    {
        return std::isfinite(v) && v >= lo && v <= hi;
    }

    // The offsets of the record's checksum and padding
    const std::size_t checkAt = 36;
    const std::size_t paddingAt = 452;

}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const std::size_t Foam::breakupEvent::recordBytes;
const std::size_t Foam::breakupEvent::headerBytes;
const Foam::label Foam::breakupEvent::nValues;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::breakupEvent::breakupEvent()
:
    timeIndex(0),
    mechanism(0),
    proc(-1),
    id(-1),
    newProc(-1),
    newId(-1),
    dt(0),
    parent(),
    load(),
    S(Zero),
    values(scalar(0)),
    a(),
    b(),
    attempt(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::breakupEvent::pack(char* buf) const
{
    std::size_t pos = 0;
    put<int32_t>(buf, pos, timeIndex);
    put<int32_t>(buf, pos, mechanism);
    put<int32_t>(buf, pos, proc);
    put<int32_t>(buf, pos, id);
    put<int32_t>(buf, pos, newProc);
    put<int32_t>(buf, pos, newId);
    put<int32_t>(buf, pos, parent.nPrimary);
    put<int32_t>(buf, pos, a.nPrimary);
    put<int32_t>(buf, pos, b.nPrimary);
    put<uint32_t>(buf, pos, 0);         // the checksum, below
    put<double>(buf, pos, dt);
    putState(buf, pos, parent);
    put<double>(buf, pos, load.epsilon);
    put<double>(buf, pos, load.nu);
    put<double>(buf, pos, load.rhoF);
    putVector(buf, pos, load.dragForce);
    put<double>(buf, pos, load.wallImpactSpeed);
    for (direction c = 0; c < symmTensor::nComponents; ++c)
    {
        put<double>(buf, pos, S[c]);
    }
    for (const scalar v : values)
    {
        put<double>(buf, pos, v);
    }
    putState(buf, pos, a);
    putState(buf, pos, b);
    put<int32_t>(buf, pos, attempt);
    put<int32_t>(buf, pos, 0);          // padding

    std::size_t at = checkAt;
    put<uint32_t>(buf, at, checksum(buf));
}


uint32_t Foam::breakupEvent::checksum(const char* buf)
{
    SHA1 sha;
    sha.append(buf, checkAt);
    sha.append(buf + checkAt + 4, recordBytes - checkAt - 4);
    return std::strtoul(sha.digest().str().substr(0, 8).c_str(), nullptr, 16);
}


void Foam::breakupEvent::unpack(const char* buf)
{
    std::size_t pos = 0;
    timeIndex = get<int32_t>(buf, pos);
    mechanism = get<int32_t>(buf, pos);
    proc = get<int32_t>(buf, pos);
    id = get<int32_t>(buf, pos);
    newProc = get<int32_t>(buf, pos);
    newId = get<int32_t>(buf, pos);
    parent.nPrimary = get<int32_t>(buf, pos);
    a.nPrimary = get<int32_t>(buf, pos);
    b.nPrimary = get<int32_t>(buf, pos);
    get<int32_t>(buf, pos);
    dt = get<double>(buf, pos);
    getState(buf, pos, parent);
    load.epsilon = get<double>(buf, pos);
    load.nu = get<double>(buf, pos);
    load.rhoF = get<double>(buf, pos);
    load.dragForce = getVector(buf, pos);
    load.wallImpactSpeed = get<double>(buf, pos);
    load.omega = parent.omega;
    for (direction c = 0; c < symmTensor::nComponents; ++c)
    {
        S[c] = get<double>(buf, pos);
    }
    for (scalar& v : values)
    {
        v = get<double>(buf, pos);
    }
    getState(buf, pos, a);
    getState(buf, pos, b);
    attempt = get<int32_t>(buf, pos);
    load.epsilonResolved = 0;           // replayLoad() gives it
}


Foam::breakupStresses::load Foam::breakupEvent::replayLoad() const
{
    // The resolved part of epsilon from the record's strain rate, as the
    // driver computed it
    breakupStresses::load L(load);
    L.epsilonResolved = breakupCriterion::dissipation(L.nu, 0, S);
    return L;
}


std::string Foam::breakupEvent::invalidHead
(
    const char* buf,
    const label nMechanisms
) const
{
    std::ostringstream os;
    std::size_t at = checkAt;
    const uint32_t check = eventRecord::get<uint32_t>(buf, at);
    if (timeIndex < 0)
    {
        os << "time index " << timeIndex << " (valid: >= 0)";
    }
    else if (mechanism < 0 || mechanism >= nMechanisms)
    {
        os << "mechanism " << mechanism << " (valid: 0-"
           << nMechanisms - 1 << ")";
    }
    else if (check != checksum(buf))
    {
        os << "checksum " << check << " (the record's bytes give "
           << checksum(buf) << ": the record was altered)";
    }
    else if (parent.nPrimary < 2)
    {
        os << "parent: nPrimary " << parent.nPrimary << " (valid: >= 2)";
    }
    else if (a.nPrimary + b.nPrimary != parent.nPrimary)
    {
        os << "fragments: nPrimary " << a.nPrimary << " + " << b.nPrimary
           << " (valid: the parent's " << parent.nPrimary << ")";
    }
    else if (!(within(dt, 0, dtMax) && dt > 0))
    {
        os << "time step " << dt << " (valid: > 0, <= " << dtMax << " s)";
    }
    return os.str();
}


std::string Foam::breakupEvent::invalidLoad() const
{
    bool boundedS = true;
    for (direction c = 0; c < symmTensor::nComponents; ++c)
    {
        boundedS = boundedS && within(S[c], -strainMax, strainMax);
    }
    std::ostringstream os;
    if
    (
        !within(load.epsilon, 0, epsilonMax)
     || !within(load.nu, nuMin, nuMax)
     || !within(load.rhoF, rhoMin, rhoMax)
     || !bounded(load.dragForce, 1)
     || !within(load.wallImpactSpeed, 0, impactMax)
     || !boundedS
    )
    {
        os << "load: epsilon " << load.epsilon << ", nu " << load.nu
           << ", rho " << load.rhoF << ", drag force "
           << text(load.dragForce) << ", wall impact speed "
           << load.wallImpactSpeed << ", strain rate (" << S.xx() << " "
           << S.xy() << " " << S.xz() << " " << S.yy() << " " << S.yz()
           << " " << S.zz() << ")"
           << " (valid: epsilon 0-" << epsilonMax
           << " m2/s3, nu " << nuMin << "-" << nuMax << " m2/s, rho "
           << rhoMin << "-" << rhoMax << " kg/m3, each component of the"
           << " drag force within +-1 N, wall impact speed 0-" << impactMax
           << " m/s, each component of the strain rate within +-"
           << strainMax << " 1/s)";
    }
    return os.str();
}


std::string Foam::breakupEvent::invalidTail
(
    const char* buf,
    const label nFields
) const
{
    std::size_t at = paddingAt;
    const int32_t padding = eventRecord::get<int32_t>(buf, at);
    bool boundedValues = true;
    forAll(values, i)
    {
        boundedValues =
            boundedValues
         && (
                i < nFields
              ? within(values[i], -valueMax, valueMax)
              : values[i] == 0
            );
    }
    std::ostringstream os;
    if (!boundedValues)
    {
        os << "the model's values (";
        forAll(values, i)
        {
            os << (i ? " " : "") << values[i];
        }
        os << ") (valid: the " << nFields << " named by the header's fields"
           << " within +-" << valueMax << ", the others 0)";
    }
    else if
    (
        attempt < 0 || attempt >= agglomerateFragmentation::maxTries
    )
    {
        os << "placement try " << attempt << " (valid: 0-"
           << agglomerateFragmentation::maxTries - 1 << ")";
    }
    else if (padding != 0)
    {
        os << "padding " << padding << " at byte " << paddingAt
           << " (valid: 0)";
    }
    return os.str();
}


std::string Foam::breakupEvent::invalid
(
    const char* buf,
    const List<wordList>& names
) const
{
    std::string why = invalidHead(buf, names[0].size());
    if (why.empty())
    {
        why = invalidLoad();
    }
    if (why.empty())
    {
        why = invalidTail(buf, names.size() > 2 ? names[2].size() : 0);
    }
    for (const hardSphereState* p : {&parent, &a, &b})
    {
        if (!why.empty())
        {
            break;
        }
        why = invalidState
        (
            *p,
            p == &parent ? "parent" : (p == &a ? "fragment a" : "fragment b")
        );
    }
    return why;
}


// ************************************************************************* //
