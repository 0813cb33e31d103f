/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

Application
    fbmFoam

Group
    grpIncompressibleSolvers

Description
    Transient solver for incompressible flow of Newtonian fluids with rigid
    bodies treated by the multigrid fictitious boundary method (FBM) on a
    fixed mesh.

    The flow step is pimpleFoam's (PIMPLE, fixed mesh; GAMG for p is set in
    fvSolution). The bodies come from the fbm library (constant/fbmProperties):
    at the start of a time step the bodies that move are advanced with the
    forces of the previous step (explicit coupling, Newton-Euler); their
    velocity is then imposed on the momentum matrix before it is solved and
    before the pressure equation uses it; after the PIMPLE loop their
    hydrodynamic forces and torques are computed (volume integral
    -int sigma . grad(alpha) dV or momentum exchange) and written.
    See src/fbm/bodySystem/bodySystem.H and src/README.md. A continued
    run first checks that its start time is complete (a run killed while
    writing leaves it incomplete): fbm::startTimeCheck.

    \heading Required fields
    \plaintable
        U       | Velocity [m/s]
        p       | Kinematic pressure, p/rho [m2/s2]
    \endplaintable

    \heading Written fields
    \plaintable
        alpha.solid | Solid volume fraction
        U.solid     | Rigid-body velocity where alpha.solid > 0
    \endplaintable

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "bodySystem.H"
#include "predictorExtrapolation.H"
#include "startTimeCheck.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for incompressible flow with rigid bodies by the"
        " fictitious boundary method on a fixed mesh."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    fbm::startTimeCheck::check(runTime);
    #include "createMesh.H"
    #include "initContinuityErrs.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    turbulence->validate();

    // The coupling's stability limit of the first step (fbm::viscousStepLimit)
    fbm.estimateMaxDeltaT(turbulence->nuEff());

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "setDeltaT.H"
        #include "setBodyDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // --- Explicit coupling: move the bodies with the forces of the
        //     last step. A body that reached a wall ends the run without
        //     writing this time: the last written time is the last good one
        if (!fbm.moveBodies())
        {
            break;
        }

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            #include "UEqn.H"

            // --- Pressure corrector loop
            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                turbulence->correct();
            }
        }

        // --- Hydrodynamic forces on the bodies (rigidProjection: the
        //     bodies move here and U takes their rigid motion)
        if (!fbm.correctForces(U, p, turbulence->nuEff()))
        {
            break;
        }

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
