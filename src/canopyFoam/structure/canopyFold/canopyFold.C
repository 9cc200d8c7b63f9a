// canopyFold.C: canopyFold, the fold itself: the driven region, the chunks with their drag, the progress table and the output.
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

#include "canopyFold.H"
#include "Time.H"
#include "OSspecific.H"

#include "canopy.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <tuple>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// path relative to the case folder, when it lies inside it
Foam::fileName caseRelative
(
    const Foam::fileName& path,
    const Foam::fileName& casePath
)
{
    const std::string prefix(casePath + "/");
    return path.compare(0, prefix.size(), prefix) == 0
        ? Foam::fileName(path.substr(prefix.size()))
        : path;
}


using namespace Foam;

// Spring strains (l - l0)/l0: largest stretch of any spring (and which),
// of a canopy (cloth or tape) spring and of a line spring; largest
// compression of a canopy spring
struct strainSummary
{
    scalar maxStretch;
    label stretchSpring;
    scalar maxCanopyStretch;
    scalar maxLineStretch;
    scalar maxCanopyCompression;
};

strainSummary strains
(
    const pointField& x,
    const std::vector<int>& ends,
    const std::vector<double>& rest,
    const std::vector<int>& groups
)
{
    strainSummary s{0, -1, 0, 0, 0};
    for (std::size_t k = 0; k < rest.size(); ++k)
    {
        const scalar e = mag(x[ends[2*k]] - x[ends[2*k + 1]])/rest[k] - 1;
        if (e > s.maxStretch)
        {
            s.maxStretch = e;
            s.stretchSpring = label(k);
        }
        const bool canopy =
            groups[k] == CANOPY_GROUP_FABRIC || groups[k] == CANOPY_GROUP_TAPE;
        if (canopy)
        {
            if (e > s.maxCanopyStretch) s.maxCanopyStretch = e;
            if (-e > s.maxCanopyCompression) s.maxCanopyCompression = -e;
        }
        else if (e > s.maxLineStretch)
        {
            s.maxLineStretch = e;
        }
    }
    return s;
}


// Closest approach of two canopy nodes that share no spring, found with a
// uniform grid of cell size h; returns h when no such pair is closer
scalar closestApproach
(
    const pointField& x,
    const std::vector<label>& canopyNodes,
    const std::vector<std::vector<label>>& neighbours,
    const scalar h
)
{
    typedef std::tuple<long, long, long> cellKey;
    std::map<cellKey, std::vector<label>> grid;
    auto keyOf = [h](const point& p)
    {
        return cellKey
        (
            long(std::floor(p.x()/h)),
            long(std::floor(p.y()/h)),
            long(std::floor(p.z()/h))
        );
    };
    for (const label i : canopyNodes)
    {
        grid[keyOf(x[i])].push_back(i);
    }

    scalar closest = h;
    for (const label i : canopyNodes)
    {
        const cellKey k = keyOf(x[i]);
        for (long a = -1; a <= 1; ++a)
        for (long b = -1; b <= 1; ++b)
        for (long c = -1; c <= 1; ++c)
        {
            const auto it = grid.find
            (
                cellKey
                (
                    std::get<0>(k) + a, std::get<1>(k) + b, std::get<2>(k) + c
                )
            );
            if (it == grid.end()) continue;
            for (const label j : it->second)
            {
                if (j <= i) continue;
                const std::vector<label>& nb = neighbours[i];
                if (std::find(nb.begin(), nb.end(), j) != nb.end()) continue;
                closest = min(closest, mag(x[i] - x[j]));
            }
        }
    }
    return closest;
}

// FatalError quoting libcanopy's message when a call failed
void check(const int status, const canopy_model* m, const char* call)
{
    if (status != CANOPY_OK)
    {
        FatalErrorInFunction
            << "libcanopy " << call << " failed: " << canopy_model_message(m)
            << nl << exit(FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::canopyFold::canopyFold
(
    canopyStructure& structure,
    const dictionary& foldDict,
    const Time& runTime
)
:
    structure_(structure),
    dict_(foldDict),
    runTime_(runTime),
    c_(foldDict, structure, runTime),
    n_(structure.nNodes()),
    ns_(structure.nSprings()),
    edge_(0),
    nDriven_(0),
    nWritten_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::canopyFold::axisDistance(const point& x) const
{
    const vector d = x - c_.centre;
    return mag(d - (d & c_.axis)*c_.axis);
}


bool Foam::canopyFold::inside(const point& x) const
{
    const scalar r = axisDistance(x);
    return r < c_.radius && r >= c_.innerRadius;
}


void Foam::canopyFold::prepare()
{
    canopy_model* m = structure_.model();
    const label n = n_;
    const label ns = ns_;

    const double zero3[3] = {0, 0, 0};
    check(canopy_model_set_gravity(m, zero3), m, "set_gravity");  // g off
    if (!c_.integrator.empty())
    {
        check(canopy_model_set_integrator(m, c_.integrator.c_str()), m, "set_integrator");
    }
    if (c_.maxOmegaDt > 0)
    {
        check(canopy_model_set_max_omega_dt(m, c_.maxOmegaDt), m, "set_max_omega_dt");
    }
    // (pressure jumps are zero: nothing sets them)
    structure_.setTime(0);

    std::vector<int> fixed0(n), groups(n);
    springEnds_.resize(2*ns);
    springGroups_.resize(ns);
    rest_.resize(ns);
    check(canopy_model_get_fixed(m, fixed0.data(), n), m, "get_fixed");
    check
    (
        canopy_model_get_node_groups(m, groups.data(), n), m, "get_node_groups"
    );
    check
    (
        canopy_model_get_springs
        (
            m, springEnds_.data(), rest_.data(), nullptr, ns
        ),
        m, "get_springs"
    );
    check
    (
        canopy_model_get_spring_groups(m, springGroups_.data(), ns),
        m, "get_spring_groups"
    );

    // Canopy nodes: cloth and tapes; those not fixed may be driven
    drivable_.assign(n, false);
    for (label i = 0; i < n; ++i)
    {
        if (groups[i] == CANOPY_GROUP_FABRIC || groups[i] == CANOPY_GROUP_TAPE)
        {
            canopyNodes_.push_back(i);
            drivable_[i] = !fixed0[i];
        }
    }

    // Spring neighbours, and the mean cloth edge
    neighbours_.assign(n, std::vector<label>());
    scalar edgeSum = 0;
    label nEdge = 0;
    for (label k = 0; k < ns; ++k)
    {
        neighbours_[springEnds_[2*k]].push_back(springEnds_[2*k + 1]);
        neighbours_[springEnds_[2*k + 1]].push_back(springEnds_[2*k]);
        if (springGroups_[k] == CANOPY_GROUP_FABRIC)
        {
            edgeSum += rest_[k];
            ++nEdge;
        }
    }
    edge_ = nEdge ? edgeSum/nEdge : 0;
    if (!(edge_ > 0))
    {
        FatalErrorInFunction
            << "The structure of " << structure_.dict().name()
            << " has no canopy cloth to fold" << exit(FatalError);
    }

    // The driven nodes at t = 0
    x0_ = structure_.points();
    initiallyInside_.assign(n, false);
    label nInitial = 0;
    for (label i = 0; i < n; ++i)
    {
        if (drivable_[i] && inside(x0_[i]))
        {
            initiallyInside_[i] = true;
            ++nInitial;
        }
    }
    if (nInitial == 0)
    {
        scalar rMin = GREAT;
        for (const label i : canopyNodes_) rMin = min(rMin, axisDistance(x0_[i]));
        FatalIOErrorInFunction(dict_.subDict("region"))
            << "Entry 'region.radius' = " << c_.radius << ": no free canopy"
            << " node lies inside the region (innerRadius " << c_.innerRadius
            << ", centre " << c_.centre << ", axis " << c_.axis << "); the"
            << " nearest canopy node is " << rMin << " m from the axis"
            << nl << exit(FatalIOError);
    }
    driven_.assign(n, false);
}


void Foam::canopyFold::setDrive(const bool drive)
{
    canopy_model* m = structure_.model();
    const pointField x(structure_.points());
    vectorField v(structure_.velocities());
    for (label i = 0; i < n_; ++i)
    {
        if (!drivable_[i]) continue;
        const bool want =
            drive && (c_.capture ? inside(x[i]) : initiallyInside_[i]);
        if (want)
        {
            v[i] = c_.velocity;
            if (!driven_[i])
            {
                check(canopy_model_set_fixed(m, i, 1), m, "set_fixed");
                driven_[i] = true;
                ++nDriven_;
            }
        }
        else if (driven_[i])
        {
            if (drive)
            {
                // Left the region (v0 not along the axis): free again
                check(canopy_model_set_fixed(m, i, 0), m, "set_fixed");
                driven_[i] = false;
                --nDriven_;
            }
            else
            {
                v[i] = Zero;    // relaxation: held where they are
            }
        }
    }
    check
    (
        canopy_model_set_velocities
        (
            m, reinterpret_cast<const double*>(v.cdata()), n_
        ),
        m, "set_velocities"
    );
}


void Foam::canopyFold::damp(const scalar dt, const bool last)
{
    canopy_model* m = structure_.model();
    vectorField v(structure_.velocities());
    std::vector<int> fixedNow(n_);
    check(canopy_model_get_fixed(m, fixedNow.data(), n_), m, "get_fixed");
    const scalar factor = std::exp(-c_.damping*dt);
    for (label i = 0; i < n_; ++i)
    {
        if (!fixedNow[i]) v[i] *= factor;
    }
    if (last)
    {
        v = Zero;       // the folded state starts at rest
    }
    check
    (
        canopy_model_set_velocities
        (
            m, reinterpret_cast<const double*>(v.cdata()), n_
        ),
        m, "set_velocities"
    );
}


void Foam::canopyFold::writeState()
{
    structure_.write(c_.output.lessExt());
    ++nWritten_;
}


void Foam::canopyFold::progress(const scalar t) const
{
    const strainSummary s
    (
        strains(structure_.points(), springEnds_, rest_, springGroups_)
    );
    const pointField x(structure_.points());
    const canopyStructure::energy e(structure_.energies());
    char line[160];
    std::snprintf
    (
        line, sizeof line,
        "    %9.4g %7d %10.5g %9.3g %9.3g %9.3g %11.3g %11.3g %8.3g",
        t, int(nDriven_), structure_.projectedDiameter(),
        100*s.maxCanopyStretch, 100*s.maxCanopyCompression,
        100*s.maxLineStretch, e.kinetic, e.spring,
        closestApproach(x, canopyNodes_, neighbours_, edge_)/edge_
    );
    Info<< line << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::canopyFold::run()
{
    prepare();
    canopy_model* m = structure_.model();

    // ---- chunks ----------------------------------------------------------------

    const scalar tEnd = c_.duration + c_.relaxation;
    scalar dtMax = min(0.1*edge_/mag(c_.velocity), tEnd/c_.nOutput);
    if (c_.damping > 0)
    {
        dtMax = min(dtMax, 0.05/c_.damping);
    }
    const label nDrive = label(std::ceil(c_.duration/dtMax - 1e-9));
    const label nRelax =
        c_.relaxation > 0 ? label(std::ceil(c_.relaxation/dtMax - 1e-9)) : 0;
    const label nChunks = nDrive + nRelax;

    label nInitial = 0;
    for (const bool in : initiallyInside_) nInitial += in;

    const scalar d0 = structure_.projectedDiameter();

    Info<< "canopyFold: " << structure_.dict().name() << nl
        << "    structure          " << n_ << " nodes (" << canopyNodes_.size()
        << " canopy), " << ns_ << " springs, " << structure_.nTriangles()
        << " triangles, mean cloth edge " << edge_ << " m" << nl
        << "    field (eq. 5.3)    v0 = " << c_.velocity << " m/s inside r < "
        << c_.radius;
    if (c_.innerRadius > 0)
    {
        Info<< " and r >= " << c_.innerRadius;
    }
    Info<< " m of the axis " << c_.axis << " through " << c_.centre
        << (c_.capture ? ", capturing" : ", initial nodes only") << nl
        << "    driven at t = 0    " << nInitial << " canopy nodes" << nl
        << "    drive              " << c_.duration << " s (displacement "
        << mag(c_.velocity)*c_.duration << " m), then " << c_.relaxation
        << " s held" << nl
        << "    damping            " << c_.damping << " 1/s per unit mass"
        << nl
        << "    payload            "
        << (structure_.hasPayload() ? (c_.holdPayload ? "held" : "free") : "none")
        << nl
        << "    chunks             " << nDrive << " + " << nRelax
        << " (at most " << dtMax << " s; stable sub-step "
        << structure_.stableStep() << " s)" << nl
        << "    output             " << c_.output.c_str() << " (+ .xdmf)" << nl
        << "    flat projected diameter " << d0 << " m" << nl << endl;

    // The file's /mesh/node_fixed holds the flags of canopyProperties
    // (those the solver runs with): created before the payload is pinned
    structure_.createOutput(c_.output.lessExt());
    if (c_.holdPayload && structure_.hasPayload())
    {
        check
        (
            canopy_model_set_fixed(m, structure_.payloadNode(), 1),
            m, "set_fixed"
        );
    }

    // Strains in %: cloth (and tapes) stretched / compressed, lines
    // stretched; closest: of two canopy nodes sharing no spring / edge
    Info<< "     time [s]  driven  diam. [m]  cloth +%  cloth -%  lines +%"
        << "  kinetic [J]  spring [J]  closest" << endl;
    writeState();
    progress(0);

    // ---- the fold ---------------------------------------------------------------

    label due0 = 0;
    for (label j = 1; j <= nChunks; ++j)
    {
        const bool drive = j <= nDrive;
        const scalar dt = drive ? c_.duration/nDrive : c_.relaxation/nRelax;

        setDrive(drive);

        label nSub = 0;
        string message;
        if (!structure_.tryAdvance(dt, nSub, message))
        {
            FatalErrorInFunction
                << "The fold failed at t = " << structure_.time() << ": "
                << message.c_str() << nl << exit(FatalError);
        }

        damp(dt, j == nChunks);

        // nOutput states, about evenly spaced, the last at the end; and a
        // spring stretched beyond maxStrain stops the fold (written first)
        const strainSummary s
        (
            strains(structure_.points(), springEnds_, rest_, springGroups_)
        );
        const bool torn = s.maxStretch > c_.maxStrain;
        const label due = (j*c_.nOutput)/nChunks;
        if (due > due0 || torn)
        {
            due0 = due;
            writeState();
            progress(structure_.time());
        }
        if (torn)
        {
            FatalErrorInFunction
                << "At t = " << structure_.time() << " spring "
                << s.stretchSpring << " (nodes "
                << springEnds_[2*s.stretchSpring] << " and "
                << springEnds_[2*s.stretchSpring + 1] << ") is stretched by "
                << 100*s.maxStretch << " %, more than maxStrain = "
                << 100*c_.maxStrain << " % (this state is the last in "
                << c_.output.c_str() << "). Drive less far (velocity x"
                << " duration), or release the payload (holdPayload false)"
                << exit(FatalError);
        }
    }

    // ---- summary ---------------------------------------------------------------

    const pointField x(structure_.points());
    scalar maxShift = 0;
    for (label i = 0; i < n_; ++i)
    {
        if (!initiallyInside_[i]) continue;
        const scalar d = mag((x[i] - x0_[i]) - c_.velocity*c_.duration);
        maxShift = max(maxShift, d);
    }
    const scalar d1 = structure_.projectedDiameter();
    Info<< nl << "canopyFold: folded in " << nChunks << " chunks, "
        << nWritten_ << " states written" << nl
        << "    projected diameter " << d0 << " m -> " << d1 << " m ("
        << 100*d1/d0 << " %)" << nl
        << "    canopy area        " << structure_.canopyArea() << " m^2" << nl
        << "    nodes driven at the end of the drive " << nDriven_ << nl
        << "    initially driven nodes moved by v0 T = "
        << c_.velocity*c_.duration << " m to within " << maxShift << " m" << nl
        << "    folded state       " << c_.output.c_str() << nl
        << "    view               " << c_.output.lessExt().c_str() << ".xdmf"
        << nl
        << "    use                initialState \""
        << caseRelative(c_.output, runTime_.globalPath()).c_str() << "\"; in "
        << "constant/canopyProperties" << nl << endl;

}


// ************************************************************************* //
