// canopyStructureIO.C: canopyStructure output (HDF5 + XDMF through libcanopy, master rank only) and restart (readState, stateAvailable).
/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | canopyFoam: parachute fluid-structure interaction
   \\    /   O peration     | for OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of canopyFoam, a plugin for OpenFOAM, and like OpenFOAM
    is distributed under the GNU General Public License version 3 or later.

Description
    Writing goes through canopy_output, reading through canopy_reader
    (canopy.h); this file knows nothing of the HDF5 layout. To restart at
    a given time, the master finds the step nearest that time within the
    tolerance (canopy_reader_find_step) and loads it
    (canopy_reader_read_state, which checks that the file holds this
    structure); in parallel it also takes the step's nodal forces
    (canopy_reader_get_nodal_forces) and broadcasts the whole state.

    The initial state (entry initialState, e.g. a folded canopy written by
    canopyFold) is the last step's positions and velocities, the latter
    plus initialVelocity (canopy_reader_read_motion, with the same
    structure checks), read on the master and broadcast.

\*---------------------------------------------------------------------------*/

#include "canopyStructure.H"
#include "scopedEntryReader.H"
#include "Time.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "Pstream.H"

#include "canopy.h"

#include <cstdio>
#include <string>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

// A canopy_reader, destroyed with the object
class outputReader
{
    canopy_reader* reader_;

public:

    outputReader()
    :
        reader_(nullptr)
    {
        if (canopy_reader_create(&reader_) != CANOPY_OK)
        {
            FatalErrorInFunction
                << "libcanopy cannot make a reader (out of memory)"
                << Foam::exit(Foam::FatalError);
        }
    }

    ~outputReader()
    {
        canopy_reader_destroy(&reader_);
    }

    outputReader(const outputReader&) = delete;
    void operator=(const outputReader&) = delete;

    canopy_reader* get() const { return reader_; }

    std::string message() const
    {
        return canopy_reader_message(reader_);
    }
};


// The group name NNNNNN of step number `number`
std::string stepGroupName(const int number)
{
    char name[32];
    std::snprintf(name, sizeof(name), "%06d", number);
    return name;
}


// path.h5 -> path, the form libcanopy takes
std::string withoutH5(const Foam::fileName& h5)
{
    return h5.ext() == "h5" ? h5.lessExt() : h5;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::canopyStructure::timeTolerance(const Time& runTime)
{
    const scalar t = runTime.value();
    return max(0.5*runTime.deltaTValue(), 1e-9*max(1.0, mag(t)));
}


Foam::label Foam::canopyStructure::findStep
(
    const fileName& h5,
    const scalar t,
    const scalar tol,
    scalar& stepTime,
    std::string& stepName,
    std::string& message
) const
{
    const outputReader reader;
    int index = -1, number = -1;
    double time = 0;
    if
    (
        canopy_reader_open(reader.get(), withoutH5(h5).c_str()) != CANOPY_OK
     || canopy_reader_find_step(reader.get(), t, tol, &index) != CANOPY_OK
     || canopy_reader_step(reader.get(), index, &number, &time) != CANOPY_OK
    )
    {
        message = reader.message();
        return -1;
    }
    stepTime = time;
    stepName = stepGroupName(number);
    return number;
}


bool Foam::canopyStructure::openOutput
(
    const fileName& path,
    const int mode,
    string& message
)
{
    output_.reset();
    mkDir(path.path());
    canopy_output* o = nullptr;
    if
    (
        canopy_output_create
        (
            model_.get(), path.c_str(), static_cast<canopy_output_mode>(mode),
            &o
        )
     != CANOPY_OK
    )
    {
        message =
            "libcanopy cannot "
          + std::string(mode == CANOPY_OUTPUT_APPEND ? "append to" : "create")
          + " the output " + path + ".h5: "
          + canopy_model_message(model_.get());
        return false;
    }
    output_.reset(o);
    outputFile_ = path;
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::canopyStructure::outputPath(const Time& runTime)
{
    return runTime.globalPath()/"postProcessing"/"canopy"/"canopy";
}


void Foam::canopyStructure::createOutput(const fileName& path)
{
    if (Pstream::master())
    {
        string message;
        if (!openOutput(path, CANOPY_OUTPUT_CREATE, message))
        {
            FatalErrorInFunction
                << message.c_str() << nl << exit(FatalError);
        }
    }
    haveLastWrite_ = false;
}


bool Foam::canopyStructure::write
(
    const fileName& path,
    const vector* frameOrigin
)
{
    const scalar t = time();

    // This state is already the last step in the file
    if
    (
        haveLastWrite_ && path == outputFile_
     && mag(t - lastWriteTime_) <= 1e-12*max(1.0, mag(t))
    )
    {
        return false;
    }

    if (Pstream::master())
    {
        string message;
        if (output_ && path != outputFile_)
        {
            output_.reset();
        }
        if
        (
            !output_
         && !openOutput
            (
                path,
                restarted_ ? CANOPY_OUTPUT_APPEND : CANOPY_OUTPUT_CREATE,
                message
            )
        )
        {
            FatalErrorInFunction
                << message.c_str() << nl << exit(FatalError);
        }
        const double origin[3] =
        {
            frameOrigin ? frameOrigin->x() : 0,
            frameOrigin ? frameOrigin->y() : 0,
            frameOrigin ? frameOrigin->z() : 0
        };
        const canopy_status st = frameOrigin
          ? canopy_output_write_framed(output_.get(), model_.get(), origin)
          : canopy_output_write(output_.get(), model_.get());
        if (st != CANOPY_OK)
        {
            FatalErrorInFunction
                << "libcanopy cannot write the step at time " << t << " to "
                << path << ".h5: " << canopy_output_message(output_.get())
                << nl << exit(FatalError);
        }
    }
    outputFile_ = path;

    lastWriteTime_ = t;
    haveLastWrite_ = true;
    return true;
}


bool Foam::canopyStructure::write
(
    const Time& runTime,
    const vector* frameOrigin
)
{
    const scalar t = time();
    if (!warnedTime_ && mag(t - runTime.value()) > timeTolerance(runTime))
    {
        WarningInFunction
            << "The structure's time " << t << " differs from the run time "
            << runTime.value() << "; the output step is stamped with the "
            << "structure's time" << endl;
        warnedTime_ = true;
    }
    return write(outputPath(runTime), frameOrigin);
}


bool Foam::canopyStructure::stateAvailable
(
    const Time& runTime,
    const scalar tolerance
) const
{
    bool found = false;
    if (Pstream::master())
    {
        const scalar tol = tolerance >= 0 ? tolerance : timeTolerance(runTime);
        scalar stepTime = 0;
        std::string stepName, message;
        found =
            findStep
            (
                outputPath(runTime) + ".h5", runTime.value(), tol, stepTime,
                stepName, message
            ) >= 0;
    }
    Pstream::scatter(found);
    return found;
}


void Foam::canopyStructure::readState
(
    const Time& runTime,
    const scalar tolerance
)
{
    const scalar t = runTime.value();
    const scalar tol = tolerance >= 0 ? tolerance : timeTolerance(runTime);
    const fileName path(outputPath(runTime));
    const fileName h5(path + ".h5");

    // Reopened below in APPEND mode
    output_.reset();

    const int n = nNodes();
    const int nt = nTriangles();

    bool ok = true;
    string message;
    scalar stepTime = 0;
    List<scalar> x, v, f, dp, acc;
    label accValid = 0;

    if (Pstream::master())
    {
        const outputReader reader;
        int index = -1, number = -1;
        double foundTime = 0;
        if
        (
            canopy_reader_open(reader.get(), path.c_str()) != CANOPY_OK
         || canopy_reader_find_step(reader.get(), t, tol, &index) != CANOPY_OK
         || canopy_reader_step(reader.get(), index, &number, &foundTime)
         != CANOPY_OK
        )
        {
            ok = false;
            message = "cannot restart the structure at time "
                + Foam::name(t) + ": " + reader.message();
        }
        else if
        (
            canopy_reader_read_state(reader.get(), index, model_.get())
         != CANOPY_OK
        )
        {
            ok = false;
            message = "cannot restart the structure at time "
                + Foam::name(t) + " from step " + stepGroupName(number)
                + " of '" + h5 + "': " + reader.message();
        }
        else if (Pstream::parRun())
        {
            // The state to broadcast: what read_state loaded
            f.setSize(3*n);
            if
            (
                canopy_reader_get_nodal_forces
                (
                    reader.get(), index, f.begin(), n
                )
             != CANOPY_OK
            )
            {
                ok = false;
                message = "cannot restart the structure: " + reader.message();
            }
            else
            {
                x.setSize(3*n);
                v.setSize(3*n);
                acc.setSize(3*n);
                dp.setSize(nt);
                int valid = 0;
                check
                (
                    canopy_model_get_positions(model_.get(), x.begin(), n),
                    FUNCTION_NAME, "canopy_model_get_positions"
                );
                check
                (
                    canopy_model_get_velocities(model_.get(), v.begin(), n),
                    FUNCTION_NAME, "canopy_model_get_velocities"
                );
                check
                (
                    canopy_model_get_acceleration_state
                    (
                        model_.get(), acc.begin(), n, &valid
                    ),
                    FUNCTION_NAME, "canopy_model_get_acceleration_state"
                );
                check
                (
                    canopy_model_get_pressure_jump(model_.get(), dp.begin(), nt),
                    FUNCTION_NAME, "canopy_model_get_pressure_jump"
                );
                accValid = valid;
                stepTime = time();
            }
        }
        else
        {
            stepTime = time();
        }
        if (ok && !openOutput(path, CANOPY_OUTPUT_APPEND, message))
        {
            ok = false;
        }
    }

    Pstream::scatter(ok);
    Pstream::scatter(message);
    if (!ok)
    {
        FatalErrorInFunction
            << message.c_str() << nl << exit(FatalError);
    }

    if (Pstream::parRun())
    {
        Pstream::scatter(stepTime);
        Pstream::scatter(x);
        Pstream::scatter(v);
        Pstream::scatter(acc);
        Pstream::scatter(accValid);
        Pstream::scatter(dp);
        Pstream::scatter(f);

        if (!Pstream::master())
        {
            canopy_model* m = model_.get();
            // The master's state exactly as it read it (set_state: the
            // setters one by one would project the guided nodes' vectors
            // again and change their last bits)
            check
            (
                canopy_model_set_state
                (
                    m, stepTime, x.cdata(), v.cdata(), acc.cdata(), accValid,
                    n
                ),
                FUNCTION_NAME, "canopy_model_set_state"
            );
            check(canopy_model_set_pressure_jump(m, dp.cdata(), nt), FUNCTION_NAME, "canopy_model_set_pressure_jump");
            check(canopy_model_set_nodal_forces(m, f.cdata(), n), FUNCTION_NAME, "canopy_model_set_nodal_forces");
        }

        if (!identicalOnAllRanks())
        {
            FatalErrorInFunction
                << "After restarting from " << h5 << " at time " << t
                << " the structure differs between ranks" << nl
                << exit(FatalError);
        }
    }

    restarted_ = true;
    outputFile_ = path;
    lastWriteTime_ = stepTime;
    haveLastWrite_ = true;

    Info<< "canopyStructure: restarted from " << h5 << " at time "
        << stepTime << endl;
}


Foam::canopyStructure::origin Foam::canopyStructure::startsFrom
(
    const Time& runTime
) const
{
    // The entry is checked first, whatever the run starts from
    const bool haveFile = !initialStateFile(runTime).empty();
    if (runTime.value() != 0 && stateAvailable(runTime))
    {
        return origin::restart;
    }
    return haveFile ? origin::initialState : origin::built;
}


Foam::fileName Foam::canopyStructure::initialStateFile
(
    const Time& runTime
) const
{
    const scopedEntryReader top(dict_, "");
    if (!top.found("initialState"))
    {
        return fileName();
    }
    fileName file
    (
        top.fileNameWithExt
        (
            "initialState",
            "an HDF5 file as canopyFold writes, e.g. "
          + defaultInitialStateName,
            "h5"
        )
    );
    if (!file.isAbsolute())
    {
        file = runTime.globalPath()/file;
    }
    return file;
}


void Foam::canopyStructure::readInitialState(const fileName& h5)
{
    const int n = nNodes();

    bool ok = true;
    string message;
    List<scalar> x, v;
    scalar stepTime = 0;
    string stepName;

    if (Pstream::master())
    {
        // The last step's positions, and its velocities with initialVelocity
        // on top, checked against this structure by libcanopy
        const outputReader reader;
        const double offset[3] =
        {
            initialVelocity_.x(), initialVelocity_.y(), initialVelocity_.z()
        };
        int number = -1;
        double t = 0;
        if (!isFile(h5))
        {
            ok = false;
            message = "'" + h5 + "' does not exist (run canopyFold first?)";
        }
        else if
        (
            canopy_reader_open(reader.get(), withoutH5(h5).c_str())
         != CANOPY_OK
        )
        {
            ok = false;
            message = reader.message();
        }
        else if (canopy_reader_step_count(reader.get()) == 0)
        {
            ok = false;
            message = "'" + h5 + "' holds no steps";
        }
        else
        {
            const int last = canopy_reader_step_count(reader.get()) - 1;
            if
            (
                canopy_reader_step(reader.get(), last, &number, &t)
             != CANOPY_OK
             || canopy_reader_read_motion
                (
                    reader.get(), last, model_.get(), offset
                )
             != CANOPY_OK
            )
            {
                ok = false;
                message = reader.message();
            }
            else
            {
                x.setSize(3*n);
                v.setSize(3*n);
                check
                (
                    canopy_model_get_positions(model_.get(), x.begin(), n),
                    FUNCTION_NAME, "canopy_model_get_positions"
                );
                check
                (
                    canopy_model_get_velocities(model_.get(), v.begin(), n),
                    FUNCTION_NAME, "canopy_model_get_velocities"
                );
                stepTime = t;
                stepName = stepGroupName(number);
            }
        }
    }

    Pstream::scatter(ok);
    Pstream::scatter(message);
    if (!ok)
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'initialState' = " << h5 << ": " << message.c_str()
            << nl << exit(FatalIOError);
    }
    Pstream::scatter(x);
    Pstream::scatter(v);
    Pstream::scatter(stepTime);
    Pstream::scatter(stepName);

    if (!Pstream::master())
    {
        // The master's motion exactly as it read it (its velocities already
        // on the guide wire), no carried acceleration, as read_motion leaves
        canopy_model* m = model_.get();
        check
        (
            canopy_model_set_state
            (
                m, time(), x.cdata(), v.cdata(), nullptr, 0, n
            ),
            FUNCTION_NAME, "canopy_model_set_state"
        );
    }

    if (!identicalOnAllRanks())
    {
        FatalErrorInFunction
            << "After reading the initial state " << h5
            << " the structure differs between ranks" << nl
            << exit(FatalError);
    }

    Info<< "canopyStructure: initial state from " << h5 << " (step "
        << stepName.c_str() << ", written at t = " << stepTime
        << " of its pre-simulation)" << endl;
}


// ************************************************************************* //
