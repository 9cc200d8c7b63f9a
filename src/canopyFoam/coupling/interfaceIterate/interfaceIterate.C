/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceIterate.C — the coupling's iterate on the interface
    velocity, its residual and the convergence decision.
\*---------------------------------------------------------------------------*/

#include "interfaceIterate.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::interfaceIterate::norm(const scalarField& change) const
{
    if (change.empty())
    {
        return 0;
    }
    if (!rms_)
    {
        return max(mag(change));
    }
    const scalarField areas(structure_.triangleAreas());
    return Foam::sqrt(sum(areas*sqr(change))/max(sum(areas), VSMALL));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::interfaceIterate::interfaceIterate
(
    const canopyStructure& structure,
    const canopyFrame& frame,
    const scalar tolerance,
    const scalar Uref,
    const bool rms
)
:
    structure_(structure),
    frame_(frame),
    tolerance_(tolerance),
    Uref_(Uref),
    rms_(rms),
    balanceRelaxed_(false),
    velocityResidual_(0),
    balanceResidual_(0),
    worst_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::interfaceIterate::fromStructure()
{
    normalVelocity_ = frame_.normalVelocities(structure_);
    velocity_ = frame_.velocities(structure_);
}


void Foam::interfaceIterate::endStep(addedMassStabiliser& addedMass)
{
    fromStructure();
    if (balanceRelaxed_)
    {
        addedMass.setBalanceAcceleration(solvedBalance_);
        balanceRelaxed_ = false;
    }
}


void Foam::interfaceIterate::hold
(
    const addedMassStabiliser& addedMass,
    const canopyMarkers& markers
)
{
    heldBalance_ = addedMass.balanceAcceleration();
    heldVelocity_ = velocity_;
    heldPoints_ = markers.points();
    heldNormals_ = markers.normals();
    heldAreas_ = markers.areas();
}


bool Foam::interfaceIterate::update
(
    const bool strong,
    interfaceAcceleration& acceleration,
    addedMassStabiliser& addedMass,
    ibForcing& forcing
)
{
    // This iteration's change of the interface velocity the forcing
    // imposes (the normal velocity; with tangential noSlip the whole
    // velocity): its norm is the velocity residual; where it is largest
    // goes to the log
    const scalarField target(frame_.normalVelocities(structure_));
    velocity_ = frame_.velocities(structure_);
    const scalar scale = max(Uref_, target.size() ? max(mag(target)) : 0);
    const scalarField change
    (
        forcing.noSlip()
      ? scalarField(mag(velocity_ - heldVelocity_))
      : scalarField(target - normalVelocity_)
    );
    velocityResidual_ = norm(change)/scale;
    worst_ = findMax(scalarField(mag(change)));
    balanceResidual_ =
        addedMass.active()
      ? norm(addedMass.balanceChange(heldBalance_))/scale
      : 0;
    if (!strong)
    {
        // Explicit: one structure solve per step; the PIMPLE outer loop
        // runs its own course
        normalVelocity_ = target;
        return true;
    }

    // The next iterate, the held secondary data moved with it (IQN-ILS
    // moves them with its columns, Aitken with its factor); the markers'
    // positions in the mesh's frame, as the velocities: the first
    // iteration's held positions are the step's start carried with the
    // frame, so that the iterates do not depend on the frame's velocity
    // (tests/openfoam/frameGalilean)
    const bool converged = residual() < tolerance_;
    const canopyMarkers& markers = forcing.markers();
    const vectorField& solvedPoints = markers.points();
    const vectorField& solvedNormals = markers.normals();
    const scalarField& solvedAreas = markers.areas();
    acceleration.relax
    (
        normalVelocity_, target,
        List<vectorField*>
        ({&heldBalance_, &heldVelocity_, &heldPoints_, &heldNormals_}),
        List<const vectorField*>
        ({
            &addedMass.balanceAcceleration(), &velocity_,
            &solvedPoints, &solvedNormals
        }),
        List<scalarField*>({&heldAreas_}),
        List<const scalarField*>({&solvedAreas})
    );
    balanceRelaxed_ = !converged;
    if (!converged)
    {
        velocity_ = heldVelocity_;
        solvedBalance_ = addedMass.balanceAcceleration();
        addedMass.setBalanceAcceleration(heldBalance_);
        forcing.moveMarkers(heldPoints_, heldNormals_, heldAreas_);
    }
    return converged;
}


// ************************************************************************* //
