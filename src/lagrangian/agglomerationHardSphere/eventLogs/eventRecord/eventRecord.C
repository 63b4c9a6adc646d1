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

#include "eventRecord.H"
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::eventRecord::putVector(char* buf, std::size_t& pos, const vector& v)
{
    for (direction c = 0; c < 3; ++c)
    {
        put<double>(buf, pos, v[c]);
    }
}


Foam::vector Foam::eventRecord::getVector(const char* buf, std::size_t& pos)
{
    vector v;
    for (direction c = 0; c < 3; ++c)
    {
        v[c] = get<double>(buf, pos);
    }
    return v;
}


void Foam::eventRecord::putState
(
    char* buf,
    std::size_t& pos,
    const hardSphereState& s
)
{
    putVector(buf, pos, s.x);
    putVector(buf, pos, s.U);
    putVector(buf, pos, s.omega);
    put<double>(buf, pos, s.d);
    put<double>(buf, pos, s.rho);
}


void Foam::eventRecord::getState
(
    const char* buf,
    std::size_t& pos,
    hardSphereState& s
)
{
    s.x = getVector(buf, pos);
    s.U = getVector(buf, pos);
    s.omega = getVector(buf, pos);
    s.d = get<double>(buf, pos);
    s.rho = get<double>(buf, pos);
}


std::string Foam::eventRecord::text(const vector& v)
{
    std::ostringstream os;
    os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
    return os.str();
}


bool Foam::eventRecord::bounded(const vector& v, const scalar bound)
{
    for (const scalar c : {v.x(), v.y(), v.z()})
    {
        if (!(std::isfinite(c) && std::abs(c) <= bound))
        {
            return false;
        }
    }
    return true;
}


std::string Foam::eventRecord::invalidState
(
    const hardSphereState& s,
    const std::string& who
)
{
    std::ostringstream os;
    if (!(std::isfinite(s.d) && s.d >= dMin && s.d <= dMax))
    {
        os << who << ": d " << s.d << " (valid: " << dMin << " - " << dMax
           << " m)";
    }
    else if (!(std::isfinite(s.rho) && s.rho >= rhoMin && s.rho <= rhoMax))
    {
        os << who << ": rho " << s.rho << " (valid: " << rhoMin << " - "
           << rhoMax << " kg/m3)";
    }
    else if (s.nPrimary < 1)
    {
        os << who << ": nPrimary " << s.nPrimary << " (valid: >= 1)";
    }
    else if (!bounded(s.x, xMax))
    {
        os << who << ": position " << text(s.x) << " (valid: finite, each"
           << " component within +-" << xMax << " m)";
    }
    else if (!bounded(s.U, UMax))
    {
        os << who << ": velocity " << text(s.U) << " (valid: finite, each"
           << " component within +-" << UMax << " m/s)";
    }
    else if (!bounded(s.omega, omegaMax))
    {
        os << who << ": spin " << text(s.omega) << " (valid: finite, each"
           << " component within +-" << omegaMax << " rad/s)";
    }
    return os.str();
}


// ************************************************************************* //
