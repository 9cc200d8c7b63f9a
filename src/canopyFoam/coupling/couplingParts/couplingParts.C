/*---------------------------------------------------------------------------*\
    canopyFoam: couplingParts.C — the coupling's parts from their
    sub-dictionaries, and their restart state.
\*---------------------------------------------------------------------------*/

#include "couplingParts.H"

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::couplingParts::subDictionaries()
{
    return
    {
        "forcing", "load", "acceleration", "addedMass", "lineDrag", "frame"
    };
}


void Foam::couplingParts::rejectMovedEntries
(
    const scopedEntryReader& coupling
)
{
    // {old entry, its sub-dictionary, its name there, what the
    // sub-dictionary needs beside it}
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingParts::couplingParts
(
    const scopedEntryReader& coupling,
    const scalar rho,
    const fvMesh& mesh,
    canopyStructure& structure,
    scalar& ibSeconds
)
:
    runStartTime_(mesh.time().startTime().value())
{
    load_ = clothLoad::New(coupling.optionalSubReader("load"), rho);
    addedMass_.reset
    (
        new addedMassStabiliser
        (
            coupling.optionalSubReader("addedMass"), structure
        )
    );
    acceleration_ =
        interfaceAcceleration::New(coupling.optionalSubReader("acceleration"));
    frame_ =
        canopyFrame::New(coupling.optionalSubReader("frame"), mesh, structure);

    // The files; on a restart the structure's state at the start time
    // and the coupling's (null when there is none)
    output_.reset(new couplingOutput(mesh, structure, rho));
    const autoPtr<localIOdictionary> state(output_->readState());

    // The markers on the canopy, their stencils and forces: with a
    // restart's subdivision levels (so that its markers match the forces
    // it carries)
    forcing_.reset
    (
        new ibForcing
        (
            coupling.optionalSubReader("forcing"), mesh, structure,
            state.valid()
          ? state->lookupOrDefault<labelList>("markerLevels", labelList())
          : labelList()
        )
    );
    addedMass_->filterThrough(forcing_());
    if (coupling.optionalDict("lineDrag"))
    {
        lineDrag_.reset
        (
            new lineDrag
            (
                coupling.optionalSubReader("lineDrag"), mesh,
                forcing_->kernel(), structure.model(), forcing_->spacing()
            )
        );
    }
    force_.reset
    (
        new couplingForce
        (
            mesh, forcing_(), lineDragPtr(), frame_(), rho, ibSeconds
        )
    );

    if (state.valid())
    {
        readState(state());
    }
}


// * * * * * * * * * * * * * * * Restart state  * * * * * * * * * * * * * * //

void Foam::couplingParts::readState(const dictionary& state)
{
    forcing_->readState(state);
    if (lineDrag_.valid())
    {
        lineDrag_->readState(state);
    }
    frame_->readState(state);
    addedMass_->readState(state);
    acceleration_->readState(state);
    state.readIfPresent("runStartTime", runStartTime_);
}


void Foam::couplingParts::writeState(dictionary& state) const
{
    forcing_->writeState(state);
    frame_->writeState(state);
    if (lineDrag_.valid())
    {
        lineDrag_->writeState(state);
    }
    addedMass_->writeState(state);
    acceleration_->writeState(state);
    state.add("runStartTime", runStartTime_);
}


void Foam::couplingParts::writeInfo(Ostream& os) const
{
    forcing_->writeInfo(os);
    if (lineDrag_.valid())
    {
        lineDrag_->writeInfo(os);
    }
    frame_->writeInfo(os);
}


// ************************************************************************* //
