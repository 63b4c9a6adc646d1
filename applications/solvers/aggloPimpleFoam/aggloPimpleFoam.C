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
    aggloPimpleFoam

Group
    grpLagrangianSolvers

Description
    Transient solver for incompressible, laminar or LES flow (PIMPLE) with
    Lagrangian particle clouds, derived from pimpleFoam.

    - Momentum: pimpleFoam plus fvOptions (e.g. meanVelocityForce for a
      constant mass flux) plus the cloud's momentum source
      (1/rhoInf) sum of cloud.SU(U) over the coupled clouds (PSI-cell).
    - Gravity acts on the particles only (constant/g); no body force is
      applied to the fluid.
    - The clouds are evolved once per step, before the PIMPLE loop, with the
      fluid field of the previous step (explicit coupling, as DPMFoam).
    - frozenFlow (PIMPLE dictionary, default no): skip the fluid solve and
      track the particles in the stored velocity field.

    Required fields: U, p (kinematic), the turbulence fields of the
    selected model; constant/transportProperties holds nu and rhoInf;
    constant/<cloud>Properties each cloud.

    Clouds: -cloud name runs one cloud; otherwise, if
    constant/cloudProperties exists, its list
    \verbatim
        clouds (EAMCloud MAMCloud);
    \endverbatim
    names the clouds, which are evolved one after the other in the same
    flow (e.g. one-way coupled clouds with different models sharing one
    LES); an empty list means single-phase flow; otherwise the cloud is
    kinematicCloud.

    couplingScale (optional, in a cloud's solution dictionary, default 1)
    multiplies that cloud's momentum source: a reduced cloud of N/s
    particles then loads the fluid like the N of the full case.

    One solver at a time in a case: a second aggloPimpleFoam started in a
    case where one runs stops with a fatal error naming it (caseLock.H).

    Write now and stop: with -opt-switch stopAtWriteNowSignal=12 (as the
    tutorials' drivers start it), kill -USR2 to the solver (or to mpirun,
    which passes it on) writes the run and stops it within the clouds'
    stopInterval() steps, where it continues exactly (writeNowStep.H).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "basicAgglomeratingCloud.H"
#include "timeNamePrecision.H"
#include "caseLock.H"
#include "purgeWriteQueue.H"
#include "writeNowStep.H"
#include "correctProcessorPatches.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "addSolverOptions.H"

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"

    // One solver at a time in a case (caseLock.H)
    caseLock lock(runTime);

    #include "restoreStartTime.H"

    // purgeWrite removes the writes made before a restart too
    purgeWriteQueue::restore(runTime);
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"

    turbulence->validate();

    // Write now and stop after a step where the run continues exactly
    labelList stopIntervals(clouds.size());
    forAll(clouds, i)
    {
        stopIntervals[i] = clouds[i].stopInterval();
    }
    writeNowStep writeNow(runTime, stopIntervals);

    if (!frozenFlow)
    {
        #include "CourantNo.H"
        #include "setInitialDeltaT.H"
    }

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"

        if (!frozenFlow)
        {
            #include "CourantNo.H"
            #include "setDeltaT.H"
        }

        writeNow.beforeStep();
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Clouds first, on the previous step's flow (explicit coupling)
        mu = laminarTransport.nu()*rhoInfValue;
        forAll(clouds, i)
        {
            clouds[i].evolve();
        }

        if (!frozenFlow)
        {
            #include "fluidStep.H"
        }

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
