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

#include "TrackedParcels.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::TrackedParcels<ParcelType>::reset(const label n)
{
    parcels_.clear();
    x1_.clear();
    parcels_.reserve(n);
    x1_.reserve(n);

    mass_ = 0;
    nPrimaries_ = 0;
    dMax_ = 0;
    dxMag_ = 0;
    dxMax_ = Zero;
    nParticleNotOne_ = 1;
}


template<class ParcelType>
template<class CloudType>
void Foam::TrackedParcels<ParcelType>::check
(
    const CloudType& cloud,
    scalar& dMax,
    scalar& dxMag,
    vector& dxMax,
    scalar& mass,
    label& nPrimaries
) const
{
    // Every parcel's track ends here or on another processor, once
    if (parcels_.size() != cloud.size())
    {
        FatalErrorInFunction
            << "Cloud " << cloud.name() << ": " << parcels_.size()
            << " tracks of the step completed on this processor for "
            << cloud.size() << " parcels" << exit(FatalError);
    }
    if (nParticleNotOne_ != 1)
    {
        FatalErrorInFunction
            << "Cloud " << cloud.name() << ": a parcel has"
            << " nParticle = " << nParticleNotOne_ << "; the"
            << " hard-sphere cloud needs one particle per parcel"
            << " (parcelBasisType fixed, nParticle 1)"
            << exit(FatalError);
    }

    dMax = returnReduce(dMax_, maxOp<scalar>());
    dxMag = returnReduce(dxMag_, maxOp<scalar>());
    dxMax = returnReduce(dxMax_, maxOp<vector>());
    mass = returnReduce(mass_, sumOp<scalar>());
    nPrimaries = returnReduce(nPrimaries_, sumOp<label>());
}


template<class ParcelType>
void Foam::TrackedParcels<ParcelType>::checkPositions
(
    const scalar L,
    const word& cloudName
) const
{
    scalar err = 0;
    forAll(parcels_, i)
    {
        err = max(err, mag(x1_[i] - parcels_[i]->position()));
    }
    reduce(err, maxOp<scalar>());

    if (err > 1e-12*L)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << ": an end position kept by the"
            << " tracking is " << err/L << " (relative to the mesh's"
            << " bounding box) from the particle's position; round-off"
            << " is below 1e-12" << exit(FatalError);
    }
}


template<class ParcelType>
void Foam::TrackedParcels<ParcelType>::finish()
{
    forAll(parcels_, i)
    {
        ParcelType& p = *parcels_[i];
        if (!p.stage().relocating() && !p.stage().removed())
        {
            p.stage().setKnownPosition(x1_[i]);
        }
    }

    parcels_.clear();
    x1_.clear();
}


// ************************************************************************* //
