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
#include "breakupCriterion.H"
#include "fvcGrad.H"
#include "hardSphereParcelStage.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
bool Foam::AgglomerateBreakup<CloudType>::anyAgglomerate() const
{
    bool agglomerates = false;
    for (const parcelType& p : this->owner())
    {
        if (p.nPrimary() > 1)
        {
            agglomerates = true;
            break;
        }
    }
    reduce(agglomerates, orOp<bool>());
    return agglomerates;
}


template<class CloudType>
Foam::breakupStresses::load Foam::AgglomerateBreakup<CloudType>::loadOf
(
    parcelType& p,
    trackingData& td,
    const symmTensor& S
) const
{
    // The carrier's fields: cell values [rec, doc/breakup.md 1.1]
    const CloudType& cloud = this->owner();
    const volScalarField* nutPtr =
        cloud.mesh().template findObject<volScalarField>("nut");
    const label celli = p.cell();
    const scalar nu = cloud.mu()[celli]/cloud.rho()[celli];
    const scalar nut = nutPtr ? (*nutPtr)[celli] : 0;

    breakupStresses::load L;
    L.epsilon = breakupCriterion::dissipation(nu, nut, S);
    L.epsilonResolved = breakupCriterion::dissipation(nu, 0, S);
    L.nu = nu;
    L.rhoF = cloud.rho()[celli];
    L.omega = p.omega();
    L.wallImpactSpeed = p.stage().wallImpactSpeed();
    L.dragForce = Zero;
    if (kernel_->needsDrag())
    {
        p.setCellValues(cloud, td);
        L.dragForce = dragForce(p, td);
    }
    return L;
}


template<class CloudType>
void Foam::AgglomerateBreakup<CloudType>::check
(
    trackingData& td,
    stepSurvey& s
)
{
    CloudType& cloud = this->owner();
    const tmp<volTensorField> tgradU(fvc::grad(cloud.U()));
    const Time& runTime = cloud.db().time();

    for (parcelType& p : cloud)
    {
        // Not moved by an event; moved out of a wall: from the target;
        // the partners merged into an agglomerate are gone
        const hardSphereParcelStage& st = p.stage();
        if
        (
            p.nPrimary() < 2
         || !(st.positionKnown() || st.relocating())
         || st.removed()
        )
        {
            continue;
        }

        const symmTensor S(symm(tgradU()[p.cell()]));
        const breakupStresses::load L(loadOf(p, td, S));
        const hardSphereState state
        (
            st.relocating() ? st.relocationTarget() : st.knownPosition(),
            p.U(), p.omega(), p.d(), p.rho(), p.nPrimary()
        );
        const breakupKernel::key k
        {
            p.origProc(), p.origId(), runTime.timeIndex()
        };
        const breakupKernel::verdict v =
            kernel_->check(state, L, runTime.deltaTValue(), k);
        ++s.nChecked;
        s.largest = max(s.largest, v.values[0]);
        if (v.mechanism >= 0 && v.deferred)
        {
            ++s.nDeferred;
            continue;
        }
        if (!v.breaks())
        {
            continue;
        }
        if (debug)
        {
            Pout<< "    break-up of (" << p.origProc() << ' '
                << p.origId() << "): N " << p.nPrimary() << ", "
                << kernel_->mechanisms()[v.mechanism] << ", values "
                << v.values << ", eps " << L.epsilon << " m2/s3, |F_D| "
                << mag(L.dragForce) << " N, |U| " << mag(p.U())
                << " m/s, |omega| " << mag(p.omega()) << " 1/s" << endl;
        }
        breakupEvent e;
        e.timeIndex = k.timeIndex;
        e.mechanism = v.mechanism;
        e.proc = k.origProc;
        e.id = k.origId;
        e.dt = runTime.deltaTValue();
        e.parent = state;
        e.load = L;
        e.S = S;
        e.values = v.values;
        s.parents.append(&p);
        s.events.append(e);
        s.ids.append(labelPair(p.origProc(), p.origId()));
    }
}


// ************************************************************************* //
