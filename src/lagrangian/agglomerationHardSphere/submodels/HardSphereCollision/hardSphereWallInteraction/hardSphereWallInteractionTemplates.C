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

#include "hardSphereWallInteraction.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
Foam::hardSphereWallInteraction::particle
Foam::hardSphereWallInteraction::wallParticle(ParcelType& p)
{
    return particle
    {
        p.origProc(), p.origId(), p.d(), p.U(), p.omega(), &p.UTurb(), 0,
        p.nPrimary(), p.nParticle()*p.mass(), false
    };
}


template<class ParcelType>
bool Foam::hardSphereWallInteraction::contactAtRadius
(
    ParcelType& p,
    const point& x,
    const PairSearch<ParcelType>& search,
    const scalar dt
) const
{
    particle wp(wallParticle(p));
    bool moved = false;
    point xNew;

    const resultType result =
        contactAtRadius
        (
            x, search.wallFaces(p.cell(), 0.5*p.d()), dt, wp, moved, xNew
        );

    if (result == DEPOSIT)
    {
        p.stage().markRemoved();
        return false;
    }
    if (moved)
    {
        p.stage().relocateTo(xNew);
    }
    if (result == IMPACT)
    {
        p.stage().noteWallImpact(wp.impactSpeed);
    }
    return result == IMPACT;
}


template<class ParcelType>
bool Foam::hardSphereWallInteraction::hitCentre(ParcelType& p) const
{
    particle wp(wallParticle(p));
    const resultType result = hitCentre(p.face(), wp, p.stepFraction());
    if (result == DEPOSIT)
    {
        p.stage().markRemoved();
    }
    else if (result == IMPACT)
    {
        p.stage().noteWallImpact(wp.impactSpeed);
        return true;
    }
    return false;
}


template<class ParcelType>
Foam::label Foam::hardSphereWallInteraction::contactsAtRadius
(
    const UList<ParcelType*>& parcels,
    UList<point>& x1,
    const PairSearch<ParcelType>& search,
    const scalar dt
) const
{
    label nImpacts = 0;
    forAll(parcels, i)
    {
        ParcelType& p = *parcels[i];

        if (p.stage().removed() || p.stage().formed())
        {
            continue;
        }

        // Relocated by an event: from the relocation target
        if (p.stage().relocating())
        {
            x1[i] = p.stage().relocationTarget();
        }

        nImpacts += contactAtRadius(p, x1[i], search, dt);
    }
    return nImpacts;
}


template<class CloudType>
Foam::label Foam::hardSphereWallInteraction::contactsOfFormed
(
    CloudType& cloud,
    const PairSearch<typename CloudType::parcelType>& search,
    const scalar dt,
    bool& relocate
) const
{
    typedef typename CloudType::parcelType parcelType;

    label nImpacts = 0;
    relocate = false;
    for (parcelType& p : cloud)
    {
        if (p.stage().formed())
        {
            // At the relocation target (exact)
            nImpacts +=
                contactAtRadius(p, p.stage().relocationTarget(), search, dt);
            relocate = relocate || p.stage().relocating();
        }
    }
    return nImpacts;
}


// ************************************************************************* //
