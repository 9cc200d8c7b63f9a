/*---------------------------------------------------------------------------*\
    canopyFoam: ibForce.C — the load on the cloth as the reaction of the
    markers' IB force.
\*---------------------------------------------------------------------------*/

#include "ibForce.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace clothLoads
{
    defineTypeNameAndDebug(ibForce, 0);
    addToRunTimeSelectionTable(clothLoad, ibForce, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::clothLoads::ibForce::ibForce
(
    const scopedEntryReader& load,
    const scalar rho
)
:
    clothLoad(load, rho),
    tangential_(load.flag("tangential", false)),
    cellReaction_
    (
        load.choice
        (
            "reaction", {"markers", "cells"},
            "load reaction", "markers"
        ) == "cells"
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::vectorField> Foam::clothLoads::ibForce::markerForces
(
    const ibForcing& ib
) const
{
    return cellReaction_ ? ib.cellForceShares() : clothLoad::markerForces(ib);
}


Foam::tmp<Foam::scalarField> Foam::clothLoads::ibForce::pressureJump
(
    const canopyMarkers& markers,
    const vectorField& markerForce,
    const ibStencil& plus,
    const ibStencil& minus,
    const volScalarField& p
) const
{
    // Newton's third law: the air pushes the canopy with minus the force
    // the markers put on it; its normal part per area is the jump
    return -rho_*(markerForce & markers.normals())/markers.areas();
}


Foam::tmp<Foam::vectorField> Foam::clothLoads::ibForce::tangentialForces
(
    const canopyMarkers& markers,
    const vectorField& markerForce
) const
{
    const vectorField& n = markers.normals();
    return -rho_*(markerForce - (markerForce & n)*n);
}


// ************************************************************************* //
