/*---------------------------------------------------------------------------*\
    canopyFoam: clothLoad.C — the air's load on the cloth: what every load
    shares.
\*---------------------------------------------------------------------------*/

#include "clothLoad.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(clothLoad, 0);
    defineRunTimeSelectionTable(clothLoad, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::clothLoad::clothLoad(const scalar rho)
:
    rho_(rho)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField> Foam::clothLoad::tangentialForces
(
    const canopyMarkers& markers,
    const vectorField& markerForce
) const
{
    return tmp<vectorField>(new vectorField(markers.size(), Zero));
}


// ************************************************************************* //
