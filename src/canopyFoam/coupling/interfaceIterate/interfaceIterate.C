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
    // The fixed point the acceleration iterates on is what the residual
    // measures: the velocity the forcing imposes (the normal velocity;
    // with tangential noSlip the whole velocity, the normal one then
    // moving with it) and, with the stabiliser, its balance as the
    // velocity change it makes over the step per triangle. So Aitken's
    // factor and IQN-ILS's Jacobian follow the balance's convergence too,
    // not the normal velocity's alone
    scalarField target(frame_.normalVelocities(structure_));
    velocity_ = frame_.velocities(structure_);
    const scalar scale = max(Uref_, target.size() ? max(mag(target)) : 0);
    const bool noSlip = forcing.noSlip();
    const scalarField change
    (
        noSlip
      ? scalarField(mag(velocity_ - heldVelocity_))
      : scalarField(target - normalVelocity_)
    );
    velocityResidual_ = norm(change)/scale;
    worst_ = findMax(scalarField(mag(change)));
    vectorField heldBalanceVelocity;
    vectorField balanceVelocity;
    balanceResidual_ = 0;
    if (addedMass.active())
    {
        heldBalanceVelocity = addedMass.balanceVelocities(heldBalance_);
        balanceVelocity =
            addedMass.balanceVelocities(addedMass.balanceAcceleration());
        balanceResidual_ =
            norm(mag(balanceVelocity - heldBalanceVelocity))/scale;
    }
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
    DynamicList<vectorField*> iterate;
    DynamicList<const vectorField*> targets;
    DynamicList<scalarField*> scalarIterate;
    DynamicList<const scalarField*> scalarTargets;
    DynamicList<vectorField*> held
    ({
        &heldBalance_, &heldPoints_, &heldNormals_
    });
    DynamicList<const vectorField*> solved
    ({
        &addedMass.balanceAcceleration(), &markers.points(),
        &markers.normals()
    });
    DynamicList<scalarField*> heldScalars({&heldAreas_});
    DynamicList<const scalarField*> solvedScalars({&markers.areas()});
    if (noSlip)
    {
        iterate.append(&heldVelocity_);
        targets.append(&velocity_);
        heldScalars.append(&normalVelocity_);
        solvedScalars.append(&target);
    }
    else
    {
        scalarIterate.append(&normalVelocity_);
        scalarTargets.append(&target);
        held.append(&heldVelocity_);
        solved.append(&velocity_);
    }
    if (addedMass.active())
    {
        iterate.append(&heldBalanceVelocity);
        targets.append(&balanceVelocity);
    }
    scalarField x(interfaceAcceleration::pack(iterate, scalarIterate));
    acceleration.relax
    (
        x, interfaceAcceleration::pack(targets, scalarTargets),
        held, solved, heldScalars, solvedScalars
    );
    interfaceAcceleration::unpack(x, iterate, scalarIterate);
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
