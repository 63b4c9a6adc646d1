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

#include "ParticleRotationModel.H"
#include "fvcCurl.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ParticleRotationModel<CloudType>::ParticleRotationModel
(
    CloudType& owner
)
:
    CloudSubModelBase<CloudType>(owner)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::ParticleRotationModel<CloudType>::storeVorticity() const
{
    const fvMesh& mesh = this->owner().mesh();
    if
    (
        !needsVorticity()
     || mesh.template foundObject<volVectorField>(vorticityName())
    )
    {
        return false;
    }

    volVectorField* curlUcPtr = new volVectorField
    (
        IOobject
        (
            vorticityName(),
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        fvc::curl(this->owner().U())
    );
    curlUcPtr->store();

    return true;
}


template<class CloudType>
void Foam::ParticleRotationModel<CloudType>::releaseVorticity
(
    const bool stored
) const
{
    const fvMesh& mesh = this->owner().mesh();
    if
    (
        stored
     && mesh.template foundObject<volVectorField>(vorticityName())
    )
    {
        mesh.template lookupObjectRef<volVectorField>(vorticityName())
            .checkOut();
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

#include "ParticleRotationModelNew.C"

// ************************************************************************* //
