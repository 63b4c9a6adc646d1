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

#include "hardSphereMaterial.H"
#include "hardSphereInput.H"
#include "mathematicalConstants.H"

using namespace Foam::hardSphereInput;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// S(zeta) of AB16 Eq. A.5: (sigma1 - sigma3)/p on the contact axis
Foam::scalar yieldFunction(const Foam::scalar zeta, const Foam::scalar nu)
{
    return
        -(1 + nu)*(1 - zeta*std::atan(1/zeta))
      + 1.5/(1 + zeta*zeta);
}

// Golden-section search for the maximum of S on (0, 5]; S is unimodal there
Foam::scalar yieldMaximum(const Foam::scalar nu)
{
    const Foam::scalar invPhi = 0.5*(std::sqrt(5.0) - 1);
    Foam::scalar a = 1e-9;
    Foam::scalar b = 5;
    Foam::scalar c = b - invPhi*(b - a);
    Foam::scalar d = a + invPhi*(b - a);
    for (int iter = 0; iter < 200 && (b - a) > 1e-14; ++iter)
    {
        if (yieldFunction(c, nu) > yieldFunction(d, nu))
        {
            b = d;
        }
        else
        {
            a = c;
        }
        c = b - invPhi*(b - a);
        d = a + invPhi*(b - a);
    }
    return 0.5*(a + b);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::hardSphereMaterial::yieldDepth(const scalar nu)
{
    return yieldMaximum(nu);
}


Foam::scalar Foam::hardSphereMaterial::yieldPressureFactor(const scalar nu)
{
    return 1/yieldFunction(yieldMaximum(nu), nu);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardSphereMaterial::hardSphereMaterial(const dictionary& dict)
:
    H_(getInRange(dict, "H", open(0), open(GREAT))),
    E_(getInRange(dict, "E", open(0), open(GREAT))),
    nu_(getInRange(dict, "nu", closed(0), open(0.5))),
    pMax_(0),
    delta0_(getInRange(dict, "delta0", open(0), open(GREAT))),
    rho0_(getInRange(dict, "rho0", open(0), open(GREAT))),
    pFromSigmaY_(false)
{
    checkKeys(dict, {"H", "E", "nu", "sigmaY", "pMax", "delta0", "rho0"});

    const bool hasP = dict.found("pMax", keyType::LITERAL);
    const bool hasSigma = dict.found("sigmaY", keyType::LITERAL);

    if (hasP == hasSigma)
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " needs exactly one of the"
            << " entries 'pMax' (maximum contact pressure [Pa], > 0) or"
            << " 'sigmaY' (compressive yield strength [Pa], > 0, from which"
            << " pMax = c(nu) sigmaY, AB16 Eq. A.5); "
            << (hasP ? "both are" : "neither is") << " given."
            << exit(FatalIOError);
    }

    if (hasP)
    {
        pMax_ = getInRange(dict, "pMax", open(0), open(GREAT));
    }
    else
    {
        const scalar sigmaY =
            getInRange(dict, "sigmaY", open(0), open(GREAT));
        pMax_ = yieldPressureFactor(nu_)*sigmaY;
        pFromSigmaY_ = true;
    }
}


Foam::hardSphereMaterial::hardSphereMaterial
(
    const scalar H,
    const scalar E,
    const scalar nu,
    const scalar pMax,
    const scalar delta0,
    const scalar rho0
)
:
    H_(H),
    E_(E),
    nu_(nu),
    pMax_(pMax),
    delta0_(delta0),
    rho0_(rho0),
    pFromSigmaY_(false)
{
    const dictionary& d = dictionary::null;
    checkInRange(d, "H", H_, open(0), open(GREAT));
    checkInRange(d, "E", E_, open(0), open(GREAT));
    checkInRange(d, "nu", nu_, closed(0), open(0.5));
    checkInRange(d, "pMax", pMax_, open(0), open(GREAT));
    checkInRange(d, "delta0", delta0_, open(0), open(GREAT));
    checkInRange(d, "rho0", rho0_, open(0), open(GREAT));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hardSphereMaterial::write(Ostream& os) const
{
    os.writeEntry("H", H_);
    os.writeEntry("E", E_);
    os.writeEntry("nu", nu_);
    os.writeEntry("pMax", pMax_);
    os.writeEntry("delta0", delta0_);
    os.writeEntry("rho0", rho0_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::hardSphereMaterial::vanDerWaalsEnergy
(
    const scalar en,
    const scalar d1,
    const scalar rho1,
    const scalar d2,
    const scalar rho2,
    const scalar vE
) const
{
    // AB16 Eq. 37
    const scalar bracket =
        rho1*rho2*(1 - en*en)
       /(
            6*pMax_*(d1 + d2)
           *(rho1*d1*d1*d1 + rho2*d2*d2*d2)
        );

    return H_/(12*sqr(delta0_))*sqr(d1*d2)*vE*std::sqrt(bracket);
}


// ************************************************************************* //
