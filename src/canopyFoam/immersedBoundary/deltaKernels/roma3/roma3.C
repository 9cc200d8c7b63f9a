/*---------------------------------------------------------------------------*\
    canopyFoam: roma3.C — the Roma, Peskin & Berger three-point kernel.
\*---------------------------------------------------------------------------*/

#include "roma3.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace deltaKernels
{
    defineTypeNameAndDebug(roma3, 0);
    addToRunTimeSelectionTable(deltaKernel, roma3, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::deltaKernels::roma3::roma3(const dictionary&)
:
    deltaKernel()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::deltaKernels::roma3::phi(const scalar r) const
{
    const scalar a = mag(r);

    if (a <= 0.5)
    {
        // max(.., 0) only guards against round-off at the branch ends
        return (1 + Foam::sqrt(max(1 - 3*a*a, scalar(0))))/3;
    }
    else if (a < 1.5)
    {
        const scalar b = 1 - a;
        return (5 - 3*a - Foam::sqrt(max(1 - 3*b*b, scalar(0))))/6;
    }

    return 0;
}


// ************************************************************************* //
