// Test-prescribedRotation.C: steps a case's canopy whose fixed nodes turn by fixedNodes.motion and checks their places, their velocities, the pivot and a restart against the rotation's closed form; exits non-zero on any mismatch.
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

Application
    Test-prescribedRotation

Description
    Builds Foam::canopyStructure from the case's constant/canopyProperties,
    which must give fixedNodes.motion (prescribedRotation) about the
    payload, and advances it -steps steps of -deltaT as canopyCoupling
    does (beginStep, checkpoint, advance, commit), under gravity and a
    uniform pressure jump -dp on the cloth. Checks, exiting 1 when any
    fails:
    - after every step each turned node lies at p + R(theta(t)) (x0 - p),
      x0 its built place, p the payload's and R the rotation of the
      dictionary's angle about its axis, written out here independently
      (the matrix of the rotation, not Rodrigues' vector form), to 1e-10 m
      (the rounding of the sub-steps' x += dt v);
    - its velocity over the step is the chord's, (x(t) - x(t - dt)) / dt,
      to 1e-9 m/s;
    - the payload has not moved;
    - before startTime nothing turned has moved;
    - a second structure given the first's state at the middle step
      (canopy_model_set_state, a restart) and stepped on ends at the same
      places, to 1e-10 m.

Usage
    Test-prescribedRotation [-case dir] [-steps N] [-deltaT dt] [-dp Pa]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "mathematicalConstants.H"
#include "canopyStructure.H"
#include "prescribedRotation.H"
#include "testCheck.H"
#include "canopyFoamCompat.H"

#include "canopy.h"

#include <cmath>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// The motion's entries, read with plain lookups (not the class's reader)
struct motionSpec
{
    vector axis;
    scalar amplitude;       // [rad]
    scalar period;
    scalar startTime;
};


scalar angleAt(const motionSpec& s, const scalar t)
{
    if (t <= s.startTime)
    {
        return 0;
    }
    return s.amplitude
       *std::sin(constant::mathematical::twoPi*(t - s.startTime)/s.period);
}


// The rotation matrix by a about the unit axis k
tensor rotationMatrix(const vector& k, const scalar a)
{
    const scalar c = std::cos(a), s = std::sin(a), C = 1 - c;
    return tensor
    (
        c + k.x()*k.x()*C,         k.x()*k.y()*C - k.z()*s, k.x()*k.z()*C + k.y()*s,
        k.y()*k.x()*C + k.z()*s,   c + k.y()*k.y()*C,       k.y()*k.z()*C - k.x()*s,
        k.z()*k.x()*C - k.y()*s,   k.z()*k.y()*C + k.x()*s, c + k.z()*k.z()*C
    );
}


std::vector<double> positions(const canopyStructure& s)
{
    std::vector<double> x(3*s.nNodes());
    canopy_model_get_positions(s.model(), x.data(), s.nNodes());
    return x;
}


std::vector<double> velocities(const canopyStructure& s)
{
    std::vector<double> v(3*s.nNodes());
    canopy_model_get_velocities(s.model(), v.data(), s.nNodes());
    return v;
}


point at(const std::vector<double>& x, const label i)
{
    return point(x[3*i], x[3*i + 1], x[3*i + 2]);
}


// One step as canopyCoupling takes it
void step(canopyStructure& s, const scalar dt, const scalarField& dp)
{
    s.beginStep(dt);
    s.checkpoint();
    s.setPressureJump(dp);
    s.advance(dt);
    s.commit();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Step a canopy whose fixed nodes turn (fixedNodes.motion) and check"
        " them against the rotation's closed form; exit 1 on any mismatch"
    );
    canopyCompat::noFunctionObjects();
    argList::addOption("steps", "N", "Steps to advance (default 40)");
    argList::addOption("deltaT", "dt", "Step [s] (default 0.05)");
    argList::addOption("dp", "Pa", "Uniform pressure jump (default 20)");

    #include "setRootCase.H"
    #include "createTime.H"

    const label nSteps = canopyCompat::argOrDefault<label>(args, "steps", 40);
    const scalar dt = canopyCompat::argOrDefault<scalar>(args, "deltaT", 0.05);
    const scalar dpValue = canopyCompat::argOrDefault<scalar>(args, "dp", 20);

    canopyStructure structure(runTime);
    structure.setTime(0);
    const prescribedRotation* motion = structure.motion();
    if (!motion || !structure.hasPayload())
    {
        FatalErrorInFunction
            << "The case must give fixedNodes.motion about the payload"
            << exit(FatalError);
    }
    const dictionary& md =
        structure.dict().subDict("fixedNodes").subDict("motion");
    motionSpec spec;
    spec.axis = vector(md.lookup("axis"));
    spec.axis /= mag(spec.axis);
    spec.amplitude =
        readScalar(md.lookup("amplitude"))*constant::mathematical::pi/180;
    spec.period = readScalar(md.lookup("period"));
    spec.startTime = md.found("startTime") ? readScalar(md.lookup("startTime")) : 0;
    Info<< "Turned nodes " << motion->nodes().size() << ", amplitude "
        << readScalar(md.lookup("amplitude")) << " deg, period " << spec.period
        << " s, start " << spec.startTime << " s; " << nSteps
        << " steps of " << dt << " s" << nl << endl;

    const scalarField dp(structure.nTriangles(), dpValue);
    const std::vector<double> x0(positions(structure));
    const point pivot(at(x0, structure.payloadNode()));
    const labelList& nodes = motion->nodes();

    scalar placeErr = 0, velocityErr = 0, pivotErr = 0, beforeStart = 0;
    scalar maxAngle = 0;
    std::vector<double> xMid, vMid, aMid;
    int accMid = 0;
    scalar tMid = 0;
    std::vector<double> previous(x0);
    for (label n = 1; n <= nSteps; ++n)
    {
        step(structure, dt, dp);
        const scalar t = structure.time();
        const std::vector<double> x(positions(structure));
        const std::vector<double> v(velocities(structure));
        const tensor R(rotationMatrix(spec.axis, angleAt(spec, t)));
        maxAngle = max(maxAngle, mag(angleAt(spec, t)));
        for (const label i : nodes)
        {
            const point expected(pivot + (R & (at(x0, i) - pivot)));
            placeErr = max(placeErr, mag(at(x, i) - expected));
            const vector chord((at(x, i) - at(previous, i))/dt);
            velocityErr = max(velocityErr, mag(at(v, i) - chord));
            if (t <= spec.startTime)
            {
                beforeStart = max(beforeStart, mag(at(x, i) - at(x0, i)));
            }
        }
        pivotErr = max(pivotErr, mag(at(x, structure.payloadNode()) - pivot));
        previous = x;
        if (n == nSteps/2)
        {
            xMid = x;
            vMid = v;
            aMid.resize(x.size());
            canopy_model_get_acceleration_state
            (
                structure.model(), aMid.data(), structure.nNodes(), &accMid
            );
            tMid = t;
        }
    }
    Info<< "Largest angle reached " << maxAngle*180/constant::mathematical::pi
        << " deg" << nl;

    // A restart from the middle state, stepped on as far
    scalar restartErr = 0;
    {
        canopyStructure again(runTime);
        canopy_model_set_state
        (
            again.model(), tMid, xMid.data(), vMid.data(), aMid.data(),
            accMid, again.nNodes()
        );
        for (label n = nSteps/2 + 1; n <= nSteps; ++n)
        {
            step(again, dt, dp);
        }
        const std::vector<double> x(positions(again));
        for (const label i : nodes)
        {
            restartErr = max(restartErr, mag(at(x, i) - at(previous, i)));
        }
    }

    // Positions: the rounding of x += dt_sub v over a step's sub-steps
    // (about 1e-16 m each, hundreds of them); a wrong rotation is off by
    // the amplitude times the radius (0.1-1 m), a wrong velocity by
    // dt^2 theta'' r (1e-3 m)
    check("turned nodes' distance from the closed form [m]", placeErr, 1e-10);
    check("their velocity's difference from the chord's [m/s]", velocityErr, 1e-9);
    check("the payload's displacement [m]", pivotErr, 0);
    check("displacement before startTime [m]", beforeStart, 0);
    check
    (
        "the angle reached short of 90 % of the amplitude [rad]",
        max(0.0, 0.9*spec.amplitude - maxAngle), 0
    );
    check("restart from the middle step: distance at the end [m]", restartErr, 1e-10);

    Info<< nl << nChecks - nFailed << " of " << nChecks << " checks passed"
        << nl << "Test-prescribedRotation: "
        << (nFailed ? "FAILED" : "PASSED") << nl << endl;
    return nFailed ? 1 : 0;
}


// ************************************************************************* //
