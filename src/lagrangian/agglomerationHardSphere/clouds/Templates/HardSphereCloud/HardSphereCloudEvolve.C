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
    The step of a HardSphereCloud: evolve() and its motion (the tracking,
    then the collision stage: collisions, break-up, relocations and the
    mass audit), and what a written time prepares for a restart.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::HardSphereCloud<CloudType>::evolve()
{
    // This step ends with a write: its record says that the write began
    // (before any file of the time), so that a write cut off before this
    // cloud's particles are complete is refused on restart
    if (this->db().time().writeTime())
    {
        hardSphereCloudState::begin(this->mesh(), this->name());
    }

    if (this->solution().canEvolve())
    {
        clockTime timer;
        trackingTime_ = 0;
        collisionTime_ = 0;

        // The vorticity for the rotation model and the lift forces
        const bool vorticity = rotationModel_->storeVorticity();

        typename parcelType::trackingData td(*this);

        this->solve(*this, td);

        // A written time is where a restart starts: after the step's
        // statistics (cloud function objects), which so add over the
        // parcels in the order of a step that is not written
        if (this->db().time().writeTime())
        {
            prepareRestart();
        }

        rotationModel_->releaseVorticity(vorticity);

        // Nothing lost or made: in flight + deposited + escaped - injected
        massBalance_.check(*this);
        massBalance_.info(Info);

        // The whole cloud step: nothing hides outside the three timers
        // (the rest: vorticity, injection, forces set-up, sources, cloud
        // function objects, the cloud's info)
        const scalar stepTime = timer.elapsedTime();
        Info<< "    Hard-sphere wall-clock time: tracking "
            << returnReduce(trackingTime_, maxOp<scalar>())
            << " s, collision stage "
            << returnReduce(collisionTime_, maxOp<scalar>())
            << " s, rest of the cloud step "
            << returnReduce
               (
                   stepTime - trackingTime_ - collisionTime_,
                   maxOp<scalar>()
               )
            << " s" << endl;
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::HardSphereCloud<CloudType>::interactions
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    collisionModel_->collide();
    debugSums("collisions");

    deleteRemoved();

    // Break-up of the agglomerates, in the state the collisions left
    breakupModel_->breakup(td);

    // Tracked moves: agglomerates to the centre of mass, particles out of
    // walls, separated partners, fragments
    bool relocate = false;
    for (const parcelType& p : *this)
    {
        if (p.stage().relocating())
        {
            relocate = true;
            break;
        }
    }

    if (returnReduce(relocate, orOp<bool>()))
    {
        td.part() = parcelType::trackingData::tpRelocate;
        CloudType::move(cloud, td, this->db().time().deltaTValue());

        // Agglomerates formed at a wall: out of it from their own place
        // (or deposited there)
        if (collisionModel_->afterRelocation())
        {
            CloudType::move(cloud, td, this->db().time().deltaTValue());
        }
        deleteRemoved();
        td.part() = parcelType::trackingData::tpLinearTrack;
    }

    this->updateCellOccupancy();
    debugSums("relocations");

    // The mass audit of the stage, in every run and build
    collisionModel_->step().auditAfter
    (
        *this, massBalance_.lostMass(), massBalance_.lostPrimaries()
    );
}


template<class CloudType>
void Foam::HardSphereCloud<CloudType>::prepareRestart()
{
    // The next step computes its start positions from the barycentric
    // coordinates, as a restart does, not from the tracked end positions
    // (equal to round-off); the written order, which a restart reads, is
    // the cell order. So a restart continues exactly.
    for (parcelType& p : *this)
    {
        p.stage().forgetPosition();
    }
    if (cellOrder_.interval() > 0)
    {
        sortByCell();
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
    const label timeIndex = this->db().time().timeIndex();

    // Every startPositionInterval steps the start positions come from the
    // coordinates, as after a restart (stopInterval: a run stopped on
    // request after the step before continues exactly)
    if ((timeIndex - 1) % startPositionInterval == 0)
    {
        for (parcelType& p : *this)
        {
            p.stage().forgetPosition();
        }
    }

    // Parcels in cell order, in the list and in memory
    if (cellOrder_.dueAtStart(timeIndex))
    {
        sortByCell();
    }

    clockTime timer;

    // Start-of-step positions: the end positions of the last collision
    // stage where known (position() is expensive), else computed
    for (parcelType& p : *this)
    {
        p.stage().startStep(p);
    }
    collisionModel_->resetStep();

    // Stage 1: motion without interactions
    td.part() = parcelType::trackingData::tpLinearTrack;
    CloudType::motion(cloud, td);

    trackingTime_ = timer.timeIncrement();
    debugSums("tracking");

    // Stage 2: collisions, agglomeration, walls
    if (collisionModel_->active())
    {
        interactions(cloud, td);
    }

    collisionTime_ = timer.timeIncrement();
}


// ************************************************************************* //
