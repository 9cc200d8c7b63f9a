// prescribedRotation.C: reading fixedNodes.motion and turning the fixed nodes of the libcanopy model at the start of each time step.
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

#include "prescribedRotation.H"
#include "scopedEntryReader.H"
#include "mathematicalConstants.H"
#include "DynamicList.H"
#include "error.H"

#include "canopy.h"

#include <cmath>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// A failed libcanopy call is a bug of this class (the counts are the
// model's own): stop with the library's message
void require
(
    const canopy_status st,
    const canopy_model* m,
    const char* call
)
{
    if (st != CANOPY_OK)
    {
        FatalErrorInFunction
            << "libcanopy " << call << " failed: "
            << canopy_model_message(m) << Foam::nl
            << Foam::exit(Foam::FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::point Foam::prescribedRotation::turned
(
    const point& p,
    const scalar angle
) const
{
    // Rodrigues: R v = v cos a + (k x v) sin a + k (k . v)(1 - cos a)
    const vector v(p - origin_);
    const scalar c = std::cos(angle);
    const scalar s = std::sin(angle);
    return origin_ + c*v + s*(axis_ ^ v) + (1 - c)*(axis_ & v)*axis_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedRotation::prescribedRotation
(
    const dictionary& dict,
    const canopy_model* m,
    const label payloadNode
)
:
    pivotNode_(-1),
    origin_(Zero),
    axis_(Zero),
    amplitude_(0),
    period_(1),
    startTime_(0),
    nodes_(),
    reference_()
{
    const scopedEntryReader r(dict, "fixedNodes.motion");
    r.choice("type", wordList{"sinusoidalRotation"}, "prescribed motion");
    if (r.given("origin") == "payload")
    {
        if (payloadNode < 0)
        {
            r.fail("origin", "= payload: there is no payload (no lines)");
        }
        pivotNode_ = payloadNode;
    }
    else
    {
        origin_ = r.vectorValue
        (
            "origin", "the point turned about [m], or the word payload"
        );
    }
    axis_ = r.nonZeroVector("axis", "the axis turned about");
    axis_ /= mag(axis_);
    amplitude_ =
        r.nonNegative("amplitude", "the angle's amplitude [degrees]")
       *constant::mathematical::pi/180;
    period_ = r.positive("period", "the period [s]");
    startTime_ = r.number("startTime", "the motion's start [s]", 0);
    r.warnUnused
    (
        wordList{"type", "origin", "axis", "amplitude", "period", "startTime"}
    );

    const int n = canopy_model_node_count(m);
    std::vector<int> fixed(n > 0 ? n : 1, 0);
    require(canopy_model_get_fixed(m, fixed.data(), n), m, "get_fixed");
    if (pivotNode_ >= 0 && !fixed[pivotNode_])
    {
        r.fail
        (
            "origin",
            "= payload needs the payload held where it is: set payload.fixed"
            " true"
        );
    }
    DynamicList<label> nodes;
    for (label i = 0; i < n; ++i)
    {
        if (fixed[i] && i != pivotNode_)
        {
            nodes.append(i);
        }
    }
    // (canopyStructure reads fixedNodes.motion only with fixedNodes.all
    // or .skirt, which fix cloth nodes: the list is never empty)
    nodes_.transfer(nodes);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::prescribedRotation::angle(const scalar t) const
{
    if (t <= startTime_)
    {
        return 0;
    }
    return
        amplitude_
       *std::sin(constant::mathematical::twoPi*(t - startTime_)/period_);
}


void Foam::prescribedRotation::beginStep(canopy_model* m, const scalar dt)
{
    const int n = canopy_model_node_count(m);
    const scalar t = canopy_model_time(m);
    std::vector<double> x(3*n), v(3*n), a(3*n);
    int accValid = 0;
    require(canopy_model_get_positions(m, x.data(), n), m, "get_positions");
    require(canopy_model_get_velocities(m, v.data(), n), m, "get_velocities");
    require
    (
        canopy_model_get_acceleration_state(m, a.data(), n, &accValid),
        m, "get_acceleration_state"
    );

    const auto at = [&x](const label i)
    {
        return point(x[3*i], x[3*i + 1], x[3*i + 2]);
    };
    if (reference_.empty())
    {
        // The state the run starts from: its place at theta = 0
        if (pivotNode_ >= 0)
        {
            origin_ = at(pivotNode_);
        }
        reference_.setSize(nodes_.size());
        const scalar back = -angle(t);
        forAll(nodes_, k)
        {
            reference_[k] = turned(at(nodes_[k]), back);
        }
    }

    const scalar now = angle(t);
    const scalar next = angle(t + dt);
    const bool still = (now == 0 && next == 0);
    forAll(nodes_, k)
    {
        // Still (before startTime): the nodes stay exactly where they are
        const point p0(still ? at(nodes_[k]) : turned(reference_[k], now));
        const vector u
        (
            still ? vector::zero : (turned(reference_[k], next) - p0)/dt
        );
        const label i = nodes_[k];
        for (direction d = 0; d < 3; ++d)
        {
            x[3*i + d] = p0[d];
            v[3*i + d] = u[d];
        }
    }
    // The whole state at once: the free nodes keep their carried
    // acceleration (the fixed nodes carry none)
    require
    (
        canopy_model_set_state
        (
            m, t, x.data(), v.data(), a.data(), accValid, n
        ),
        m, "set_state"
    );
}


void Foam::prescribedRotation::writeInfo(Ostream& os) const
{
    os  << "prescribed rotation of " << nodes_.size() << " fixed nodes about ";
    if (pivotNode_ >= 0)
    {
        os  << "the payload";
    }
    else
    {
        os  << origin_;
    }
    os  << ", axis " << axis_ << ": "
        << amplitude_*180/constant::mathematical::pi << " deg sin(2 pi (t - "
        << startTime_ << ")/" << period_ << " s)";
}


// ************************************************************************* //
