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

#include "sandgrainWall.H"
#include "hardSphereInput.H"
#include "smoothWall.H"
#include "unitConversion.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(sandgrainWall, 0);
    addToRunTimeSelectionTable(wallCollisionModel, sandgrainWall, dictionary);
}


const Foam::Enum<Foam::sandgrainWall::shadowModeType>
Foam::sandgrainWall::shadowModeNames
({
    { shadowModeType::SHADOW_REJECT, "reject" },
    { shadowModeType::SHADOW_WEIGHTED, "weighted" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sandgrainWall::sandgrainWall(const dictionary& dict)
:
    wallCollisionModel(dict, typeName),
    coeffs_(coeffDict_),
    Rz_(-1),
    CSurface_(-1),
    grainDiameterFactor_
    (
        coeffDict_.getOrDefault<scalar>("grainDiameterFactor", 1)
    ),
    sigmaGamma_(-1),
    shadowMode_
    (
        shadowModeNames.getOrDefault("shadowMode", coeffDict_, SHADOW_REJECT)
    ),
    maxResample_(coeffDict_.getOrDefault<label>("maxResample", 100)),
    maxMultipleImpacts_
    (
        coeffDict_.getOrDefault<label>("maxMultipleImpacts", 100)
    )
{
    hardSphereInput::checkKeys
    (
        coeffDict_,
        {
            "en", "et", "muSt", "muKin", "Rz", "CSurface",
            "grainDiameterFactor", "sigmaGamma", "shadowMode", "maxResample",
            "maxMultipleImpacts"
        }
    );

    if (coeffDict_.found("sigmaGamma"))
    {
        const scalar sg = coeffDict_.get<scalar>("sigmaGamma");
        if (sg < 0 || sg >= 90)
        {
            FatalIOErrorInFunction(coeffDict_)
                << "sigmaGamma " << sg << " out of range."
                << " Valid range: sigmaGamma [deg] in [0, 90)"
                << exit(FatalIOError);
        }
        sigmaGamma_ = degToRad(sg);
    }
    else
    {
        Rz_ = coeffDict_.get<scalar>("Rz");
        CSurface_ = coeffDict_.get<scalar>("CSurface");

        if (Rz_ <= 0)
        {
            FatalIOErrorInFunction(coeffDict_)
                << "Rz " << Rz_ << " out of range. Valid range: Rz > 0"
                << " (or give sigmaGamma)" << exit(FatalIOError);
        }
        if (CSurface_ <= 0)
        {
            FatalIOErrorInFunction(coeffDict_)
                << "CSurface " << CSurface_ << " out of range."
                << " Valid range: CSurface > 0" << exit(FatalIOError);
        }
        if (grainDiameterFactor_ <= 0)
        {
            FatalIOErrorInFunction(coeffDict_)
                << "grainDiameterFactor " << grainDiameterFactor_
                << " out of range. Valid range: grainDiameterFactor > 0"
                << exit(FatalIOError);
        }
    }

    if (maxResample_ < 1 || maxMultipleImpacts_ < 0)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "maxResample must be >= 1 and maxMultipleImpacts >= 0"
            << exit(FatalIOError);
    }

    Info<< "    sandgrain wall: ";
    if (sigmaGamma_ >= 0)
    {
        Info<< "sigmaGamma " << radToDeg(sigmaGamma_) << " deg (given)";
    }
    else
    {
        Info<< "Rz " << Rz_ << " CSurface " << CSurface_
            << " grainDiameterFactor " << grainDiameterFactor_;
    }
    Info<< ", shadowMode " << shadowModeNames[shadowMode_]
        << ", maxResample " << maxResample_
        << ", maxMultipleImpacts " << maxMultipleImpacts_ << endl;
}


Foam::sandgrainWall::sandgrainWall
(
    const collisionCoefficients& coeffs,
    const scalar Rz,
    const scalar CSurface,
    const scalar grainDiameterFactor,
    const scalar sigmaGamma,
    const shadowModeType shadowMode,
    const label maxResample,
    const label maxMultipleImpacts
)
:
    wallCollisionModel(),
    coeffs_(coeffs),
    Rz_(Rz),
    CSurface_(CSurface),
    grainDiameterFactor_(grainDiameterFactor),
    sigmaGamma_(sigmaGamma),
    shadowMode_(shadowMode),
    maxResample_(maxResample),
    maxMultipleImpacts_(maxMultipleImpacts)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::sandgrainWall::sigmaGamma(const scalar d) const
{
    if (sigmaGamma_ >= 0)
    {
        return sigmaGamma_;
    }

    const scalar D = grainDiameterFactor_*Rz_;

    return asin(D/(D + d))/CSurface_;
}


Foam::vector Foam::sandgrainWall::sampleNormal
(
    const vector& nw,
    const vector& uRel,
    const scalar d,
    keyedRandom& rnd,
    scalar& gamma1,
    scalar& gamma2
) const
{
    gamma1 = 0;
    gamma2 = 0;

    const scalar sigma = sigmaGamma(d);
    const scalar magU = mag(uRel);

    if (sigma <= 0 || magU <= 0)
    {
        return nw;
    }

    // Impact plane: t1 along the tangential relative velocity
    vector t1(uRel - (uRel & nw)*nw);
    scalar magT1 = mag(t1);

    if (magT1 <= SMALL*magU)
    {
        // Normal incidence: a random direction in the wall plane
        vector a(vector(1, 0, 0) - nw.x()*nw);
        if (mag(a) < 0.5)
        {
            a = vector(0, 1, 0) - nw.y()*nw;
        }
        a /= mag(a);
        const vector b(nw ^ a);
        const scalar phi = constant::mathematical::twoPi*rnd.sample01();
        t1 = cos(phi)*a + sin(phi)*b;
        magT1 = 1;
    }
    t1 /= magT1;

    const vector t2(nw ^ t1);

    for (label i = 0; i < maxResample_; ++i)
    {
        const scalar g1 = sigma*rnd.GaussNormal();
        const scalar g2 = sigma*rnd.GaussNormal();

        const vector n1(cos(g1)*nw - sin(g1)*t1);
        const vector n(cos(g2)*n1 + sin(g2)*t2);

        const scalar proj = uRel & n;

        bool accept = (proj < 0);

        if (accept && shadowMode_ == SHADOW_WEIGHTED)
        {
            accept = rnd.sample01() < -proj/magU;
        }

        if (accept)
        {
            gamma1 = g1;
            gamma2 = g2;
            return n;
        }
    }

    return nw;
}


bool Foam::sandgrainWall::impact
(
    const vector& nw,
    const vector& Uw,
    const scalar d,
    vector& U,
    vector& omega,
    keyedRandom& rnd
) const
{
    bool sticking = false;
    scalar g1, g2;

    for (label i = 0; i <= maxMultipleImpacts_; ++i)
    {
        const vector uRel(U - Uw);

        if (i > 0 && (uRel & nw) > 0)
        {
            return sticking;
        }

        const vector n(sampleNormal(nw, uRel, d, rnd, g1, g2));

        if ((uRel & n) >= 0)
        {
            // Moving along the wall: no facet can be hit
            return sticking;
        }

        sticking = smoothWall::smoothImpact(coeffs_, n, Uw, d, U, omega);
    }

    // Still into the wall after the repeated impacts: smooth impact
    if (((U - Uw) & nw) < 0)
    {
        sticking = smoothWall::smoothImpact(coeffs_, nw, Uw, d, U, omega);
    }

    return sticking;
}


// ************************************************************************* //
