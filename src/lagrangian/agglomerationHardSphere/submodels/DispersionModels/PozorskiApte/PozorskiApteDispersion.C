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

#include "PozorskiApteDispersion.H"
#include "randomStreams.H"
#include "hardSphereInput.H"
#include "particleKernels.H"
#include "keyedRandom.H"
#include "turbulenceModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::PozorskiApteDispersion<CloudType>::kSgsSourceType
>
Foam::PozorskiApteDispersion<CloudType>::kSgsSourceNames
({
    { kSgsSourceType::KSGS_NUT, "nut" },
    { kSgsSourceType::KSGS_TURBULENCEK, "turbulenceK" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PozorskiApteDispersion<CloudType>::PozorskiApteDispersion
(
    const dictionary& dict,
    CloudType& owner
)
:
    DispersionModel<CloudType>(dict, owner, typeName),
    particleKeyedModel(),
    kSgsSource_(kSgsSourceNames.get("kSgsSource", this->coeffDict())),
    Ck_(this->coeffDict().template getOrDefault<scalar>("Ck", 0.094)),
    CT_(this->coeffDict().template getOrDefault<scalar>("CT", 1)),
    betaC_(this->coeffDict().template getOrDefault<scalar>("betaC", 1)),
    seed_(hardSphereInput::getSeed(this->coeffDict(), "seed")),
    wallReflection_(this->coeffDict().template get<bool>("wallReflection")),
    sigmaPtr_(nullptr),
    deltaPtr_(nullptr)
{
    hardSphereInput::checkKeys
    (
        this->coeffDict(),
        {"kSgsSource", "Ck", "CT", "betaC", "seed", "wallReflection"}
    );

    if (Ck_ <= 0 || CT_ <= 0 || betaC_ < 0)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Out of range: Ck " << Ck_ << ", CT " << CT_ << ", betaC "
            << betaC_ << ". Valid ranges: Ck > 0, CT > 0, betaC >= 0"
            << exit(FatalIOError);
    }

    Info<< "    PozorskiApte SGS model: kSgsSource "
        << kSgsSourceNames[kSgsSource_];
    if (kSgsSource_ == KSGS_NUT)
    {
        Info<< " (k_sgs = (nu_t/(Ck Delta))^2, Ck " << Ck_ << ")";
    }
    Info<< ", CT " << CT_ << ", betaC " << betaC_ << ", seed " << seed_
        << ", wallReflection " << wallReflection_ << endl;
}


template<class CloudType>
Foam::PozorskiApteDispersion<CloudType>::PozorskiApteDispersion
(
    const PozorskiApteDispersion& dm
)
:
    DispersionModel<CloudType>(dm),
    particleKeyedModel(dm),
    kSgsSource_(dm.kSgsSource_),
    Ck_(dm.Ck_),
    CT_(dm.CT_),
    betaC_(dm.betaC_),
    seed_(dm.seed_),
    wallReflection_(dm.wallReflection_),
    sigmaPtr_(nullptr),
    deltaPtr_(nullptr)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::PozorskiApteDispersion<CloudType>::cacheFields(const bool store)
{
    if (!store)
    {
        sigmaPtr_.clear();
        deltaPtr_.clear();
        return;
    }

    const fvMesh& mesh = this->owner().mesh();

    const word turbName
    (
        IOobject::groupName
        (
            turbulenceModel::propertiesName,
            this->owner().U().group()
        )
    );

    const turbulenceModel* turb =
        mesh.template findObject<turbulenceModel>(turbName);

    if (!turb)
    {
        FatalErrorInFunction
            << "The PozorskiApte dispersion model needs a turbulence model"
            << " (" << turbName << ") in the mesh database"
            << exit(FatalError);
    }

    deltaPtr_.reset(new scalarField(cbrt(mesh.V().field())));
    const scalarField& delta = deltaPtr_();

    scalarField k;
    if (kSgsSource_ == KSGS_NUT)
    {
        const tmp<volScalarField> tnut(turb->nut());
        k = sqr(tnut().primitiveField()/(Ck_*delta));
    }
    else
    {
        const tmp<volScalarField> tk(turb->k());
        k = tk().primitiveField();
    }

    sigmaPtr_.reset(new scalarField(sqrt(2.0/3.0*max(k, scalar(0)))));
}


template<class CloudType>
Foam::vector Foam::PozorskiApteDispersion<CloudType>::update
(
    const scalar dt,
    const label celli,
    const vector& U,
    const vector& Uc,
    vector& UTurb,
    scalar& tTurb
)
{
    const scalar sigma = sigmaPtr_()[celli];

    if (sigma <= 0)
    {
        // No SGS energy: the resolved velocity; w is kept
        return Uc;
    }

    keyedRandom rnd
    (
        seed_, randomStreams::sgsDispersion, keyProc_, keyId_,
        this->owner().db().time().timeIndex(), keyFraction_
    );

    vector w;
    if (tTurb > 0)
    {
        w = UTurb/tTurb;
    }
    else
    {
        w = vector(rnd.GaussNormal(), rnd.GaussNormal(), rnd.GaussNormal());
    }

    const vector xi(rnd.GaussNormal(), rnd.GaussNormal(), rnd.GaussNormal());

    const scalar tauL = CT_*deltaPtr_()[celli]/sigma;

    w = particleKernels::PozorskiApteStep
    (
        w, Uc - U, sigma, tauL, betaC_, dt, xi
    );

    UTurb = sigma*w;
    tTurb = sigma;

    return Uc + UTurb;
}


// ************************************************************************* //
