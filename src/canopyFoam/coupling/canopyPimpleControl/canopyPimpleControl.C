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
    // loop() ends (and resets its counters) when converged_ is set
    converged_ = true;
}
