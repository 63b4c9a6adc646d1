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

#include "binaryCollision.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::binaryCollision::binaryCollision
(
    const hardSphereState& p1,
    const hardSphereState& p2
)
:
    n_(p2.x - p1.x),
    ur_(p2.U - p1.U),
    un_(0),
    uc_(Zero),
    s_(0),
    t_(Zero),
    m1_(p1.mass()),
    m2_(p2.mass()),
    mHat_(0),
    ell_(0.5*(p1.d + p2.d)),
    d1_(p1.d),
    d2_(p2.d)
{
    const scalar dist = mag(n_);
    if (!(dist > 0) || !(p1.d > 0) || !(p2.d > 0) || !(m1_ > 0) || !(m2_ > 0))
    {
        FatalErrorInFunction
            << "Invalid collision pair: centre distance " << dist
            << ", diameters " << p1.d << ", " << p2.d
            << ", densities " << p1.rho << ", " << p2.rho << nl
            << "    The centres must differ and d, rho must be positive."
            << abort(FatalError);
    }
    n_ /= dist;

    // AB16 Eq. 2
    mHat_ = m1_*m2_/(m1_ + m2_);

    un_ = ur_ & n_;

    // AB16 Eq. 9: slip of the contact point of 2 relative to that of 1
    uc_ = ur_ - un_*n_ - ((0.5*d1_*p1.omega + 0.5*d2_*p2.omega) ^ n_);

    // AB16 Eq. 14; s = 0 leaves t = 0 (doc/models.md 1, A14)
    s_ = mag(uc_);
    if (s_ > 0)
    {
        t_ = uc_/s_;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::binaryCollision::sticking
(
    const collisionCoefficients& coeffs,
    const scalar fF
) const
{
    return s_ <= 7*coeffs.muSt()*fF/(2*(1 + coeffs.et()));
}


Foam::vector Foam::binaryCollision::impulse
(
    const collisionCoefficients& coeffs,
    const scalar fN,
    const scalar fF,
    bool& isSticking
) const
{
    isSticking = sticking(coeffs, fF);

    if (isSticking)
    {
        // AB16 Eqs. 10, 11 (78): the slip is reversed with factor e_t
        return fN*n_ - (2.0/7.0)*(1 + coeffs.et())*uc_;
    }

    // AB16 Eqs. 13, 15 (77, 79): kinetic Coulomb friction against the slip
    return fN*n_ - coeffs.muKin()*fF*t_;
}


void Foam::binaryCollision::apply
(
    const vector& fHat,
    hardSphereState& p1,
    hardSphereState& p2
) const
{
    // AB16 Eq. 1a-d
    const vector nxf = n_ ^ fHat;
    p1.U -= (mHat_/m1_)*fHat;
    p2.U += (mHat_/m2_)*fHat;
    p1.omega -= (5*mHat_/(d1_*m1_))*nxf;
    p2.omega -= (5*mHat_/(d2_*m2_))*nxf;
}


Foam::vector Foam::binaryCollision::angularMomentum
(
    const hardSphereState& p1,
    const hardSphereState& p2
) const
{
    // AB16 Eq. 41
    return
        p1.inertia()*p1.omega + p2.inertia()*p2.omega
      + mHat_*ell_*(n_ ^ (p2.U - p1.U));
}


// ************************************************************************* //
