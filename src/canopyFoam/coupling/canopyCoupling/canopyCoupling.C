/*---------------------------------------------------------------------------*\
    canopyFoam: canopyCoupling.C — immersed-boundary coupling of the flow
    with the libcanopy structure.
\*---------------------------------------------------------------------------*/

#include "canopyCoupling.H"
#include "surfaceInterpolate.H"
#include "addedMassStabiliser.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The coupling's entries that now live in a part's sub-dictionary: each
// stops naming its new place and how to write it there
void rejectMovedEntries(const Foam::scopedEntryReader& coupling)
{
    static const struct
    {
        const char* key;        // the entry in the coupling dictionary
        const char* section;    // the sub-dictionary it moved to
        const char* newKey;     // its name there
        const char* with;       // what the example writes before it
    } moved[] =
    {
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
    };
    for (const auto& m : moved)
    {
        // acceleration and addedMass are sub-dictionaries now: only a
        // value in their place has moved
        if (coupling.found(m.key) && !coupling.dict().isDict(m.key))
        {
            coupling.rejectMoved
            (
                m.key,
                coupling.name(m.section) + '.' + m.newKey,
                std::string(m.section) + " { " + m.with + m.newKey + ' '
              + coupling.given(m.key) + "; }"
            );
        }
    }
}


// The components of vector fields one after another: the secondary data
// of the interface acceleration (interfaceAcceleration.H)
Foam::scalarField packVectors
(
    const Foam::vectorField& a,
    const Foam::vectorField& b
)
{
    Foam::scalarField s(3*(a.size() + b.size()));
    Foam::label i = 0;
    for (const Foam::vectorField* f : {&a, &b})
    {
        for (const Foam::vector& v : *f)
        {
            for (Foam::direction d = 0; d < 3; ++d)
            {
                s[i++] = v[d];
            }
        }
    }
    return s;
}


// The inverse of packVectors (a and b keep their sizes)
void unpackVectors
(
    const Foam::scalarField& s,
    Foam::vectorField& a,
    Foam::vectorField& b
)
{
    Foam::label i = 0;
    for (Foam::vectorField* f : {&a, &b})
    {
        for (Foam::vector& v : *f)
        {
            for (Foam::direction d = 0; d < 3; ++d)
            {
                v[d] = s[i++];
            }
        }
    }
}


} // End anonymous namespace

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::canopyCoupling::updateStencils()
{
    sectionTimer timer(ibSeconds_);
    return ib_->updateStencils();
}


void Foam::canopyCoupling::spreadForce()
{
    sectionTimer timer(ibSeconds_);
    vectorField f(mesh_.nCells(), Zero);
    ib_->spread(f);
    if (lineDrag_.valid())
    {
        lineDrag_->spreadReaction(f, rho_);
    }
    force_.primitiveFieldRef() = f;
    force_.correctBoundaryConditions();
    faceForce_.clear();
}


void Foam::canopyCoupling::readCouplingState(const IOdictionary& state)
{
    ib_->readState(state);
    if (lineDrag_.valid())
    {
        const vectorField L
        (
            state.getOrDefault<vectorField>("lineDragForce", vectorField())
        );
        if (L.size() != lineDrag_->size())
        {
            FatalIOErrorInFunction(state)
                << "Entry 'lineDragForce' holds " << L.size() << " forces,"
                << " but the lines have " << lineDrag_->size() << " sample"
                << " points (was coupling.lineDrag added or changed since it"
                << " was written?)" << exit(FatalIOError);
        }
        lineDrag_->setForces(L);
    }
    frame_->readState(state);
    if (addedMass_->active())
    {
        if (state.found("addedMassBalance"))
        {
            addedMass_->restart
            (
                state, "addedMassBalance",
                state.get<vectorField>("addedMassBalance")
            );
        }
        else
        {
            WarningInFunction
                << "No entry 'addedMassBalance' in " << state.objectPath()
                << ": the added-mass stabiliser's first balance after the"
                << " restart is zero" << endl;
        }
    }
    acceleration_->readState(state);
    state.readIfPresent("runStartTime", runStartTime_);
}


void Foam::canopyCoupling::addCouplingState(dictionary& state) const
{
    ib_->writeState(state);
    frame_->writeState(state);
    if (lineDrag_.valid())
    {
        state.add("lineDragForce", lineDrag_->forces());
    }
    if (addedMass_->active())
    {
        state.add("addedMassBalance", addedMass_->balanceAcceleration());
    }
    acceleration_->writeState(state);
    state.add("runStartTime", runStartTime_);
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


void Foam::canopyCoupling::placeMarkers()
{
    // A trial structure state at t + dt is seen from the frame's origin at
    // t + dt (canopyFrame::originAt)
    ib_->place(structure_.model(), frame_->originAt(structure_.time()));
}


void Foam::canopyCoupling::returnToStepStart()
{
    // A failed step: every part back to the step's start (the last good
    // state written next is then the state the step started from)
    addedMass_->returnToStepStart();
    acceleration_->discardStep();
    structure_.restore();
    placeMarkers();
    updateStencils();
    ib_->returnToStepStart();
    spreadForce();
}


void Foam::canopyCoupling::writeSeries()
{
    couplingOutput::stepSummary step;
    step.load = pressureForce_;
    step.iterations = iteration_;
    step.residual = residual_;
    step.slip = slip_;
    step.subSteps = subSteps_;
    step.frameOrigin = frame_->origin();
    step.lineDrag = lineDrag_.valid() ? lineDrag_->total() : vector::zero;
    output_->writeSeries(step);
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


Foam::canopyCoupling::canopyCoupling
(
    const fvMesh& mesh
)
:
    mesh_(mesh),
    structure_(mesh.time()),
    scheme_(scheme::strong),
    rho_(1.2),
    tolerance_(1e-3),
    Uref_(1),
    rmsResidual_(false),
    acceleration_(),
    lineDrag_(),
    UName_("U"),
    force_
    (
        IOobject
        (
            "canopyForce",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity/dimTime, Zero)
    ),
    iteration_(0),
    structureSolves_(0),
    residual_(0),
    converged_(false),
    subSteps_(0),
    pressureForce_(Zero),
    slip_(0),
    stopIfNotConverged_(true),
    restartFluid_(false),
    failure_(),
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

    scheme_ =
        coupling.choice
        (
            "scheme", {"strong", "explicit"}, "coupling scheme", "strong"
        )
     == "strong"
      ? scheme::strong
      : scheme::explicitScheme;
    rho_ = coupling.positive("rho", "fluid density [kg/m^3]", 1.2);
    tolerance_ = coupling.positive("tolerance", "coupling tolerance", 1e-3);
    Uref_ = coupling.positive("Uref", "velocity scale [m/s]", 1);
    rmsResidual_ =
        coupling.choice
        (
            "residualNorm", {"max", "rms"}, "residual norm", "max"
        )
     == "rms";
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

    // A restart continues from the structure's state at the start time
    // (canopyStructure::startsFrom decides; the constructor has read an
    // initial state otherwise)
    const Time& runTime = mesh.time();
    if (structure_.startsFrom(runTime) == canopyStructure::origin::restart)
    {
        Info<< "canopyCoupling: restarting the structure from its state"
            << " at t = " << runTime.timeName() << " in "
            << canopyStructure::outputPath(runTime) << ".h5" << endl;
        structure_.readState(runTime);
    }
    else if (runTime.value() != 0)
    {
        WarningInFunction
            << "No structure state at the start time " << runTime.timeName()
            << " in " << canopyStructure::outputPath(runTime) << ".h5:"
            << " the canopy starts from its initial shape" << endl;
    }

    // The files; a restart's coupling state (null when there is none)
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

    // The IB force is carried by the markers; a restart reads it and the
    // frame
    if (runTime.value() != 0)
    {
        if (state.valid())
        {
            readCouplingState(state());
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
    placeMarkers();
    if (lineDrag_.valid())
    {
        lineDrag_->place(structure_.model(), frame_->origin());
    }

    // Interface velocity from the structure's initial state
    normalVelocity_ = frame_->normalVelocities(structure_);
    triangleVelocity_ = frame_->velocities(structure_);
    const string problem(updateStencils());
    if (!problem.empty())
    {
        FatalErrorInFunction
            << "At the start: " << problem.c_str() << exit(FatalError);
    }

    spreadForce();

    Info<< "canopyCoupling: structure of " << structure_.nNodes()
        << " nodes, total mass " << structure_.totalMass() << " kg, canopy"
        << " area " << structure_.canopyArea() << " m^2, nominal diameter "
        << output_->nominalDiameter()
        << " m" << nl;
    Info<< "canopyCoupling: "
        << (scheme_ == scheme::strong ? "strong" : "explicit") << " coupling, ";
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
        faceForce_.clear();
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
    iteration_ = 0;
    structureSolves_ = 0;
    converged_ = false;
    residual_ = 0;
}


void Foam::canopyCoupling::forcingIncrement(const volVectorField& U)
{
    sectionTimer timer(ibSeconds_);
    slip_ = ib_->forcingIncrement
    (
        U, normalVelocity_, triangleVelocity_, Uref_, force_
    );
    force_.correctBoundaryConditions();
    faceForce_.clear();
}


const Foam::surfaceScalarField& Foam::canopyCoupling::faceForce() const
{
    if (!faceForce_.valid())
    {
        sectionTimer timer(ibSeconds_);
        faceForce_.reset
        (
            new surfaceScalarField
            (
                "canopyFaceForce",
                (
                    fvc::interpolate(force_)
                  - dimensionedVector
                    (
                        "A", force_.dimensions(), frame_->acceleration()
                    )
                ) & mesh_.Sf()
            )
        );

        // The air entering where the frame sets the far field already
        // moves with the frame: no flux of the fictitious force there
        // (else a spurious pressure gradient builds up across the box,
        // which the pressure sampling at x +- delta n would read as a jump
        // of rho A 2 delta)
        frame_->zeroFictitiousFlux(faceForce_->boundaryFieldRef());
    }
    return faceForce_();
}


bool Foam::canopyCoupling::correctStructure(const volScalarField& p)
{
    ++iteration_;
    if (scheme_ == scheme::explicitScheme && structureSolves_ > 0)
    {
        return false;
    }

    const canopyMarkers& mk = ib_->markers();

    // The load on the cloth (clothLoad): the pressure jump per marker,
    // then per triangle, and a tangential force per marker, to the nodes
    scalarField dpMarker;
    {
        sectionTimer timer(ibSeconds_);
        dpMarker = load_->pressureJump
        (
            mk, ib_->markerForces(), ib_->plusStencil(), ib_->minusStencil(),
            p
        );
    }
    pressureForce_ = sum(dpMarker*mk.areas()*mk.normals());
    vectorField tangentialNodal;
    if (load_->tangential())
    {
        const vectorField tangential
        (
            load_->tangentialForces(mk, ib_->markerForces())
        );
        pressureForce_ += sum(tangential);
        tangentialNodal = mk.toNodes(tangential);
    }

    // The secondary part of the iterate this solve reads (besides the
    // normal velocity): the stabiliser's balancing acceleration and the
    // no-slip velocity the forcing used
    const vectorField balanceUsed(addedMass_->balanceAcceleration());
    const vectorField triangleVelocityUsed(triangleVelocity_);

    label substeps = 0;
    string message;
    bool advanced = false;
    {
        sectionTimer timer(structureSeconds_);
        structure_.restore();
        structure_.setPressureJump(mk.triangleAverage(dpMarker));
        if (addedMass_->active() || lineDrag_.valid() || load_->tangential())
        {
            vectorField nodal(structure_.nNodes(), Zero);
            if (addedMass_->active())
            {
                nodal = addedMass_->balancingForces();
            }
            if (load_->tangential())
            {
                nodal += tangentialNodal;
            }
            if (lineDrag_.valid())
            {
                // From the air's current velocity and the lines at the
                // step's start (the sample points were placed there)
                lineDrag_->compute
                (
                    mesh_.lookupObject<volVectorField>(UName_),
                    structure_.model(), frame_->velocity(), rho_
                );
                lineDrag_->addNodalForces(nodal);
            }
            structure_.setNodalForces(nodal);
        }
        advanced =
            structure_.tryAdvance(mesh_.time().deltaTValue(), substeps, message);
        if (advanced)
        {
            addedMass_->update(structure_, mesh_.time().deltaTValue());
        }
    }
    if (!advanced)
    {
        failure_ =
            "the structure's time step to t = " + mesh_.time().timeName()
          + " failed (coupling iteration " + Foam::name(iteration_) + "): "
          + message;
        converged_ = true;
        return true;            // ends the outer loop
    }
    subSteps_ = substeps;
    ++structureSolves_;

    const scalarField target(frame_->normalVelocities(structure_));
    triangleVelocity_ = frame_->velocities(structure_);
    const label nt = target.size();

    const scalar scale = max(Uref_, nt ? max(mag(target)) : 0);
    bool stop = false;
    // This iteration's change of the interface velocity: its norm is the
    // residual; where it is largest goes to the log
    const scalarField change(target - normalVelocity_);
    residual_ = residualNorm(change)/scale;
    const label worst = findMax(scalarField(mag(change)));
    if (scheme_ == scheme::strong)
    {
        converged_ = residual_ < tolerance_;
        stop = converged_;
        // The stabiliser's balance and the no-slip velocity are the
        // acceleration's secondary data (interfaceAcceleration.H: IQN-ILS
        // moves them with its columns, Aitken hands them the last solve's);
        // on convergence they are the last solve's, so the balance cancels
        // as before
        vectorField balance(addedMass_->balanceAcceleration());
        scalarField secondary(packVectors(balanceUsed, triangleVelocityUsed));
        acceleration_->relax
        (
            normalVelocity_, target,
            secondary, packVectors(balance, triangleVelocity_)
        );
        if (!stop)
        {
            unpackVectors(secondary, balance, triangleVelocity_);
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

    placeMarkers();
    const string problem(updateStencils());
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
    if (scheme_ == scheme::strong && !stop)
    {
        ib_->returnToStepStart();
    }
    spreadForce();

    Info<< "canopyCoupling: iteration " << iteration_
        << ", interface residual " << residual_;
    if (worst >= 0)
    {
        Info<< " (largest at " << structure_.triangleCentres()()[worst]
            << ")";
    }
    Info
        << ", slip " << slip_
        << ", " << acceleration_->describe().c_str()
        << ", structure sub-steps " << substeps
        << (load_->tangential() ? ", load on the cloth " : ", pressure force ")
        << pressureForce_
        << ", IB force " << rho_*ib_->totalForce();
    if (lineDrag_.valid())
    {
        Info<< ", line drag " << lineDrag_->total();
    }
    Info<< endl;

    return stop;
}


bool Foam::canopyCoupling::endTimeStep()
{
    if (!failed() && scheme_ == scheme::strong && !converged_)
    {
        const string text =
            "the coupling did not converge at t = " + mesh_.time().timeName()
          + " in " + Foam::name(iteration_) + " iterations (residual "
          + Foam::name(residual_) + ", slip " + Foam::name(slip_)
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
        placeMarkers();
        const string problem(updateStencils());
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
        spreadForce();
    }

    // The next step starts from the committed structure's interface
    // velocity (not the relaxed iterate), so that a restart, which knows
    // only the structure's state, continues exactly
    normalVelocity_ = frame_->normalVelocities(structure_);
    writeSeries();
    if (mesh_.time().writeTime())
    {
        writeStructure();
    }
    return true;
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
            [this](dictionary& state) { addCouplingState(state); }
        );
    }
    Info<< "canopyCoupling: wall time since the run started: structure "
        << structureSeconds_ << " s, immersed boundary " << ibSeconds_
        << " s (the rest of ClockTime is the fluid)" << endl;
}
