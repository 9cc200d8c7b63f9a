/*---------------------------------------------------------------------------*\
    canopyFoam: peskin4.C — Peskin's standard four-point kernel.
\*---------------------------------------------------------------------------*/

#include "peskin4.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deltaKernels
{
    defineTypeNameAndDebug(peskin4, 0);
    addToRunTimeSelectionTable(deltaKernel, peskin4, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deltaKernels::peskin4::peskin4(const dictionary&)
:
    deltaKernel()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::deltaKernels::peskin4::phi(const scalar r) const
{
    const scalar a = mag(r);

    if (a <= 1)
    {
        // max(.., 0) only guards against round-off at the branch ends
        return (3 - 2*a + Foam::sqrt(max(1 + 4*a - 4*a*a, scalar(0))))/8;
    }
    else if (a < 2)
    {
        return (5 - 2*a - Foam::sqrt(max(-7 + 12*a - 4*a*a, scalar(0))))/8;
    }

    return 0;
}


// ************************************************************************* //
