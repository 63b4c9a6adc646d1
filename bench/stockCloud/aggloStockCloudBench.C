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

Application
    aggloStockCloudBench

Group
    grpBenchmarks

Description
    The baseline of bench/hardSphereCloud.py: OpenFOAM's own
    basicKinematicCloud (KinematicCloud of KinematicParcel, no collisions)
    evolved in the frozen fluid of a case, with the carrier fields built as
    aggloPimpleFoam builds them in frozenFlow mode (U, rhoInf, mu from
    constant/transportProperties). It reads the particles aggloPimpleFoam
    reads (the kinematic fields are a subset of ours) and the cloud's
    <cloud>Properties, and prints the wall-clock time of each cloud step,
    the whole evolve():

        Stock cloud wall-clock time: step 0.123 s

    Usage: aggloStockCloudBench [-cloud name]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "basicKinematicCloud.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Stock basicKinematicCloud in a frozen fluid: the baseline of the"
        " hard-sphere cloud benchmark"
    );
    argList::addOption("cloud", "name", "cloud name (kinematicCloud)");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    volVectorField U
    (
        IOobject
        (
            "U",
            runTime.timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        ),
        mesh
    );

    #include "createPhi.H"

    singlePhaseTransportModel laminarTransport(U, phi);

    const dimensionedScalar rhoInfValue
    (
        "rhoInf",
        dimDensity,
        laminarTransport
    );

    const volScalarField rhoInf
    (
        IOobject("rho", runTime.timeName(), mesh),
        mesh,
        rhoInfValue
    );

    const volScalarField mu
    (
        IOobject("mu", runTime.timeName(), mesh),
        laminarTransport.nu()*rhoInfValue
    );

    const word cloudName(args.get<word>("cloud", "kinematicCloud"));

    basicKinematicCloud cloud(cloudName, rhoInf, U, mu, g);

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;

        clockTime timer;
        cloud.evolve();
        Info<< "    Stock cloud wall-clock time: step "
            << returnReduce(timer.elapsedTime(), maxOp<scalar>()) << " s"
            << endl;

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
