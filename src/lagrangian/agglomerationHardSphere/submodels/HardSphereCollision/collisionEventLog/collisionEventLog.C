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

#include "collisionEventLog.H"
#include "meshWavePatchDistMethod.H"
#include "volFields.H"
#include "wallPolyPatch.H"
#include "OSspecific.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Wall distance of the cell centres (meshWave with wall correction; no
//  fvSchemes entry needed)
Foam::scalarField wallDistance(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const labelHashSet walls
    (
        mesh.boundaryMesh().findPatchIDs<wallPolyPatch>()
    );
    volScalarField y
    (
        IOobject
        (
            "eventLogWallDistance", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedScalar("y", dimLength, GREAT),
        patchDistMethod::patchTypes<scalar>(mesh, walls)
    );
    if (walls.size())
    {
        patchDistMethods::meshWave(mesh, walls, true).correct(y);
    }
    return y.primitiveField();
}

} // End anonymous namespace

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionEventLog::collisionEventLog
(
    const fvMesh& mesh,
    const word& cloudName
)
:
    mesh_(mesh),
    file_
    (
        folder(mesh.time(), cloudName)
       /("events" + Foam::name(Pstream::myProcNo()) + ".bin")
    ),
    buffer_(),
    nWritten_(0),
    y_(wallDistance(mesh))
{
    const fileName dir(folder(mesh.time(), cloudName));
    const label start = mesh.time().timeIndex();
    label removed = 0;
    if (Pstream::master())
    {
        mkDir(dir);
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            if (f.hasExt("bin") && f.startsWith("events"))
            {
                removed += collisionEventFile::truncateAfter(dir/f, start);
            }
        }
    }
    // Every rank appends only after the master has cut the files back;
    // its file exists from the start (an empty log is a log)
    reduce(removed, sumOp<label>());
    mkDir(dir);
    collisionEventFile::append(file_, List<collisionEvent>());

    Info<< "    eventLog: " << dir << " (time index " << start;
    if (removed)
    {
        Info<< "; " << removed << " events after it removed";
    }
    Info<< ")" << endl;
}


Foam::collisionEventLog::~collisionEventLog()
{
    flush();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::collisionEventLog::folder
(
    const Time& runTime,
    const word& cloudName
)
{
    return
        runTime.globalPath()/"postProcessing"
       /(cloudName + "CollisionEvents");
}


void Foam::collisionEventLog::record
(
    const hardSphereState& s1,
    const hardSphereState& s2,
    const labelPair& id1,
    const labelPair& id2,
    const label category,
    const scalar s,
    const label celli,
    const collisionOutcome* outcome
)
{
    const Time& runTime = mesh_.time();
    collisionEvent e;
    e.timeIndex = runTime.timeIndex();
    e.category = category;
    e.setOutcome(outcome);
    e.time = runTime.value() - (1 - s)*runTime.deltaTValue();
    e.proc[0] = id1.first();
    e.id[0] = id1.second();
    e.proc[1] = id2.first();
    e.id[1] = id2.second();
    e.p1 = s1;
    e.p2 = s2;
    e.wallDistance = y_[celli];
    buffer_.append(e);
}


void Foam::collisionEventLog::flush()
{
    if (buffer_.size())
    {
        collisionEventFile::append(file_, buffer_);
        nWritten_ += buffer_.size();
        buffer_.clear();
    }
}


// ************************************************************************* //
