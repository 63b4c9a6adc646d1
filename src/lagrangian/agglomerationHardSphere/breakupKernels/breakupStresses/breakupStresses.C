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

#include "breakupStresses.H"
#include "hardSphereInput.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::breakupStresses::mechanismType>
Foam::breakupStresses::mechanismTypeNames
({
    { mechanismType::TURBULENCE, "turbulence" },
    { mechanismType::DRAG, "drag" },
    { mechanismType::ROTATION, "rotation" },
    { mechanismType::WALL_IMPACT, "wallImpact" },
});

const Foam::Enum<Foam::breakupStresses::dissipationType>
Foam::breakupStresses::dissipationTypeNames
({
    { dissipationType::TOTAL, "total" },
    { dissipationType::SUBGRID, "subgrid" },
    { dissipationType::RESOLVED_SHEAR, "resolvedShear" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::FixedList<bool, 4> Foam::breakupStresses::readMechanisms
(
    const dictionary& dict
)
{
    FixedList<bool, 4> on(false);
    const wordList names(dict.get<wordList>("mechanisms"));
    if (names.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'mechanisms' of " << dict.name() << " is empty"
            << nl << "    Valid mechanisms: "
            << flatOutput(mechanismTypeNames.names()) << exit(FatalIOError);
    }
    for (const word& name : names)
    {
        if (names.found(name) && names.find(name) != names.rfind(name))
        {
            FatalIOErrorInFunction(dict)
                << "Mechanism '" << name << "' named twice in entry"
                << " 'mechanisms' of " << dict.name() << nl
                << "    Name each mechanism once: "
                << flatOutput(mechanismTypeNames.names())
                << exit(FatalIOError);
        }
        if (!mechanismTypeNames.found(name))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown mechanism '" << name << "' in entry"
                << " 'mechanisms' of " << dict.name() << nl
                << "    Valid mechanisms: "
                << flatOutput(mechanismTypeNames.names())
                << exit(FatalIOError);
        }
        on[mechanismTypeNames[name]] = true;
    }

    return on;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::breakupStresses::breakupStresses(const dictionary& dict)
:
    on_(false),
    Cv_(0),
    Ci_(0),
    Cd_(0),
    cRot_(0),
    Cw_(0),
    dissipation_(dissipationType::TOTAL)
{
    using namespace hardSphereInput;
    checkKeys
    (
        dict,
        {
            "mechanisms", "dissipation", "Cv", "Ci", "Cd", "rotationFactor",
            "Cw"
        }
    );

    on_ = readMechanisms(dict);
    const wordList names(dict.get<wordList>("mechanisms"));

    // A coefficient is read where its mechanism is on, and only there
    const bool t = on_[TURBULENCE];
    const bool d = on_[DRAG];
    const bool r = on_[ROTATION];
    const bool w = on_[WALL_IMPACT];
    const wordList need
    ({
        t ? "dissipation" : "", t ? "Cv" : "", t ? "Ci" : "",
        d ? "Cd" : "", r ? "rotationFactor" : "", w ? "Cw" : ""
    });
    for
    (
        const char* key
      : {"dissipation", "Cv", "Ci", "Cd", "rotationFactor", "Cw"}
    )
    {
        if (dict.found(key) && !need.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' of " << dict.name() << " belongs"
                << " to a mechanism that is off (mechanisms "
                << flatOutput(names) << ")" << exit(FatalIOError);
        }
    }
    if (t)
    {
        dissipation_ = dissipationTypeNames.get("dissipation", dict);
        Cv_ = getInRange(dict, "Cv", open(0), open(GREAT));
        Ci_ = getInRange(dict, "Ci", open(0), open(GREAT));
    }
    if (d)
    {
        Cd_ = getInRange(dict, "Cd", open(0), open(GREAT));
    }
    if (r)
    {
        cRot_ = getInRange(dict, "rotationFactor", open(0), open(GREAT));
    }
    if (w)
    {
        Cw_ = getInRange(dict, "Cw", open(0), open(GREAT));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::breakupStresses::turbulent
(
    const scalar epsilon,
    const scalar nu,
    const scalar rhoF,
    const scalar da
) const
{
    if (!(epsilon > 0))
    {
        return 0;
    }

    // Kolmogorov length [paper: S8]
    const scalar eta = std::pow(nu*nu*nu/epsilon, 0.25);
    if (da <= eta)
    {
        // Viscous subrange [rec; the group mu (eps/nu)^1/2: paper S5]
        return Cv_*rhoF*nu*std::sqrt(epsilon/nu);
    }
    // Inertial subrange [rec]
    return Ci_*rhoF*std::cbrt(sqr(epsilon*da));
}


Foam::scalar Foam::breakupStresses::turbulent
(
    const load& L,
    const scalar da
) const
{
    // doc/breakup.md 1.1 [rec]: the readings of the dissipation rate
    const scalar sgs = max(L.epsilon - L.epsilonResolved, scalar(0));
    switch (dissipation_)
    {
        case dissipationType::SUBGRID:
        {
            return turbulent(sgs, L.nu, L.rhoF, da);
        }
        case dissipationType::RESOLVED_SHEAR:
        {
            // The resolved strain as a shear: the viscous form at any
            // size; the sub-grid eddies by their subrange
            const scalar shear =
                Cv_*L.rhoF*L.nu*std::sqrt(L.epsilonResolved/L.nu);
            return std::hypot(shear, turbulent(sgs, L.nu, L.rhoF, da));
        }
        default:
        {
            return turbulent(L.epsilon, L.nu, L.rhoF, da);
        }
    }
}


Foam::scalar Foam::breakupStresses::drag
(
    const scalar magF,
    const scalar da
) const
{
    // Mean surface traction [rec]
    return Cd_*magF/(constant::mathematical::pi*da*da);
}


Foam::scalar Foam::breakupStresses::rotational
(
    const scalar rhoA,
    const vector& omega,
    const scalar da
) const
{
    // Centrifugal tension across a plane through the spin axis [rec,
    // doc/breakup.md 1.4]
    return cRot_*rhoA*magSqr(omega)*da*da;
}


Foam::FixedList<Foam::scalar, 3> Foam::breakupStresses::stresses
(
    const load& L,
    const scalar da,
    const scalar rhoA
) const
{
    FixedList<scalar, 3> s(Zero);
    if (on_[TURBULENCE])
    {
        s[TURBULENCE] = turbulent(L, da);
    }
    if (on_[DRAG])
    {
        s[DRAG] = drag(mag(L.dragForce), da);
    }
    if (on_[ROTATION])
    {
        s[ROTATION] = rotational(rhoA, L.omega, da);
    }
    return s;
}


void Foam::breakupStresses::write(Ostream& os) const
{
    os  << "stresses:";
    forAll(on_, m)
    {
        if (on_[m])
        {
            os  << ' ' << mechanismTypeNames[mechanismType(m)];
        }
    }
    if (on_[TURBULENCE])
    {
        os  << ", dissipation " << dissipationTypeNames[dissipation_]
            << ", Cv " << Cv_ << ", Ci " << Ci_;
    }
    if (on_[DRAG])
    {
        os  << ", Cd " << Cd_;
    }
    if (on_[ROTATION])
    {
        os  << ", rotationFactor " << cRot_;
    }
    if (on_[WALL_IMPACT])
    {
        os  << ", Cw " << Cw_;
    }
}


// ************************************************************************* //
