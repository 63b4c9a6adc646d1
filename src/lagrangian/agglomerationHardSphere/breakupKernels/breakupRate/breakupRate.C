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

#include "breakupRate.H"
#include "hardSphereInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::breakupRate::timeScaleType>
Foam::breakupRate::timeScaleTypeNames
({
    { timeScaleType::KOLMOGOROV, "kolmogorov" },
    { timeScaleType::EDDY, "eddy" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::breakupRate::breakupRate()
:
    stochastic_(false),
    timeScale_(KOLMOGOROV)
{}


Foam::breakupRate::breakupRate(const dictionary& dict)
:
    breakupRate()
{
    const word model(dict.get<word>("model"));
    if (model == "stochastic")
    {
        hardSphereInput::checkKeys(dict, {"model", "timeScale"});
        stochastic_ = true;
        timeScale_ = timeScaleTypeNames.get("timeScale", dict);
    }
    else if (model == "deterministic")
    {
        hardSphereInput::checkKeys(dict, {"model"});
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown rate model '" << model << "' in " << dict.name()
            << nl << "    Valid models: (deterministic stochastic)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::breakupRate::timeScale
(
    const scalar epsilon,
    const scalar nu,
    const scalar da
) const
{
    if (timeScale_ == KOLMOGOROV)
    {
        // [paper: S8]
        return std::sqrt(nu/epsilon);
    }
    // [paper: S16]
    return std::cbrt(da*da/epsilon);
}


Foam::scalar Foam::breakupRate::probability
(
    const scalar dt,
    const scalar epsilon,
    const scalar nu,
    const scalar da
) const
{
    if (!stochastic_)
    {
        return 1;
    }
    if (!(epsilon > 0))
    {
        return 0;
    }
    // [rec, doc/breakup.md 1.6]
    return 1 - std::exp(-dt/timeScale(epsilon, nu, da));
}


void Foam::breakupRate::write(Ostream& os) const
{
    os  << "rate: " << (stochastic_ ? "stochastic" : "deterministic");
    if (stochastic_)
    {
        os  << ", timeScale " << timeScaleTypeNames[timeScale_];
    }
}


// ************************************************************************* //
