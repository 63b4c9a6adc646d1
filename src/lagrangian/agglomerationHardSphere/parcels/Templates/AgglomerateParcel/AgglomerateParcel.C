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

#include "AgglomerateParcel.H"
#include "cloudMassBalance.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include "particleKeyedModel.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

template<class ParcelType>
Foam::wordList Foam::AgglomerateParcel<ParcelType>::ownFieldNames()
{
    return wordList
    ({
        "omega", "nPrimary", "lastPartnerProc", "lastPartnerId",
        "lastContactTime"
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::AgglomerateParcel<ParcelType>::AgglomerateParcel
(
    const AgglomerateParcel<ParcelType>& p
)
:
    ParcelType(p),
    omega_(p.omega_),
    lastContactTime_(p.lastContactTime_),
    nPrimary_(p.nPrimary_),
    lastPartnerProc_(p.lastPartnerProc_),
    lastPartnerId_(p.lastPartnerId_),
    stage_(p.stage_)
{}


template<class ParcelType>
Foam::AgglomerateParcel<ParcelType>::AgglomerateParcel
(
    const AgglomerateParcel<ParcelType>& p,
    const polyMesh& mesh
)
:
    ParcelType(p, mesh),
    omega_(p.omega_),
    lastContactTime_(p.lastContactTime_),
    nPrimary_(p.nPrimary_),
    lastPartnerProc_(p.lastPartnerProc_),
    lastPartnerId_(p.lastPartnerId_),
    stage_(p.stage_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
void Foam::AgglomerateParcel<ParcelType>::calcDispersion
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar dt
)
{
    particleKeyedModel* keyed = cloud.keyedDispersion();

    if (keyed)
    {
        keyed->setParticleKey
        (
            this->origProc(),
            this->origId(),
            this->stepFraction()
        );
    }

    ParcelType::calcDispersion(cloud, td, dt);
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::AgglomerateParcel<ParcelType>::calc
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar dt
)
{
    ParcelType::calc(cloud, td, dt);

    cloud.rotation().correct
    (
        static_cast<typename TrackCloudType::parcelType&>(*this),
        td,
        dt
    );
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::AgglomerateParcel<ParcelType>::hitPatch
(
    TrackCloudType& cloud,
    trackingData& td
)
{
    typename TrackCloudType::parcelType& p =
        static_cast<typename TrackCloudType::parcelType&>(*this);

    const polyPatch& pp = this->mesh().boundaryMesh()[this->patch()];

    if (td.part() == trackingData::tpRelocate)
    {
        if (polyPatch::constraintType(pp.type()))
        {
            // Processor, cyclic, ...: the generic handling transfers
            return false;
        }

        // A relocation ends at any other boundary
        p.stepFraction() = 1;
        return true;
    }

    if (isA<wallPolyPatch>(pp))
    {
        // The collision model's wall interaction, if it handles the patch;
        // a deposited parcel leaves the cloud
        if (cloud.collision().hitWall(p, pp))
        {
            td.keepParticle = !p.stage().removed();
            return true;
        }

        // Else the stock patch interaction; the SGS velocity seen is
        // reflected like the particle velocity
        const particleKeyedModel* keyed = cloud.keyedDispersion();

        if (keyed && keyed->reflectAtWalls())
        {
            particleKeyedModel::reflect
            (
                p.UTurb(),
                -pp.faceNormals()[pp.whichFace(p.face())]
            );
        }
    }

    // The stock patch interaction: a parcel it removes (escape) enters
    // the cloud's mass balance
    const bool handled = ParcelType::hitPatch(cloud, td);
    if (!td.keepParticle)
    {
        cloud.massBalance().lose
        (
            cloudMassBalance::ESCAPED, pp.index(), pp.whichFace(p.face()),
            p.nPrimary(), p.nParticle()*p.mass()
        );
    }
    return handled;
}


template<class ParcelType>
void Foam::AgglomerateParcel<ParcelType>::transformProperties
(
    const tensor& T
)
{
    ParcelType::transformProperties(T);

    omega_ = transform(T, omega_);
    stage_.transform(T);
}


template<class ParcelType>
void Foam::AgglomerateParcel<ParcelType>::transformProperties
(
    const vector& separation
)
{
    ParcelType::transformProperties(separation);

    // A position moves with the parcel; omega is translation invariant
    stage_.translate(separation);
}


// * * * * * * * * * * * * * * IOStream operators  * * * * * * * * * * * * * //

#include "AgglomerateParcelTracking.C"
#include "AgglomerateParcelIO.C"
#include "AgglomerateParcelPool.C"

// ************************************************************************* //
