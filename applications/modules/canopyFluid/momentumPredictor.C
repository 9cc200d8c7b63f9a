/*---------------------------------------------------------------------------*\
    canopyFoam: momentumPredictor.C — canopyFluid's momentum predictor: the
    immersed-boundary force enters on faces, like the pressure gradient.
\*---------------------------------------------------------------------------*/

#include "canopyFluid.H"
#include "pressureFaceGradient.H"
#include "fvmDdt.H"
#include "fvmDiv.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solvers::canopyFluid::momentumPredictor()
{
    if (couplingDone_)
    {
        return;     // the outer iteration after the coupling has finished
    }
    volVectorField& U(U_);

    tUEqn =
    (
        fvm::ddt(U) + fvm::div(phi, U)
      + momentumTransport->divDevSigma(U)
     ==
        fvModels().source(U)
    );
    fvVectorMatrix& UEqn = tUEqn.ref();

    UEqn.relax();
    fvConstraints().constrain(UEqn);

    if (pimple.momentumPredictor())
    {
        solve
        (
            UEqn
         ==
            reconstruct_
            (
                coupling_.faceForce()
              - pressureFaceGradient(p, pNeedsNonOrthCorrection_)
            )
        );
        fvConstraints().constrain(U);
    }

    // Multi-direct forcing: drive the predicted velocity to the canopy's at
    // the markers (updates the coupling's force)
    coupling_.forcingIncrement(U);
}


// ************************************************************************* //
