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

Description
    The tracking of an AgglomerateParcel: move() (a linear track, or a
    relocation after the collision stage) and trackLinear(), the copy of
    KinematicParcel::move that keeps the tracked position.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::AgglomerateParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    typename TrackCloudType::parcelType& p =
        static_cast<typename TrackCloudType::parcelType&>(*this);

    td.switchProcessor = false;

    switch (td.part())
    {
        case trackingData::tpLinearTrack:
        {
            trackLinear(cloud, td, trackTime);
            break;
        }
        case trackingData::tpRelocate:
        {
            td.keepParticle = true;

            if (!stage_.relocating())
            {
                p.stepFraction() = 1;
                break;
            }

            // Straight line to the target, no forces, no time
            while
            (
                td.keepParticle
             && !td.switchProcessor
             && p.stepFraction() < 1
            )
            {
                const scalar f = 1 - p.stepFraction();
                const vector s = (stage_.relocationTarget() - p.position())/f;

                p.trackToAndHitFace(f*s, f, cloud, td);
            }

            if (!td.switchProcessor)
            {
                stage_.relocated();
            }
            break;
        }
    }

    return td.keepParticle;
}


// A copy, with changes, of KinematicParcel<ParcelType>::move of OpenFOAM
// v1912 (src/lagrangian/intermediate/parcels/Templates/KinematicParcel/
// KinematicParcel.C): the same sub-steps (maxCo limits on time and
// distance, setCellValues, calcDispersion, cellValueSourceCorrection, calc,
// age, postFace, postMove, hitFace), in the same order. What differs:
//   - a parcel completed in an earlier pass of the cloud's move returns at
//     once;
//   - the position is kept in x from the track's own displacement (the
//     fraction trackToFace leaves) instead of being computed with
//     position() at each sub-step, starting from the stage's start
//     position (the last collision stage's end position);
//   - a cyclic face hit moves x with the parcel (translated, or computed
//     again after a rotation);
//   - a completed track reports its end position to the collision model
//     (trackedTo).
// An upgrade of OpenFOAM must compare this function with the new move():
// the upstream function's text (from its last template line to its
// closing brace) has the SHA-256
// 39476cb24516d426b9987a82746ef782dd4bcc7f23074127976d02ae3175121b,
// and tests/setup/test_upstreamCopies.py fails when the installed source
// differs from it.
template<class ParcelType>
template<class TrackCloudType>
bool Foam::AgglomerateParcel<ParcelType>::trackLinear
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    typename TrackCloudType::parcelType& p =
        static_cast<typename TrackCloudType::parcelType&>(*this);
    typename TrackCloudType::parcelType::trackingData& ttd =
        static_cast<typename TrackCloudType::parcelType::trackingData&>(td);

    ttd.switchProcessor = false;
    ttd.keepParticle = true;

    // Completed in an earlier pass of the cloud's move
    if (p.stepFraction() >= 1)
    {
        return true;
    }

    // The position: the start of the step, or, continuing after a
    // processor transfer, computed once
    point x(p.stepFraction() > 0 ? p.position() : stage_.startPosition());

    const cloudSolution& solution = cloud.solution();
    const scalarField& cellLengthScale = cloud.cellLengthScale();
    const scalar maxCo = solution.maxCo();

    while (ttd.keepParticle && !ttd.switchProcessor && p.stepFraction() < 1)
    {
        const point start(x);
        const scalar sfrac = p.stepFraction();

        // Total displacement over the time step
        const vector s(trackTime*p.U());

        // Deviation from the mesh centre for reduced-D cases
        const vector d(p.deviationFromMeshCentre());

        // Fraction of the displacement of this sub-step: time and
        // distance each at most maxCo times the step's and the cell's
        const scalar l = cellLengthScale[p.cell()];
        scalar f = 1 - p.stepFraction();
        f = min(f, maxCo);
        f = min(f, maxCo*l/max(SMALL*l, mag(s)));

        if (p.active())
        {
            // Track to the next face: the part of the displacement not
            // completed is returned
            const vector dx(f*s - d);
            x += (1 - p.trackToFace(dx, f))*dx;
        }
        else
        {
            // Stuck to a wall (a stick interaction): time passes
            p.stepFraction() += f;
        }

        const scalar dt = (p.stepFraction() - sfrac)*trackTime;

        if (dt > ROOTVSMALL)
        {
            p.setCellValues(cloud, ttd);
            p.calcDispersion(cloud, ttd, dt);
            if (solution.cellValueSourceCorrection())
            {
                p.cellValueSourceCorrection(cloud, ttd, dt);
            }
            p.calc(cloud, ttd, dt);
        }

        p.age() += dt;

        if (p.active() && p.onFace())
        {
            cloud.functions().postFace(p, ttd.keepParticle);
        }

        cloud.functions().postMove(p, dt, start, ttd.keepParticle);

        if (p.active() && p.onFace() && ttd.keepParticle)
        {
            // A cyclic patch moves the start position with the parcel: x
            // moves with it (a translation), or is computed again (a
            // rotation)
            const point x0(stage_.startPosition());
            p.hitFace(s, cloud, ttd);
            if (stage_.takeRotated())
            {
                x = p.position();
            }
            else
            {
                x += stage_.startPosition() - x0;
            }
        }
    }

    if (ttd.keepParticle && !ttd.switchProcessor)
    {
        cloud.collision().trackedTo(p, x);
    }

    return ttd.keepParticle;
}


// ************************************************************************* //
