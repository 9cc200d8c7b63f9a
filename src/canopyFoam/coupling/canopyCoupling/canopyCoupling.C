/*---------------------------------------------------------------------------*\
    canopyFoam: canopyCoupling.C — the fluid–structure iteration of a time
    step: begin, correct, end.
\*---------------------------------------------------------------------------*/

#include "canopyCoupling.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The coupling's entries that now live in a part's sub-dictionary: each
// stops naming its new place and how to write it there
void rejectMovedEntries(const Foam::scopedEntryReader& coupling)
{
    coupling.rejectMovedInto
    ({
        {"kernel", "forcing", "kernel", ""},
        {"markerSpacing", "forcing", "markerSpacing", ""},
        {"forcingIterations", "forcing", "iterations", ""},
        {"tangential", "forcing", "tangential", ""},
        {"pressureOffset", "forcing", "pressureOffset", ""},
        {"pressureJump", "load", "type", ""},
        {"tangentialLoad", "load", "tangential", "type ibForce; "},
        {"acceleration", "acceleration", "type", ""},
        {"initialRelaxation", "acceleration", "initial", "type aitken; "},
        {"maxRelaxation", "acceleration", "max", "type aitken; "},
        {"reuse", "acceleration", "reuse", "type IQN-ILS; "},
        {"filter", "acceleration", "filter", "type IQN-ILS; "},
        {"addedMass", "addedMass", "mass", ""},
        {"addedMassPredictor", "addedMass", "predictor", "mass ..; "},
        {"addedMassBalance", "addedMass", "balance", "mass ..; "},
        {"addedMassDirection", "addedMass", "direction", "mass ..; "},
    });
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::canopyCoupling::placeMarkers()
{
    // A trial structure state at t + dt is seen from the frame's origin at
    // t + dt (canopyFrame::originAt)
    sectionTimer timer(ibSeconds_);
    ib_->place(structure_.model(), frame_->originAt(structure_.time()));
    return ib_->updateStencils();
}


void Foam::canopyCoupling::returnToStepStart()
{
    // A failed step: every part back to the step's start (the last good
    // state written next is then the state the step started from)
    addedMass_->returnToStepStart();
    acceleration_->discardStep();
    structure_.restore();
    placeMarkers();
    ib_->returnToStepStart();
    force_->spread();
}


void Foam::canopyCoupling::setNodalForces(const vectorField& tangential)
{
    if (addedMass_->active())
    {
        structure_.setNodalForces
        (
            "addedMassBalance", addedMass_->balancingForces()
        );
    }
    if (load_->tangential())
    {
        structure_.setNodalForces("tangentialLoad", tangential);
    }
    if (lineDrag_.valid())
    {
        // From the air's current velocity and the lines at the step's
        // start (the sample points were placed there)
        lineDrag_->compute
        (
            mesh_.lookupObject<volVectorField>(UName_), structure_.model(),
            frame_->velocity(), rho_
        );
        labelList nodes;
        vectorField forces;
        lineDrag_->nodalForces(nodes, forces);
        structure_.setNodalForces("lineDrag", nodes, forces);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::canopyCoupling::validKeys()
{
    return
    {
        "scheme", "rho", "tolerance", "Uref", "residualNorm",
        "stopIfNotConverged", "restartFluid", "U",
        "forcing", "load", "acceleration", "addedMass", "lineDrag", "frame"
    };
}


Foam::canopyCoupling::canopyCoupling(const fvMesh& mesh)
:
    mesh_(mesh),
    structure_(mesh.time()),
    step_{Zero, 0, 0, 0, 0, Zero, Zero},
    structureSolves_(0),
    converged_(false),
    runStartTime_(mesh.time().startTime().value()),
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
    rejectMovedEntries(coupling);
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
    load_ = clothLoad::New(coupling.optionalSubReader("load"), rho_);
    addedMass_.reset
    (
        new addedMassStabiliser
        (
            coupling.optionalSubReader("addedMass"), structure_
        )
    );
    acceleration_ =
        interfaceAcceleration::New(coupling.optionalSubReader("acceleration"));
    frame_ =
        canopyFrame::New(coupling.optionalSubReader("frame"), mesh, structure_);
    iterate_.reset
    (
        new interfaceIterate(structure_, frame_(), tolerance, Uref, rms)
    );

    // The files; on a restart the structure's state at the start time
    // and the coupling's (null when there is none)
    output_.reset(new couplingOutput(mesh, structure_, rho_));
    const autoPtr<IOdictionary> state(output_->readState());

    // The markers on the canopy, their stencils and forces: with a
    // restart's subdivision levels (so that its markers match the forces
    // it carries)
    ib_.reset
    (
        new ibForcing
        (
            coupling.optionalSubReader("forcing"), mesh, structure_,
            state.valid()
          ? state->getOrDefault<labelList>("markerLevels", labelList())
          : labelList()
        )
    );
    if (coupling.optionalDict("lineDrag"))
    {
        lineDrag_.reset
        (
            new lineDrag
            (
                coupling.optionalSubReader("lineDrag"), mesh, ib_->kernel(),
                structure_.model(), ib_->spacing()
            )
        );
    }
    force_.reset
    (
        new couplingForce
        (
            mesh, ib_(), lineDrag_.get(), frame_(), rho_, ibSeconds_
        )
    );

    // The IB force is carried by the markers; a restart reads it and the
    // parts' states
    if (state.valid())
    {
        readState(state());
    }
    frame_->startAt(structure_.time());
    const string problem(placeMarkers());
    if (lineDrag_.valid())
    {
        lineDrag_->place(structure_.model(), frame_->origin());
    }

    // Interface velocity from the structure's initial state
    iterate_->fromStructure();
    if (!problem.empty())
    {
        FatalErrorInFunction
            << "At the start: " << problem.c_str() << exit(FatalError);
    }
    force_->spread();

    output_->writeInfo(Info);
    Info<< "canopyCoupling: " << (strong_ ? "strong" : "explicit")
        << " coupling, ";
    ib_->writeInfo(Info);
    if (lineDrag_.valid())
    {
        lineDrag_->writeInfo(Info);
    }
    frame_->writeInfo(Info);
    Info<< nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::canopyCoupling::beginTimeStep(volVectorField& U)
{
    if (frame_->beginStep(U))
    {
        // The interface velocities relative to the frame's new velocity;
        // the fictitious force changed with its acceleration
        iterate_->fromStructure();
        force_->frameChanged();
    }
    beginTimeStep();
}


void Foam::canopyCoupling::beginTimeStep()
{
    failure_.clear();
    structure_.checkpoint();
    frame_->startAt(structure_.time());
    addedMass_->beginStep(structure_);
    ib_->beginStep();
    acceleration_->reset();
    step_.iterations = 0;
    structureSolves_ = 0;
    converged_ = false;
    step_.residual = 0;
}


void Foam::canopyCoupling::forcingIncrement(const volVectorField& U)
{
    step_.slip =
        force_->forcingIncrement
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
        step_.load = load_->onCloth(ib_(), p, dp, tangentialNodal);
    }

    // The secondary part of the iterate this solve reads (besides the
    // normal velocity): the stabiliser's balance and the no-slip velocity
    iterate_->hold(addedMass_());

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
            addedMass_->update(structure_, mesh_.time().deltaTValue());
        }
    }
    if (!advanced)
    {
        failure_ =
            "the structure's time step to t = " + mesh_.time().timeName()
          + " failed (coupling iteration " + Foam::name(step_.iterations)
          + "): " + message;
        converged_ = true;
        return true;            // ends the outer loop
    }
    ++structureSolves_;

    // The residual, the convergence decision and the next iterate
    converged_ = iterate_->update(strong_, acceleration_(), addedMass_());
    step_.residual = iterate_->residual();

    const string problem(placeMarkers());
    if (!problem.empty())
    {
        failure_ = "at t = " + mesh_.time().timeName() + ", " + problem;
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
        ib_->returnToStepStart();
    }
    force_->spread();

    // The iteration's line in the log
    const vector drag(lineDrag_.valid() ? lineDrag_->total() : vector::zero);
    output_->logIteration
    (
        step_, iterate_->worst(), acceleration_->describe(),
        load_->tangential(), rho_*ib_->totalForce(),
        lineDrag_.valid() ? &drag : nullptr
    );

    return stop;
}


bool Foam::canopyCoupling::endTimeStep()
{
    if (!failed() && strong_ && !converged_)
    {
        const string text(output_->notConverged(step_, iterate_->tolerance()));
        if (stopIfNotConverged_)
        {
            failure_ = text;
        }
        else
        {
            WarningInFunction << text.c_str() << endl;
        }
    }

    // The frame moves on with the step; the markers with it
    const bool frameMoved =
        !failed()
     && frame_->moveOn(mesh_.time().deltaTValue(), structure_.time());
    if (frameMoved)
    {
        const string problem(placeMarkers());
        if (!problem.empty())
        {
            frame_->undoMove();
            failure_ =
                "at t = " + mesh_.time().timeName() + " (frame moved), "
              + problem;
        }
    }

    if (failed())
    {
        // Back to the last good state (the start of this step)
        frame_->returnToStepStart();
        returnToStepStart();
        structure_.commit();
        return false;
    }

    {
        sectionTimer timer(structureSeconds_);
        structure_.commit();
    }
    if (lineDrag_.valid())
    {
        // The reaction acts from where the lines are now (and where the
        // next step's drag is computed): a restart, which knows only this
        // state, places it the same way
        sectionTimer timer(ibSeconds_);
        lineDrag_->place(structure_.model(), frame_->origin());
    }
    if (frameMoved || lineDrag_.valid())
    {
        // The force from the markers' and the lines' new places
        force_->spread();
    }

    // The next step starts from the committed structure's interface
    // velocity (not the relaxed iterate), so that a restart, which knows
    // only the structure's state, continues exactly
    iterate_->normalFromStructure();
    step_.frameOrigin = frame_->origin();
    step_.lineDrag = lineDrag_.valid() ? lineDrag_->total() : vector::zero;
    output_->writeSeries(step_);
    if (mesh_.time().writeTime())
    {
        writeStructure();
    }
    return true;
}


// * * * * * * * * * * * * * * * Restart state  * * * * * * * * * * * * * * //

void Foam::canopyCoupling::readState(const IOdictionary& state)
{
    ib_->readState(state);
    if (lineDrag_.valid())
    {
        lineDrag_->readState(state);
    }
    frame_->readState(state);
    addedMass_->readState(state);
    acceleration_->readState(state);
    state.readIfPresent("runStartTime", runStartTime_);
}


void Foam::canopyCoupling::writeState(dictionary& state) const
{
    ib_->writeState(state);
    frame_->writeState(state);
    if (lineDrag_.valid())
    {
        lineDrag_->writeState(state);
    }
    addedMass_->writeState(state);
    acceleration_->writeState(state);
    state.add("runStartTime", runStartTime_);
}


void Foam::canopyCoupling::writeStructure()
{
    {
        sectionTimer timer(structureSeconds_);
        // with a mesh that follows the payload, also in the mesh's frame
        // (canopy-frame.xdmf beside case.foam)
        output_->write
        (
            frame_->meshFrameOrigin(),
            [this](dictionary& state) { writeState(state); }
        );
    }
    Info<< "canopyCoupling: wall time since the run started: structure "
        << structureSeconds_ << " s, immersed boundary " << ibSeconds_
        << " s (the rest of ClockTime is the fluid)" << endl;
}


// ************************************************************************* //
