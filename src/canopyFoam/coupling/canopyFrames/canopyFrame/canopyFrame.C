/*---------------------------------------------------------------------------*\
    canopyFoam: canopyFrame.C — the mesh's frame seen from the ground frame:
    the state every frame shares.
\*---------------------------------------------------------------------------*/

#include "canopyFrame.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(canopyFrame, 0);
    defineRunTimeSelectionTable(canopyFrame, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::canopyFrame::canopyFrame(const fvMesh& mesh)
:
    mesh_(mesh),
    origin_(Zero),
    originTime_(0),
    velocity_(Zero),
    velocityStart_(Zero),
    acceleration_(Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::canopyFrame::beginStep(volVectorField& U)
{
    velocityStart_ = velocity_;
    return false;
}


Foam::tmp<Foam::scalarField> Foam::canopyFrame::normalVelocities
(
    const canopyStructure& structure
) const
{
    return structure.normalVelocities();
}


Foam::tmp<Foam::vectorField> Foam::canopyFrame::velocities
(
    const canopyStructure& structure
) const
{
    return structure.triangleVelocities();
}


void Foam::canopyFrame::writeState(dictionary& dict) const
{
    dict.add("frameOrigin", origin_);
    dict.add("frameVelocity", velocity_);
}


// ************************************************************************* //
