/*---------------------------------------------------------------------------*\
    canopyFoam: deltaKernel.C — type name and run-time selection table of
    the delta kernels.
\*---------------------------------------------------------------------------*/

#include "deltaKernel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(deltaKernel, 0);
    defineRunTimeSelectionTable(deltaKernel, dictionary);
}


// ************************************************************************* //
