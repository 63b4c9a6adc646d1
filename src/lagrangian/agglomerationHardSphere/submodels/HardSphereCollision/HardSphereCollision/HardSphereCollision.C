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
#include "hardSphereInput.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCollision<CloudType>::checkParticles() const
{
    if (!kernel_.agglomeration().cohesive())
    {
        return;
    }
    const scalar rho0 = kernel_.material().rho0();

    // Injected particles take the density of constantProperties: it must
    // be the material's too, or the first injection makes particles that a
    // restart refuses
    const scalar rhoInjected = this->owner().constProps().rho0();
    if (mag(rhoInjected - rho0) > 1e-9*rho0)
    {
        FatalIOErrorInFunction(this->owner().particleProperties())
            << "Cloud " << this->owner().name() << ": constantProperties"
            << " rho0 = " << rhoInjected << " (the density of injected"
            << " particles) differs from the material's rho0 = " << rho0
            << " of hardSphereCoeffs: a primary has the material's density"
            << " (the structure model builds agglomerates from rho0); set"
            << " both to the same value" << exit(FatalIOError);
    }

    const bool vsm = kernel_.structure().primaryDensity();
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


template<class CloudType>
Foam::scalar Foam::HardSphereCollision<CloudType>::gather()
{
    scalar dMax, dxMag, mass;
    vector dxMax;
    label nPrimaries;
    tracked_.check(this->owner(), dMax, dxMag, dxMax, mass, nPrimaries);
    // What left the cloud counts as kept (deposits in the stage)
    const cloudMassBalance& balance = this->owner().massBalance();
    this->step_.auditBefore
    (
        mass + balance.lostMass(), nPrimaries + balance.lostPrimaries()
    );

    return search_->checkedDistance
    (
        dMax, dxMag, dxMax, memory_.reach()*dMax, this->owner().name()
    );
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::resolveEvents
(
    const UList<parcelType*>& parcels,
    const UList<point>& x1
)
{
    const label n = parcels.size();
    const scalar dt = this->owner().db().time().deltaTValue();
    const scalar tStart = this->owner().db().time().value() - dt;

    resolver_->startStep();

    for (label a = 0; a < candidates_.nAccepted(); ++a)
    {
        const typename CollisionCandidates<parcelType>::candidate& c =
            candidates_.accepted(a);

        // Every copy of the pair (from the other processor, through another
        // image) at the event's contact time: one geometry for both
        const scalar s = candidates_.acceptedS(a);

        parcelType& pi = *parcels[c.i];
        parcelType* pjReal = c.j < n ? parcels[c.j] : nullptr;
        const parcelType& pj = pjReal ? *pjReal : search_->referred(c.j - n);
        const point& xj1 =
            pjReal ? x1[c.j] : search_->referredPosition(c.j - n);

        const labelPair idI(pi.origProc(), pi.origId());
        const labelPair idJ(pj.origProc(), pj.origId());

        if (resolver_->duplicate(pi, idI, idJ))
        {
            continue;
        }

        // The state of a partner at the contact, on its linear track
        auto atContact = [s](const parcelType& p, const point& x1p)
        {
            return hardSphereState
            (
                p.stage().startPosition() + s*(x1p - p.stage().startPosition()),
                p.U(), p.omega(), p.d(), p.rho(), p.nPrimary()
            );
        };

        event_.set
        (
            idI, atContact(pi, x1[c.i]), idJ, atContact(pj, xj1),
            c.iLow, c.category, s, tStart + s*dt,
            (c.iLow || !pjReal) ? pi.cell() : pjReal->cell()
        );

        resolver_->resolve(event_, pi, pjReal, c.iLow, x1[c.i], xj1, dt);

        // Counted (and logged) once: where the lower-id partner is real
        if (c.iLow || pjReal)
        {
            for (collisionObserver* o : observers_)
            {
                o->observe(event_);
            }
        }
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
    kernel_(this->coeffDict()),
    walls_
    (
        this->coeffDict(), owner.U(), owner.keyedDispersion(),
        owner.massBalance()
    ),
    memory_(this->coeffDict()),
    search_
    (
        PairSearch<parcelType>::New
        (
            this->coeffDict(), owner.mesh(), owner.U().name()
        )
    ),
    oracle_(nullptr),
    resolver_
    (
        CollisionResolver<parcelType>::New(this->coeffDict(), kernel_)
    ),
    candidates_(),
    event_(),
    log_(nullptr),
    observers_()
{
    const dictionary& coeffs = this->coeffDict();

    // Every entry of hardSphereCoeffs is read by one of the parts
    wordList valid({"eventLog"});
    valid.append(encounterMemory::keys());
    valid.append(PairSearch<parcelType>::keys());
    valid.append(CollisionResolver<parcelType>::keys());
    valid.append(hardSphereWallInteraction::keys());
    valid.append(hardSphereCollisionKernel::keys(coeffs));
    hardSphereInput::checkKeys(coeffs, valid);

    if (coeffs.getOrDefault<bool>("pairSearchCheck", false))
    {
        if (search_->type() != "particleGrid")
        {
            FatalIOErrorInFunction(coeffs)
                << "pairSearchCheck checks pairSearch particleGrid (it is "
                << search_->type() << ")" << exit(FatalIOError);
        }
        oracle_ = PairSearch<parcelType>::New
        (
            "bruteForce", coeffs, owner.mesh(), owner.U().name()
        );
    }

    this->step_.setModel(kernel_.agglomeration());
    observers_.append(&this->step_);
    if (coeffs.getOrDefault<bool>("eventLog", false))
    {
        log_.reset
        (
            new collisionEventLog
            (
                owner.mesh(),
                owner.name(),
                kernel_.agglomeration().branchNames()
            )
        );
        observers_.append(log_.get());
    }
    else
    {
        eventLogFiles<collisionEvent>::refuseLaterEvents
        (
            owner.mesh(), owner.name(), "CollisionEvents"
        );
    }

    Info<< "    pairSearch " << search_->type() << ", ";
    resolver_->write(Info);
    Info<< ", ";
    memory_.write(Info);
    Info<< nl << "    ";
    walls_.info(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCollision<CloudType>::collide()
{
    CloudType& cloud = this->owner();
    hardSphereStep& step = this->step_;

    // The parcels in the order their tracks completed, and their end
    // positions from the tracking; the audit's sums before the stage
    const scalar distance = gather();
    const UList<parcelType*>& parcels = tracked_.parcels();
    UList<point>& x1 = tracked_.x1();

    const scalar dt = cloud.db().time().deltaTValue();
    const scalar tStart = cloud.db().time().value() - dt;
    if (oracle_.valid())
    {
        tracked_.checkPositions
        (
            cloud.mesh().bounds().mag(), cloud.name()
        );
        search_->check
        (
            oracle_(), parcels, x1, distance, memory_.reach(), cloud.name()
        );
    }
    candidates_.find(parcels, x1, search_(), distance, memory_, tStart, dt);

    candidates_.select(resolver_->onePerParticle());
    if (Pstream::master())
    {
        step.counts[hardSphereStep::SUPPRESSED] += candidates_.nSuppressed();
        step.counts[hardSphereStep::SKIP_SEPARATING] +=
            candidates_.nSeparating();
    }

    resolveEvents(parcels, x1);

    // Wall contacts at one radius (the agglomerates formed in the step
    // are left to afterRelocation)
    if (walls_.atRadius())
    {
        step.counts[hardSphereStep::WALL] +=
            walls_.contactsAtRadius(parcels, x1, search_(), dt);
    }

    // The end positions are the next step's start positions
    tracked_.finish();

    // The log goes with the written state
    if (log_.valid() && cloud.db().time().writeTime())
    {
        log_->write();
    }
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::resetStep()
{
    HardSphereCollisionModel<CloudType>::resetStep();

    tracked_.reset(this->owner().size());
}


template<class CloudType>
void Foam::HardSphereCollision<CloudType>::trackedTo
(
    parcelType& p,
    const point& x
)
{
    tracked_.append(p, x);
}


template<class CloudType>
bool Foam::HardSphereCollision<CloudType>::hitWall
(
    parcelType& p,
    const polyPatch& pp
)
{
    if (!walls_.handles(pp.index()))
    {
        return false;
    }

    if (walls_.hitCentre(p))
    {
        ++this->step_.counts[hardSphereStep::WALL_CENTRE];
    }

    return true;
}


template<class CloudType>
bool Foam::HardSphereCollision<CloudType>::afterRelocation()
{
    bool relocate = false;

    if (walls_.atRadius())
    {
        this->step_.counts[hardSphereStep::WALL] +=
            walls_.contactsOfFormed
            (
                this->owner(), search_(),
                this->owner().db().time().deltaTValue(), relocate
            );
    }

    return returnReduce(relocate, orOp<bool>());
}


// ************************************************************************* //
