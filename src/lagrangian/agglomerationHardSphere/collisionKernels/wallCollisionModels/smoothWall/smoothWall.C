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

#include "smoothWall.H"
#include "hardSphereInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(smoothWall, 0);
    addToRunTimeSelectionTable(wallCollisionModel, smoothWall, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::smoothWall::smoothWall(const dictionary& dict)
:
    wallCollisionModel(dict, typeName),
    coeffs_(coeffDict_)
{
    hardSphereInput::checkKeys(coeffDict_, {"en", "et", "muSt", "muKin"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::smoothWall::smoothImpact
(
    const collisionCoefficients& coeffs,
    const vector& nw,
    const vector& Uw,
    const scalar d,
    vector& U,
    vector& omega
)
{
    const vector uRel(U - Uw);
    const scalar un = uRel & nw;

    if (un >= 0)
    {
        FatalErrorInFunction
            << "Particle does not approach the wall: u_n = " << un
            << " m/s (normal " << nw << ")" << exit(FatalError);
    }

    const scalar r = 0.5*d;
    const vector uc(uRel - un*nw - r*(omega ^ nw));
    const scalar s = mag(uc);

    const scalar en = coeffs.en();
    const scalar et = coeffs.et();
    const scalar Jn = -(1 + en)*un;

    const bool sticking =
        s <= 3.5*coeffs.muSt()*(1 + en)*mag(un)/(1 + et);

    vector J(Jn*nw);

    if (sticking)
    {
        J -= (2.0/7.0)*(1 + et)*uc;
    }
    else
    {
        J -= coeffs.muKin()*Jn*uc/s;
    }

    U += J;
    omega -= (5.0/d)*(nw ^ J);

    return sticking;
}


bool Foam::smoothWall::impact
(
    const vector& nw,
    const vector& Uw,
    const scalar d,
    vector& U,
    vector& omega,
    keyedRandom&
) const
{
    return smoothImpact(coeffs_, nw, Uw, d, U, omega);
}


// ************************************************************************* //
