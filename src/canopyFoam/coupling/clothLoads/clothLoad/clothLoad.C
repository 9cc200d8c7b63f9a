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

Foam::clothLoad::clothLoad(const scopedEntryReader& load, const scalar rho)
:
    rho_(rho),
    pressureHeld_(load.flag("pressureHeld", false))
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


Foam::tmp<Foam::vectorField> Foam::clothLoad::markerForces
(
    const ibForcing& ib
) const
{
    return tmp<vectorField>(ib.markerForces());
}


Foam::vector Foam::clothLoad::onCloth
(
    const ibForcing& ib,
    const volScalarField& p,
    scalarField& dpTriangle,
    vectorField& tangentialNodal
) const
{
    const canopyMarkers& mk = ib.markers();
    const tmp<vectorField> tF(markerForces(ib));
    const scalarField dpMarker
    (
        pressureJump(mk, tF(), ib.plusStencil(), ib.minusStencil(), p)
    );
    vector load = sum(dpMarker*mk.areas()*mk.normals());
    if (tangential())
    {
        const vectorField t(tangentialForces(mk, tF()));
        load += sum(t);
        tangentialNodal = mk.toNodes(t);
    }
    dpTriangle = mk.triangleAverage(dpMarker);
    return load;
}


// ************************************************************************* //
