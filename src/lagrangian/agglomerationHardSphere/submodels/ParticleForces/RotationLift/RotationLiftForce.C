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

#include "RotationLiftForce.H"
#include "particleKernels.H"
#include "hardSphereInput.H"
#include "fvcCurl.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum<typename Foam::RotationLiftForce<CloudType>::liftModelType>
Foam::RotationLiftForce<CloudType>::liftModelNames
({
    { liftModelType::OESTERLE_BUI_DINH, "OesterleBuiDinh" },
    { liftModelType::RUBINOW_KELLER, "RubinowKeller" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RotationLiftForce<CloudType>::RotationLiftForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    UName_(this->coeffs().template getOrDefault<word>("U", "U")),
    model_(liftModelNames.get("model", this->coeffs())),
    curlUcInterpPtr_(nullptr),
    nOutOfRange_(0)
{
    hardSphereInput::checkKeys(this->coeffs(), {"model", "U"});

    Info<< "    rotationLift: model " << liftModelNames[model_] << endl;
}


template<class CloudType>
Foam::RotationLiftForce<CloudType>::RotationLiftForce
(
    const RotationLiftForce& lf
)
:
    ParticleForce<CloudType>(lf),
    UName_(lf.UName_),
    model_(lf.model_),
    curlUcInterpPtr_(nullptr),
    nOutOfRange_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RotationLiftForce<CloudType>::cacheFields(const bool store)
{
    // Shared with the stock lift forces: one curl field per step
    static const word fName("curlUcDt");

    const bool fieldExists =
        this->mesh().template foundObject<volVectorField>(fName);

    if (store)
    {
        if (!fieldExists)
        {
            const volVectorField& Uc =
                this->mesh().template lookupObject<volVectorField>(UName_);

            volVectorField* curlUcPtr =
                new volVectorField(fName, fvc::curl(Uc));

            curlUcPtr->store();
        }

        const volVectorField& curlUc =
            this->mesh().template lookupObject<volVectorField>(fName);

        curlUcInterpPtr_.reset
        (
            interpolation<vector>::New
            (
                this->owner().solution().interpolationSchemes(),
                curlUc
            ).ptr()
        );
    }
    else
    {
        curlUcInterpPtr_.clear();

        if (fieldExists)
        {
            volVectorField& curlUc =
                this->mesh().template lookupObjectRef<volVectorField>(fName);

            curlUc.checkOut();
        }

        const label n = returnReduce(nOutOfRange_, sumOp<label>());
        if (n)
        {
            Info<< "    rotationLift: " << n << " evaluations outside the"
                << " validity range Re_p < 140 of the lift coefficient"
                << endl;
        }
        nOutOfRange_ = 0;
    }
}


template<class CloudType>
Foam::forceSuSp Foam::RotationLiftForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    forceSuSp value(Zero);

    const vector curlUc
    (
        curlUcInterpPtr_->interpolate(p.coordinates(), p.currentTetIndices())
    );

    const vector Omega(0.5*curlUc - p.omega());

    if (Re >= 140)
    {
        ++nOutOfRange_;
    }

    value.Su() =
        particleKernels::rotationLift
        (
            td.Uc() - p.U(),
            Omega,
            p.d(),
            td.rhoc(),
            muc,
            model_ == RUBINOW_KELLER
        );

    return value;
}


// ************************************************************************* //
