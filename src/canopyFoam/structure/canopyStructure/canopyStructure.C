// canopyStructure.C: construction, destruction and the thin wrappers of canopyStructure over libcanopy (state, loads, time integration, diagnostics, parallel check).
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

\*---------------------------------------------------------------------------*/

#include "canopyStructure.H"
#include "prescribedRotation.H"
#include "Time.H"
#include "IOdictionary.H"
#include <fenv.h>
#include "uniformDimensionedFields.H"
#include "PstreamReduceOps.H"

#include "canopy.h"

#include <cstdint>
#include <cstring>
#include <type_traits>
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(canopyStructure, 0);
}

const Foam::word Foam::canopyStructure::propertiesName("canopyProperties");

const Foam::fileName Foam::canopyStructure::defaultInitialStateName
(
    "constant/canopyInitialState.h5"
);


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// OpenFOAM fields cross the C ABI as plain arrays: a vector is three
// contiguous doubles and a label an int.
static_assert(std::is_same<Foam::scalar, double>::value, "scalar != double");
static_assert(sizeof(Foam::vector) == 3*sizeof(double), "vector layout");
static_assert(sizeof(Foam::label) == sizeof(int), "label != int");

inline double* raw(Foam::UList<Foam::vector>& f)
{
    return reinterpret_cast<double*>(f.begin());
}

inline const double* raw(const Foam::UList<Foam::vector>& f)
{
    return reinterpret_cast<const double*>(f.cdata());
}

// FNV-1a over the bytes of a block of memory
inline void hashBytes(std::uint64_t& h, const void* data, std::size_t n)
{
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i)
    {
        h ^= p[i];
        h *= 1099511628211ULL;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::canopyStructure::modelDeleter::operator()(canopy_model* m) const
{
    canopy_model_destroy(&m);
}


void Foam::canopyStructure::outputDeleter::operator()(canopy_output* o) const
{
    canopy_output_destroy(&o);
}


void Foam::canopyStructure::check
(
    const int status,
    const char* caller,
    const char* call
) const
{
    if (status != CANOPY_OK)
    {
        // The library's message starts with the status name
        FatalErrorIn(caller)
            << "libcanopy " << call << " failed: "
            << canopy_model_message(model_.get()) << nl
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::canopyStructure::canopyStructure
(
    const Time& runTime,
    const bool useInitialState
)
:
    dict_(),
    model_(nullptr),
    output_(nullptr),
    attachments_(),
    payloadNode_(-1),
    restarted_(false),
    lastWriteTime_(0),
    haveLastWrite_(false),
    warnedTime_(false),
    builtCanopyArea_(0),
    initialVelocity_(Zero),
    nodalForcesChanged_(false),
    motion_(nullptr),
    bendingDampingUntil_(VGREAT)
{
    {
        // A number beyond the double range (1e999) overflows in
        // OpenFOAM's parser, which dies of SIGFPE with FOAM_SIGFPE's
        // overflow trap on; with the trap off for the read the parser
        // stops with an IO error at the entry's line instead
        const int traps = fegetexcept();
        fedisableexcept(FE_OVERFLOW);
        const IOdictionary properties
        (
            IOobject
            (
                propertiesName,
                runTime.constant(),
                runTime,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false               // not registered: the caller owns nothing
            )
        );
        feclearexcept(FE_OVERFLOW);
        feenableexcept(traps);
        dict_ = properties;
    }

    // Gravity default: constant/g (uniformDimensionedVectorField) if present
    vector g(0, 0, -9.81);
    IOobject gIO
    (
        "g",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (canopyCompat::headerOk<uniformDimensionedVectorField>(gIO))
    {
        g = uniformDimensionedVectorField(gIO).value();
    }

    build(g);

    // The initial state (e.g. a folded canopy), unless the run restarts
    // from the structure's own output (which canopyCoupling then reads)
    if (useInitialState && startsFrom(runTime) == origin::initialState)
    {
        readInitialState(initialStateFile(runTime));
    }
}


Foam::canopyStructure::canopyStructure
(
    const dictionary& dict,
    const vector& defaultGravity
)
:
    dict_(dict),
    model_(nullptr),
    output_(nullptr),
    attachments_(),
    payloadNode_(-1),
    restarted_(false),
    lastWriteTime_(0),
    haveLastWrite_(false),
    warnedTime_(false),
    builtCanopyArea_(0),
    initialVelocity_(Zero),
    nodalForcesChanged_(false),
    motion_(nullptr),
    bendingDampingUntil_(VGREAT)
{
    build(defaultGravity);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::canopyStructure::~canopyStructure()
{
    output_.reset();    // closes the HDF5 file
    model_.reset();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::canopyStructure::nNodes() const
{
    return canopy_model_node_count(model_.get());
}


Foam::label Foam::canopyStructure::nSprings() const
{
    return canopy_model_spring_count(model_.get());
}


Foam::label Foam::canopyStructure::nTriangles() const
{
    return canopy_model_triangle_count(model_.get());
}


Foam::word Foam::canopyStructure::integrator() const
{
    return word(canopy_model_integrator(model_.get()));
}


Foam::scalar Foam::canopyStructure::time() const
{
    return canopy_model_time(model_.get());
}


void Foam::canopyStructure::setTime(const scalar t)
{
    check
    (
        canopy_model_set_time(model_.get(), t),
        FUNCTION_NAME, "canopy_model_set_time"
    );
}


Foam::tmp<Foam::pointField> Foam::canopyStructure::points() const
{
    tmp<pointField> tfld(new pointField(nNodes()));
    check
    (
        canopy_model_get_positions(model_.get(), raw(tfld.ref()), nNodes()),
        FUNCTION_NAME, "canopy_model_get_positions"
    );
    return tfld;
}


Foam::tmp<Foam::vectorField> Foam::canopyStructure::velocities() const
{
    tmp<vectorField> tfld(new vectorField(nNodes()));
    check
    (
        canopy_model_get_velocities(model_.get(), raw(tfld.ref()), nNodes()),
        FUNCTION_NAME, "canopy_model_get_velocities"
    );
    return tfld;
}


Foam::tmp<Foam::vectorField> Foam::canopyStructure::accelerationState() const
{
    tmp<vectorField> tfld(new vectorField(nNodes(), Zero));
    int valid = 0;
    check
    (
        canopy_model_get_acceleration_state
        (
            model_.get(), raw(tfld.ref()), nNodes(), &valid
        ),
        FUNCTION_NAME, "canopy_model_get_acceleration_state"
    );
    if (!valid)
    {
        FatalErrorInFunction
            << "The structure holds no step-end acceleration (integrator "
            << integrator() << " at t = " << time() << "): only newmark and "
            << "hht keep one, from the end of their last step"
            << exit(FatalError);
    }
    return tfld;
}


Foam::tmp<Foam::scalarField> Foam::canopyStructure::masses() const
{
    tmp<scalarField> tfld(new scalarField(nNodes()));
    check
    (
        canopy_model_get_masses(model_.get(), tfld.ref().begin(), nNodes()),
        FUNCTION_NAME, "canopy_model_get_masses"
    );
    return tfld;
}


Foam::scalar Foam::canopyStructure::totalMass() const
{
    return sum(masses());
}


Foam::triFaceList Foam::canopyStructure::triangles() const
{
    const label nt = nTriangles();
    List<int> tri(3*nt);
    check
    (
        canopy_model_get_triangles(model_.get(), tri.begin(), nt),
        FUNCTION_NAME, "canopy_model_get_triangles"
    );
    triFaceList result(nt);
    forAll(result, t)
    {
        result[t] = triFace(tri[3*t], tri[3*t + 1], tri[3*t + 2]);
    }
    return result;
}


void Foam::canopyStructure::triangleGeometry
(
    pointField& centres,
    vectorField& normals,
    scalarField& areas
) const
{
    const label nt = nTriangles();
    centres.setSize(nt);
    normals.setSize(nt);
    areas.setSize(nt);
    check
    (
        canopy_model_get_triangle_geometry
        (
            model_.get(), raw(centres), raw(normals), areas.begin(), nt
        ),
        FUNCTION_NAME, "canopy_model_get_triangle_geometry"
    );
}


Foam::tmp<Foam::pointField> Foam::canopyStructure::triangleCentres() const
{
    tmp<pointField> tfld(new pointField(nTriangles()));
    check
    (
        canopy_model_get_triangle_geometry
        (
            model_.get(), raw(tfld.ref()), nullptr, nullptr, nTriangles()
        ),
        FUNCTION_NAME, "canopy_model_get_triangle_geometry"
    );
    return tfld;
}


Foam::tmp<Foam::vectorField> Foam::canopyStructure::triangleNormals() const
{
    tmp<vectorField> tfld(new vectorField(nTriangles()));
    check
    (
        canopy_model_get_triangle_geometry
        (
            model_.get(), nullptr, raw(tfld.ref()), nullptr, nTriangles()
        ),
        FUNCTION_NAME, "canopy_model_get_triangle_geometry"
    );
    return tfld;
}


Foam::tmp<Foam::scalarField> Foam::canopyStructure::triangleAreas() const
{
    tmp<scalarField> tfld(new scalarField(nTriangles()));
    check
    (
        canopy_model_get_triangle_geometry
        (
            model_.get(), nullptr, nullptr, tfld.ref().begin(), nTriangles()
        ),
        FUNCTION_NAME, "canopy_model_get_triangle_geometry"
    );
    return tfld;
}


Foam::tmp<Foam::vectorField> Foam::canopyStructure::triangleVelocities() const
{
    tmp<vectorField> tfld(new vectorField(nTriangles()));
    check
    (
        canopy_model_get_triangle_velocities
        (
            model_.get(), raw(tfld.ref()), nTriangles()
        ),
        FUNCTION_NAME, "canopy_model_get_triangle_velocities"
    );
    return tfld;
}


Foam::tmp<Foam::scalarField> Foam::canopyStructure::normalVelocities() const
{
    tmp<scalarField> tfld(new scalarField(nTriangles()));
    check
    (
        canopy_model_get_normal_velocities
        (
            model_.get(), tfld.ref().begin(), nTriangles()
        ),
        FUNCTION_NAME, "canopy_model_get_normal_velocities"
    );
    return tfld;
}


Foam::tmp<Foam::scalarField> Foam::canopyStructure::pressureJump() const
{
    tmp<scalarField> tfld(new scalarField(nTriangles()));
    check
    (
        canopy_model_get_pressure_jump
        (
            model_.get(), tfld.ref().begin(), nTriangles()
        ),
        FUNCTION_NAME, "canopy_model_get_pressure_jump"
    );
    return tfld;
}


void Foam::canopyStructure::setPressureJump(const scalarField& dp)
{
    check
    (
        canopy_model_set_pressure_jump(model_.get(), dp.cdata(), dp.size()),
        FUNCTION_NAME, "canopy_model_set_pressure_jump"
    );
}


void Foam::canopyStructure::setPressureHeld(const bool held)
{
    check
    (
        canopy_model_set_pressure_frozen(model_.get(), held ? 1 : 0),
        FUNCTION_NAME, "canopy_model_set_pressure_frozen"
    );
}


const Foam::wordList& Foam::canopyStructure::nodalForceNames()
{
    static const wordList names
    ({
        "addedMassBalance", "tangentialLoad", "lineDrag"
    });
    return names;
}


void Foam::canopyStructure::setNodalForces
(
    const word& name,
    const vectorField& f
)
{
    setNodalForces(name, labelList(), f);
}


void Foam::canopyStructure::setNodalForces
(
    const word& name,
    const labelList& nodes,
    const vectorField& f
)
{
    const label slot = canopyCompat::indexOf(nodalForceNames(), name);
    const label n = nNodes();
    if (slot < 0)
    {
        FatalErrorInFunction
            << "Unknown nodal force contribution '" << name << "'; valid: "
            << nodalForceNames() << exit(FatalError);
    }
    if (nodes.empty() ? f.size() != n : nodes.size() != f.size())
    {
        FatalErrorInFunction
            << "Nodal force contribution '" << name << "': " << f.size()
            << " forces for " << (nodes.empty() ? n : nodes.size())
            << (nodes.empty() ? " nodes" : " node indices")
            << exit(FatalError);
    }
    for (const label node : nodes)
    {
        if (node < 0 || node >= n)
        {
            FatalErrorInFunction
                << "Nodal force contribution '" << name << "': node " << node
                << " outside 0.." << n - 1 << exit(FatalError);
        }
    }
    nodalForces_.setSize(nodalForceNames().size());
    nodalContribution& c = nodalForces_[slot];
    c.set = true;
    c.nodes = nodes;
    c.forces = f;
    nodalForcesChanged_ = true;
}


void Foam::canopyStructure::applyNodalForces()
{
    if (!nodalForcesChanged_)
    {
        return;
    }
    vectorField sum(nNodes(), Zero);
    bool first = true;
    for (const nodalContribution& part : nodalForces_)
    {
        if (!part.set)
        {
            continue;
        }
        if (part.nodes.empty())
        {
            if (first)
            {
                sum = part.forces;
            }
            else
            {
                sum += part.forces;
            }
        }
        else
        {
            forAll(part.nodes, i)
            {
                sum[part.nodes[i]] += part.forces[i];
            }
        }
        first = false;
    }
    check
    (
        canopy_model_set_nodal_forces(model_.get(), raw(sum), sum.size()),
        FUNCTION_NAME, "canopy_model_set_nodal_forces"
    );
    nodalForcesChanged_ = false;
}


void Foam::canopyStructure::setAddedMass(const scalarField& addedMass)
{
    check
    (
        canopy_model_set_added_mass
        (
            model_.get(), addedMass.cdata(), addedMass.size()
        ),
        FUNCTION_NAME, "canopy_model_set_added_mass"
    );
}


void Foam::canopyStructure::setDirectionalAddedMass
(
    const scalarField& addedMass,
    const vectorField& direction
)
{
    if (direction.size() != addedMass.size())
    {
        FatalErrorInFunction
            << direction.size() << " directions for " << addedMass.size()
            << " nodes" << exit(FatalError);
    }
    check
    (
        canopy_model_set_directional_added_mass
        (
            model_.get(), addedMass.cdata(), raw(direction), addedMass.size()
        ),
        FUNCTION_NAME, "canopy_model_set_directional_added_mass"
    );
}


void Foam::canopyStructure::setTriangleAddedMass
(
    const scalarField& addedMass
)
{
    check
    (
        canopy_model_set_triangle_added_mass
        (
            model_.get(), addedMass.cdata(), addedMass.size()
        ),
        FUNCTION_NAME, "canopy_model_set_triangle_added_mass"
    );
}


void Foam::canopyStructure::beginStep(const scalar dt)
{
    if (motion_)
    {
        motion_->beginStep(model_.get(), dt);
    }
    if (time() + 0.5*dt >= bendingDampingUntil_)
    {
        check
        (
            canopy_model_set_bending_damping(model_.get(), 0),
            FUNCTION_NAME, "canopy_model_set_bending_damping"
        );
        Info<< "canopyStructure: the hinge dashpots are off from t = "
            << Foam::name(time()) << " (fabric.bendingDampingUntil "
            << Foam::name(bendingDampingUntil_) << ")" << endl;
        bendingDampingUntil_ = VGREAT;
    }
}


Foam::label Foam::canopyStructure::advance(const scalar dt)
{
    applyNodalForces();
    int nSub = 0;
    check
    (
        canopy_model_advance(model_.get(), dt, &nSub),
        FUNCTION_NAME, "canopy_model_advance"
    );
    return nSub;
}


bool Foam::canopyStructure::tryAdvance
(
    const scalar dt,
    label& nSubSteps,
    string& message
)
{
    applyNodalForces();
    int nSub = 0;
    const canopy_status st = canopy_model_advance(model_.get(), dt, &nSub);
    nSubSteps = nSub;
    if (st != CANOPY_OK)
    {
        message = canopy_model_message(model_.get());
        return false;
    }
    message.clear();
    return true;
}


Foam::scalar Foam::canopyStructure::stableStep()
{
    double dt = 0;
    check
    (
        canopy_model_stable_step(model_.get(), &dt),
        FUNCTION_NAME, "canopy_model_stable_step"
    );
    return dt;
}


void Foam::canopyStructure::checkpoint()
{
    check
    (
        canopy_model_checkpoint(model_.get()),
        FUNCTION_NAME, "canopy_model_checkpoint"
    );
}


void Foam::canopyStructure::restore()
{
    check
    (
        canopy_model_restore(model_.get()),
        FUNCTION_NAME, "canopy_model_restore"
    );
}


void Foam::canopyStructure::commit()
{
    check
    (
        canopy_model_commit(model_.get()),
        FUNCTION_NAME, "canopy_model_commit"
    );
}


Foam::point Foam::canopyStructure::payloadPosition() const
{
    point x(Zero);
    vector v(Zero);
    check
    (
        canopy_model_payload_state(model_.get(), &x.x(), &v.x()),
        FUNCTION_NAME, "canopy_model_payload_state"
    );
    return x;
}


Foam::vector Foam::canopyStructure::payloadVelocity() const
{
    point x(Zero);
    vector v(Zero);
    check
    (
        canopy_model_payload_state(model_.get(), &x.x(), &v.x()),
        FUNCTION_NAME, "canopy_model_payload_state"
    );
    return v;
}


Foam::canopyStructure::energy Foam::canopyStructure::energies() const
{
    canopy_energies e;
    check
    (
        canopy_model_energies(model_.get(), &e),
        FUNCTION_NAME, "canopy_model_energies"
    );
    return energy{e.kinetic, e.spring, e.gravity, e.total};
}


Foam::scalar Foam::canopyStructure::canopyArea() const
{
    double a = 0;
    check
    (
        canopy_model_canopy_area(model_.get(), &a),
        FUNCTION_NAME, "canopy_model_canopy_area"
    );
    return a;
}


Foam::scalar Foam::canopyStructure::projectedDiameter() const
{
    double d = 0;
    check
    (
        canopy_model_projected_diameter(model_.get(), &d),
        FUNCTION_NAME, "canopy_model_projected_diameter"
    );
    return d;
}


Foam::scalar Foam::canopyStructure::seepageVelocity(const scalar dp) const
{
    return canopy_model_seepage_velocity(model_.get(), dp);
}


bool Foam::canopyStructure::identicalOnAllRanks() const
{
    if (!Pstream::parRun())
    {
        return true;
    }

    // FNV-1a over the node count, time, positions and velocities
    std::uint64_t h = 14695981039346656037ULL;
    const int n = nNodes();
    const double t = time();
    hashBytes(h, &n, sizeof(n));
    hashBytes(h, &t, sizeof(t));
    const tmp<pointField> tx(points());
    const tmp<vectorField> tv(velocities());
    hashBytes(h, tx().cdata(), sizeof(double)*3*n);
    hashBytes(h, tv().cdata(), sizeof(double)*3*n);

    // Two 32-bit halves, each exact as a double: equal on all ranks iff
    // the minimum equals the maximum
    const scalar hi = static_cast<scalar>(h >> 32);
    const scalar lo = static_cast<scalar>(h & 0xffffffffULL);
    const scalar hiMin = returnReduce(hi, minOp<scalar>());
    const scalar hiMax = returnReduce(hi, maxOp<scalar>());
    const scalar loMin = returnReduce(lo, minOp<scalar>());
    const scalar loMax = returnReduce(lo, maxOp<scalar>());

    return hiMin == hiMax && loMin == loMax;
}


// ************************************************************************* //
