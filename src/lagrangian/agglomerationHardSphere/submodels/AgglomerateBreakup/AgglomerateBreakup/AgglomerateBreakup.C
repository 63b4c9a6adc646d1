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
Foam::vector Foam::AgglomerateBreakup<CloudType>::dragForce
(
    parcelType& p,
    trackingData& td
) const
{
    // The velocity seen: the carrier velocity as in the tracking plus the
    // SGS velocity of the dispersion model
    td.Uc() += p.UTurb();

    const scalar dt = this->owner().db().time().deltaTValue();
    const forceSuSp F =
        this->owner().forces().calcCoupled
        (
            p, td, dt, p.mass(), p.Re(td), td.muc()
        );

    // The part linear in the slip: the drag laws' implicit coefficient
    return F.Sp()*(td.Uc() - p.U());
}


template<class CloudType>
Foam::scalar Foam::AgglomerateBreakup<CloudType>::split
(
    parcelType& p,
    breakupEvent& e
)
{
    breakupKernel::verdict v;
    v.mechanism = e.mechanism;
    v.values = e.values;
    const agglomerateFragmentation::fragments f =
        kernel_->split(e.parent, v, e.S, {e.proc, e.id, e.timeIndex});
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
    wordList counters(mechanisms.size());
    forAll(counters, m)
    {
        word name(mechanisms[m]);
        name[0] = toupper(name[0]);
        counters[m] = "nBreakup" + name;
    }
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
void Foam::AgglomerateBreakup<CloudType>::breakup(trackingData& td)
{
    CloudType& cloud = this->owner();
    const fvMesh& mesh = cloud.mesh();

    // The velocity gradient only if an agglomerate is there on some rank
    // (the gradient is collective across processor patches)
    bool agglomerates = false;
    for (const parcelType& p : cloud)
    {
        if (p.nPrimary() > 1)
        {
            agglomerates = true;
            break;
        }
    }
    reduce(agglomerates, orOp<bool>());

    // The carrier's fields: cell values [rec, doc/breakup.md 1.1]
    const tmp<volTensorField> tgradU
    (
        agglomerates ? fvc::grad(cloud.U()) : tmp<volTensorField>()
    );
    const volScalarField* nutPtr =
        mesh.template findObject<volScalarField>("nut");
    const volScalarField& rho = cloud.rho();
    const volScalarField& mu = cloud.mu();

    // The agglomerates that break, checked once each after the step's
    // collisions and agglomerations (doc/breakup.md 4.1: the state a
    // collision or an agglomeration left, at the end position of the
    // stage or the target of its relocation); the partners merged into
    // an agglomerate are gone
    const Time& runTime = cloud.db().time();
    DynamicList<parcelType*> parents;
    DynamicList<breakupEvent> events;
    DynamicList<labelPair> ids;
    label nDeferred = 0;
    label nChecked = 0;
    scalar largest = -GREAT;        // the verdicts' largest first value
    for (parcelType& p : cloud)
    {
        // Not moved by an event; moved out of a wall: from the target
        const hardSphereParcelStage& st = p.stage();
        if
        (
            !agglomerates
         || p.nPrimary() < 2
         || !(st.positionKnown() || st.relocating())
         || st.removed()
        )
        {
            continue;
        }

        const label celli = p.cell();
        const symmTensor S(symm(tgradU()[celli]));
        const scalar nu = mu[celli]/rho[celli];
        const scalar nut = nutPtr ? (*nutPtr)[celli] : 0;

        breakupStresses::load L;
        L.epsilon = breakupCriterion::dissipation(nu, nut, S);
        L.nu = nu;
        L.rhoF = rho[celli];
        L.omega = p.omega();
        L.wallImpactSpeed = st.wallImpactSpeed();
        L.dragForce = Zero;
        if (kernel_->needsDrag())
        {
            p.setCellValues(cloud, td);
            L.dragForce = dragForce(p, td);
        }

        const hardSphereState s
        (
            st.relocating() ? st.relocationTarget() : st.knownPosition(),
            p.U(), p.omega(), p.d(), p.rho(), p.nPrimary()
        );
        const breakupKernel::key k
        {
            p.origProc(), p.origId(), runTime.timeIndex()
        };
        const breakupKernel::verdict v =
            kernel_->check(s, L, runTime.deltaTValue(), k);
        ++nChecked;
        largest = max(largest, v.values[0]);
        if (v.mechanism >= 0 && v.deferred)
        {
            ++nDeferred;
            continue;
        }
        if (v.breaks())
        {
            if (debug)
            {
                Pout<< "    break-up of (" << p.origProc() << ' '
                    << p.origId() << "): N " << p.nPrimary() << ", "
                    << kernel_->mechanisms()[v.mechanism] << ", values "
                    << v.values << ", eps " << L.epsilon << " m2/s3, |F_D| "
                    << mag(L.dragForce) << " N, |U| " << mag(p.U())
                    << " m/s, |omega| " << mag(p.omega()) << " 1/s"
                    << endl;
            }
            breakupEvent e;
            e.timeIndex = k.timeIndex;
            e.mechanism = v.mechanism;
            e.proc = k.origProc;
            e.id = k.origId;
            e.dt = runTime.deltaTValue();
            e.parent = s;
            e.load = L;
            e.S = S;
            e.values = v.values;
            parents.append(&p);
            events.append(e);
            ids.append(labelPair(p.origProc(), p.origId()));
        }
    }

    // The new parcels' global ids (collective)
    const labelList newIds(this->ids_.assign(ids));

    const wordList& mechanisms = kernel_->mechanisms();
    labelList nEvents(mechanisms.size(), Zero);
    scalar dKE = 0;
    forAll(parents, i)
    {
        breakupEvent& e = events[i];
        e.newProc = fragmentIds::origProc;
        e.newId = newIds[i];
        dKE += split(*parents[i], e);
        ++nEvents[e.mechanism];
        if (log_.valid())
        {
            log_->append(e);
        }
    }

    // The log goes with the written state
    if (log_.valid() && runTime.writeTime())
    {
        log_->write();
    }

    // The statistics' columns (local: the statistics sum over the ranks)
    hardSphereStep& step =
        cloud.template lookupObjectRef<hardSphereStep>
        (
            hardSphereStep::typeName
        );
    forAll(nEvents, m)
    {
        step.counts[columns_.first() + m] += nEvents[m];
    }
    step.sums[columns_.second()] += dKE;

    Pstream::listCombineGather(nEvents, plusEqOp<label>());
    Pstream::listCombineScatter(nEvents);
    reduce(dKE, sumOp<scalar>());
    reduce(nDeferred, sumOp<label>());
    reduce(nChecked, sumOp<label>());
    reduce(largest, maxOp<scalar>());

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


// ************************************************************************* //
