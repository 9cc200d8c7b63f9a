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
    Writing goes through canopy_output (canopy.h). To restart at a given
    time, the step holding that time is looked up in the file's documented
    layout (/steps/NNNNNN groups with a scalar attribute 'time') with the
    HDF5 C library, read-only, and then loaded with
    canopy_model_read_state. In parallel the master also reads that step's
    nodal forces (/steps/NNNNNN/f_ext), which libcanopy has no getter for,
    and broadcasts the whole state.

    The initial state (entry initialState, e.g. a folded canopy written by
    canopyFold) is read the same way, with the HDF5 C library from the
    documented layout: /mesh attributes nodes, springs, triangles;
    /mesh/triangles, /mesh/springs and /mesh/spring_rest_length to check
    that the file holds this structure; x and v of the last /steps group.

\*---------------------------------------------------------------------------*/

#include "canopyStructure.H"
#include "Time.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "Pstream.H"

#include "canopy.h"
#include <hdf5.h>

#include <cmath>
#include <string>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// HDF5's automatic error printing off for the lifetime of the object
class hdf5Quiet
{
    H5E_auto2_t func_;
    void* data_;

public:

    hdf5Quiet()
    :
        func_(nullptr),
        data_(nullptr)
    {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }

    ~hdf5Quiet()
    {
        H5Eset_auto2(H5E_DEFAULT, func_, data_);
    }

    hdf5Quiet(const hdf5Quiet&) = delete;
    void operator=(const hdf5Quiet&) = delete;
};


// An open HDF5 object, closed with the given function
class hdf5Handle
{
    hid_t id_;
    herr_t (*close_)(hid_t);

public:

    hdf5Handle(hid_t id, herr_t (*close)(hid_t))
    :
        id_(id),
        close_(close)
    {}

    ~hdf5Handle()
    {
        if (id_ >= 0) close_(id_);
    }

    hdf5Handle(const hdf5Handle&) = delete;
    void operator=(const hdf5Handle&) = delete;

    hid_t id() const { return id_; }
    bool valid() const { return id_ >= 0; }
};


struct outputStep
{
    std::string name;   // NNNNNN
    int number;
    double time;
};


// Open path.h5 read-only (no file locking, as libcanopy does, so a file
// open for writing elsewhere can be read)
hid_t openReadOnly(const std::string& h5)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0) return -1;
#if H5_VERSION_GE(1, 10, 7)
    H5Pset_file_locking(fapl, 0, 1);
#endif
    const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, fapl);
    H5Pclose(fapl);
    return file;
}


// The steps of an output file (name, number, time); false with a message
// when the file cannot be read
bool listSteps
(
    const std::string& h5,
    std::vector<outputStep>& steps,
    std::string& message
)
{
    steps.clear();
    const hdf5Quiet quiet;

    if (!Foam::isFile(h5))
    {
        message = "'" + h5 + "' does not exist";
        return false;
    }
    const hdf5Handle file(openReadOnly(h5), H5Fclose);
    if (!file.valid())
    {
        message = "cannot open '" + h5 + "' (unreadable or not HDF5)";
        return false;
    }
    if (H5Lexists(file.id(), "steps", H5P_DEFAULT) <= 0)
    {
        return true;    // no steps yet
    }
    const hdf5Handle group(H5Gopen2(file.id(), "steps", H5P_DEFAULT), H5Gclose);
    H5G_info_t info;
    if (!group.valid() || H5Gget_info(group.id(), &info) < 0)
    {
        message = "cannot list /steps in '" + h5 + "'";
        return false;
    }
    for (hsize_t i = 0; i < info.nlinks; ++i)
    {
        char name[64];
        const ssize_t len = H5Lget_name_by_idx
        (
            group.id(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name,
            sizeof(name), H5P_DEFAULT
        );
        if (len <= 0 || len >= ssize_t(sizeof(name)) || len > 9)
        {
            continue;
        }
        bool digits = true;
        int number = 0;
        for (ssize_t c = 0; c < len; ++c)
        {
            digits = digits && name[c] >= '0' && name[c] <= '9';
            number = 10*number + (name[c] - '0');
        }
        if (!digits)
        {
            continue;   // not a step group
        }
        const hdf5Handle step(H5Gopen2(group.id(), name, H5P_DEFAULT), H5Gclose);
        double t = 0;
        bool ok = false;
        if (step.valid())
        {
            const hdf5Handle attr(H5Aopen(step.id(), "time", H5P_DEFAULT), H5Aclose);
            ok = attr.valid()
              && H5Aread(attr.id(), H5T_NATIVE_DOUBLE, &t) >= 0;
        }
        if (!ok)
        {
            message =
                "'" + h5 + "': /steps/" + name + " has no readable attribute"
                " 'time'";
            return false;
        }
        steps.push_back(outputStep{std::string(name), number, t});
    }
    return true;
}


// The n x 3 dataset /steps/<name>/f_ext
bool readNodalForces
(
    const std::string& h5,
    const std::string& stepName,
    const int n,
    std::vector<double>& f,
    std::string& message
)
{
    const hdf5Quiet quiet;
    const std::string path = "/steps/" + stepName + "/f_ext";
    f.assign(3*std::size_t(n), 0.0);
    const hdf5Handle file(openReadOnly(h5), H5Fclose);
    const hdf5Handle set
    (
        file.valid() ? H5Dopen2(file.id(), path.c_str(), H5P_DEFAULT) : -1,
        H5Dclose
    );
    if (!set.valid())
    {
        message = "cannot open " + path + " in '" + h5 + "'";
        return false;
    }
    const hdf5Handle space(H5Dget_space(set.id()), H5Sclose);
    hsize_t dims[2] = {0, 0};
    if
    (
        !space.valid()
     || H5Sget_simple_extent_ndims(space.id()) != 2
     || H5Sget_simple_extent_dims(space.id(), dims, nullptr) != 2
     || dims[0] != hsize_t(n) || dims[1] != 3
    )
    {
        message = path + " in '" + h5 + "' is not " + std::to_string(n) + " x 3";
        return false;
    }
    if
    (
        n > 0
     && H5Dread
        (
            set.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
            f.data()
        ) < 0
    )
    {
        message = "cannot read " + path + " in '" + h5 + "'";
        return false;
    }
    return true;
}


// A dataset of rows x cols (cols 0: one-dimensional) of the given memory
// type (H5T_NATIVE_DOUBLE or H5T_NATIVE_INT), read whole into data
template<class T>
bool readDataset
(
    const hid_t file,
    const std::string& h5,
    const std::string& path,
    const hid_t memType,
    const hsize_t rows,
    const hsize_t cols,
    std::vector<T>& data,
    std::string& message
)
{
    data.assign(std::size_t(rows*(cols > 0 ? cols : 1)), T(0));
    const hdf5Handle set(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid())
    {
        message = "'" + h5 + "' has no dataset " + path;
        return false;
    }
    const hdf5Handle space(H5Dget_space(set.id()), H5Sclose);
    const int rank = cols > 0 ? 2 : 1;
    hsize_t dims[2] = {0, 0};
    if
    (
        !space.valid()
     || H5Sget_simple_extent_ndims(space.id()) != rank
     || H5Sget_simple_extent_dims(space.id(), dims, nullptr) != rank
     || dims[0] != rows
     || (cols > 0 && dims[1] != cols)
    )
    {
        message =
            "'" + h5 + "': " + path + " is not "
          + std::to_string(rows)
          + (cols > 0 ? " x " + std::to_string(cols) : " values");
        return false;
    }
    if
    (
        rows > 0
     && H5Dread(set.id(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data())
      < 0
    )
    {
        message = "cannot read " + path + " in '" + h5 + "'";
        return false;
    }
    return true;
}


// An integer attribute of the object at path (e.g. /mesh nodes)
bool readIntAttribute
(
    const hid_t file,
    const std::string& h5,
    const std::string& path,
    const char* name,
    int& value,
    std::string& message
)
{
    const hdf5Handle obj(H5Oopen(file, path.c_str(), H5P_DEFAULT), H5Oclose);
    const hdf5Handle attr
    (
        obj.valid() ? H5Aopen(obj.id(), name, H5P_DEFAULT) : -1,
        H5Aclose
    );
    if (!attr.valid() || H5Aread(attr.id(), H5T_NATIVE_INT, &value) < 0)
    {
        message =
            "'" + h5 + "' has no readable attribute '" + name + "' on "
          + path;
        return false;
    }
    return true;
}


// The state of the last step of an output file, checked against the
// model: counts, spring ends, triangles and rest lengths. Positions and
// velocities in x and v (3 n each); false with a message.
bool readLastState
(
    const canopy_model* m,
    const std::string& h5,
    std::vector<double>& x,
    std::vector<double>& v,
    std::string& stepName,
    double& stepTime,
    std::string& message
)
{
    std::vector<outputStep> steps;
    if (!listSteps(h5, steps, message))
    {
        return false;
    }
    if (steps.empty())
    {
        message = "'" + h5 + "' holds no steps";
        return false;
    }

    const hdf5Quiet quiet;
    const hdf5Handle file(openReadOnly(h5), H5Fclose);
    if (!file.valid())
    {
        message = "cannot open '" + h5 + "' (unreadable or not HDF5)";
        return false;
    }

    // Counts
    const int n = canopy_model_node_count(m);
    const int ns = canopy_model_spring_count(m);
    const int nt = canopy_model_triangle_count(m);
    const struct { const char* name; int model; } counts[] =
    {
        {"nodes", n}, {"springs", ns}, {"triangles", nt}
    };
    for (const auto& c : counts)
    {
        int inFile = -1;
        if (!readIntAttribute(file.id(), h5, "/mesh", c.name, inFile, message))
        {
            return false;
        }
        if (inFile != c.model)
        {
            message =
                "'" + h5 + "' does not hold this structure: "
              + std::to_string(inFile) + " " + c.name + " in the file, "
              + std::to_string(c.model) + " in the model built from the "
                "dictionary";
            return false;
        }
    }

    // Connectivity and rest lengths
    std::vector<int> tri(3*std::size_t(nt)), ends(2*std::size_t(ns));
    std::vector<double> rest(ns);
    canopy_model_get_triangles(m, tri.data(), nt);
    canopy_model_get_springs(m, ends.data(), rest.data(), nullptr, ns);

    std::vector<int> triFile, endsFile;
    std::vector<double> restFile;
    if
    (
        !readDataset(file.id(), h5, "/mesh/triangles", H5T_NATIVE_INT,
            nt, 3, triFile, message)
     || !readDataset(file.id(), h5, "/mesh/springs", H5T_NATIVE_INT,
            ns, 2, endsFile, message)
     || !readDataset(file.id(), h5, "/mesh/spring_rest_length",
            H5T_NATIVE_DOUBLE, ns, 0, restFile, message)
    )
    {
        return false;
    }
    for (std::size_t i = 0; i < tri.size(); ++i)
    {
        if (tri[i] != triFile[i])
        {
            message =
                "'" + h5 + "' does not hold this structure: triangle "
              + std::to_string(i/3) + " has other vertices in the file";
            return false;
        }
    }
    for (std::size_t i = 0; i < ends.size(); ++i)
    {
        if (ends[i] != endsFile[i])
        {
            message =
                "'" + h5 + "' does not hold this structure: spring "
              + std::to_string(i/2) + " joins other nodes in the file";
            return false;
        }
    }
    for (int k = 0; k < ns; ++k)
    {
        if (!(std::abs(rest[k] - restFile[k]) <= 1e-9*rest[k]))
        {
            Foam::OStringStream os;
            os  << "'" << h5.c_str() << "' does not hold this structure: the"
                << " rest length of spring " << k << " is " << restFile[k]
                << " m in the file, " << rest[k] << " m in the model (was"
                << " it written for another canopy size or edge length?)";
            message = os.str();
            return false;
        }
    }

    // The last step (highest number)
    std::size_t last = 0;
    for (std::size_t s = 1; s < steps.size(); ++s)
    {
        if (steps[s].number > steps[last].number) last = s;
    }
    stepName = steps[last].name;
    stepTime = steps[last].time;
    const std::string group = "/steps/" + stepName;
    if
    (
        !readDataset(file.id(), h5, group + "/x", H5T_NATIVE_DOUBLE, n, 3,
            x, message)
     || !readDataset(file.id(), h5, group + "/v", H5T_NATIVE_DOUBLE, n, 3,
            v, message)
    )
    {
        return false;
    }
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        if (!std::isfinite(x[i]) || !std::isfinite(v[i]))
        {
            message =
                "'" + h5 + "': " + group + " holds a value that is not"
                " finite (node " + std::to_string(i/3) + ")";
            return false;
        }
    }
    return true;
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
    std::vector<outputStep> steps;
    if (!listSteps(h5, steps, message))
    {
        return -1;
    }
    label best = -1;
    for (std::size_t s = 0; s < steps.size(); ++s)
    {
        if
        (
            mag(steps[s].time - t) <= tol
         && (best < 0 || mag(steps[s].time - t) < mag(steps[best].time - t))
        )
        {
            best = label(s);
        }
    }
    if (best < 0)
    {
        OStringStream os;
        os  << "'" << h5.c_str() << "' holds no step at time " << t
            << " (tolerance " << tol << "); ";
        if (steps.empty())
        {
            os  << "it holds no steps";
        }
        else
        {
            scalar tMin = steps[0].time, tMax = steps[0].time;
            label nearest = 0;
            for (std::size_t s = 0; s < steps.size(); ++s)
            {
                tMin = min(tMin, steps[s].time);
                tMax = max(tMax, steps[s].time);
                if (mag(steps[s].time - t) < mag(steps[nearest].time - t))
                {
                    nearest = label(s);
                }
            }
            os  << steps.size() << " steps from t = " << tMin << " to "
                << tMax << ", the nearest at t = " << steps[nearest].time;
        }
        message = os.str();
        return -1;
    }
    stepTime = steps[best].time;
    stepName = steps[best].name;
    return steps[best].number;
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
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::canopyStructure::outputPath(const Time& runTime)
{
    return runTime.globalPath()/"postProcessing"/"canopy"/"canopy";
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

    // This state is already the last step in the file
    if (haveLastWrite_ && mag(t - lastWriteTime_) <= 1e-12*max(1.0, mag(t)))
    {
        return false;
    }

    if (Pstream::master())
    {
        const fileName path(outputPath(runTime));
        string message;
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

    lastWriteTime_ = t;
    haveLastWrite_ = true;
    return true;
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
        std::string stepName, findMessage;
        const label number =
            findStep(h5, t, tol, stepTime, stepName, findMessage);
        if (number < 0)
        {
            ok = false;
            message = "cannot restart the structure at time "
                + Foam::name(t) + ": " + findMessage;
        }
        else if
        (
            canopy_model_read_state(model_.get(), path.c_str(), number)
         != CANOPY_OK
        )
        {
            ok = false;
            message = "cannot restart the structure at time "
                + Foam::name(t) + " from step " + stepName + " of '" + h5
                + "': " + canopy_model_message(model_.get());
        }
        else if (!openOutput(path, CANOPY_OUTPUT_APPEND, message))
        {
            ok = false;
        }
        else if (Pstream::parRun())
        {
            // The state to broadcast: what read_state loaded
            std::vector<double> fExt;
            std::string fMessage;
            if (!readNodalForces(h5, stepName, n, fExt, fMessage))
            {
                ok = false;
                message = "cannot restart the structure: " + fMessage;
            }
            else
            {
                x.setSize(3*n);
                v.setSize(3*n);
                acc.setSize(3*n);
                dp.setSize(nt);
                f.setSize(3*n);
                forAll(f, i)
                {
                    f[i] = fExt[i];
                }
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
            // Positions and velocities first: setting them clears the
            // carried acceleration, which is restored after
            check(canopy_model_set_positions(m, x.cdata(), n), FUNCTION_NAME, "canopy_model_set_positions");
            check(canopy_model_set_velocities(m, v.cdata(), n), FUNCTION_NAME, "canopy_model_set_velocities");
            check
            (
                canopy_model_set_acceleration_state(m, acc.cdata(), n, accValid),
                FUNCTION_NAME, "canopy_model_set_acceleration_state"
            );
            check(canopy_model_set_pressure_jump(m, dp.cdata(), nt), FUNCTION_NAME, "canopy_model_set_pressure_jump");
            check(canopy_model_set_nodal_forces(m, f.cdata(), n), FUNCTION_NAME, "canopy_model_set_nodal_forces");
            check(canopy_model_set_time(m, stepTime), FUNCTION_NAME, "canopy_model_set_time");
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
    lastWriteTime_ = stepTime;
    haveLastWrite_ = true;

    Info<< "canopyStructure: restarted from " << h5 << " at time "
        << stepTime << endl;
}


Foam::fileName Foam::canopyStructure::initialStateFile
(
    const Time& runTime
) const
{
    const word key("initialState");
    const entry* e = dict_.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return fileName();
    }
    if (e->isDict())
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' must be a file name (e.g. "
            << defaultInitialStateName << "), not a sub-dictionary" << nl
            << exit(FatalIOError);
    }
    ITstream& is = e->stream();
    if (is.size() != 1 || !is[0].isStringType())
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' must be a single file name (e.g. "
            << defaultInitialStateName << "), found " << is.toString().c_str()
            << nl << exit(FatalIOError);
    }
    fileName file(is[0].stringToken());
    file.expand();
    if (file.ext() != "h5")
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' = " << file << " must name an HDF5"
            << " file ending in .h5 (as canopyFold writes)" << nl
            << exit(FatalIOError);
    }
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
        std::vector<double> xs, vs;
        std::string name, why;
        double t = 0;
        if (!isFile(h5))
        {
            ok = false;
            message = "'" + h5 + "' does not exist (run canopyFold first?)";
        }
        else if (!readLastState(model_.get(), h5, xs, vs, name, t, why))
        {
            ok = false;
            message = why;
        }
        else
        {
            x.setSize(3*n);
            v.setSize(3*n);
            forAll(x, i)
            {
                x[i] = xs[i];
                v[i] = vs[i];
            }
            stepTime = t;
            stepName = name;
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

    // initialVelocity comes on top of the state's velocities
    for (label i = 0; i < n; ++i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            v[3*i + d] += initialVelocity_[d];
        }
    }

    canopy_model* m = model_.get();
    check
    (
        canopy_model_set_positions(m, x.cdata(), n),
        FUNCTION_NAME, "canopy_model_set_positions"
    );
    check
    (
        canopy_model_set_velocities(m, v.cdata(), n),
        FUNCTION_NAME, "canopy_model_set_velocities"
    );

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
