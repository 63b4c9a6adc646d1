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

#include "HardSphereCloud.H"
#include "wallPolyPatch.H"
#include "HashSet.H"
#include "clockTime.H"
#include "fvcCurl.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::HardSphereCloud<CloudType>::overlapTreatmentType
>
Foam::HardSphereCloud<CloudType>::overlapTreatmentNames
({
    { overlapTreatmentType::OVERLAP_NONE, "none" },
    { overlapTreatmentType::OVERLAP_SEPARATE, "separate" },
});


template<class CloudType>
const Foam::Enum
<
    typename Foam::HardSphereCloud<CloudType>::wallContactType
>
Foam::HardSphereCloud<CloudType>::wallContactNames
({
    { wallContactType::WALL_RADIUS, "radius" },
    { wallContactType::WALL_CENTRE, "centre" },
});


template<class CloudType>
const Foam::Enum
<
    typename Foam::HardSphereCloud<CloudType>::wallPositionCorrectionType
>
Foam::HardSphereCloud<CloudType>::wallPositionCorrectionNames
({
    { wallPositionCorrectionType::WALLPOS_REFLECT, "reflect" },
    { wallPositionCorrectionType::WALLPOS_NONE, "none" },
});


template<class CloudType>
const Foam::Enum
<
    typename Foam::HardSphereCloud<CloudType>::collisionResponseType
>
Foam::HardSphereCloud<CloudType>::collisionResponseNames
({
    { collisionResponseType::RESPONSE_PHYSICAL, "physical" },
    { collisionResponseType::RESPONSE_GHOST, "ghost" },
});


// * * * * * * * * * * * * * * * Local Helpers * * * * * * * * * * * * * * * //

namespace Foam
{
namespace hardSphereCloudDetail
{

typedef FixedList<label, 2> globalId;
typedef FixedList<label, 4> pairKey;

//- Lexicographic order of two global ids
inline bool lessId(const globalId& a, const globalId& b)
{
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
}

//- A candidate event of this processor
struct candidate
{
    scalar s;               // step fraction of the contact
    label i;                // real parcel index
    label j;                // real parcel index, or -1 if referred
    label refCell;          // referred cell of the partner
    label refIndex;         // index in that referred cell
    globalId lo;            // lower global id of the pair
    globalId hi;            // higher global id of the pair
    label category;         // hardSphereStatistics::categoryType
    bool separating;        // separating in velocity at the contact
};

//- A candidate event as seen by every processor
struct event
{
    scalar s;
    globalId lo;
    globalId hi;
    bool separating;
};

//- Order by (s, lo, hi), the total order of physics.md 6.4
inline bool eventLess(const event& a, const event& b)
{
    if (a.s != b.s) return a.s < b.s;
    if (a.lo != b.lo) return lessId(a.lo, b.lo);
    return lessId(a.hi, b.hi);
}

//- Order by (lo, hi, s), to remove duplicates of a pair
inline bool pairLess(const event& a, const event& b)
{
    if (a.lo != b.lo) return lessId(a.lo, b.lo);
    if (a.hi != b.hi) return lessId(a.hi, b.hi);
    return a.s < b.s;
}

inline pairKey key(const globalId& lo, const globalId& hi)
{
    pairKey k;
    k[0] = lo[0]; k[1] = lo[1]; k[2] = hi[0]; k[3] = hi[1];
    return k;
}

} // End namespace hardSphereCloudDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCloud<CloudType>::setModels()
{
    active_ = hsDict_.get<bool>("active");

    overlapTreatment_ = overlapTreatmentNames.getOrDefault
    (
        "overlapTreatment",
        hsDict_,
        OVERLAP_NONE
    );

    encounterMemory_ = VGREAT;
    if (hsDict_.found("encounterMemory"))
    {
        ITstream& is = hsDict_.lookup("encounterMemory");
        const token t(is);
        if (t.isWord() && t.wordToken() == "unlimited")
        {
            encounterMemory_ = VGREAT;
        }
        else if (t.isNumber() && t.number() >= 0)
        {
            encounterMemory_ = t.number();
        }
        else
        {
            FatalIOErrorInFunction(hsDict_)
                << "encounterMemory " << t << " is not valid: give a time"
                << " >= 0 [s] or unlimited" << exit(FatalIOError);
        }
    }

    encounterRelease_ = 0.1;
    if (hsDict_.found("encounterRelease"))
    {
        ITstream& is = hsDict_.lookup("encounterRelease");
        const token t(is);
        if (t.isWord() && t.wordToken() == "none")
        {
            encounterRelease_ = -1;
        }
        else if (t.isNumber() && t.number() >= 0)
        {
            encounterRelease_ = t.number();
        }
        else
        {
            FatalIOErrorInFunction(hsDict_)
                << "encounterRelease " << t << " is not valid: give the"
                << " relative distance eps >= 0 (the last partner is"
                << " forgotten beyond (1 + eps)(r1 + r2)) or none"
                << exit(FatalIOError);
        }
    }

    collisionResponse_ = collisionResponseNames.getOrDefault
    (
        "collisionResponse",
        hsDict_,
        RESPONSE_PHYSICAL
    );

    {
        const dictionary& rotDict =
            this->particleProperties().subDict("particleRotation");
        rotationActive_ = rotDict.get<bool>("active");
        Info<< "    particleRotation: "
            << (rotationActive_ ? "fluid torque and spin update" : "off")
            << endl;
    }

    keyedDispersion_ =
        dynamic_cast<particleKeyedModel*>(&this->dispersion());

    randomSeed_ = hsDict_.getOrDefault<label>("randomSeed", 0);

    wallContact_ = wallContactNames.getOrDefault
    (
        "wallContact",
        hsDict_,
        WALL_RADIUS
    );

    wallPositionCorrection_ = wallPositionCorrectionNames.getOrDefault
    (
        "wallPositionCorrection",
        hsDict_,
        WALLPOS_REFLECT
    );

    if (active_)
    {
        kernel_.reset(new hardSphereCollisionKernel(hsDict_));

        if
        (
            collisionResponse_ == RESPONSE_GHOST
         && kernel_->agglomeration().type() != "none"
        )
        {
            FatalIOErrorInFunction(hsDict_)
                << "collisionResponse ghost counts contacts without"
                << " applying them: set agglomerationModel none (it is "
                << kernel_->agglomeration().type() << ")"
                << exit(FatalIOError);
        }

        // One wall model per wall patch
        const polyBoundaryMesh& pbm = this->mesh().boundaryMesh();
        wallModels_.setSize(pbm.size());

        const dictionary& wallsDict = hsDict_.subDict("walls");

        forAll(pbm, patchi)
        {
            if (!isA<wallPolyPatch>(pbm[patchi]))
            {
                continue;
            }

            const entry* ePtr =
                wallsDict.findEntry(pbm[patchi].name(), keyType::REGEX);

            if (!ePtr || !ePtr->isDict())
            {
                FatalIOErrorInFunction(wallsDict)
                    << "No wall model for the wall patch "
                    << pbm[patchi].name() << ": add a dictionary entry "
                    << pbm[patchi].name() << " (or a matching regular"
                    << " expression) to walls. Wall models: "
                    << wallCollisionModel::
                       dictionaryConstructorTablePtr_->sortedToc()
                    << exit(FatalIOError);
            }

            Info<< "    Wall patch " << pbm[patchi].name() << ": wallModel "
                << ePtr->dict().get<word>("wallModel") << endl;

            wallModels_.set(patchi, wallCollisionModel::New(ePtr->dict()));
        }

        Info<< "    overlapTreatment "
            << overlapTreatmentNames[overlapTreatment_]
            << ", wallContact " << wallContactNames[wallContact_]
            << ", wallPositionCorrection "
            << wallPositionCorrectionNames[wallPositionCorrection_]
            << nl << "    collisionResponse "
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

    stats_.reset
    (
        new hardSphereStatistics
        (
            this->mesh(),
            this->name(),
            hsDict_.subOrEmptyDict("statistics")
        )
    );
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::checkInteractionLists
(
    const scalar distance
)
{
    if (ilPtr_.valid() && distance <= ilDistance_)
    {
        return;
    }

    // Some headroom so that growing agglomerates do not rebuild every step
    ilDistance_ = max
    (
        1.5*distance,
        hsDict_.getOrDefault<scalar>("interactionDistance", 0)
    );

    Info<< "    Hard-sphere interaction lists, distance " << ilDistance_
        << " m" << endl;

    ilPtr_.reset
    (
        new InteractionLists<parcelType>
        (
            this->mesh(),
            ilDistance_,
            false,
            this->U().name()
        )
    );
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::collide
(
    List<label>& counts,
    scalar& sumDeltaL,
    scalar& energyGain,
    scalarField& colBin,
    scalarField& colFirstBin,
    scalarField& aggBin
)
{
    using namespace hardSphereCloudDetail;
    typedef hardSphereStatistics hs;

    const fvMesh& mesh = this->mesh();
    const scalar dt = this->db().time().deltaTValue();
    const scalar tStart = this->db().time().value() - dt;

    // Cached positions and the search distance
    // ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~

    const label n = this->size();
    List<parcelType*> parcels(n);
    List<point> x1(n);
    labelList cellStart(mesh.nCells() + 1, Zero);

    scalar dMax = 0;
    scalar dxMax = 0;
    {
        label i = 0;
        for (parcelType& p : *this)
        {
            if (p.nParticle() != 1)
            {
                FatalErrorInFunction
                    << "Cloud " << this->name() << ": a parcel has nParticle"
                    << " = " << p.nParticle() << "; the hard-sphere cloud"
                    << " needs one particle per parcel (parcelBasisType"
                    << " fixed, nParticle 1)" << exit(FatalError);
            }

            parcels[i] = &p;
            x1[i] = p.position();
            dMax = max(dMax, p.d());
            dxMax = max(dxMax, mag(x1[i] - p.position0()));
            ++cellStart[p.cell() + 1];
            ++i;
        }
    }
    reduce(dMax, maxOp<scalar>());
    reduce(dxMax, maxOp<scalar>());

    const bool ghost = collisionResponse_ == RESPONSE_GHOST;
    const bool release = encounterRelease_ >= 0;
    checkInteractionLists
    (
        max(dMax + 2*dxMax, (release ? 1 + encounterRelease_ : 1)*dMax)
    );
    InteractionLists<parcelType>& il = ilPtr_();

    // Parcels per cell (counting sort)
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        cellStart[celli + 1] += cellStart[celli];
    }
    labelList cellParcels(n);
    {
        labelList fill(SubList<label>(cellStart, mesh.nCells()));
        forAll(parcels, i)
        {
            cellParcels[fill[parcels[i]->cell()]++] = i;
        }
    }

    // Referred parcels: send now, receive after the real-real search
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    const label startOfRequests = Pstream::nRequests();
    il.sendReferredData(this->cellOccupancy(), pBufs);


    // Candidate events
    // ~~~~~~~~~~~~~~~~

    DynamicList<candidate> candidates;
    pairContact pc;

    // Real parcels whose last partner is still within the release distance
    boolList partnerNear(n, false);

    auto evaluate = [&]
    (
        const label i,
        const parcelType& pj,
        const point& xj1,
        const label j,
        const label refCell,
        const label refIndex
    )
    {
        const parcelType& pi = *parcels[i];
        const vector dxi(x1[i] - pi.position0());
        const vector dxj(xj1 - pj.position0());
        const scalar R = 0.5*(pi.d() + pj.d());

        if
        (
            release
         && (pi.lastPartner()[1] >= 0 || (j >= 0 && pj.lastPartner()[1] >= 0))
         && magSqr(xj1 - x1[i]) <= sqr((1 + encounterRelease_)*R)
        )
        {
            if (pi.lastPartner() == labelPair(pj.origProc(), pj.origId()))
            {
                partnerNear[i] = true;
            }
            if
            (
                j >= 0
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

        const globalId idI({pi.origProc(), pi.origId()});
        const globalId idJ({pj.origProc(), pj.origId()});

        candidate c;
        c.s = pc.s;
        c.i = i;
        c.j = j;
        c.refCell = refCell;
        c.refIndex = refIndex;

        const bool iLow = lessId(idI, idJ);
        c.lo = iLow ? idI : idJ;
        c.hi = iLow ? idJ : idI;

        const vector xij
        (
            (pj.position0() + pc.s*dxj) - (pi.position0() + pc.s*dxi)
        );
        const scalar mxij = mag(xij);
        c.separating =
            mxij < VSMALL || ((pj.U() - pi.U()) & (xij/mxij)) >= 0;

        const scalar tc = tStart + pc.s*dt;
        if (pc.overlapStart)
        {
            c.category = hs::OVERLAP_START;
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
            c.category = hs::REPEAT;
        }
        else
        {
            c.category = hs::FIRST;
        }

        candidates.append(c);
    };

    // Real-real: same cell and the direct interaction list
    const labelListList& dil = il.dil();
    forAll(dil, celli)
    {
        for (label a = cellStart[celli]; a < cellStart[celli + 1]; ++a)
        {
            const label i = cellParcels[a];

            for (label b = a + 1; b < cellStart[celli + 1]; ++b)
            {
                const label j = cellParcels[b];
                evaluate(i, *parcels[j], x1[j], j, -1, -1);
            }

            for (const label cellj : dil[celli])
            {
                for (label b = cellStart[cellj]; b < cellStart[cellj+1]; ++b)
                {
                    const label j = cellParcels[b];
                    evaluate(i, *parcels[j], x1[j], j, -1, -1);
                }
            }
        }
    }

    // Real-referred
    il.receiveReferredData(pBufs, startOfRequests);

    const labelListList& ril = il.ril();
    const List<IDLList<parcelType>>& referred = il.referredParticles();
    List<List<point>> referredX1(ril.size());

    forAll(ril, refCelli)
    {
        const IDLList<parcelType>& refParcels = referred[refCelli];
        referredX1[refCelli].setSize(refParcels.size());

        label refIndex = 0;
        for (const parcelType& pj : refParcels)
        {
            const point xj1(pj.position());
            referredX1[refCelli][refIndex] = xj1;

            for (const label celli : ril[refCelli])
            {
                for (label a = cellStart[celli]; a < cellStart[celli+1]; ++a)
                {
                    evaluate
                    (
                        cellParcels[a], pj, xj1, -1, refCelli, refIndex
                    );
                }
            }
            ++refIndex;
        }
    }

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

    // Referred parcels by index, for applying events
    List<List<const parcelType*>> referredPtrs(ril.size());
    forAll(ril, refCelli)
    {
        referredPtrs[refCelli].setSize(referred[refCelli].size());
        label k = 0;
        for (const parcelType& pj : referred[refCelli])
        {
            referredPtrs[refCelli][k++] = &pj;
        }
    }


    // Global order: gather the events of all processors
    // ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~

    List<scalarList> allEvents(Pstream::nProcs());
    {
        scalarList& mine = allEvents[Pstream::myProcNo()];
        mine.setSize(6*candidates.size());
        forAll(candidates, k)
        {
            const candidate& c = candidates[k];
            mine[6*k] = c.s;
            mine[6*k + 1] = c.lo[0];
            mine[6*k + 2] = c.lo[1];
            mine[6*k + 3] = c.hi[0];
            mine[6*k + 4] = c.hi[1];
            mine[6*k + 5] = c.separating;
        }
    }
    Pstream::gatherList(allEvents);
    Pstream::scatterList(allEvents);

    DynamicList<event> events;
    for (const scalarList& evs : allEvents)
    {
        for (label k = 0; k < evs.size()/6; ++k)
        {
            event e;
            e.s = evs[6*k];
            e.lo = globalId({label(evs[6*k + 1]), label(evs[6*k + 2])});
            e.hi = globalId({label(evs[6*k + 3]), label(evs[6*k + 4])});
            e.separating = evs[6*k + 5] > 0.5;
            events.append(e);
        }
    }

    // One event per pair (the partners of a pair across a processor or
    // cyclic patch see it twice), the earliest
    std::sort(events.begin(), events.end(), pairLess);
    {
        label nUnique = 0;
        forAll(events, k)
        {
            if
            (
                nUnique == 0
             || events[k].lo != events[nUnique - 1].lo
             || events[k].hi != events[nUnique - 1].hi
            )
            {
                events[nUnique++] = events[k];
            }
        }
        events.setSize(nUnique);
    }
    std::sort(events.begin(), events.end(), eventLess);

    // Greedy: at most one event per particle per step
    HashSet<globalId, globalId::Hash<>> taken(2*events.size() + 1);
    HashSet<pairKey, pairKey::Hash<>> accepted(events.size() + 1);

    for (const event& e : events)
    {
        if (e.separating)
        {
            if (Pstream::master()) ++counts[hs::SKIP_SEPARATING];
            continue;
        }
        if (!ghost && (taken.found(e.lo) || taken.found(e.hi)))
        {
            if (Pstream::master()) ++counts[hs::SUPPRESSED];
            continue;
        }
        taken.insert(e.lo);
        taken.insert(e.hi);
        accepted.insert(key(e.lo, e.hi));
    }


    // Apply the accepted events to the real parcels
    // ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~

    collisionOutcome outcome;

    // Profile bins of an event at the contact point, seen from partner 1
    auto binEvent = [&]
    (
        const point& xc1,
        const scalar d1,
        const point& xc2,
        const label category,
        const bool agglomerates
    )
    {
        if (!stats_->profiles())
        {
            return;
        }
        const vector n12((xc2 - xc1)/mag(xc2 - xc1));
        const label b = stats_->bin(xc1 + 0.5*d1*n12);
        if (b >= 0)
        {
            colBin[b] += 1;
            if (category == hs::FIRST)
            {
                colFirstBin[b] += 1;
            }
            if (agglomerates)
            {
                aggBin[b] += 1;
            }
        }
    };

    // Ghost mode: (pair, real side) already counted, against a second
    // periodic image of the same pair
    HashSet<pairKey, pairKey::Hash<>> ghostDone;

    for (const candidate& c : candidates)
    {
        if (c.separating || !accepted.found(key(c.lo, c.hi)))
        {
            continue;
        }

        if (ghost)
        {
            // Count once per pair where the lower-id partner is real;
            // both real partners remember each other
            parcelType& pi = *parcels[c.i];
            parcelType* pjRealPtr = c.j >= 0 ? parcels[c.j] : nullptr;
            const parcelType& pj =
                c.j >= 0
              ? *parcels[c.j]
              : *referredPtrs[c.refCell][c.refIndex];
            const point& xj1 =
                c.j >= 0 ? x1[c.j] : referredX1[c.refCell][c.refIndex];

            const globalId idI({pi.origProc(), pi.origId()});
            const globalId idJ({pj.origProc(), pj.origId()});
            if (!ghostDone.insert(key(idI, idJ)))
            {
                continue;
            }

            const bool iLow = c.lo == idI;
            if (iLow || pjRealPtr)
            {
                ++counts[hs::COL];
                ++counts[hs::COL_FIRST + c.category];

                binEvent
                (
                    pi.position0() + c.s*(x1[c.i] - pi.position0()),
                    pi.d(),
                    pj.position0() + c.s*(xj1 - pj.position0()),
                    c.category,
                    false
                );
            }

            const scalar tc = tStart + c.s*dt;
            pi.lastPartnerProc() = idJ[0];
            pi.lastPartnerId() = idJ[1];
            pi.lastContactTime() = tc;
            if (pjRealPtr)
            {
                pjRealPtr->lastPartnerProc() = idI[0];
                pjRealPtr->lastPartnerId() = idI[1];
                pjRealPtr->lastContactTime() = tc;
            }
            continue;
        }

        parcelType& pi = *parcels[c.i];
        parcelType* pjRealPtr = c.j >= 0 ? parcels[c.j] : nullptr;
        const parcelType& pj =
            c.j >= 0 ? *parcels[c.j] : *referredPtrs[c.refCell][c.refIndex];
        const point& xj1 =
            c.j >= 0 ? x1[c.j] : referredX1[c.refCell][c.refIndex];

        if (pi.hasStatus(parcelType::COLLIDED))
        {
            // The same pair through a second periodic image
            continue;
        }

        const vector dxi(x1[c.i] - pi.position0());
        const vector dxj(xj1 - pj.position0());
        const point xic(pi.position0() + c.s*dxi);
        const point xjc(pj.position0() + c.s*dxj);

        const hardSphereState si
        (
            xic, pi.U(), pi.omega(), pi.d(), pi.rho(), pi.nPrimary()
        );
        const hardSphereState sj
        (
            xjc, pj.U(), pj.omega(), pj.d(), pj.rho(), pj.nPrimary()
        );

        const bool iLow =
            c.lo == globalId({pi.origProc(), pi.origId()});

        const hardSphereState& s1 = iLow ? si : sj;
        const hardSphereState& s2 = iLow ? sj : si;

        kernel_->collide(s1, s2, outcome);

        const scalar tc = tStart + c.s*dt;

        // Counted once: where the lower-id partner is real
        if (iLow || pjRealPtr)
        {
            ++counts[hs::COL];
            ++counts[hs::COL_FIRST + c.category];
            if (outcome.agglomerates)
            {
                ++counts[hs::AGG];
                ++counts[hs::AGG_FIRST + c.category];

                if (outcome.dKEformation > 0)
                {
                    ++counts[hs::ENERGY_GAIN];
                    energyGain += outcome.dKEformation;
                }
            }
            if (outcome.isSticking())
            {
                ++counts[hs::STICKING];
            }
            if (outcome.branch == collisionOutcome::CASE_II)
            {
                ++counts[hs::CASE_II];
                sumDeltaL += outcome.deltaL;
            }
            if (outcome.spinClamped)
            {
                ++counts[hs::SPIN_CLAMPED];
            }
            if
            (
                !outcome.isSticking()
             && outcome.critI
             && outcome.critII
            )
            {
                ++counts[hs::MAM_CRIT_II];
            }

            binEvent(s1.x, s1.d, s2.x, c.category, outcome.agglomerates);
        }

        if (outcome.agglomerates)
        {
            // The lower-id partner becomes the agglomerate at the centre of
            // mass of the end-of-step positions (Eq. 81); the other goes
            const scalar mi = si.mass();
            const scalar mj = sj.mass();
            const point xAg((mi*x1[c.i] + mj*xj1)/(mi + mj));

            auto makeAgglomerate = [&](parcelType& p)
            {
                const hardSphereState& ag = outcome.agglomerate;
                p.U() = ag.U;
                p.omega() = ag.omega;
                p.d() = ag.d;
                p.rho() = ag.rho;
                p.nPrimary() = ag.nPrimary;
                p.lastPartnerProc() = -1;
                p.lastPartnerId() = -1;
                p.lastContactTime() = -GREAT;
                p.position0() = xAg;
                p.setStatus(parcelType::COLLIDED);
                p.setStatus(parcelType::RELOCATE);
            };

            if (iLow)
            {
                makeAgglomerate(pi);
                if (pjRealPtr)
                {
                    pjRealPtr->setStatus(parcelType::COLLIDED);
                    pjRealPtr->setStatus(parcelType::REMOVE);
                }
            }
            else
            {
                pi.setStatus(parcelType::COLLIDED);
                pi.setStatus(parcelType::REMOVE);
                if (pjRealPtr)
                {
                    makeAgglomerate(*pjRealPtr);
                }
            }
            continue;
        }

        // Rebound
        const hardSphereState& newI = iLow ? outcome.p1 : outcome.p2;
        const hardSphereState& newJ = iLow ? outcome.p2 : outcome.p1;

        point xiNew(x1[c.i]);
        point xjNew(xj1);
        if (overlapTreatment_ == OVERLAP_SEPARATE)
        {
            const scalar rest = (1 - c.s)*dt;
            xiNew = xic + rest*newI.U;
            xjNew = xjc + rest*newJ.U;

            const scalar R = 0.5*(pi.d() + pj.d());
            const vector e(xjNew - xiNew);
            const scalar me = mag(e);
            if (me < R && me > VSMALL)
            {
                const scalar delta = R - me;
                const scalar mi = si.mass();
                const scalar mj = sj.mass();
                xiNew -= (mj/(mi + mj))*delta*e/me;
                xjNew += (mi/(mi + mj))*delta*e/me;
            }
        }

        auto rebound = [&]
        (
            parcelType& p,
            const hardSphereState& s,
            const globalId& partner,
            const point& xNew
        )
        {
            p.U() = s.U;
            p.omega() = s.omega;
            p.lastPartnerProc() = partner[0];
            p.lastPartnerId() = partner[1];
            p.lastContactTime() = tc;
            p.setStatus(parcelType::COLLIDED);
            if (overlapTreatment_ == OVERLAP_SEPARATE)
            {
                p.position0() = xNew;
                p.setStatus(parcelType::RELOCATE);
            }
        };

        const globalId idI({pi.origProc(), pi.origId()});
        const globalId idJ({pj.origProc(), pj.origId()});

        rebound(pi, newI, idJ, xiNew);
        if (pjRealPtr)
        {
            rebound(*pjRealPtr, newJ, idI, xjNew);
        }
    }

    // Wall contacts at one radius
    // ~~~~~~~~~~~~~~~~~~~~~~~~~~~

    if (wallContact_ == WALL_RADIUS)
    {
        forAll(parcels, i)
        {
            if (parcels[i]->hasStatus(parcelType::RELOCATE))
            {
                x1[i] = parcels[i]->position0();
            }
        }
        wallContacts(parcels, x1, counts);
    }
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::wallContacts
(
    const UList<parcelType*>& parcels,
    const UList<point>& positions,
    List<label>& counts
)
{
    const fvMesh& mesh = this->mesh();
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    const labelListList& dwfil = ilPtr_().dwfil();
    const scalar dt = this->db().time().deltaTValue();
    const bool reflect = (wallPositionCorrection_ == WALLPOS_REFLECT);

    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];

        if (p.hasStatus(parcelType::REMOVE))
        {
            continue;
        }

        const labelList& wallFaces = dwfil[p.cell()];
        if (wallFaces.empty())
        {
            continue;
        }

        const point& x = positions[i];
        const scalar r = 0.5*p.d();

        // Nearest wall face
        scalar h = GREAT;
        label nearestFace = -1;
        point nearest(Zero);
        for (const label facei : wallFaces)
        {
            const pointHit ph =
                mesh.faces()[facei].nearestPoint(x, mesh.points());

            if (ph.distance() < h)
            {
                h = ph.distance();
                nearestFace = facei;
                nearest = ph.rawPoint();
            }
        }

        if (h >= r)
        {
            continue;
        }

        const label patchi = pbm.whichPatch(nearestFace);
        const polyPatch& pp = pbm[patchi];
        const label patchFacei = pp.whichFace(nearestFace);

        vector nw(x - nearest);
        if (h > SMALL*r)
        {
            nw /= h;
        }
        else
        {
            nw = -pp.faceNormals()[patchFacei];
        }

        const vector& Uw = this->U().boundaryField()[patchi][patchFacei];
        const scalar un = (p.U() - Uw) & nw;

        if (un < 0)
        {
            const vector U0(p.U());
            keyedRandom rnd
            (
                randomSeed_, wallRandomStream, p.origProc(), p.origId(),
                this->db().time().timeIndex(), 2.0
            );
            wallModels_[patchi].impact
            (
                nw, Uw, p.d(), p.U(), p.omega(), rnd
            );
            ++counts[hardSphereStatistics::WALL];

            if (keyedDispersion_ && keyedDispersion_->reflectAtWalls())
            {
                particleKeyedModel::reflect(p.UTurb(), nw);
            }

            if (reflect)
            {
                // Back to the contact, then on with the new velocity
                const scalar tau = min((r - h)/(-un), dt);
                p.position0() = x + tau*(p.U() - U0);
                p.setStatus(parcelType::RELOCATE);
            }
        }
        else if (reflect)
        {
            // Overlapping without approaching: out to one radius
            p.position0() = x + (r - h)*nw;
            p.setStatus(parcelType::RELOCATE);
        }
    }
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::audit
(
    scalar& mass,
    label& nPrimaries
) const
{
    mass = 0;
    nPrimaries = 0;
    for (const parcelType& p : *this)
    {
        mass += p.nParticle()*p.mass();
        nPrimaries += p.nPrimary();
    }
    reduce(mass, sumOp<scalar>());
    reduce(nPrimaries, sumOp<label>());
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::statistics
(
    const List<label>& counts,
    const scalar sumDeltaL,
    const scalar energyGain,
    scalarField& colBin,
    scalarField& colFirstBin,
    scalarField& aggBin,
    const scalar mass0,
    const label nPrimaries0
)
{
    hardSphereStatistics& st = *stats_;

    labelField globalCounts(counts);
    reduce(globalCounts, sumOp<labelField>());
    st.addCounts
    (
        globalCounts,
        returnReduce(sumDeltaL, sumOp<scalar>()),
        returnReduce(energyGain, sumOp<scalar>())
    );

    label nParticles = 0;
    label nPrimaries = 0;
    label nAgglomerates = 0;
    label nPrimariesInAgglomerates = 0;
    label maxPrimaries = 0;
    scalar sumD = 0;
    scalar Dmax = 0;
    scalar mass = 0;

    const bool profiles = st.profiles();
    const label nBins = colBin.size();
    scalarField visits(nBins, Zero);
    scalarField volume(nBins, Zero);
    scalarField sumDBin(nBins, Zero);
    vectorField sumU(nBins, Zero);
    symmTensorField sumUU(nBins, Zero);
    const vectorField& K = st.meanU();

    const bool writeTime = this->db().time().writeTime();
    Map<label> histogram;

    for (const parcelType& p : *this)
    {
        ++nParticles;
        nPrimaries += p.nPrimary();
        if (p.nPrimary() > 1)
        {
            ++nAgglomerates;
            nPrimariesInAgglomerates += p.nPrimary();
            if (writeTime)
            {
                ++histogram(p.nPrimary(), 0);
            }
        }
        maxPrimaries = max(maxPrimaries, p.nPrimary());
        sumD += p.d();
        Dmax = max(Dmax, p.d());
        mass += p.nParticle()*p.mass();

        if (profiles)
        {
            const label b = st.bin(p.position());
            if (b >= 0)
            {
                visits[b] += 1;
                volume[b] += p.nParticle()*p.volume();
                sumDBin[b] += p.d();
                sumU[b] += p.U();
                sumUU[b] += sqr(p.U() - K[b]);
            }
        }
    }

    reduce(nParticles, sumOp<label>());
    reduce(nPrimaries, sumOp<label>());
    reduce(nAgglomerates, sumOp<label>());
    reduce(nPrimariesInAgglomerates, sumOp<label>());
    reduce(maxPrimaries, maxOp<label>());
    reduce(sumD, sumOp<scalar>());
    reduce(Dmax, maxOp<scalar>());
    reduce(mass, sumOp<scalar>());

    // Audit of the collision stage (mass0 < 0: the stage did not run)
    if
    (
        mass0 >= 0
     && (
            nPrimaries != nPrimaries0
         || mag(mass - mass0) > 1e-11*max(mass0, VSMALL)
        )
    )
    {
        if (Cloud<parcelType>::debug)
        {
            FatalErrorInFunction
                << "Particle mass or primaries not conserved by the"
                << " collision stage: mass " << mass0 << " -> " << mass
                << ", primaries " << nPrimaries0 << " -> " << nPrimaries
                << exit(FatalError);
        }
        WarningInFunction
            << "Particle mass or primaries not conserved by the"
            << " collision stage: mass " << mass0 << " -> " << mass
            << ", primaries " << nPrimaries0 << " -> " << nPrimaries
            << endl;
    }

    if (profiles)
    {
        reduce(colBin, sumOp<scalarField>());
        reduce(colFirstBin, sumOp<scalarField>());
        reduce(aggBin, sumOp<scalarField>());
        reduce(visits, sumOp<scalarField>());
        reduce(volume, sumOp<scalarField>());
        reduce(sumDBin, sumOp<scalarField>());
        reduce(sumU, sumOp<vectorField>());
        reduce(sumUU, sumOp<symmTensorField>());

        st.addEventProfiles(colBin, colFirstBin, aggBin);
        st.addParticleProfiles(visits, volume, sumDBin, sumU, sumUU);
    }

    st.writeStep
    (
        this->db().time().value(),
        nParticles,
        nPrimaries,
        nAgglomerates,
        nPrimariesInAgglomerates,
        maxPrimaries,
        nParticles ? sumD/nParticles : 0,
        Dmax,
        mass
    );

    if (writeTime)
    {
        Pstream::mapCombineGather(histogram, plusEqOp<label>());
        Pstream::mapCombineScatter(histogram);
        st.writeTime(histogram);
    }

    const label* c = st.counters().cdata();
    Info<< "    Hard-sphere: nCol " << c[hardSphereStatistics::COL]
        << " (step " << globalCounts[hardSphereStatistics::COL]
        << "), nAgg " << c[hardSphereStatistics::AGG]
        << " (step " << globalCounts[hardSphereStatistics::AGG]
        << "), nWall " << c[hardSphereStatistics::WALL]
        << ", suppressed " << c[hardSphereStatistics::SUPPRESSED]
        << ", particles " << nParticles
        << ", agglomerates " << nAgglomerates << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::HardSphereCloud<CloudType>::HardSphereCloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& mu,
    const dimensionedVector& g,
    bool readFields
)
:
    CloudType(cloudName, rho, U, mu, g, false),
    hsDict_(this->particleProperties().subDict("hardSphereCollision")),
    active_(false),
    overlapTreatment_(OVERLAP_NONE),
    encounterMemory_(VGREAT),
    encounterRelease_(0.1),
    collisionResponse_(RESPONSE_PHYSICAL),
    wallContact_(WALL_RADIUS),
    wallPositionCorrection_(WALLPOS_REFLECT),
    kernel_(nullptr),
    wallModels_(),
    ilPtr_(nullptr),
    ilDistance_(0),
    stats_(nullptr),
    nWallCentre_(0),
    stepIndex_(0),
    rotationActive_(false),
    curlUcPtr_(nullptr),
    curlUcInterpPtr_(nullptr),
    keyedDispersion_(nullptr),
    randomSeed_(0)
{
    if (this->solution().steadyState())
    {
        FatalErrorInFunction
            << "The hard-sphere cloud is transient only"
            << exit(FatalError);
    }

    if (this->solution().active())
    {
        setModels();

        if (readFields)
        {
            parcelType::readFields(*this);
            this->deleteLostParticles();
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCloud<CloudType>::evolve()
{
    if (this->solution().canEvolve())
    {
        typename parcelType::trackingData td(*this);

        // Vorticity for the spin update (injection and motion)
        if (rotationActive_)
        {
            curlUcPtr_.reset
            (
                new volVectorField
                (
                    IOobject
                    (
                        "curlUcDt",
                        this->db().time().timeName(),
                        this->mesh(),
                        IOobject::NO_READ,
                        IOobject::NO_WRITE,
                        false
                    ),
                    fvc::curl(this->U())
                )
            );
            curlUcInterpPtr_.reset
            (
                interpolation<vector>::New
                (
                    this->solution().interpolationSchemes(),
                    curlUcPtr_()
                ).ptr()
            );
        }

        this->solve(*this, td);

        curlUcInterpPtr_.clear();
        curlUcPtr_.clear();
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::HardSphereCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    clockTime timer;

    // Start-of-step positions
    for (parcelType& p : *this)
    {
        p.position0() = p.position();
        p.status() = 0;
    }
    nWallCentre_ = 0;

    // Stage 1: motion without interactions
    td.part() = parcelType::trackingData::tpLinearTrack;
    CloudType::motion(cloud, td);

    const scalar trackingTime = timer.timeIncrement();

    List<label> counts(hardSphereStatistics::N_COUNTERS, Zero);
    scalar sumDeltaL = 0;
    scalar energyGain = 0;
    const label nBins = stats_->profiles() ? stats_->meanU().size() : 0;
    scalarField colBin(nBins, Zero);
    scalarField colFirstBin(nBins, Zero);
    scalarField aggBin(nBins, Zero);

    // Stage 2: collisions, agglomeration, walls; the mass and primaries
    // before it are compared with the statistics pass after it
    scalar mass0 = -1;
    label nPrimaries0 = -1;
    if (active_)
    {
        audit(mass0, nPrimaries0);

        collide(counts, sumDeltaL, energyGain, colBin, colFirstBin, aggBin);
        counts[hardSphereStatistics::WALL_CENTRE] += nWallCentre_;

        // Mark-then-delete
        for (parcelType& p : *this)
        {
            if (p.hasStatus(parcelType::REMOVE))
            {
                this->deleteParticle(p);
            }
        }

        // Tracked moves: agglomerates to the centre of mass, particles out
        // of walls, separated partners
        bool relocate = false;
        for (const parcelType& p : *this)
        {
            if (p.hasStatus(parcelType::RELOCATE))
            {
                relocate = true;
                break;
            }
        }

        if (returnReduce(relocate, orOp<bool>()))
        {
            td.part() = parcelType::trackingData::tpRelocate;
            CloudType::move(cloud, td, this->db().time().deltaTValue());
            td.part() = parcelType::trackingData::tpLinearTrack;
        }

        this->updateCellOccupancy();
    }
    else
    {
        counts[hardSphereStatistics::WALL_CENTRE] += nWallCentre_;
    }

    const scalar collisionTime = timer.timeIncrement();

    statistics
    (
        counts, sumDeltaL, energyGain, colBin, colFirstBin, aggBin,
        mass0, nPrimaries0
    );

    Info<< "    Hard-sphere wall-clock time: tracking "
        << returnReduce(trackingTime, maxOp<scalar>())
        << " s, collision stage "
        << returnReduce(collisionTime, maxOp<scalar>()) << " s" << endl;

    ++stepIndex_;
}


template<class CloudType>
bool Foam::HardSphereCloud<CloudType>::hitWallCentre
(
    parcelType& p,
    const polyPatch& pp
)
{
    if (!active_ || !wallModels_.set(pp.index()))
    {
        return false;
    }

    const label patchFacei = pp.whichFace(p.face());
    const vector nw(-pp.faceNormals()[patchFacei]);
    const vector& Uw = this->U().boundaryField()[pp.index()][patchFacei];

    if (((p.U() - Uw) & nw) < 0)
    {
        keyedRandom rnd
        (
            randomSeed_, wallRandomStream, p.origProc(), p.origId(),
            this->db().time().timeIndex(), p.stepFraction()
        );
        wallModels_[pp.index()].impact
        (
            nw, Uw, p.d(), p.U(), p.omega(), rnd
        );
        ++nWallCentre_;
    }

    return true;
}


// ************************************************************************* //
