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

#include "collisionCoefficients.H"
#include "hardSphereInput.H"

using namespace Foam::hardSphereInput;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::collisionCoefficients::check(const dictionary& dict) const
{
    checkInRange(dict, "en", en_, open(0), closed(1));
    checkInRange(dict, "et", et_, closed(0), closed(1));
    checkInRange(dict, "muSt", muSt_, closed(0), open(GREAT));
    checkInRange(dict, "muKin", muKin_, closed(0), open(GREAT));

    if (muKin_ > 2*muSt_/(1 + et_))
    {
        WarningInFunction
            << "In " << dict.name() << ": muKin = " << muKin_
            << " > 2 muSt/(1 + et) = " << 2*muSt_/(1 + et_) << nl
            << "    A sliding collision can then gain kinetic energy"
            << " (doc/models.md 1.5)." << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionCoefficients::collisionCoefficients(const dictionary& dict)
:
    en_(getInRange(dict, "en", open(0), closed(1))),
    et_(getInRange(dict, "et", closed(0), closed(1))),
    muSt_(getInRange(dict, "muSt", closed(0), open(GREAT))),
    muKin_(getInRange(dict, "muKin", closed(0), open(GREAT)))
{
    check(dict);
}


Foam::collisionCoefficients::collisionCoefficients
(
    const scalar en,
    const scalar et,
    const scalar muSt,
    const scalar muKin
)
:
    en_(en),
    et_(et),
    muSt_(muSt),
    muKin_(muKin)
{
    check(dictionary::null);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionCoefficients::write(Ostream& os) const
{
    os.writeEntry("en", en_);
    os.writeEntry("et", et_);
    os.writeEntry("muSt", muSt_);
    os.writeEntry("muKin", muKin_);
}


// ************************************************************************* //
