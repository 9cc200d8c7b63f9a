/*---------------------------------------------------------------------------*\
    canopyFoam: Test-interfaceAcceleration.C — the strong coupling's
    accelerations (Aitken, IQN-ILS) on linear fixed-point problems.
-------------------------------------------------------------------------------
Application
    Test-interfaceAcceleration

Description
    A model of the coupling iteration x <- G(x) for a light canopy:

        G(x) = x* + M (x - x*),   M = H diag(lambda) H,

    H a Householder reflection (orthogonal), the eigenvalues lambda spread
    over [-lambdaMax, 0.5]: the strongly negative ones are the added-mass
    modes (G overshoots by m_added/m_canopy), which make plain iteration and
    Aitken's relaxation diverge or crawl. Checks (each prints PASS/FAIL):

    1. IQN-ILS without reuse reaches |x - x*| < 1e-8 |x*| within n + 2
       evaluations of G (exact least squares on a linear G of dimension n).
    2. The problem is hard: Aitken's relaxation (bounds [0.05, 1]) has not
       reached that after 200 evaluations.
    3. IQN-ILS reusing 8 time steps, over 6 time steps whose fixed points
       differ (same M): every step after the first converges within 4
       evaluations, with the filter dropping the surplus columns.
    4. The same steps without reuse each need more than 4 evaluations (the
       reuse is what helps).
    5. A failed time step (discardStep) writes the step's start state.
    6. A map with memory, the model of the stabilised coupling: the
       stabiliser's balance s is the last output, G(x, s) = x* + A (x - x*)
       + rho (s - x*). With s as secondary data (moved with x) IQN-ILS
       reaches the fixed point within n + 2 evaluations; updating x alone
       while s jumps to the output it does not.
    7. IQN-ILS restarted from its written state (with the secondary
       columns, quasiNewtonWs) moves x and s as the uninterrupted one.
    8. Aitken's relaxation (factor from 1, floor 0.05) on a map with
       memory whose pair gains reach -1.6 (plain iteration diverges):
       moving s with the factor it converges within 100 evaluations;
       updating x alone while s jumps to the output it does not within
       200.
    9. Secondary data given as a list of vector fields moves exactly as
       the same components packed in one scalar field.
   10. The same with a vector and a scalar field.
   11. A map changed since the reused steps (another reflection): the
       update fitted to the past steps' columns raises the residual above
       the step's first, IQN-ILS drops them there, and the step converges
       within n + 2 evaluations of the drop.

    Exit status 0 only when every check passes.

    With -select TEXT it only selects an acceleration from TEXT, the body
    of a coupling's acceleration sub-dictionary (e.g. "type IQN-ILS;
    reuse 4;"),
    prints what it selected and exits: a bad entry stops with the
    FatalIOError naming it (checked by tests/openfoam/interfaceAcceleration).

Usage
    Test-interfaceAcceleration [-n N] [-lambdaMax L] [-select TEXT]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "interfaceQuasiNewton.H"
#include "aitkenRelaxation.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "canopyFoamCompat.H"

using namespace Foam;

// Apply the reflection H = I - 2 u u^T / (u.u)
static scalarField reflect(const scalarField& u, const scalarField& v)
{
    return v - 2*sum(u*v)/sum(u*u)*u;
}


struct linearProblem
{
    scalarField u;          // reflection vector
    scalarField lambda;     // eigenvalues
    scalarField xStar;      // fixed point

    scalarField G(const scalarField& x) const
    {
        return xStar + reflect(u, lambda*reflect(u, x - xStar));
    }
};


// A map with memory, the model of the stabilised coupling: the structure
// adds a lumped mass rho/(1 - rho) of its own and balances it with what it
// made of the last evaluation, s (the stabiliser's balance; its target is
// the output itself):
//     G(x, s) = x* + A (x - x*) + rho (s - x*),   S(x, s) = G(x, s),
// A = H diag(lambda) H: on the pair moved together (s = x) the map is
// x* + (A + rho) (x - x*), stationary.
struct memoryProblem
{
    linearProblem P;        // x* and A (its lambda)
    scalar rho;

    scalarField G(const scalarField& x, const scalarField& s) const
    {
        return P.G(x) + rho*(s - P.xStar);
    }
};


// The model of the 7 ft canopy's stabilised coupling on P's fixed point
// and reflection: rho 0.935 (its m_A/(m + m_A)), the pair's gains A + rho
// spread evenly over [lowest, highest]
static memoryProblem stabilisedModel
(
    const linearProblem& P,
    const scalar lowest,
    const scalar highest
)
{
    memoryProblem Q;
    Q.P = P;
    Q.rho = 0.935;
    const label n = Q.P.lambda.size();
    forAll(Q.P.lambda, i)
    {
        const scalar s = scalar(i)/max(n - 1, 1);
        Q.P.lambda[i] = lowest - Q.rho + (highest - lowest)*s;
    }
    return Q;
}


// Iterate the map with memory; consistent: s is the acceleration's
// secondary data, else s jumps to the last output (IQN-ILS before the
// secondary data). Returns the evaluations as solve() does
static label solveMemory
(
    interfaceAcceleration& acc,
    const memoryProblem& Q,
    scalarField& x,
    scalarField& s,
    const bool consistent,
    label maxEval,
    scalar tol
)
{
    const scalar scale = max(mag(Q.P.xStar));
    for (label k = 1; k <= maxEval; ++k)
    {
        const scalarField target(Q.G(x, s));
        if (max(mag(target - x)) < tol*scale)
        {
            return k;
        }
        if (consistent)
        {
            acc.relax(x, target, s, target);
        }
        else
        {
            acc.relax(x, target);
            s = target;
        }
        if (max(mag(x)) > 1e30*scale)
        {
            return maxEval + 1;
        }
    }
    return maxEval + 1;
}


// Iterate until |x - x*| < tol |x*| or maxEval evaluations; returns the
// number of evaluations of G (maxEval + 1 when not converged or diverged)
static label solve
(
    interfaceAcceleration& acc,
    const linearProblem& P,
    scalarField& x,
    label maxEval,
    scalar tol
)
{
    const scalar scale = max(mag(P.xStar));
    for (label k = 1; k <= maxEval; ++k)
    {
        const scalarField target(P.G(x));
        if (max(mag(x - P.xStar)) < tol*scale)
        {
            return k;
        }
        acc.relax(x, target);
        if (max(mag(x)) > 1e30*scale)
        {
            // Diverged (stop before the arithmetic overflows)
            return maxEval + 1;
        }
    }
    return maxEval + 1;
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    canopyCompat::noBanner();
    argList::addOption("n", "N", "dimension of the interface (default 24)");
    argList::addOption("lambdaMax", "L", "added-mass ratio (default 140)");
    argList::addOption
    (
        "select",
        "TEXT",
        "only select an acceleration from the body of a coupling"
        " acceleration sub-dictionary"
    );
    argList args(argc, argv, false, false);

    if (canopyCompat::argFound(args, "select"))
    {
        const dictionary dict(IStringStream(canopyCompat::argRead<string>(args, "select"))());
        autoPtr<interfaceAcceleration> acc
        (
            interfaceAcceleration::New
            (
                scopedEntryReader(dict, "coupling.acceleration")
            )
        );
        Info<< "selected: " << acc->describe().c_str() << endl;
        return 0;
    }

    const label n = canopyCompat::argOrDefault<label>(args, "n", 24);
    const scalar lambdaMax = canopyCompat::argOrDefault<scalar>(args, "lambdaMax", 140);
    const scalar tol = 1e-8;

    linearProblem P;
    P.u.setSize(n);
    P.lambda.setSize(n);
    P.xStar.setSize(n);
    forAll(P.u, i)
    {
        P.u[i] = 1 + 0.5*Foam::sin(1.3*i + 0.2);
        // -lambdaMax ... 0.5, a few strongly negative modes
        const scalar s = scalar(i)/max(n - 1, 1);
        P.lambda[i] = 0.5 - (lambdaMax + 0.5)*Foam::pow(1 - s, 4);
        P.xStar[i] = Foam::cos(0.7*i) + 0.1*i/n;
    }
    Info<< "Linear fixed point of dimension " << n << ", eigenvalues of M in ["
        << min(P.lambda) << ", " << max(P.lambda) << "]" << nl << endl;

    label failures = 0;
    auto check = [&](bool ok, const std::string& what)
    {
        Info<< (ok ? "PASS " : "FAIL ") << what.c_str() << endl;
        if (!ok) ++failures;
    };

    // 1. IQN-ILS without reuse
    {
        interfaceQuasiNewton iqn(0.1, 0, 1e-10);
        scalarField x(n, Zero);
        const label k = solve(iqn, P, x, 4*n, tol);
        check
        (
            k <= n + 2,
            "IQN-ILS (no reuse) converged in " + std::to_string(k)
          + " evaluations (limit n + 2 = " + std::to_string(n + 2) + ")"
        );
    }

    // 2. Aitken's relaxation on the same problem
    {
        aitkenRelaxation aitken(0.5, 0.05, 1);
        scalarField x(n, Zero);
        const label k = solve(aitken, P, x, 200, tol);
        check
        (
            k > 200,
            "Aitken's relaxation has not converged after 200 evaluations"
            " (the problem needs more than relaxation): "
          + std::string(k > 200 ? "not converged" : "converged in "
          + std::to_string(k))
        );
    }

    // 3. and 4. Six time steps with moving fixed points
    {
        interfaceQuasiNewton reused(0.1, 8, 1e-3);
        interfaceQuasiNewton fresh(0.1, 0, 1e-3);
        scalarField xr(n, Zero), xf(n, Zero);
        label worstReused = 0, bestFresh = labelMax, dropped = 0;
        bool allConverged = true;
        for (label step = 0; step < 6; ++step)
        {
            linearProblem Ps(P);
            forAll(Ps.xStar, i)
            {
                Ps.xStar[i] += 0.3*step*Foam::sin(0.5*i + step);
            }
            reused.reset();
            fresh.reset();
            const label kr = solve(reused, Ps, xr, 4*n, tol);
            const label kf = solve(fresh, Ps, xf, 4*n, tol);
            Info<< "  step " << step << ": evaluations with reuse " << kr
                << " (" << reused.describe().c_str() << "), without " << kf
                << endl;
            allConverged = allConverged && kr <= 4*n && kf <= 4*n;
            if (step > 0)
            {
                worstReused = max(worstReused, kr);
                bestFresh = min(bestFresh, kf);
            }
            dropped = max(dropped, reused.columnsDropped());
        }
        check
        (
            allConverged && worstReused <= 4,
            "IQN-ILS reusing 8 steps: every step after the first converged"
            " within " + std::to_string(worstReused) + " evaluations (limit 4)"
            ", largest number of filtered columns " + std::to_string(dropped)
        );
        check
        (
            bestFresh > 4,
            "IQN-ILS without reuse needs at least " + std::to_string(bestFresh)
          + " evaluations per step (more than 4)"
        );
    }

    // 5. A failed time step (discardStep): the state written afterwards
    //    (the last good state) is the one the step started from
    {
        interfaceQuasiNewton iqn(0.1, 8, 1e-3);
        scalarField x(n, Zero);
        solve(iqn, P, x, 4*n, tol);             // a first, completed step
        iqn.reset();
        dictionary atStart;
        iqn.writeState(atStart);
        linearProblem Ps(P);
        forAll(Ps.xStar, i)
        {
            Ps.xStar[i] += 0.2*Foam::cos(0.3*i);
        }
        solve(iqn, Ps, x, 3, tol);              // a step cut short
        dictionary cutShort, discarded;
        iqn.writeState(cutShort);
        iqn.discardStep();
        iqn.writeState(discarded);
        const auto columns = [](const dictionary& d)
        {
            return List<List<scalarField>>(d.lookup("quasiNewtonV")).size();
        };
        OStringStream a, b;
        a << atStart;
        b << discarded;
        check
        (
            a.str() == b.str() && columns(cutShort) > columns(atStart),
            "IQN-ILS after a failed step writes the step's start state ("
          + std::to_string(columns(discarded)) + " past steps' columns; "
          + std::to_string(columns(cutShort)) + " with the cut-short step's)"
        );
    }

    // 6. The map with memory of the stabilised coupling (rho 0.935, the
    //    7 ft canopy's m_A/(m + m_A); the pair's gain A + rho in
    //    [-0.6, 0.9]): with the stabiliser's state as secondary data
    //    IQN-ILS iterates one stationary map; updating x alone it does not
    {
        const memoryProblem Q(stabilisedModel(P, -0.6, 0.9));
        const label maxEval = 200;
        const scalar tolM = 1e-6;
        label kIqn[2];
        for (const bool consistent : {true, false})
        {
            interfaceQuasiNewton iqn(0.3, 0, 1e-10);
            scalarField x(n, Zero), s(n, Zero);
            kIqn[consistent] =
                solveMemory(iqn, Q, x, s, consistent, maxEval, tolM);
            Info<< "  memory, " << (consistent ? "secondary data" : "x alone")
                << ": IQN-ILS " << kIqn[consistent] << " evaluations" << endl;
        }
        check
        (
            kIqn[true] <= n + 2 && kIqn[false] > n + 2,
            "IQN-ILS on the map with memory: " + std::to_string(kIqn[true])
          + " evaluations with the secondary data (limit n + 2), "
          + std::to_string(kIqn[false]) + " updating x alone"
        );
    }

    // 8. Aitken's relaxation on the map with memory whose pair has gains
    //    below -1 (a mode whose air outweighs the stabiliser: plain
    //    iteration diverges; pair gains in [-1.6, 0.5], rho 0.935), from
    //    the tutorials' factor 1 with the floor 0.05: moving the
    //    stabiliser's state with the factor (as aitkenRelaxation does)
    //    relaxes the pair's map, which converges for a factor below
    //    2/2.6; handing it the last output instead leaves a loop the
    //    factor does not reach, which converges by about rho per
    //    evaluation at best
    {
        const memoryProblem Q(stabilisedModel(P, -1.6, 0.5));
        const label maxEval = 200;
        const scalar tolM = 1e-6;
        label kAitken[2];
        for (const bool consistent : {true, false})
        {
            aitkenRelaxation aitken(1, 0.05, 1);
            scalarField x(n, Zero), s(n, Zero);
            kAitken[consistent] =
                solveMemory(aitken, Q, x, s, consistent, maxEval, tolM);
            Info<< "  memory, gains below -1, "
                << (consistent ? "secondary data relaxed" : "x alone")
                << ": Aitken " << kAitken[consistent] << " evaluations"
                << endl;
        }
        check
        (
            kAitken[true] <= 100 && kAitken[false] > maxEval,
            "Aitken on the map with memory (pair gains down to -1.6): "
          + std::to_string(kAitken[true]) + " evaluations with the"
            " stabiliser's state relaxed (limit 100), "
          + std::string(kAitken[false] > maxEval ? "not converged after 200"
            : "converged in " + std::to_string(kAitken[false]))
          + " relaxing x alone"
        );
    }

    // 7. The secondary columns go with the restart state
    {
        interfaceQuasiNewton iqn(0.3, 8, 1e-3), restarted(0.3, 8, 1e-3);
        memoryProblem Q;
        Q.P = P;
        Q.rho = 0.5;
        scalarField x(n, Zero), s(n, Zero);
        solveMemory(iqn, Q, x, s, true, 3, 1e-12);
        // Every digit, as canopyCoupling writes its state
        const unsigned precision = IOstream::defaultPrecision(17);
        dictionary state;
        iqn.writeState(state);
        IOstream::defaultPrecision(precision);
        restarted.readState(state);
        iqn.reset();
        restarted.reset();
        scalarField x1(x), s1(s), x2(x), s2(s);
        const scalarField target(Q.G(x, s));
        iqn.relax(x1, target, s1, target);
        restarted.relax(x2, target, s2, target);
        check
        (
            max(mag(x1 - x2)) == 0 && max(mag(s1 - s2)) == 0
         && state.found("quasiNewtonWs"),
            "IQN-ILS restarted from its written state moves x and s as the"
            " uninterrupted one (quasiNewtonWs written)"
        );
    }

    // 9. Vector fields as the secondary data, as interfaceIterate hands
    //    them (the stabiliser's balance, the no-slip velocity, the
    //    markers' positions and normals, in a list): IQN-ILS moves them
    //    exactly as the same components packed in one scalar field (s
    //    split into two vector fields, padded with zeros to whole
    //    vectors)
    {
        const memoryProblem Q(stabilisedModel(P, -0.6, 0.9));
        const label nv = (n + 2)/3;
        const label na = nv/2;
        auto toVectors = [&](const scalarField& v, vectorField& a, vectorField& b)
        {
            a.setSize(na);
            b.setSize(nv - na);
            for (label i = 0; i < 3*nv; ++i)
            {
                vector& w = i < 3*na ? a[i/3] : b[i/3 - na];
                w[i % 3] = i < n ? v[i] : 0;
            }
        };
        auto toScalars = [&](const vectorField& a, const vectorField& b)
        {
            scalarField v(n);
            forAll(v, i)
            {
                v[i] = (i < 3*na ? a[i/3] : b[i/3 - na])[i % 3];
            }
            return v;
        };
        interfaceQuasiNewton packed(0.3, 0, 1e-10), listed(0.3, 0, 1e-10);
        scalarField x1(n, Zero), s1(n, Zero), x2(n, Zero);
        vectorField a, b, aTarget, bTarget;
        toVectors(s1, a, b);
        scalar difference = 0;
        for (label k = 0; k < 8; ++k)
        {
            const scalarField target1(Q.G(x1, s1));
            packed.relax(x1, target1, s1, target1);
            const scalarField target2(Q.G(x2, toScalars(a, b)));
            toVectors(target2, aTarget, bTarget);
            listed.relax
            (
                x2, target2,
                List<vectorField*>({&a, &b}),
                List<const vectorField*>({&aTarget, &bTarget})
            );
            difference = max
            (
                difference,
                max(max(mag(x1 - x2)), max(mag(s1 - toScalars(a, b))))
            );
        }
        check
        (
            difference == 0,
            "vector fields as the secondary data move as the packed scalar"
            " field (largest difference over 8 evaluations: "
          + std::to_string(difference) + ")"
        );
    }

    // 10. A vector field and a scalar field as the secondary data (the
    //    markers' positions and areas, interfaceIterate) move exactly as
    //    the same values packed in one scalar field, the vectors'
    //    components first
    {
        const memoryProblem Q(stabilisedModel(P, -0.6, 0.9));
        const label na = n/6;
        auto toMixed = [&](const scalarField& v, vectorField& a, scalarField& c)
        {
            a.setSize(na);
            c.setSize(n - 3*na);
            forAll(v, i)
            {
                if (i < 3*na)
                {
                    a[i/3][i % 3] = v[i];
                }
                else
                {
                    c[i - 3*na] = v[i];
                }
            }
        };
        auto fromMixed = [&](const vectorField& a, const scalarField& c)
        {
            scalarField v(n);
            forAll(v, i)
            {
                v[i] = i < 3*na ? a[i/3][i % 3] : c[i - 3*na];
            }
            return v;
        };
        interfaceQuasiNewton packed(0.3, 0, 1e-10), listed(0.3, 0, 1e-10);
        scalarField x1(n, Zero), s1(n, Zero), x2(n, Zero);
        vectorField a, aTarget;
        scalarField c, cTarget;
        toMixed(s1, a, c);
        scalar difference = 0;
        for (label k = 0; k < 8; ++k)
        {
            const scalarField target1(Q.G(x1, s1));
            packed.relax(x1, target1, s1, target1);
            const scalarField target2(Q.G(x2, fromMixed(a, c)));
            toMixed(target2, aTarget, cTarget);
            listed.relax
            (
                x2, target2,
                List<vectorField*>({&a}), List<const vectorField*>({&aTarget}),
                List<scalarField*>({&c}), List<const scalarField*>({&cTarget})
            );
            difference = max
            (
                difference,
                max(max(mag(x1 - x2)), max(mag(s1 - fromMixed(a, c))))
            );
        }
        check
        (
            difference == 0 && na > 0 && n - 3*na > 0,
            "a vector and a scalar field as the secondary data move as the"
            " packed scalar field (largest difference over 8 evaluations: "
          + std::to_string(difference) + ")"
        );
    }

    // 11. A map that changes between time steps, as the added-mass modes
    //    of an inflating canopy turn: six steps on P (the columns of eight
    //    steps reused), then a step on a map whose modes point elsewhere
    //    (another reflection, the same eigenvalues). The update fitted to
    //    the past steps' columns raises the residual above the step's
    //    first; IQN-ILS drops those columns there, and goes on with the
    //    step's own, which bounds what the drop costs: the fixed point
    //    within n + 2 evaluations of the drop, as without reuse
    {
        linearProblem P2(P);
        forAll(P2.u, i)
        {
            P2.u[i] = 1 + 0.8*Foam::cos(2.1*i + 1.0);
        }
        interfaceQuasiNewton iqn(0.1, 8, 1e-3);
        scalarField x(n, Zero);
        for (label step = 0; step < 6; ++step)
        {
            linearProblem Ps(P);
            forAll(Ps.xStar, i)
            {
                Ps.xStar[i] += 0.3*step*Foam::sin(0.5*i + step);
            }
            iqn.reset();
            solve(iqn, Ps, x, 4*n, tol);
        }
        iqn.reset();
        const scalar scale = max(mag(P2.xStar));
        label k = 1, dropAt = 0;
        for (; k <= 4*n; ++k)
        {
            const scalarField target(P2.G(x));
            if (max(mag(x - P2.xStar)) < tol*scale)
            {
                break;
            }
            iqn.relax(x, target);
            if (!dropAt && iqn.pastDropped())
            {
                dropAt = k;
            }
        }
        Info<< "  changed map: past steps' columns dropped at evaluation "
            << dropAt << ", converged at " << k << endl;
        check
        (
            dropAt > 0 && k <= 4*n && k - dropAt <= n + 2,
            "IQN-ILS on a map changed since the reused steps: the past"
            " steps' columns dropped at evaluation " + std::to_string(dropAt)
          + ", converged " + std::to_string(k - dropAt) + " evaluations"
            " later (limit n + 2 = " + std::to_string(n + 2) + ")"
        );
    }

    Info<< nl << (failures ? "FAILED: " : "PASSED: ") << failures
        << " of 11 checks failed" << endl;
    return failures ? 1 : 0;
}


// ************************************************************************* //
