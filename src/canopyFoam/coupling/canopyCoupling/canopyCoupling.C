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


Foam::scalar Foam::canopyCoupling::residualNorm
(
    const scalarField& change
) const
{
    if (change.empty())
    {
        return 0;
    }
    if (!rmsResidual_)
    {
        return max(mag(change));
    }
    const scalarField areas(structure_.triangleAreas());
    return Foam::sqrt(sum(areas*sqr(change))/max(sum(areas), VSMALL));
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
    tolerance_ = coupling.positive("tolerance", "coupling tolerance", 1e-3);
    Uref_ = coupling.positive("Uref", "velocity scale [m/s]", 1);
    rmsResidual_ =
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

    // The files; on a restart the structure's state at the start time
    // and the coupling's (null when there is none)
    const Time& runTime = mesh.time();
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
    if (runTime.value() != 0)
    {
        if (state.valid())
        {
            readState(state());
        }
        else
        {
            WarningInFunction
                << "No " << output_->statePath() << ": the immersed-boundary"
                << " force restarts from zero and the frame from the payload"
                << endl;
        }
    }
    frame_->startAt(structure_.time());
    const string problem(placeMarkers());
    if (lineDrag_.valid())
    {
        lineDrag_->place(structure_.model(), frame_->origin());
    }

    // Interface velocity from the structure's initial state
    normalVelocity_ = frame_->normalVelocities(structure_);
    triangleVelocity_ = frame_->velocities(structure_);
    if (!problem.empty())
    {
        FatalErrorInFunction
            << "At the start: " << problem.c_str() << exit(FatalError);
    }
    force_->spread();

    Info<< "canopyCoupling: structure of " << structure_.nNodes()
        << " nodes, total mass " << structure_.totalMass() << " kg, canopy"
        << " area " << structure_.canopyArea() << " m^2, nominal diameter "
        << output_->nominalDiameter() << " m" << nl
        << "canopyCoupling: " << (strong_ ? "strong" : "explicit")
        << " coupling, ";
    ib_->writeInfo(Info);
    if (lineDrag_.valid())
    {
        Info<< ", line drag at " << lineDrag_->size() << " points ("
            << lineDrag_->nOutside() << " outside the mesh)";
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
        normalVelocity_ = frame_->normalVelocities(structure_);
        triangleVelocity_ = frame_->velocities(structure_);
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
        force_->forcingIncrement(U, normalVelocity_, triangleVelocity_, Uref_);
}


bool Foam::canopyCoupling::correctStructure(const volScalarField& p)
{
    ++step_.iterations;
    if (!strong_ && structureSolves_ > 0)
    {
        return false;
    }

    // The load on the cloth (clothLoad): the pressure jump per marker,
    // then per triangle, and a tangential force per marker, to the nodes
    const canopyMarkers& mk = ib_->markers();
    scalarField dpMarker;
    {
        sectionTimer timer(ibSeconds_);
        dpMarker = load_->pressureJump
        (
            mk, ib_->markerForces(), ib_->plusStencil(), ib_->minusStencil(),
            p
        );
    }
    step_.load = sum(dpMarker*mk.areas()*mk.normals());
    vectorField tangentialNodal;
    if (load_->tangential())
    {
        const vectorField tangential
        (
            load_->tangentialForces(mk, ib_->markerForces())
        );
        step_.load += sum(tangential);
        tangentialNodal = mk.toNodes(tangential);
    }

    // The secondary part of the iterate this solve reads (besides the
    // normal velocity): the stabiliser's balancing acceleration and the
    // no-slip velocity the forcing used
    vectorField balance(addedMass_->balanceAcceleration());
    vectorField velocity(triangleVelocity_);

    // The structure's time step from its start under these loads
    string message;
    bool advanced = false;
    {
        sectionTimer timer(structureSeconds_);
        structure_.restore();
        structure_.setPressureJump(mk.triangleAverage(dpMarker));
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

    // This iteration's change of the interface velocity: its norm is the
    // residual; where it is largest goes to the log
    const scalarField target(frame_->normalVelocities(structure_));
    triangleVelocity_ = frame_->velocities(structure_);
    const scalar scale = max(Uref_, target.size() ? max(mag(target)) : 0);
    const scalarField change(target - normalVelocity_);
    step_.residual = residualNorm(change)/scale;
    const label worst = findMax(scalarField(mag(change)));
    if (strong_)
    {
        // The next iterate; the stabiliser's balance and the no-slip
        // velocity are the acceleration's secondary data (IQN-ILS moves
        // them with its columns, Aitken hands them the last solve's); on
        // convergence they stay the last solve's, so the balance cancels
        converged_ = step_.residual < tolerance_;
        acceleration_->relax
        (
            normalVelocity_, target, balance, velocity,
            addedMass_->balanceAcceleration(), triangleVelocity_
        );
        if (!converged_)
        {
            triangleVelocity_ = velocity;
            addedMass_->setBalanceAcceleration(balance);
        }
    }
    else
    {
        // Explicit: one structure solve per step; the PIMPLE outer loop
        // runs its own course
        normalVelocity_ = target;
        converged_ = true;
    }

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

    Info<< "canopyCoupling: iteration " << step_.iterations
        << ", interface residual " << step_.residual;
    if (worst >= 0)
    {
        Info<< " (largest at " << structure_.triangleCentres()()[worst]
            << ")";
    }
    Info<< ", slip " << step_.slip
        << ", " << acceleration_->describe().c_str()
        << ", structure sub-steps " << step_.subSteps
        << (load_->tangential() ? ", load on the cloth " : ", pressure force ")
        << step_.load << ", IB force " << rho_*ib_->totalForce();
    if (lineDrag_.valid())
    {
        Info<< ", line drag " << lineDrag_->total();
    }
    Info<< endl;

    return stop;
}


bool Foam::canopyCoupling::endTimeStep()
{
    if (!failed() && strong_ && !converged_)
    {
        const string text =
            "the coupling did not converge at t = " + mesh_.time().timeName()
          + " in " + Foam::name(step_.iterations) + " iterations (residual "
          + Foam::name(step_.residual) + ", slip " + Foam::name(step_.slip)
          + ", tolerance " + Foam::name(tolerance_) + ")";
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
    normalVelocity_ = frame_->normalVelocities(structure_);
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
