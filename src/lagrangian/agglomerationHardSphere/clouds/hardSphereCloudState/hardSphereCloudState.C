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

#include "hardSphereCloudState.H"
#include "localIOdictionary.H"
#include "IOField.H"
#include "Time.H"
#include "cloud.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::word Foam::hardSphereCloudState::recordName
(
    "hardSphereCloudState"
);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::IOobject recordIO
(
    const Foam::polyMesh& mesh,
    const Foam::word& cloudName,
    const Foam::IOobject::readOption r
)
{
    return Foam::IOobject
    (
        Foam::hardSphereCloudState::recordName,
        mesh.time().timeName(),
        "uniform"/Foam::cloud::prefix/cloudName,
        mesh,
        r,
        Foam::IOobject::NO_WRITE,
        false
    );
}


Foam::IOobject fieldIO
(
    const Foam::polyMesh& mesh,
    const Foam::word& cloudName,
    const Foam::word& field
)
{
    return Foam::IOobject
    (
        field,
        mesh.time().timeName(),
        Foam::cloud::prefix/cloudName,
        mesh,
        Foam::IOobject::MUST_READ,
        Foam::IOobject::NO_WRITE,
        false
    );
}


//- True if the file of an IOobject is there (any field type)
bool present(const Foam::IOobject& io)
{
    return
        Foam::isFile(io.objectPath())
     || Foam::isFile(io.objectPath() + ".gz");
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hardSphereCloudState::write
(
    const polyMesh& mesh,
    const word& cloudName,
    const label nParticles,
    const label nPrimaries
)
{
    localIOdictionary record(recordIO(mesh, cloudName, IOobject::NO_READ));
    const string app(getEnv("FOAM_EXECUTABLE"));
    record.add("writer", word(app.empty() ? "OpenFOAM" : app.c_str()));
    record.add("nProcs", Pstream::nProcs());
    record.add("nParticles", nParticles);
    record.add("nParticlesTotal", returnReduce(nParticles, sumOp<label>()));
    record.add("nPrimariesTotal", returnReduce(nPrimaries, sumOp<label>()));
    record.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        mesh.time().writeCompression(),
        true
    );
}


void Foam::hardSphereCloudState::check
(
    const polyMesh& mesh,
    const word& cloudName,
    const label nParticles,
    const label nPrimaries,
    const wordList& fields
)
{
    const Time& time = mesh.time();
    const IOobject io(recordIO(mesh, cloudName, IOobject::MUST_READ));
    const bool here = present(io);

    // The same reductions on every rank before any rank may stop
    const bool anywhere = returnReduce(here, orOp<bool>());
    const label nTotal = returnReduce(nParticles, sumOp<label>());
    const label nPrimTotal = returnReduce(nPrimaries, sumOp<label>());

    wordList missing;
    wordList there;
    for (const word& f : fields)
    {
        (present(fieldIO(mesh, cloudName, f)) ? there : missing).append(f);
    }
    const bool solverTime = isFile(time.timePath()/"uniform"/"time");

    if (!anywhere)
    {
        // Only a solver-written time with the parcel's own fields must
        // have the record: its uniform folder was lost. A time written
        // before the record existed has the cloud's uniform folder
        // (cloudProperties) without it: read as before, with a warning
        const fileName uniformDir
        (
            time.timePath()/"uniform"/cloud::prefix/cloudName
        );
        if (solverTime && there.size() && isDir(uniformDir))
        {
            WarningInFunction
                << "Cloud " << cloudName << " at time " << time.timeName()
                << ": no record " << recordName << " in " << uniformDir
                << " (written by a version without it): the particles"
                << " read are not checked against what was written"
                << endl;
        }
        else if (solverTime && there.size())
        {
            FatalErrorInFunction
                << "Cloud " << cloudName << " at time " << time.timeName()
                << ": the particle fields " << there << " are there but"
                << " the record " << io.objectPath() << " is missing (the"
                << " uniform folder of the cloud was lost or its write cut"
                << " off). Restart from an earlier time, or remove "
                << time.timePath()/cloud::prefix/cloudName
                << " to restart without particles" << exit(FatalError);
        }
        return;
    }
    if (!here)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the record " << io.objectPath() << " is missing on this"
            << " processor while others have it (a processor folder"
            << " incomplete?)" << exit(FatalError);
    }

    const localIOdictionary record(io);
    const label recTotal = record.get<label>("nParticlesTotal");
    const label recPrim = record.get<label>("nPrimariesTotal");

    if (nTotal != recTotal)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": " << nTotal << " particles read, but " << recTotal
            << " were written (" << io.objectPath() << "). A particle file"
            << " of this time is missing or cut off; restart from an"
            << " earlier time" << exit(FatalError);
    }
    if (nParticles > 0 && missing.size())
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the particle fields " << missing << " are missing in "
            << time.timePath()/cloud::prefix/cloudName << " (written: "
            << there << "); without them agglomerates would become"
            << " primaries. Restart from an earlier time"
            << exit(FatalError);
    }
    if (nPrimTotal != recPrim)
    {
        FatalErrorInFunction
            << "Cloud " << cloudName << " at time " << time.timeName()
            << ": the particles read hold " << nPrimTotal << " primaries,"
            << " but " << recPrim << " were written ("
            << io.objectPath() << ")" << exit(FatalError);
    }
}


// ************************************************************************* //
