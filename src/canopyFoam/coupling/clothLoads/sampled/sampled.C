/*---------------------------------------------------------------------------*\
    canopyFoam: sampled.C — the pressure jump sampled on each side of the
    markers.
\*---------------------------------------------------------------------------*/

#include "sampled.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace clothLoads
{
    defineTypeNameAndDebug(sampled, 0);
    addToRunTimeSelectionTable(clothLoad, sampled, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::clothLoads::sampled::sampled
(
    const scopedEntryReader& load,
    const scalar rho
)
:
    clothLoad(load, rho)
{
    if (load.flag("tangential", false))
    {
        load.fail
        (
            "tangential",
            "= true needs '" + load.name("type") + "' = ibForce (the"
            " tangential load is the rest of the markers' IB force)"
        );
    }
    if (load.found("reaction"))
    {
        load.fail
        (
            "reaction",
            "needs '" + load.name("type") + "' = ibForce (it says which IB"
            " force the cloth's load is the reaction of)"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::clothLoads::sampled::pressureJump
(
    const canopyMarkers& markers,
    const vectorField& markerForce,
    const ibStencil& plus,
    const ibStencil& minus,
    const volScalarField& p
) const
{
    const scalarField pPlus(plus.interpolate(p));
    const scalarField pMinus(minus.interpolate(p));
    return rho_*(pMinus - pPlus);
}


// ************************************************************************* //
