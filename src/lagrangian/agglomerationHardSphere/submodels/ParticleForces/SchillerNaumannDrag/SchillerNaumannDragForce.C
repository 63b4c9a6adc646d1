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

#include "SchillerNaumannDragForce.H"
#include "hardSphereInput.H"
#include "particleKernels.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SchillerNaumannDragForce<CloudType>::SchillerNaumannDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, false)
{
    // No coefficients (given as a word, the force gets the list's
    // dictionary; as a dictionary, its own)
    if (dict.dictName() == typeName)
    {
        hardSphereInput::checkKeys(dict, wordList());
    }
}


template<class CloudType>
Foam::SchillerNaumannDragForce<CloudType>::SchillerNaumannDragForce
(
    const SchillerNaumannDragForce& df
)
:
    ParticleForce<CloudType>(df)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::forceSuSp Foam::SchillerNaumannDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    // Sp = mass f_D/tau_p, tau_p = rho_p d^2/(18 mu)
    forceSuSp value(Zero);

    value.Sp() =
        mass*18.0*muc*particleKernels::SchillerNaumannFactor(Re)
       /(p.rho()*sqr(p.d()));

    return value;
}


// ************************************************************************* //
