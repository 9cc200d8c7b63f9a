/*---------------------------------------------------------------------------*\
    canopyFoam: canopyCoupling.C — the fluid–structure iteration of a time
    step: begin, correct, end.
\*---------------------------------------------------------------------------*/

#include "canopyCoupling.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::canopyCoupling::placeMarkers()
{
    // A trial structure state at t + dt is seen from the frame's origin at
    // t + dt (canopyFrame::originAt)
    sectionTimer timer(ibSeconds_);
    parts_->forcing().place
    (
        structure_.model(), parts_->frame().originAt(structure_.time())
    );
    return parts_->forcing().updateStencils();
}


void Foam::canopyCoupling::returnToStepStart()
{
    // A failed step: every part back to the step's start (the last good
    // state written next is then the state the step started from)
    parts_->addedMass().returnToStepStart();
    parts_->acceleration().discardStep();
    structure_.restore();
    placeMarkers();
    parts_->forcing().returnToStepStart();
    parts_->force().spread();
}


void Foam::canopyCoupling::setNodalForces(const vectorField& tangential)
{
    if (parts_->addedMass().active())
    {
        structure_.setNodalForces
        (
            "addedMassBalance", parts_->addedMass().balancingForces()
        );
    }
    if (parts_->load().tangential())
    {
        structure_.setNodalForces("tangentialLoad", tangential);
    }
    if (lineDrag* lines = parts_->lineDragPtr())
    {
        // From the air's current velocity and the lines at the step's
        // start (the sample points were placed there)
        lines->compute
        (
            mesh_.lookupObject<volVectorField>(UName_), structure_.model(),
            parts_->frame().velocity(), rho_
        );
        labelList nodes;
        vectorField forces;
        lines->nodalForces(nodes, forces);
        structure_.setNodalForces("lineDrag", nodes, forces);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::canopyCoupling::validKeys()
{
    wordList keys
    {
        "scheme", "rho", "tolerance", "Uref", "residualNorm",
        "stopIfNotConverged", "restartFluid", "U"
    };
    keys.append(couplingParts::subDictionaries());
    return keys;
}


Foam::canopyCoupling::canopyCoupling(const fvMesh& mesh)
:
    mesh_(mesh),
    structure_(mesh.time()),
    step_{Zero, 0, 0, 0, 0, Zero, Zero, 0, -1},
    structureSolves_(0),
    converged_(false),
    structureSeconds_(0),
    ibSeconds_(0)
{
    // mesh.pointInCell (the cell tree's findInside) needs the tet
    // decomposition's base points, which polyMesh computes collectively
    // on first use: compute them on every rank now, before any rank looks
    // up only the points it holds (a deadlock otherwise)
    (void)mesh_.tetBasePtIs();

    const scopedEntryReader coupling
    (
        scopedEntryReader(structure_.dict(), "").optionalSubReader("coupling")
    );
    couplingParts::rejectMovedEntries(coupling);
    coupling.rejectUnknown(validKeys());

    strong_ =
        coupling.choice
        (
            "scheme", {"strong", "explicit"}, "coupling scheme", "strong"
        ) == "strong";
    rho_ = coupling.positive("rho", "fluid density [kg/m^3]", 1.2);
    const scalar tolerance =
        coupling.positive("tolerance", "coupling tolerance", 1e-3);
    const scalar Uref = coupling.positive("Uref", "velocity scale [m/s]", 1);
    const bool rms =
        coupling.choice
        (
            "residualNorm", {"max", "rms"}, "residual norm", "max"
        ) == "rms";
    stopIfNotConverged_ = coupling.flag("stopIfNotConverged", true);
    restartFluid_ = coupling.flag("restartFluid", false);
    UName_ = coupling.wordValue("U", "velocity field name", "U");

    // The parts, with a restart's state (the IB force is carried by the
    // markers); the markers and the lines where the structure is
    parts_.reset
    (
        new couplingParts(coupling, rho_, mesh, structure_, ibSeconds_)
    );
    structure_.setPressureHeld(parts_->load().pressureHeld());
    iterate_.reset
    (
        new interfaceIterate(structure_, parts_->frame(), tolerance, Uref, rms)
    );
    parts_->frame().startAt(structure_.time());
    const string problem(placeMarkers());
    if (lineDrag* lines = parts_->lineDragPtr())
    {
        lines->place(structure_.model(), parts_->frame().origin());
    }

    // Interface velocity from the structure's initial state
    iterate_->fromStructure();
    if (!problem.empty())
    {
        FatalErrorInFunction
            << "At the start: " << problem.c_str() << exit(FatalError);
    }
    parts_->force().spread();

    parts_->output().writeInfo(Info);
    Info<< "canopyCoupling: " << (strong_ ? "strong" : "explicit")
        << " coupling, ";
    parts_->writeInfo(Info);
    Info<< nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::canopyCoupling::beginTimeStep(volVectorField& U)
{
    if (parts_->frame().beginStep(U))
    {
        // The interface velocities relative to the frame's new velocity;
        // the fictitious force changed with its acceleration
        iterate_->fromStructure();
        parts_->force().frameChanged();
    }
    beginTimeStep();
}


void Foam::canopyCoupling::beginTimeStep()
{
    failure_.clear();
    structure_.beginStep(mesh_.time().deltaTValue());
    structure_.checkpoint();
    parts_->frame().startAt(structure_.time());
    parts_->addedMass().beginStep(structure_);
    parts_->forcing().beginStep();
    parts_->acceleration().reset();
    step_.iterations = 0;
    structureSolves_ = 0;
    converged_ = false;
    step_.residual = 0;
    step_.velocityResidual = 0;
    step_.balanceResidual = -1;
}


void Foam::canopyCoupling::forcingIncrement(const volVectorField& U)
{
    step_.slip =
        parts_->force().forcingIncrement
        (
            U, iterate_->normalVelocity(), iterate_->velocity(),
            iterate_->Uref()
        );
}


bool Foam::canopyCoupling::correctStructure(const volScalarField& p)
{
    ++step_.iterations;
    if (!strong_ && structureSolves_ > 0)
    {
        return false;
    }

    // The load on the cloth (clothLoad) from p and the markers: the
    // pressure jump per triangle and the tangential force on the nodes
    scalarField dp;
    vectorField tangentialNodal;
    {
        sectionTimer timer(ibSeconds_);
        step_.load =
            parts_->load().onCloth(parts_->forcing(), p, dp, tangentialNodal);
    }

    // The secondary part of the iterate this solve reads (besides the
    // normal velocity): the stabiliser's balance, the no-slip velocity and
    // the markers' geometry
    iterate_->hold(parts_->addedMass(), parts_->forcing().markers());

    // The structure's time step from its start under these loads
    string message;
    bool advanced = false;
    {
        sectionTimer timer(structureSeconds_);
        structure_.restore();
        structure_.setPressureJump(dp);
        setNodalForces(tangentialNodal);
        advanced =
            structure_.tryAdvance
            (
                mesh_.time().deltaTValue(), step_.subSteps, message
            );
        if (advanced)
        {
            parts_->addedMass().update(structure_, mesh_.time().deltaTValue());
        }
    }
    if (!advanced)
    {
        failure_ =
            "the structure's time step to t = "
          + canopyCompat::timeName(mesh_.time())
          + " failed (coupling iteration " + Foam::name(step_.iterations)
          + "): " + message;
        converged_ = true;
        return true;            // ends the outer loop
    }
    ++structureSolves_;

    // The markers on the structure's result, then the residual, the
    // convergence decision and the next iterate (unconverged, the markers
    // move to its geometry)
    {
        sectionTimer timer(ibSeconds_);
        parts_->forcing().place
        (
            structure_.model(), parts_->frame().originAt(structure_.time())
        );
    }
    converged_ =
        iterate_->update
        (
            strong_, parts_->acceleration(), parts_->addedMass(),
            parts_->forcing()
        );
    step_.residual = iterate_->residual();
    step_.velocityResidual = iterate_->velocityResidual();
    step_.balanceResidual =
        parts_->addedMass().active() ? iterate_->balanceResidual() : -1;

    string problem;
    {
        sectionTimer timer(ibSeconds_);
        problem = parts_->forcing().updateStencils();
    }
    if (!problem.empty())
    {
        failure_ =
            "at t = " + canopyCompat::timeName(mesh_.time()) + ", " + problem;
        // Markers and stencils back at the step's start for what follows
        returnToStepStart();
        converged_ = true;
        return true;            // ends the outer loop
    }

    // Strong coupling: the next iteration's fluid solve starts from the
    // step's IB force, so that the fluid's response is a function of the
    // interface velocity alone (not of the iteration history); the
    // markers' forces move with them
    const bool stop = strong_ && converged_;
    if (strong_ && !stop)
    {
        parts_->forcing().returnToStepStart();
    }
    parts_->force().spread();

    // The iteration's line in the log
    const lineDrag* lines = parts_->lineDragPtr();
    const vector drag(lines ? lines->total() : vector::zero);
    parts_->output().logIteration
    (
        step_, iterate_->worst(), parts_->acceleration().describe(),
        parts_->load().tangential(), rho_*parts_->forcing().totalForce(),
        lines ? &drag : nullptr
    );

    return stop;
}


bool Foam::canopyCoupling::endTimeStep()
{
    if (!failed() && strong_ && !converged_)
    {
        const string text
        (
            parts_->output().notConverged(step_, iterate_->tolerance())
        );
        if (stopIfNotConverged_)
        {
            failure_ = text;
        }
        else
        {
            WarningInFunction << text.c_str() << endl;
        }
    }

    // The frame moves on with the step; the markers with it, and back on
    // the structure when an unconverged step left them at the relaxed
    // iterate
    const bool frameMoved =
        !failed()
     && parts_->frame().moveOn(mesh_.time().deltaTValue(), structure_.time());
    const bool markersRelaxed = !failed() && strong_ && !converged_;
    if (frameMoved || markersRelaxed)
    {
        const string problem(placeMarkers());
        if (!problem.empty())
        {
            if (frameMoved)
            {
                parts_->frame().undoMove();
            }
            failure_ =
                "at t = " + canopyCompat::timeName(mesh_.time())
              + (frameMoved ? " (frame moved), " : " (markers placed), ")
              + problem;
        }
    }

    if (failed())
    {
        // Back to the last good state (the start of this step)
        parts_->frame().returnToStepStart();
        returnToStepStart();
        structure_.commit();
        return false;
    }

    {
        sectionTimer timer(structureSeconds_);
        structure_.commit();
    }
    lineDrag* lines = parts_->lineDragPtr();
    if (lines)
    {
        // The reaction acts from where the lines are now (and where the
        // next step's drag is computed): a restart, which knows only this
        // state, places it the same way
        sectionTimer timer(ibSeconds_);
        lines->place(structure_.model(), parts_->frame().origin());
    }
    if (frameMoved || markersRelaxed || lines)
    {
        // The force from the markers' and the lines' new places
        parts_->force().spread();
    }

    // The next step starts from the committed structure's interface
    // velocities and the last solve's balance (not the relaxed iterate),
    // so that a restart, which knows only that state, continues exactly
    // and the frame does not matter
    iterate_->endStep(parts_->addedMass());
    step_.frameOrigin = parts_->frame().origin();
    step_.lineDrag = lines ? lines->total() : vector::zero;
    parts_->output().writeSeries(step_);
    if (mesh_.time().writeTime())
    {
        writeStructure();
    }
    return true;
}


// * * * * * * * * * * * * * * * Restart state  * * * * * * * * * * * * * * //

void Foam::canopyCoupling::writeStructure()
{
    {
        sectionTimer timer(structureSeconds_);
        // with a mesh that follows the payload, also in the mesh's frame
        // (canopy-frame.xdmf beside case.foam)
        parts_->output().write
        (
            parts_->frame().meshFrameOrigin(),
            [this](dictionary& state) { parts_->writeState(state); }
        );
    }
    Info<< "canopyCoupling: wall time since the run started: structure "
        << structureSeconds_ << " s, immersed boundary " << ibSeconds_
        << " s (the rest of ClockTime is the fluid)" << endl;
}


void Foam::canopyCoupling::stopAtLastGoodState()
{
    writeStructure();
    FatalErrorInFunction
        << "Stopping: " << failure_.c_str() << nl
        << "    The last good state (t = "
        << canopyCompat::timeName(mesh_.time())
        << ") is written; to go on, e.g. reduce deltaT, add coupling"
        << " iterations (nOuterCorrectors) or lower"
        << " coupling.acceleration.initial, and restart with startFrom"
        << " latestTime." << exit(FatalError);
}


// ************************************************************************* //
