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

#include "KeyedPatchInjection.H"
#include "keyedRandom.H"
#include "randomStreams.H"
#include "particleIds.H"
#include "hardSphereInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::KeyedPatchInjection<CloudType>::placementType
>
Foam::KeyedPatchInjection<CloudType>::placementNames
({
    { placementType::AREA, "area" },
    { placementType::FLUX, "flux" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The patch named by the entry "patch"; fatal if there is none
Foam::label injectionPatch
(
    const Foam::polyMesh& mesh,
    const Foam::dictionary& dict
)
{
    const Foam::word name(dict.get<Foam::word>("patch"));
    const Foam::label patchi = mesh.boundaryMesh().findPatchID(name);
    if (patchi < 0)
    {
        FatalIOErrorInFunction(dict)
            << "patch " << name << ": no such patch; the patches are "
            << mesh.boundaryMesh().names() << Foam::exit(Foam::FatalIOError);
    }
    return patchi;
}


//- The injector's key from its name (the same on every rank and run)
Foam::label nameKey(const Foam::word& name)
{
    return Foam::label(Foam::string::hash()(name) & 0x7fffffff);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::KeyedPatchInjection<CloudType>::KeyedPatchInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    InjectionModel<CloudType>(dict, owner, modelName, typeName),
    patchi_(injectionPatch(owner.mesh(), this->coeffDict())),
    duration_
    (
        hardSphereInput::getInRange
        (
            this->coeffDict(), "duration",
            hardSphereInput::open(0), hardSphereInput::open(GREAT)
        )
    ),
    parcelsPerSecond_
    (
        hardSphereInput::getInRange
        (
            this->coeffDict(), "parcelsPerSecond",
            hardSphereInput::open(0), hardSphereInput::open(GREAT)
        )
    ),
    placement_(placementNames.get("placement", this->coeffDict())),
    U0_(Zero),
    face_(-1),
    seed_(hardSphereInput::getSeed(this->coeffDict())),
    nameKey_(nameKey(modelName)),
    triangles_(owner.mesh(), patchi_, faceWeights()),
    sizeRnd_(0),
    sizeDistribution_
    (
        distributionModel::New
        (
            this->coeffDict().subDict("sizeDistribution"),
            sizeRnd_
        )
    )
{
    hardSphereInput::checkKeys
    (
        this->coeffDict(),
        {
            "type", "patch", "SOI", "duration", "parcelsPerSecond",
            "placement", "massTotal", "parcelBasisType", "nParticle",
            "randomSeed", "sizeDistribution",
            placement_ == AREA ? "U0" : "placement"
        }
    );
    if (placement_ == AREA)
    {
        this->coeffDict().readEntry("U0", U0_);
    }
    if (!(triangles_.area() > 0))
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Injector " << modelName << ": no inflow through patch "
            << owner.mesh().boundaryMesh()[patchi_].name()
            << " (placement flux needs the carrier to enter there)"
            << exit(FatalIOError);
    }

    // One particle per parcel: a hard-sphere parcel is one particle
    if
    (
        this->parcelBasis_ != InjectionModel<CloudType>::pbFixed
     || this->nParticleFixed_ != 1
    )
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Injector " << modelName << ": a hard-sphere parcel is one"
            << " particle; set parcelBasisType fixed and nParticle 1"
            << exit(FatalIOError);
    }

    duration_ = owner.db().time().userTimeToTime(duration_);
    this->volumeTotal_ = duration_;
}


template<class CloudType>
Foam::KeyedPatchInjection<CloudType>::KeyedPatchInjection
(
    const KeyedPatchInjection<CloudType>& im
)
:
    InjectionModel<CloudType>(im),
    patchi_(im.patchi_),
    duration_(im.duration_),
    parcelsPerSecond_(im.parcelsPerSecond_),
    placement_(im.placement_),
    U0_(im.U0_),
    face_(-1),
    seed_(im.seed_),
    nameKey_(im.nameKey_),
    triangles_(im.triangles_),
    sizeRnd_(im.sizeRnd_),
    sizeDistribution_(im.sizeDistribution_->clone())
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::tmp<Foam::scalarField>
Foam::KeyedPatchInjection<CloudType>::faceWeights() const
{
    const polyPatch& pp = this->owner().mesh().boundaryMesh()[patchi_];
    if (placement_ == AREA)
    {
        return tmp<scalarField>::New(pp.size(), scalar(1));
    }

    // The inflow per area: minus the carrier's velocity along the outward
    // normal, none where it leaves
    const vectorField& Up = this->owner().U().boundaryField()[patchi_];
    return max(-(Up & pp.faceNormals()), scalar(0));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::KeyedPatchInjection<CloudType>::timeEnd() const
{
    return this->SOI_ + duration_;
}


template<class CloudType>
Foam::label Foam::KeyedPatchInjection<CloudType>::parcelsToInject
(
    const scalar time0,
    const scalar time1
)
{
    if (time0 < 0 || time0 >= duration_)
    {
        return 0;
    }

    // floor(rate t) by the time t: the count does not depend on the
    // steps (1e-9: a whole number that round-off left just below)
    const scalar t1 = min(time1, duration_);
    return
        label(floor(parcelsPerSecond_*t1 + 1e-9))
      - label(floor(parcelsPerSecond_*time0 + 1e-9));
}


template<class CloudType>
Foam::scalar Foam::KeyedPatchInjection<CloudType>::volumeToInject
(
    const scalar time0,
    const scalar time1
)
{
    if (time0 < 0 || time0 >= duration_)
    {
        return 0;
    }
    return min(time1, duration_) - time0;
}


template<class CloudType>
void Foam::KeyedPatchInjection<CloudType>::setPositionAndCell
(
    const label parcelI,
    const label,
    const scalar,
    vector& position,
    label& cellOwner,
    label& tetFacei,
    label& tetPti
)
{
    keyedRandom rnd
    (
        seed_, randomStreams::injection, nameKey_, parcelNumber(parcelI),
        0, 0
    );
    const scalar u = rnd.sample01();
    const scalar v = rnd.sample01();
    const scalar w = rnd.sample01();
    const label facei = triangles_.pick(u, v, w, position);

    tetFacei = -1;
    tetPti = -1;
    face_ = facei;
    if (facei < 0)
    {
        // Another rank's face
        cellOwner = -1;
        position = pTraits<vector>::max;
        return;
    }

    // Just inside the domain
    const polyPatch& pp = this->owner().mesh().boundaryMesh()[patchi_];
    const vector& Sf = pp.faceAreas()[facei];
    position -= 1e-6*sqrt(mag(Sf))*Sf/mag(Sf);
    cellOwner = pp.faceCells()[facei];
}


template<class CloudType>
void Foam::KeyedPatchInjection<CloudType>::setProperties
(
    const label parcelI,
    const label,
    const scalar,
    typename CloudType::parcelType& parcel
)
{
    parcel.U() =
        placement_ == AREA
      ? U0_
      : this->owner().U().boundaryField()[patchi_][face_];

    keyedRandom rnd
    (
        seed_, randomStreams::injection, nameKey_, parcelNumber(parcelI),
        1, 0
    );
    sizeRnd_.reset(label(2147483646*rnd.sample01()));
    parcel.d() = sizeDistribution_->sample();

    // The global number of the parcel among all injectors' parcels
    label n = parcelI;
    forAll(this->owner().injectors(), i)
    {
        n += this->owner().injectors()[i].parcelsAddedTotal();
    }
    parcel.origProc() = particleIds::injected;
    parcel.origId() = n;
}


// ************************************************************************* //
