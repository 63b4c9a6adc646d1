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
    const word& cloudName,
    const wordList& branches
)
:
    mesh_(mesh),
    files_
    (
        mesh, cloudName, "CollisionEvents", "collisionEventLog",
        List<wordList>(1, branches)
    ),
    y_(wallDistance(mesh))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::collisionEventLog::folder
(
    const Time& runTime,
    const word& cloudName
)
{
    return
        eventLogFiles<collisionEvent>::folder
        (
            runTime, cloudName, "CollisionEvents"
        );
}


void Foam::collisionEventLog::observe(const collisionEventRecord& event)
{
    collisionEvent e(event);
    e.timeIndex = mesh_.time().timeIndex();
    e.setOutcome(event.outcomePtr());
    e.wallDistance = y_[event.celli];
    files_.append(e);
}


// ************************************************************************* //
