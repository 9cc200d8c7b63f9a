/*---------------------------------------------------------------------------*\
    canopyFoam: payload.C — the frame of a mesh that follows the payload.
\*---------------------------------------------------------------------------*/

#include "payload.H"
#include "inletOutletFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace canopyFrames
{
    defineTypeNameAndDebug(payload, 0);
    addToRunTimeSelectionTable(canopyFrame, payload, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::canopyFrames::payload::setFarField
(
    fvPatchVectorField& Up,
    const vector& value
) const
{
    // inletOutlet (a side of the box): the far field where the air enters,
    // zero gradient where it leaves, so the side does not confine the flow
    if (isA<inletOutletFvPatchVectorField>(Up))
    {
        refCast<inletOutletFvPatchVectorField>(Up).refValue() = value;
        return;
    }
    if (!Up.fixesValue())
    {
        FatalErrorInFunction
            << "Entry 'coupling.frame.inletPatches' names patch "
            << Up.patch().name() << " of " << Up.internalField().name()
            << ", whose type " << Up.type() << " cannot take the far"
            << " field's velocity: use fixedValue (an inlet) or inletOutlet"
            << " (a side)" << exit(FatalError);
    }
    Up == value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::canopyFrames::payload::validKeys()
{
    return {"type", "inletPatches", "wind"};
}


Foam::canopyFrames::payload::payload
(
    const scopedEntryReader& frame,
    const fvMesh& mesh,
    const canopyStructure& structure
)
:
    canopyFrame(mesh),
    structure_(structure),
    wind_(frame.vectorValue("wind", "ambient wind [m/s]", Zero)),
    inletPatches_(),
    shift_(Zero),
    shiftTime_(0)
{
    frame.rejectUnknown(validKeys());
    const dictionary& dict = frame.dict();
    if (!structure_.hasPayload())
    {
        frame.fail("type", "= payload, but the structure has no payload");
    }
    if (!frame.found("inletPatches"))
    {
        frame.fail
        (
            "inletPatches",
            "is missing (required: the far field's patches)"
        );
    }
    const wordReList names
    (
        canopyCompat::readValue<wordReList>(dict, "inletPatches")
    );
    inletPatches_ = mesh.boundaryMesh().patchSet(names, false).sortedToc();
    if (inletPatches_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.frame.inletPatches' = " << names
            << " matches no patch; patches: " << mesh.boundaryMesh().names()
            << exit(FatalIOError);
    }
    velocity_ = structure_.payloadVelocity();
    velocityStart_ = velocity_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::canopyFrames::payload::normalVelocities
(
    const canopyStructure& structure
) const
{
    tmp<scalarField> tvn(structure.normalVelocities());
    tvn.ref() -= velocity_ & structure.triangleNormals();
    return tvn;
}


Foam::tmp<Foam::vectorField> Foam::canopyFrames::payload::velocities
(
    const canopyStructure& structure
) const
{
    tmp<vectorField> tv(structure.triangleVelocities());
    tv.ref() -= velocity_;
    return tv;
}


bool Foam::canopyFrames::payload::beginStep(volVectorField& U)
{
    canopyFrame::beginStep(U);

    // The frame moves at the payload's velocity over this step; its
    // change is a uniform fictitious force -A on the air
    const scalar dt = mesh_.time().deltaTValue();
    velocity_ = structure_.payloadVelocity();
    acceleration_ = (velocity_ - velocityStart_)/dt;
    volVectorField::Boundary& Ub = U.boundaryFieldRef();
    for (const label patchi : inletPatches_)
    {
        setFarField(Ub[patchi], wind_ - velocity_);
    }
    return true;
}


void Foam::canopyFrames::payload::zeroFictitiousFlux
(
    surfaceScalarField::Boundary& faceForce
) const
{
    for (const label patchi : inletPatches_)
    {
        faceForce[patchi] = 0;
    }
}


bool Foam::canopyFrames::payload::moveOn(const scalar dt, const scalar t)
{
    shift_ = velocity_*dt;
    shiftTime_ = originTime_;
    origin_ += shift_;
    originTime_ = t;
    return true;
}


void Foam::canopyFrames::payload::undoMove()
{
    origin_ -= shift_;
    originTime_ = shiftTime_;
}


void Foam::canopyFrames::payload::readState(const dictionary& dict)
{
    origin_ = canopyCompat::readValue<vector>(dict, "frameOrigin");
    velocity_ = canopyCompat::readValue<vector>(dict, "frameVelocity");
    velocityStart_ = velocity_;
}


void Foam::canopyFrames::payload::writeInfo(Ostream& os) const
{
    os  << ", the mesh follows the payload (inlet patches " << inletPatches_
        << ", wind " << wind_ << ")";
}


// ************************************************************************* //
