// Test-addedMassStabiliser.C: the coupling's added-mass stabiliser on a canopy without air: whether its vibration grows, and that a converged balance leaves the cloth's own inertia.
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
    Test-addedMassStabiliser

Description
    Builds the structure of constant/canopyProperties and its
    addedMassStabiliser (the sub-dictionary coupling.addedMass, mass > 0)
    and advances it as the strong coupling
    does, with no air: every time step a fixed number of iterations, each
    restoring the step's start, setting the balancing forces m_a (d.abar) d
    and advancing; no pressure jump. This is a cloth node inside a fold,
    whose motion the air does not resist: the stabiliser's iteration then
    converges only by m_a/(m + m_a) per iteration, and what is left
    unconverged either acts as an inertia (predictor zero) or as a lag of
    the acceleration behind the force (predictor lastStep), a negative
    damping.

    With gravity and a pinned skirt the cloth sags from rest, so that the
    structure's total energy E (kinetic + springs + gravity) of the exact
    motion never exceeds its start value E0 (the cloth's dashpots only take
    energy out). Printed: E - E0, the kinetic energy and the fastest node
    every tenth of the run, and the largest gain max(E - E0).

    -expect stable: passes when every step advances and
        max(E - E0) <= 0.01 max(KE): the inertia the unconverged part adds
        (up to m_a on a node whose own mass is 70 times less) makes the
        structure's own energy, which counts only m, swing below the
        effective system's; it can exceed E0 only by the RK4 sub-steps'
        error (~1e-4 per sub-step on the highest mode, dissipative) and the
        change of the inertia from step to step: a gain of 1 % of the
        largest kinetic energy is far above these and far below a growing
        vibration.
    -expect unstable: passes when the vibration grows: a step fails (a
        node passes the structure's speed limit) or the largest gain
        max(E - E0) exceeds the largest kinetic energy of the run's first
        tenth.
    -expect balanced: a step load instead (the pressure jump
        -pressureJump, default 2 Pa, from t = 0), and every step iterates
        until the balancing forces change by at most 1e-10 of their size
        (at most 2000 iterations), beside a second structure built from the
        same dictionary without the stabiliser and given the same loads.
        The balance's fixed point is the structure's equation without the
        added mass (with coupling.addedMass.balance endOfStep and an
        implicit integrator), so the two must move alike: passes when the
        largest position difference at the end is at most 1e-6 of the
        largest displacement (the iteration's remaining error, ~1e-9 of the
        acceleration per step, summed over the steps) and the reference
        moved at all. Both take the first step without the stabiliser (hht
        starts from M^-1 F, which the added mass and its balance would
        change). With a zero balance the stabiliser's mass is real inertia
        and the cloth moves many times less far.

Usage
    Test-addedMassStabiliser -expect stable|unstable|balanced
        [-iterations 6] [-deltaT 0.02] [-endTime 2] [-pressureJump 2]
        [-case dir]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "IOmanip.H"
#include "canopyStructure.H"
#include "addedMassStabiliser.H"
#include "testCheck.H"
#include "canopyFoamCompat.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// One step of dt: advance, or stop the test with the structure's message
void advanceOrDie(canopyStructure& structure, const scalar dt)
{
    label subSteps = 0;
    string failure;
    if (!structure.tryAdvance(dt, subSteps, failure))
    {
        FatalErrorInFunction
            << "The structure's step failed: " << failure.c_str()
            << exit(FatalError);
    }
}


// -expect balanced (see the header); returns the exit status
int balancedRun
(
    canopyStructure& structure,
    canopyStructure& reference,
    addedMassStabiliser& stabiliser,
    const scalar jump,
    const scalar dt,
    const label nSteps
)
{
    const label maxIterations = 2000;
    const scalarField dp(structure.nTriangles(), jump);
    const pointField start(reference.points());
    structure.setPressureJump(dp);
    reference.setPressureJump(dp);

    Info<< "Step load " << jump << " Pa on a canopy without air: "
        << structure.nNodes() << " nodes, integrator "
        << structure.integrator() << ", dt " << dt << " s, " << nSteps
        << " steps; the stabiliser's balance iterated to 1e-10" << nl << nl
        << "        t [s]   iterations   displacement [m]   difference [m]"
        << endl;

    advanceOrDie(reference, dt);
    advanceOrDie(structure, dt);
    label mostIterations = 0;
    scalar difference = 0, displacement = 0;
    for (label step = 2; step <= nSteps; ++step)
    {
        advanceOrDie(reference, dt);

        structure.checkpoint();
        stabiliser.beginStep(structure);
        label k = 0;
        for (bool converged = false; !converged; )
        {
            if (++k > maxIterations)
            {
                FatalErrorInFunction
                    << "The balance did not converge in " << maxIterations
                    << " iterations at step " << step << exit(FatalError);
            }
            structure.restore();
            structure.setPressureJump(dp);
            const vectorField before(stabiliser.balancingForces());
            structure.setNodalForces("addedMassBalance", before);
            advanceOrDie(structure, dt);
            stabiliser.update(structure, dt);
            const vectorField after(stabiliser.balancingForces());
            converged = max(mag(after - before)) <= 1e-10*max(mag(after));
        }
        structure.commit();
        mostIterations = max(mostIterations, k);

        const pointField x(reference.points());
        difference = max(mag(structure.points() - x));
        displacement = max(mag(x - start));
        if (step % max(label(1), nSteps/10) == 0)
        {
            Info<< "    " << setw(9) << step*dt << "  " << setw(11) << k
                << "  " << setw(17) << displacement << "  " << setw(15)
                << difference << endl;
        }
    }
    Info<< nl << "Largest number of iterations in a step: " << mostIterations
        << nl << "Largest displacement " << displacement << " m, position"
        << " difference from the structure without stabiliser " << difference
        << " m" << nl << endl;
    check("1e-3/(largest displacement [m])", 1e-3/max(displacement, VSMALL), 1);
    check("difference/displacement", difference/max(displacement, VSMALL), 1e-6);
    Info<< nChecks - nFailed << " of " << nChecks << " checks passed" << endl;
    return nFailed ? 1 : 0;
}

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Advance a canopy without air with the coupling's added-mass"
        " stabiliser and a fixed number of iterations per step; check that"
        " its energy stays bounded (-expect stable) or grows"
        " (-expect unstable)"
    );
    canopyCompat::noFunctionObjects();
    argList::addOption("expect", "stable|unstable", "The expected outcome");
    argList::addOption("iterations", "K", "Iterations per step (default 6)");
    argList::addOption("deltaT", "dt", "Time step [s] (default 0.02)");
    argList::addOption("endTime", "T", "Run length [s] (default 2)");
    argList::addOption
    (
        "pressureJump", "dp", "-expect balanced: the step load [Pa] (default 2)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    const word expect(canopyCompat::argOrDefault<word>(args, "expect", ""));
    if (expect != "stable" && expect != "unstable" && expect != "balanced")
    {
        FatalErrorInFunction
            << "Option -expect must be stable, unstable or balanced, not '"
            << expect << "'" << exit(FatalError);
    }
    const label nIterations = canopyCompat::argOrDefault<label>(args, "iterations", 6);
    const scalar dt = canopyCompat::argOrDefault<scalar>(args, "deltaT", 0.02);
    const scalar endTime = canopyCompat::argOrDefault<scalar>(args, "endTime", 2);
    const label nSteps = label(endTime/dt + 0.5);

    const IOdictionary props
    (
        IOobject
        (
            "canopyProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    canopyStructure structure(runTime);
    structure.setTime(0);
    const scopedEntryReader addedMass
    (
        scopedEntryReader(props, "")
       .optionalSubReader("coupling").optionalSubReader("addedMass")
    );
    addedMassStabiliser stabiliser(addedMass, structure);
    if (!stabiliser.active())
    {
        FatalIOErrorInFunction(props)
            << "Entry 'coupling.addedMass.mass' must be > 0 for this test"
            << exit(FatalIOError);
    }
    if (expect == "balanced")
    {
        const scalar jump = canopyCompat::argOrDefault<scalar>(args, "pressureJump", 2);
        canopyStructure reference(props);
        reference.setTime(0);
        return balancedRun(structure, reference, stabiliser, jump, dt, nSteps);
    }
    const scalarField noJump(structure.nTriangles(), Zero);

    Info<< "Canopy without air: " << structure.nNodes() << " nodes, "
        << "total mass " << structure.totalMass() << " kg; predictor "
        << addedMass.wordValue("predictor", "predictor", "lastStep").c_str()
        << ", " << nIterations << " iterations per step, dt " << dt
        << " s, " << nSteps << " steps" << nl << nl
        << "        t [s]      E - E0 [J]      KE [J]   fastest node [m/s]"
        << endl;

    const scalar E0 = structure.energies().total;
    scalar maxGain = 0, maxKinetic = 0, earlyKinetic = 0;
    label stepsDone = 0;
    string failure;
    for (label step = 1; step <= nSteps && failure.empty(); ++step)
    {
        structure.checkpoint();
        stabiliser.beginStep(structure);
        for (label k = 0; k < nIterations; ++k)
        {
            structure.restore();
            structure.setPressureJump(noJump);
            structure.setNodalForces
            (
                "addedMassBalance", stabiliser.balancingForces()
            );
            label subSteps = 0;
            if (!structure.tryAdvance(dt, subSteps, failure))
            {
                break;
            }
            stabiliser.update(structure, dt);
        }
        if (!failure.empty())
        {
            break;
        }
        structure.commit();
        ++stepsDone;

        const canopyStructure::energy e(structure.energies());
        maxGain = max(maxGain, e.total - E0);
        maxKinetic = max(maxKinetic, e.kinetic);
        if (step <= nSteps/10)
        {
            earlyKinetic = max(earlyKinetic, e.kinetic);
        }
        if (step % max(label(1), nSteps/10) == 0)
        {
            Info<< "    " << setw(9) << step*dt << "  " << setw(14)
                << e.total - E0 << "  " << setw(10) << e.kinetic << "  "
                << setw(12) << max(mag(structure.velocities())) << endl;
        }
    }

    Info<< nl << "Steps advanced: " << stepsDone << " of " << nSteps;
    if (!failure.empty())
    {
        Info<< "; stopped: " << failure.c_str();
    }
    Info<< nl << "Largest gain max(E - E0) = " << maxGain << " J, largest"
        << " kinetic energy " << maxKinetic << " J (first tenth: "
        << earlyKinetic << " J)" << nl << endl;

    if (expect == "stable")
    {
        check("steps not advanced", scalar(nSteps - stepsDone), 0);
        check
        (
            "max(E - E0)/max(KE)", maxGain/max(maxKinetic, VSMALL), 0.01
        );
    }
    else
    {
        // Grows: a failed step, or a gain above the early kinetic energy
        const scalar earlyOverGain =
            failure.empty() ? earlyKinetic/max(maxGain, VSMALL) : 0;
        check("early kinetic energy/max(E - E0)", earlyOverGain, 1);
    }
    Info<< nChecks - nFailed << " of " << nChecks << " checks passed" << endl;
    return nFailed ? 1 : 0;
}


// ************************************************************************* //
