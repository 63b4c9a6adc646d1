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

#include "hardSphereInput.H"
#include "error.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::hardSphereInput::inRange
(
    const scalar value,
    const bound& lower,
    const bound& upper
)
{
    if (!std::isfinite(value))
    {
        return false;
    }
    const bool lowerOk =
        lower.inclusive ? (value >= lower.value) : (value > lower.value);
    const bool upperOk =
        upper.inclusive ? (value <= upper.value) : (value < upper.value);
    return lowerOk && upperOk;
}


Foam::string Foam::hardSphereInput::rangeText
(
    const bound& lower,
    const bound& upper
)
{
    OStringStream os;
    os  << (lower.inclusive ? "[" : "(");
    if (lower.value <= -GREAT) { os << "-inf"; } else { os << lower.value; }
    os  << ", ";
    if (upper.value >= GREAT) { os << "inf"; } else { os << upper.value; }
    os  << (upper.inclusive ? "]" : ")");
    return os.str();
}


void Foam::hardSphereInput::checkInRange
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const bound& lower,
    const bound& upper
)
{
    if (!inRange(value, lower, upper))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value
            << " in dictionary " << dict.name()
            << " is out of range." << nl
            << "    Valid range: " << key << " in "
            << rangeText(lower, upper).c_str()
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::hardSphereInput::getInRange
(
    const dictionary& dict,
    const word& key,
    const bound& lower,
    const bound& upper
)
{
    if (!dict.found(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' not found in dictionary "
            << dict.name() << nl
            << "    It is required, in SI units, in the range "
            << rangeText(lower, upper).c_str()
            << exit(FatalIOError);
    }

    const scalar value = dict.get<scalar>(key, keyType::LITERAL);
    checkInRange(dict, key, value, lower, upper);
    return value;
}


Foam::label Foam::hardSphereInput::getSeed
(
    const dictionary& dict,
    const word& key
)
{
    const label seed = dict.getOrDefault<label>(key, 0, keyType::LITERAL);
    if (seed < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' of " << dict.name() << " is " << seed
            << nl << "    The seed of the keyed random numbers is an"
            << " integer in [0, " << labelMax << "]" << exit(FatalIOError);
    }
    return seed;
}


// ************************************************************************* //
