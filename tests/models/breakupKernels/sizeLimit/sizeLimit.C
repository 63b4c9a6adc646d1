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

#include "sizeLimit.H"
#include "hardSphereCollisionKernel.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(sizeLimit, 0);
    addToRunTimeSelectionTable(breakupKernel, sizeLimit, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::sizeLimit::fragmentationDict(const dictionary& coeffs)
{
    dictionary d;
    d.add("mode", word("erosion"));
    d.add("direction", word("extensional"));
    d.add("gap", coeffs.get<scalar>("gap"));
    d.add("spin", word("conserveL"));
    d.add("tries", 1);
    d.name() = coeffs.name();
    return d;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sizeLimit::sizeLimit
(
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision
)
:
    breakupKernel(coeffs, {"randomSeed", "nMax", "gap"}),
    nMax_(coeffs.get<label>("nMax")),
    fragmentation_
    (
        fragmentationDict(coeffs),
        collision.structure(),
        collision.material().rho0()
    )
{
    if (nMax_ < 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "nMax = " << nMax_ << " is out of range [1, inf)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList& Foam::sizeLimit::mechanisms() const
{
    static const wordList names({"size"});
    return names;
}


Foam::wordList Foam::sizeLimit::fields() const
{
    return {"excess"};
}


Foam::breakupKernel::verdict Foam::sizeLimit::check
(
    const hardSphereState& s,
    const breakupStresses::load&,
    const scalar,
    const key&
) const
{
    verdict v;
    v.values[0] = s.nPrimary - nMax_;
    if (s.nPrimary > nMax_)
    {
        v.mechanism = 0;
    }
    return v;
}


Foam::agglomerateFragmentation::fragments Foam::sizeLimit::split
(
    const hardSphereState& parent,
    const verdict&,
    const symmTensor&,
    const key& k,
    const label
) const
{
    const scalar angle =
        constant::mathematical::twoPi*(k.timeIndex % 7)/7.0;
    return
        fragmentation_.split
        (
            parent, 1, vector(std::cos(angle), std::sin(angle), 0)
        );
}


void Foam::sizeLimit::write(Ostream& os) const
{
    os  << "sizeLimit: nMax " << nMax_;
}


// ************************************************************************* //
