/*---------------------------------------------------------------------------*\
    canopyFoam: canopyPimpleFoam.C — transient incompressible PIMPLE solver
    with an immersed-boundary parachute canopy coupled to libcanopy.
-------------------------------------------------------------------------------
Application
    canopyPimpleFoam

Description
    pimpleFoam (incompressible, laminar or turbulent, fvOptions) plus a
    flexible canopy, its suspension lines and payload (libcanopy), coupled
    through immersed-boundary forcing:

        ddt(U) + div(phi, U) - div(R) = -grad(p) + f_IB + S_U,   div(U) = 0,

    where f_IB drives the fluid's velocity at the canopy markers to the
    canopy's own velocity (normal: its motion plus the porous seepage from
    Darcy-Forchheimer; tangential: no slip by default). Each PIMPLE outer
    iteration: momentum predictor, multi-direct forcing, pressure
    correctors, then the structure re-runs the time step from its
    checkpoint with the pressure jump dp = rho (p- - p+) sampled on both
    sides of the canopy; the interface velocity is Aitken-relaxed and the
    outer loop ends when it has converged (strong coupling), or after the
    first structure solve (explicit coupling). nOuterCorrectors in
    fvSolution's PIMPLE dictionary is the maximum number of coupling
    iterations per time step.

    Required fields
        U       | Velocity [m/s]
        p       | Kinematic pressure p/rho [m2/s2]
        <turbulence fields> | As required by the turbulence model

    Required dictionaries
        constant/canopyProperties | the structure and the coupling
                                    (see canopyStructure.H, canopyCoupling.H)
        constant/transportProperties, constant/turbulenceProperties
        system/fvSolution (PIMPLE), system/fvSchemes, system/controlDict

    Divergence
        When the structure's step fails (NaN, runaway speed, implicit
        solve), the canopy leaves the mesh (a marker without a stencil), or
        the coupling has not converged when the outer loop ends (with
        coupling.stopIfNotConverged, the default), the fields and the
        structure are written at the last good time (the start of the
        failed step) and the run stops with the reason.

    Restart
        startFrom latestTime continues from the written fields, the time
        value to every digit (restoreExactTime), the coupling's state
        (<time>/uniform/canopyCoupling: the IB force, the frame, the
        stabiliser's balance, IQN-ILS's columns) and the structure's
        state at that time, bit for bit as if uninterrupted
        (tests/openfoam/restartMatrix).

    Output
        canopyForce (the IB force density, written with the fields);
        postProcessing/canopy/canopy.h5 + .xdmf (the structure, ParaView);
        postProcessing/canopy/<startTime>/canopy.dat (time series).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "canopyPimpleControl.H"
#include "fvOptions.H"
#include "canopyCoupling.H"
#include "cachedReconstruct.H"
#include "pressureFaceGradient.H"
#include "restoreExactTime.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient incompressible PIMPLE solver with an immersed-boundary"
        " parachute canopy coupled to the libcanopy structure."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    restoreExactTime(runTime);
    #include "createMesh.H"
    canopyPimpleControl pimple(mesh);
    #include "createTimeControls.H"
    #include "initContinuityErrs.H"
    #include "createFields.H"
    #include "createFaceNumerics.H"
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    turbulence->validate();

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "setCanopyDeltaT.H"

        // The last good state, written if this step fails
        #include "storeLastGoodState.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        coupling.beginTimeStep(U);

        // --- Pressure-velocity PIMPLE corrector loop with the coupling
        while (pimple.loop())
        {
            #include "restartFluidIteration.H"

            #include "UEqn.H"

            // --- Pressure corrector loop
            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            // The coupling decides whether this outer iteration is the
            // last; the turbulence model (corrected on the final iteration
            // only, by default) is corrected after it has
            if (coupling.correctStructure(p))
            {
                pimple.stopAfterThisIteration();
            }

            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                turbulence->correct();
            }
        }

        if (!coupling.endTimeStep())
        {
            #include "writeLastGoodStateAndStop.H"
        }

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}
