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

#include "AgglomerateBreakup.H"
#include "hardSphereCollisionKernel.H"
#include "breakupCriterion.H"
#include "fvcGrad.H"
#include "hardSphereStep.H"
#include "hardSphereParcelStage.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::hardSphereCollisionKernel&
Foam::AgglomerateBreakup<CloudType>::collisionOf
(
    const CloudType& owner,
    const word& type
)
{
    const hardSphereCollisionKernel* k = owner.collision().kernel();
    if (!k)
    {
        FatalIOErrorInFunction(owner.subModelProperties())
            << "breakupModel " << type << " in cloud " << owner.name()
            << " needs collisionModel hardSphere: the agglomerates and"
            << " their material are its" << exit(FatalIOError);
    }
    return *k;
}


template<class CloudType>
Foam::agglomerateFragmentation::fragments
Foam::AgglomerateBreakup<CloudType>::splitOf
(
    const breakupEvent& e,
    const label attempt
) const
{
    breakupKernel::verdict v;
    v.mechanism = e.mechanism;
    v.values = e.values;
    return
        kernel_->split
        (
            e.parent, v, e.S, {e.proc, e.id, e.timeIndex}, attempt
        );
}


template<class CloudType>
Foam::scalar Foam::AgglomerateBreakup<CloudType>::split
(
    parcelType& p,
    breakupEvent& e,
    const agglomerateFragmentation::fragments& f
)
{
    e.a = f.a;
    e.b = f.b;

    // Fragment a: a new parcel, a copy of the parent in its cell
    parcelType* q = static_cast<parcelType*>(p.clone().ptr());
    q->origProc() = e.newProc;
    q->origId() = e.newId;
    q->lastPartnerProc() = -1;
    q->lastPartnerId() = -1;

    const auto set = [](parcelType& r, const hardSphereState& s)
    {
        r.U() = s.U;
        r.omega() = s.omega;
        r.d() = s.d;
        r.rho() = s.rho;
        r.nPrimary() = s.nPrimary;
        r.stage().forgetPosition();
        r.stage().relocateTo(s.x);
        r.stage().markFormed();
    };
    set(*q, f.a);
    set(p, f.b);

    this->owner().addParticle(q);

    return f.dKE;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::AgglomerateBreakup<CloudType>::AgglomerateBreakup
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    AgglomerateBreakupModel<CloudType>(dict, owner, type),
    kernel_
    (
        breakupKernel::New(type, this->coeffDict(), collisionOf(owner, type))
    ),
    log_(nullptr),
    columns_(-1, -1)
{
    // The model's columns of the statistics: one per mechanism
    const wordList& mechanisms = kernel_->mechanisms();
    wordList counters(mechanisms.size() + 1);
    forAll(mechanisms, m)
    {
        word name(mechanisms[m]);
        name[0] = toupper(name[0]);
        counters[m] = "nBreakup" + name;
    }
    counters.last() = "nBreakupNoRoom";
    columns_ =
        owner.template lookupObjectRef<hardSphereStep>
        (
            hardSphereStep::typeName
        ).addColumns(counters, {"breakupEnergyChange"});

    Info<< "    agglomerate break-up: " << type << " (doc/breakup.md), ";
    kernel_->write(Info);
    Info<< endl;

    if (this->coeffDict().template getOrDefault<bool>("eventLog", false))
    {
        log_.reset
        (
            new eventLogFiles<breakupEvent>
            (
                owner.mesh(), owner.name(), "BreakupEvents",
                "breakupEventLog",
                List<wordList>({mechanisms, wordList(1, type),
                                kernel_->fields()})
            )
        );
    }
    else
    {
        eventLogFiles<breakupEvent>::refuseLaterEvents
        (
            owner.mesh(), owner.name(), "BreakupEvents"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::AgglomerateBreakup<CloudType>::report
(
    const stepSurvey& s,
    labelList nEvents,
    scalar dKE
)
{
    // The statistics' columns (local: the statistics sum over the ranks)
    hardSphereStep& step =
        this->owner().template lookupObjectRef<hardSphereStep>
        (
            hardSphereStep::typeName
        );
    forAll(nEvents, m)
    {
        step.counts[columns_.first() + m] += nEvents[m];
    }
    step.counts[columns_.first() + nEvents.size()] += s.nNoRoom;
    step.sums[columns_.second()] += dKE;

    label nDeferred = s.nDeferred;
    label nNoRoom = s.nNoRoom;
    label nChecked = s.nChecked;
    scalar largest = s.largest;
    Pstream::listCombineGather(nEvents, plusEqOp<label>());
    Pstream::listCombineScatter(nEvents);
    reduce(dKE, sumOp<scalar>());
    reduce(nDeferred, sumOp<label>());
    reduce(nNoRoom, sumOp<label>());
    reduce(nChecked, sumOp<label>());
    reduce(largest, maxOp<scalar>());

    const wordList& mechanisms = kernel_->mechanisms();
    Info<< "    Break-up: " << sum(nEvents) << " events (";
    forAll(nEvents, m)
    {
        Info<< (m ? ", " : "") << mechanisms[m] << ' ' << nEvents[m];
    }
    Info<< ")";
    if (kernel_->defers())
    {
        Info<< ", deferred by the rate " << nDeferred;
    }
    Info<< ", waiting for room " << nNoRoom;
    // How near the agglomerates that hold came to breaking: the largest
    // first value the model declares (stressThreshold: the ratio of the
    // load to the strength)
    Info<< ", " << nChecked << " agglomerates checked";
    if (nChecked && !kernel_->fields().empty())
    {
        Info<< ", largest " << kernel_->fields()[0] << ' ' << largest;
    }
    Info<< ", fragment ids handed out " << this->ids_.next()
        << ", kinetic energy change " << dKE << " J" << endl;
}


template<class CloudType>
void Foam::AgglomerateBreakup<CloudType>::breakup(trackingData& td)
{
    // The agglomerates that break, checked once each after the step's
    // collisions and agglomerations (doc/breakup.md 4.1: the state a
    // collision or an agglomeration left, at the end position of the
    // stage or the target of its relocation); none unless an agglomerate
    // is there on some rank (the velocity gradient is collective across
    // processor patches)
    stepSurvey s;
    if (anyAgglomerate())
    {
        check(td, s);
    }

    // Their fragments among the neighbours (doc/breakup.md 3.2)
    place(s);

    // The new parcels' global ids (collective), the splits, the log
    const labelList newIds(this->ids_.assign(s.ids));
    labelList nEvents(kernel_->mechanisms().size(), Zero);
    scalar dKE = 0;
    forAll(s.parents, i)
    {
        breakupEvent& e = s.events[i];
        e.newProc = fragmentIds::origProc;
        e.newId = newIds[i];
        dKE += split(*s.parents[i], e, s.fragments[i]);
        ++nEvents[e.mechanism];
        if (log_.valid())
        {
            log_->append(e);
        }
    }

    // The log goes with the written state
    if (log_.valid() && this->owner().db().time().writeTime())
    {
        log_->write();
    }

    report(s, nEvents, dKE);
}


// ************************************************************************* //
