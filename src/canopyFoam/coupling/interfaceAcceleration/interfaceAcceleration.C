/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceAcceleration.C — type name and run-time selection
    table of the interface accelerations.
\*---------------------------------------------------------------------------*/

#include "interfaceAcceleration.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(interfaceAcceleration, 0);
    defineRunTimeSelectionTable(interfaceAcceleration, dictionary);
}


// ************************************************************************* //
