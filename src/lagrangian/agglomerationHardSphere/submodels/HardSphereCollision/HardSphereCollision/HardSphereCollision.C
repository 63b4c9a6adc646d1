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

#include "HardSphereCollision.H"
#include "HashSet.H"
#include "cyclicPolyPatch.H"
#include "hardSphereInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::HardSphereCollision<CloudType>::overlapTreatmentType
>
Foam::HardSphereCollision<CloudType>::overlapTreatmentNames
({
    { overlapTreatmentType::OVERLAP_NONE, "none" },
    { overlapTreatmentType::OVERLAP_SEPARATE, "separate" },
});


template<class CloudType>
const Foam::Enum
<
    typename Foam::HardSphereCollision<CloudType>::collisionResponseType
>
Foam::HardSphereCollision<CloudType>::collisionResponseNames
({
    { collisionResponseType::RESPONSE_PHYSICAL, "physical" },
    { collisionResponseType::RESPONSE_GHOST, "ghost" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::HardSphereCollision<CloudType>::readWordOrNumber
(
    const word& key,
    const word& wordName,
    const scalar wordValue,
    const scalar defaultValue,
    const string& meaning
) const
{
    const dictionary& dict = this->coeffDict();

    if (!dict.found(key))
    {
        return defaultValue;
    }

    ITstream& is = dict.lookup(key);
    const token t(is);
    if (t.isWord() && t.wordToken() == wordName)
    {
        return wordValue;
    }
    if (t.isNumber() && t.number() >= 0)
    {
        return t.number();
    }

    FatalIOErrorInFunction(dict)
        << key << " " << t << " is not valid: give " << meaning.c_str()
        << " or " << wordName << exit(FatalIOError);

    return defaultValue;
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::audit
(
    scalar& mass,
    label& nPrimaries
) const
{
    mass = 0;
    nPrimaries = 0;
    for (const parcelType& p : this->owner())
    {
        mass += p.nParticle()*p.mass();
        nPrimaries += p.nPrimary();
    }
    reduce(mass, sumOp<scalar>());
    reduce(nPrimaries, sumOp<label>());
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::checkParticles() const
{
    if (kernel_.agglomeration().type() == "none")
    {
        return;
    }
    const scalar rho0 = kernel_.material().rho0();
    const bool vsm = kernel_.structure().type() == "VSM";
    label i = 0;
    for (const parcelType& p : this->owner())
    {
        if
        (
            (p.nPrimary() == 1 || vsm)
         && mag(p.rho() - rho0) > 1e-9*rho0
        )
        {
            FatalErrorInFunction
                << "Cloud " << this->owner().name() << ": particle " << i
                << " (nPrimary " << p.nPrimary() << ") has rho = "
                << p.rho() << " in "
                << this->owner().time().timeName()/cloud::prefix
                  /this->owner().name()/"rho" << ", but the material of"
                << " hardSphereCoeffs has rho0 = " << rho0 << ": "
                << (vsm ? "under VSM every particle" : "a primary")
                << " has the material's density (the structure model"
                << " builds agglomerates from rho0)" << exit(FatalError);
        }
        ++i;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::HardSphereCollision<CloudType>::HardSphereCollision
(
    const dictionary& dict,
    CloudType& owner
)
:
    HardSphereCollisionModel<CloudType>(dict, owner, typeName),
    overlapTreatment_
    (
        overlapTreatmentNames.getOrDefault
        (
            "overlapTreatment", this->coeffDict(), OVERLAP_NONE
        )
    ),
    encounterMemory_
    (
        readWordOrNumber
        (
            "encounterMemory", "unlimited", VGREAT, VGREAT,
            "a time >= 0 [s]"
        )
    ),
    encounterRelease_
    (
        readWordOrNumber
        (
            "encounterRelease", "none", -1, 0.1,
            "the relative distance eps >= 0 (the last partner is"
            " forgotten beyond (1 + eps)(r1 + r2))"
        )
    ),
    collisionResponse_
    (
        collisionResponseNames.getOrDefault
        (
            "collisionResponse", this->coeffDict(), RESPONSE_PHYSICAL
        )
    ),
    kernel_(this->coeffDict()),
    walls_(this->coeffDict(), owner.U(), owner.keyedDispersion()),
    gridSearch_(nullptr),
    ilSearch_(nullptr),
    bfSearch_(nullptr),
    bfCheck_(nullptr),
    noOccupancy_(),
    schedule_(),
    candidates_(),
    log_(nullptr),
    period_(GREAT, GREAT, GREAT)
{
    setPeriods();

    // Every entry of hardSphereCoeffs is read by this model, the wall
    // interaction or the kernel
    wordList valid
    ({
        "overlapTreatment", "encounterMemory", "encounterRelease",
        "collisionResponse", "interactionDistance", "pairSearch",
        "pairSearchCheck", "eventLog"
    });
    valid.append(hardSphereWallInteraction::keys());
    valid.append(hardSphereCollisionKernel::keys(this->coeffDict()));
    hardSphereInput::checkKeys(this->coeffDict(), valid);

    const word search
    (
        this->coeffDict().template getOrDefault<word>
        (
            "pairSearch", "particleGrid"
        )
    );
    if (search == "particleGrid")
    {
        gridSearch_.reset
        (
            new ParticleGridPairSearch<parcelType>(owner.mesh())
        );
    }
    else if (search == "interactionLists")
    {
        ilSearch_.reset
        (
            new InteractionListsPairSearch<parcelType>
            (
                owner.mesh(),
                owner.U().name(),
                this->coeffDict().template getOrDefault<scalar>
                (
                    "interactionDistance", 0
                )
            )
        );
    }
    else if (search == "bruteForce")
    {
        bfSearch_.reset(new BruteForcePairSearch<parcelType>(owner.mesh()));
    }
    else
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "pairSearch " << search << " is not valid; valid choices:"
            << " (particleGrid interactionLists bruteForce)"
            << exit(FatalIOError);
    }

    const bool check =
        this->coeffDict().template getOrDefault<bool>
        (
            "pairSearchCheck", false
        );
    if (check)
    {
        if (!gridSearch_.valid())
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "pairSearchCheck checks pairSearch particleGrid (it is "
                << search << ")" << exit(FatalIOError);
        }
        bfCheck_.reset(new BruteForcePairSearch<parcelType>(owner.mesh()));
    }

    if
    (
        collisionResponse_ == RESPONSE_GHOST
     && kernel_.agglomeration().type() != "none"
    )
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "collisionResponse ghost counts contacts without"
            << " applying them: set agglomerationModel none (it is "
            << kernel_.agglomeration().type() << ")"
            << exit(FatalIOError);
    }

    if (this->coeffDict().template getOrDefault<bool>("eventLog", false))
    {
        log_.reset(new collisionEventLog(owner.mesh(), owner.name()));
    }

    Info<< "    overlapTreatment "
        << overlapTreatmentNames[overlapTreatment_] << ", ";
    walls_.info(Info);
    Info<< nl << "    collisionResponse "
        << collisionResponseNames[collisionResponse_]
        << ", encounterRelease ";
    if (encounterRelease_ < 0)
    {
        Info<< "none" << endl;
    }
    else
    {
        Info<< encounterRelease_ << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCollision<CloudType>::collide()
{
    CloudType& cloud = this->owner();
    hardSphereStep& step = this->step_;

    audit(step.mass0, step.nPrimaries0);

    const scalar dt = cloud.db().time().deltaTValue();
    const scalar tStart = cloud.db().time().value() - dt;

    // End-of-step positions and the search distance
    const label n = cloud.size();
    List<parcelType*> parcels(n);
    List<point> x1(n);

    scalar dMax = 0;
    scalar dxMag = 0;
    vector dxMax(Zero);
    {
        label i = 0;
        for (parcelType& p : cloud)
        {
            if (p.nParticle() != 1)
            {
                FatalErrorInFunction
                    << "Cloud " << cloud.name() << ": a parcel has"
                    << " nParticle = " << p.nParticle() << "; the"
                    << " hard-sphere cloud needs one particle per parcel"
                    << " (parcelBasisType fixed, nParticle 1)"
                    << exit(FatalError);
            }

            parcels[i] = &p;
            x1[i] = p.position();
            dMax = max(dMax, p.d());
            const vector dx(x1[i] - p.position0());
            dxMag = max(dxMag, mag(dx));
            dxMax = max(dxMax, cmptMag(dx));
            ++i;
        }
    }
    reduce(dMax, maxOp<scalar>());
    reduce(dxMag, maxOp<scalar>());
    reduce(dxMax, maxOp<vector>());

    const bool release = encounterRelease_ >= 0;
    const scalar distance = checkedDistance
    (
        dMax, dxMag, dxMax, (release ? 1 + encounterRelease_ : 1)*dMax
    );


    // Candidate events
    // ~~~~~~~~~~~~~~~~

    schedule_.clear();
    candidates_.clear();
    pairContact pc;

    // Real parcels whose last partner is still within the release distance
    boolList partnerNear(n, false);

    auto evaluate = [&](const label i, const label j)
    {
        const parcelType& pi = *parcels[i];
        const bool jReal = j < n;
        const parcelType& pj = jReal ? *parcels[j] : referred(j - n);
        const point& xj1 = jReal ? x1[j] : referredPosition(j - n);

        const vector dxi(x1[i] - pi.position0());
        const vector dxj(xj1 - pj.position0());
        const scalar R = 0.5*(pi.d() + pj.d());

        if
        (
            release
         && (pi.lastPartner()[1] >= 0 || (jReal && pj.lastPartner()[1] >= 0))
         && magSqr(xj1 - x1[i]) <= sqr((1 + encounterRelease_)*R)
        )
        {
            if (pi.lastPartner() == labelPair(pj.origProc(), pj.origId()))
            {
                partnerNear[i] = true;
            }
            if
            (
                jReal
             && pj.lastPartner() == labelPair(pi.origProc(), pi.origId())
            )
            {
                partnerNear[j] = true;
            }
        }

        if (!pc.find(pi.position0(), dxi, pj.position0(), dxj, R))
        {
            return;
        }

        const collisionSchedule::globalId idI({pi.origProc(), pi.origId()});
        const collisionSchedule::globalId idJ({pj.origProc(), pj.origId()});

        candidate c;
        c.i = i;
        c.j = j;
        c.iLow = collisionSchedule::lessId(idI, idJ);

        const vector xij
        (
            (pj.position0() + pc.s*dxj) - (pi.position0() + pc.s*dxi)
        );
        const scalar mxij = mag(xij);
        const bool separating =
            mxij < VSMALL || ((pj.U() - pi.U()) & (xij/mxij)) >= 0;

        const scalar tc = tStart + pc.s*dt;
        if (pc.overlapStart)
        {
            c.category = hardSphereStep::OVERLAP_START;
        }
        else if
        (
            (
                pi.lastPartner() == labelPair(idJ[0], idJ[1])
             && tc - pi.lastContactTime() <= encounterMemory_
            )
         || (
                pj.lastPartner() == labelPair(idI[0], idI[1])
             && tc - pj.lastContactTime() <= encounterMemory_
            )
        )
        {
            c.category = hardSphereStep::REPEAT;
        }
        else
        {
            c.category = hardSphereStep::FIRST;
        }

        schedule_.append(pc.s, idI, idJ, separating);
        candidates_.append(c);
    };

    // Boxes inflated to cover contacts and the release distance
    const scalar inflate = release ? 1 + encounterRelease_ : 1;
    search(parcels, x1, distance, inflate, evaluate);

    // Forget the last partners that moved beyond the release distance
    // (the categories of this step's events are already set)
    if (release)
    {
        forAll(parcels, i)
        {
            if (!partnerNear[i] && parcels[i]->lastPartnerId() >= 0)
            {
                parcels[i]->lastPartnerProc() = -1;
                parcels[i]->lastPartnerId() = -1;
            }
        }
    }

    // Global order, one event per particle (every event when ghost)
    schedule_.select(collisionResponse_ != RESPONSE_GHOST);
    if (Pstream::master())
    {
        step.counts[hardSphereStep::SUPPRESSED] += schedule_.nSuppressed();
        step.counts[hardSphereStep::SKIP_SEPARATING] +=
            schedule_.nSeparating();
    }

    applyEvents(parcels, x1);

    if (walls_.atRadius())
    {
        wallContacts(parcels, x1);
    }

    // The end positions are the next step's start positions, except for
    // the parcels still to be moved or removed
    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];
        if
        (
            !p.hasStatus(parcelType::RELOCATE)
         && !p.hasStatus(parcelType::REMOVE)
        )
        {
            p.position0() = x1[i];
            p.setStatus(parcelType::POSITION_KNOWN);
        }
    }

    // The log goes with the written state
    if (log_.valid() && cloud.db().time().writeTime())
    {
        log_->write();
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

#include "HardSphereCollisionSearch.C"
#include "HardSphereCollisionApply.C"

// ************************************************************************* //
