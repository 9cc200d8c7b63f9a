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
    residual_(0),
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


void Foam::interfaceIterate::hold(const addedMassStabiliser& addedMass)
{
    heldBalance_ = addedMass.balanceAcceleration();
    heldVelocity_ = velocity_;
}


bool Foam::interfaceIterate::update
(
    const bool strong,
    interfaceAcceleration& acceleration,
    addedMassStabiliser& addedMass
)
{
    // This iteration's change of the interface velocity: its norm is the
    // residual; where it is largest goes to the log
    const scalarField target(frame_.normalVelocities(structure_));
    velocity_ = frame_.velocities(structure_);
    const scalar scale = max(Uref_, target.size() ? max(mag(target)) : 0);
    const scalarField change(target - normalVelocity_);
    residual_ = norm(change)/scale;
    worst_ = findMax(scalarField(mag(change)));
    if (!strong)
    {
        // Explicit: one structure solve per step; the PIMPLE outer loop
        // runs its own course
        normalVelocity_ = target;
        return true;
    }

    // The next iterate, the held secondary data moved with it (IQN-ILS
    // moves them with its columns, Aitken with its factor)
    const bool converged = residual_ < tolerance_;
    acceleration.relax
    (
        normalVelocity_, target, heldBalance_, heldVelocity_,
        addedMass.balanceAcceleration(), velocity_
    );
    balanceRelaxed_ = !converged;
    if (!converged)
    {
        velocity_ = heldVelocity_;
        solvedBalance_ = addedMass.balanceAcceleration();
        addedMass.setBalanceAcceleration(heldBalance_);
    }
    return converged;
}


// ************************************************************************* //
