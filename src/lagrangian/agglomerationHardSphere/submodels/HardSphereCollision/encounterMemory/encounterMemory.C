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

#include "encounterMemory.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::encounterMemory::readWordOrNumber
(
    const dictionary& dict,
    const word& key,
    const word& wordName,
    const scalar wordValue,
    const scalar defaultValue,
    const string& meaning
)
{
    if (!dict.found(key))
    {
        return defaultValue;
    }

    ITstream& is = dict.lookup(key);
    const token t(is);
    if (t.isWord() && t.wordToken() == wordName)
    {
        return wordValue;
    }
    if (t.isNumber() && t.number() >= 0)
    {
        return t.number();
    }

    FatalIOErrorInFunction(dict)
        << key << " " << t << " is not valid: give " << meaning.c_str()
        << " or " << wordName << exit(FatalIOError);

    return defaultValue;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::encounterMemory::encounterMemory(const dictionary& dict)
:
    memory_
    (
        readWordOrNumber
        (
            dict, "encounterMemory", "unlimited", VGREAT, VGREAT,
            "a time >= 0 [s]"
        )
    ),
    release_
    (
        readWordOrNumber
        (
            dict, "encounterRelease", "none", -1, 0.1,
            "the relative distance eps >= 0 (the last partner is"
            " forgotten beyond (1 + eps)(r1 + r2))"
        )
    )
{}


Foam::encounterMemory::encounterMemory
(
    const scalar memory,
    const scalar release
)
:
    memory_(memory),
    release_(release)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::encounterMemory::keys()
{
    return wordList({"encounterMemory", "encounterRelease"});
}


Foam::encounterMemory::categoryType Foam::encounterMemory::category
(
    const bool overlapStart,
    const memory& a,
    const memory& b,
    const scalar tc
) const
{
    if (overlapStart)
    {
        return OVERLAP_START;
    }
    if
    (
        (a.lastPartner == b.id && tc - a.lastContactTime <= memory_)
     || (b.lastPartner == a.id && tc - b.lastContactTime <= memory_)
    )
    {
        return REPEAT;
    }
    return FIRST;
}


void Foam::encounterMemory::write(Ostream& os) const
{
    os  << "encounterRelease ";
    if (releases())
    {
        os  << release_;
    }
    else
    {
        os  << "none";
    }
}


// ************************************************************************* //
