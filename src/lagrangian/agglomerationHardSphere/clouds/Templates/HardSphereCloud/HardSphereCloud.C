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

#include "HardSphereCloud.H"
#include "wallPolyPatch.H"
#include "clockTime.H"
#include "hardSphereCloudState.H"
#include "stepPeriod.H"
#include "hardSphereInput.H"
#include "AgglomerateBreakup.H"

// * * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::label
Foam::HardSphereCloud<CloudType>::startPositionInterval = 20;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCloud<CloudType>::setModels()
{
    // The solution dictionary: the entries of v1912's cloudSolution and
    // this cloud's own; a misspelt one stops instead of being ignored
    const dictionary& sd = this->solution().dict();
    hardSphereInput::checkKeys
    (
        sd,
        {
            "active", "coupled", "transient", "cellValueSourceCorrection",
            "maxCo", "deltaTMax", "calcFrequency", "maxTrackTime",
            "sourceTerms", "interpolationSchemes", "integrationSchemes",
            "couplingScale", "cellOrderInterval"
        }
    );
    couplingScale_ = sd.getOrDefault<scalar>("couplingScale", 1);
    if (!(couplingScale_ > 0))
    {
        FatalIOErrorInFunction(sd)
            << "couplingScale = " << couplingScale_ << " in cloud "
            << this->name() << ": it must be > 0 (1: the paper's"
            << " coupling)" << exit(FatalIOError);
    }
    if (couplingScale_ != 1)
    {
        Info<< "Cloud " << this->name() << ": momentum source scaled by"
            << " couplingScale = " << couplingScale_ << endl;
    }

    // The subModels dictionary: the entries of v1912's kinematic cloud and
    // this cloud's own, and the models' <model>Coeffs; a misspelt one
    // (say breakUpModel, which would leave break-up off) stops
    hardSphereInput::checkKeysOrCoeffs
    (
        this->subModelProperties(),
        {
            "particleForces", "injectionModels", "dispersionModel",
            "patchInteractionModel", "stochasticCollisionModel",
            "surfaceFilmModel", "collisionModel", "rotationModel",
            "breakupModel"
        }
    );

    rotationModel_.reset
    (
        ParticleRotationModel<hardSphereCloudType>::New
        (
            this->subModelProperties(),
            *this
        ).ptr()
    );

    keyedDispersion_ =
        dynamic_cast<particleKeyedModel*>(&this->dispersion());

    collisionModel_.reset
    (
        HardSphereCollisionModel<hardSphereCloudType>::New
        (
            this->subModelProperties(),
            *this
        ).ptr()
    );

    // After the collision model, whose material and structure it uses
    breakupModel_.reset
    (
        AgglomerateBreakupModel<hardSphereCloudType>::New
        (
            this->subModelProperties(),
            *this
        ).ptr()
    );
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::sortByCell()
{
    clockTime sortTimer;
    CloudCellOrder<hardSphereCloudType>::sort(*this);
    this->updateCellOccupancy();
    Info<< "    Cloud " << this->name() << ": parcels in cell order ("
        << returnReduce(sortTimer.elapsedTime(), maxOp<scalar>())
        << " s)" << endl;
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::deleteRemoved()
{
    for (parcelType& p : *this)
    {
        if (p.stage().removed())
        {
            this->deleteParticle(p);
        }
    }
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::debugSums(const char* phase) const
{
    if (!HardSphereCollisionModel<hardSphereCloudType>::debug)
    {
        return;
    }
    vector momentum(Zero);
    vector position(Zero);
    for (const parcelType& p : *this)
    {
        momentum += p.mass()*p.U();
        position += p.position();
    }
    reduce(momentum, sumOp<vector>());
    reduce(position, sumOp<vector>());
    const vector source(gSum(this->UTrans().field()));
    Info<< setprecision(17) << "    Sums after " << phase << ": momentum "
        << momentum << ", positions " << position << ", UTrans " << source
        << setprecision(IOstream::defaultPrecision()) << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::HardSphereCloud<CloudType>::HardSphereCloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& mu,
    const dimensionedVector& g,
    bool readFields
)
:
    CloudType(cloudName, rho, U, mu, g, false),
    keyedDispersion_(nullptr),
    massBalance_(this->mesh(), cloudName),
    collisionModel_(nullptr),
    rotationModel_(nullptr),
    breakupModel_(nullptr),
    couplingScale_(1),
    cellOrder_(this->solution().dict(), cloudName),
    trackingTime_(0),
    collisionTime_(0)
{
    if (this->solution().steadyState())
    {
        FatalErrorInFunction
            << "The hard-sphere cloud is transient only"
            << exit(FatalError);
    }

    if (this->solution().active())
    {
        setModels();

        if (readFields)
        {
            parcelType::readFields(*this);
            const label nFragmentIds = hardSphereCloudState::check
            (
                this->mesh(), this->name(), this->size(), nPrimaries(),
                parcelType::ownFieldNames()
            );
            this->deleteLostParticles();
            breakupModel_->restartIds(nFragmentIds);
        }
        collisionModel_->checkParticles();
        massBalance_.start(*this);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::HardSphereCloud<CloudType>::stopInterval() const
{
    // Both schedules' steps
    stepPeriod period;
    period.include(startPositionInterval);
    period.include(cellOrder_.interval());
    return period.steps();
}


template<class CloudType>
Foam::label Foam::HardSphereCloud<CloudType>::nPrimaries() const
{
    label n = 0;
    for (const parcelType& p : *this)
    {
        n += p.nPrimary();
    }
    return n;
}


template<class CloudType>
bool Foam::HardSphereCloud<CloudType>::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    const bool ok = CloudType::writeObject(fmt, ver, cmp, valid);
    massBalance_.write();
    hardSphereCloudState::write
    (
        this->mesh(), this->name(), this->size(), nPrimaries(),
        breakupModel_.valid() && breakupModel_->active()
      ? breakupModel_->nFragmentIds()
      : -1
    );
    return ok;
}


// The step: evolve, motion and its stages
#include "HardSphereCloudEvolve.C"


// ************************************************************************* //
