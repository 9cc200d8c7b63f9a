/*---------------------------------------------------------------------------*\
    canopyFoam: canopyPimpleControl.C — PIMPLE control ended by coupling
    convergence.
\*---------------------------------------------------------------------------*/

#include "canopyPimpleControl.H"

Foam::canopyPimpleControl::canopyPimpleControl(fvMesh& mesh)
:
    pimpleControl(mesh)
{}


void Foam::canopyPimpleControl::stopAfterThisIteration()
{
    // loop() ends (and resets its counters) when converged_ is set; at
    // the last iteration it ends by the count and would leave converged_
    // set for the next time step, so it is not set there
    if (corr_ < nCorrPIMPLE_)
    {
        converged_ = true;
    }
}
