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

#include "basicAgglomeratingCloud.H"

#include "makeParcelCloudFunctionObjects.H"
#include "makeParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

#include "SchillerNaumannDragForce.H"
#include "RotationLiftForce.H"
#include "PozorskiApteDispersion.H"
#include "NoHardSphereCollision.H"
#include "HardSphereCollision.H"
#include "ParticleGridPairSearch.H"
#include "InteractionListsPairSearch.H"
#include "BruteForcePairSearch.H"
#include "PhysicalCollisionResolver.H"
#include "GhostCollisionResolver.H"
#include "HardSphereStatistics.H"
#include "NoParticleRotation.H"
#include "FluidTorqueRotation.H"
#include "NoAgglomerateBreakup.H"
#include "AgglomerateBreakup.H"
#include "KeyedPatchInjection.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicAgglomeratingCloud);

// Kinematic sub-models
makeParcelForces(basicAgglomeratingCloud);
makeParcelDispersionModels(basicAgglomeratingCloud);
makeParcelInjectionModels(basicAgglomeratingCloud);
makeParcelPatchInteractionModels(basicAgglomeratingCloud);
makeParcelStochasticCollisionModels(basicAgglomeratingCloud);
makeParcelSurfaceFilmModels(basicAgglomeratingCloud);

// Sub-models of this library
makeParticleForceModelType(SchillerNaumannDragForce, basicAgglomeratingCloud);
makeParticleForceModelType(RotationLiftForce, basicAgglomeratingCloud);
makeDispersionModelType(PozorskiApteDispersion, basicAgglomeratingCloud);
makeCloudFunctionObjectType(HardSphereStatistics, basicAgglomeratingCloud);
makeInjectionModelType(KeyedPatchInjection, basicAgglomeratingCloud);

// The collision stage
makeHardSphereCollisionModel(basicAgglomeratingCloud);
makeHardSphereCollisionModelType
(
    NoHardSphereCollision,
    basicAgglomeratingCloud
);
makeHardSphereCollisionModelType(HardSphereCollision, basicAgglomeratingCloud);

makePairSearch(basicAgglomerateParcel);
makePairSearchType(ParticleGridPairSearch, basicAgglomerateParcel);
makePairSearchType(InteractionListsPairSearch, basicAgglomerateParcel);
makePairSearchType(BruteForcePairSearch, basicAgglomerateParcel);

makeCollisionResolver(basicAgglomerateParcel);
makeCollisionResolverType(PhysicalCollisionResolver, basicAgglomerateParcel);
makeCollisionResolverType(GhostCollisionResolver, basicAgglomerateParcel);

// The particle rotation
makeParticleRotationModel(basicAgglomeratingCloud);
makeParticleRotationModelType(NoParticleRotation, basicAgglomeratingCloud);
makeParticleRotationModelType(FluidTorqueRotation, basicAgglomeratingCloud);

// The agglomerate break-up
makeAgglomerateBreakupModel(basicAgglomeratingCloud);
makeAgglomerateBreakupModelType
(
    NoAgglomerateBreakup,
    basicAgglomeratingCloud
);
// the driver of the break-up family (breakupKernel), selected by the
// model's name
defineNamedTemplateTypeNameAndDebug
(
    Foam::AgglomerateBreakup<Foam::basicAgglomeratingCloud>,
    0
);


// ************************************************************************* //
