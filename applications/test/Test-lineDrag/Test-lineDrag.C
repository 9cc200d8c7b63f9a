/*---------------------------------------------------------------------------*\
    canopyFoam: Test-lineDrag.C — verification of the suspension lines' drag
    (lineDrag): closed-form drag of a line in uniform and linear flows, the
    split to its end nodes, the reaction on the air, and bad entries.
-------------------------------------------------------------------------------
Application
    Test-lineDrag

Description
    On the mesh of the case (a box [0, 1]^3), serial or parallel, with
    rho = 1.2, d = 2 mm, Cd = 1.1, Cf = 0.01, and one suspension line (a
    libcanopy spring of the line group between two nodes):

    1. across a uniform flow U0 x: drag 1/2 rho Cd d L U0^2 x;
    2. at 50 degrees to the flow: normal part 1/2 rho Cd d L (U0 sin)^2
       along the normal in the plane of line and flow, tangential part
       1/2 rho Cf pi d L (U0 cos)^2 along the line;
    3. a line moving with the air (line velocity = air velocity + the
       frame's velocity, the air being given in the frame): no drag;
    4. across a linear shear flow U = c (z - z0) x over z0 .. z0 + L: the
       composite midpoint rule on n pieces of the exact integral,
       1/2 rho Cd d c^2 (L^3/3 - L h^2/12), h = L/n (the rule's error for
       a quadratic is exactly L h^2 f''/24): checks where the sample
       points sit and their length shares;
    5. half the line outside the mesh: half the pieces outside, the drag
       of the inside half only;
    and in every case: the nodal forces add up to the drag and carry its
    moment about the origin (the linear split), and the reaction spread to
    the air, sum_i f_i V_i rho over all ranks, is minus the drag. All to
    a relative 1e-10 (round-off: interpolation of constant and linear
    fields is exact, spreading conserves exactly).

    Option -perturb makes the drag with Cd 1e-6 too large: the run must
    fail (a check of the checks).

    6. Bad entries: a missing diameter, a negative Cd or Cf, a zero
       spacing, and a model without lines each fail with an IOerror naming
       the entry.

    Failures stop through FatalError (v1912's argList ends every run with
    exit status 0 otherwise); a passing run prints "Test-lineDrag: PASSED".

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "testCheck.H"
#include "mathematicalConstants.H"
#include "deltaKernel.H"
#include "lineDrag.H"
#include "canopy.h"
#include "canopyFoamCompat.H"

using namespace Foam;

namespace
{

const scalar rho = 1.2;
const scalar d = 0.002;
const scalar Cd = 1.1;

// The Cd the lineDrag is made with (-perturb: 1e-6 too large, so that the
// checks must fail)
scalar CdUsed = Cd;
const scalar Cf = 0.01;
const scalar tol = 1e-10;


// A model holding one line a-b (both ends free) with node velocities v
struct oneLine
{
    canopy_model* model = nullptr;

    oneLine(const point& a, const point& b, const vector& v)
    {
        canopy_model_create(&model);
        const double xa[3] = {a.x(), a.y(), a.z()};
        const double xb[3] = {b.x(), b.y(), b.z()};
        canopy_model_add_node(model, xa, 0.01, CANOPY_GROUP_LINE, nullptr);
        canopy_model_add_node(model, xb, 0.01, CANOPY_GROUP_LINE, nullptr);
        canopy_model_add_spring
        (
            model, 0, 1, 1000, 0, CANOPY_SPRING_TENSION_ONLY,
            CANOPY_GROUP_LINE, nullptr
        );
        const double vel[6] = {v.x(), v.y(), v.z(), v.x(), v.y(), v.z()};
        canopy_model_set_velocities(model, vel, 2);
    }

    ~oneLine()
    {
        canopy_model_destroy(&model);
    }
};


dictionary dragDict(const scalar spacing)
{
    dictionary dict;
    dict.add("diameter", d);
    dict.add("Cd", CdUsed);
    dict.add("Cf", Cf);
    dict.add("spacing", spacing);
    return dict;
}


// Drag of line a-b in the air U (frame velocity V, node velocities v),
// checked against the expected total drag and pieces outside
void checkLine
(
    const word& name,
    const fvMesh& mesh,
    const deltaKernel& kernel,
    const volVectorField& U,
    const point& a,
    const point& b,
    const vector& v,
    const vector& V,
    const scalar spacing,
    const vector& expected,
    const label expectedOutside,
    const scalar scale
)
{
    Info<< name.c_str() << nl;
    oneLine line(a, b, v);
    const dictionary dict(dragDict(spacing));
    lineDrag drag
    (
        scopedEntryReader(dict, "coupling.lineDrag"), mesh, kernel,
        line.model, 1
    );
    drag.place(line.model, Zero);
    drag.compute(U, line.model, V, rho);
    const vector total = drag.total();
    Info<< "    drag " << total << ", expected " << expected << ", "
        << drag.size() << " sample points, " << drag.nOutside()
        << " outside" << nl;
    check("|drag - expected|/scale", mag(total - expected)/scale, tol);
    check
    (
        "|sample points outside - expected|",
        mag(scalar(drag.nOutside() - expectedOutside)), 0
    );

    // Nodal forces: the drag and its moment about the origin
    vectorField nodal(2, Zero);
    {
        labelList nodes;
        vectorField forces;
        drag.nodalForces(nodes, forces);
        forAll(nodes, i)
        {
            nodal[nodes[i]] += forces[i];
        }
    }
    check("|sum of nodal forces - drag|/scale", mag(sum(nodal) - total)/scale, tol);
    const vector moment = (a ^ nodal[0]) + (b ^ nodal[1]);
    // The moment of the sample forces: their points, as placed
    vector sampleMoment(Zero);
    {
        const label n = drag.size();
        for (label k = 0; k < n; ++k)
        {
            const scalar s = (k + 0.5)/n;
            sampleMoment += (((1 - s)*a + s*b) ^ drag.forces()[k]);
        }
    }
    check
    (
        "|nodal moment - moment of the sample forces|/(scale |b|)",
        mag(moment - sampleMoment)/(scale*max(mag(a), mag(b))), tol
    );

    // Reaction on the air
    vectorField f(mesh.nCells(), Zero);
    drag.spreadReaction(f, rho);
    const vector reaction = rho*gSum(f*mesh.cellVolumes());
    check("|reaction + drag|/scale", mag(reaction + total)/scale, tol);
}


// Constructing from dict must fail with an IOerror naming entry
void expectBadEntry
(
    const word& name,
    const dictionary& dict,
    const fvMesh& mesh,
    const deltaKernel& kernel,
    const canopy_model* model,
    const string& entry
)
{
    ++nChecks;
    bool named = false;
    string message("no error");
    try
    {
        lineDrag drag
        (
            scopedEntryReader(dict, "coupling.lineDrag"), mesh, kernel,
            model, 0.1
        );
    }
    catch (const Foam::IOerror& err)
    {
        message = err.message();
        named = message.find("'" + entry + "'") != string::npos;
    }
    if (!named)
    {
        ++nFailed;
    }
    Info<< "    " << (named ? "ok  " : "FAIL") << "  " << name.c_str()
        << ": " << message.c_str() << nl;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    canopyCompat::noFunctionObjects();
    argList::addBoolOption
    (
        "perturb",
        "make the drag with Cd 1e-6 too large: the checks must fail"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            canopyCompat::timeName(runTime),
            runTime,
            IOobject::MUST_READ
        )
    );

    if (canopyCompat::argFound(args, "perturb"))
    {
        CdUsed = Cd*(1 + 1e-6);
    }

    autoPtr<deltaKernel> kernel(deltaKernel::New("roma3"));
    const scalar pi = constant::mathematical::pi;
    const scalar U0 = 5;

    volVectorField U
    (
        IOobject("U", canopyCompat::timeName(runTime), mesh),
        mesh,
        dimensionedVector("U0", dimVelocity, vector(U0, 0, 0))
    );

    // 1. Across a uniform flow
    {
        const scalar L = 0.6;
        const vector expected(0.5*rho*Cd*d*L*U0*U0, 0, 0);
        checkLine
        (
            "1. line across a uniform flow", mesh, kernel(), U,
            point(0.5, 0.5, 0.2), point(0.5, 0.5, 0.8), Zero, Zero, 0.05,
            expected, 0, mag(expected)
        );
    }

    // 2. At 50 degrees to the flow
    {
        const scalar L = 0.6, theta = 50*pi/180;
        const vector t(std::cos(theta), 0, std::sin(theta));
        const point a(0.3, 0.5, 0.25);
        const vector normal((vector(1, 0, 0) - std::cos(theta)*t)/std::sin(theta));
        const scalar un = U0*std::sin(theta), ut = U0*std::cos(theta);
        const vector expected =
            0.5*rho*d*L*(Cd*un*un*normal + Cf*pi*ut*ut*t);
        checkLine
        (
            "2. line at 50 degrees to a uniform flow", mesh, kernel(), U,
            a, a + L*t, Zero, Zero, 0.05, expected, 0, mag(expected)
        );
    }

    // 3. Moving with the air, in a moving frame
    {
        const vector V(0, 0, -4);
        checkLine
        (
            "3. line moving with the air (frame velocity (0 0 -4))", mesh,
            kernel(), U, point(0.4, 0.5, 0.2), point(0.6, 0.4, 0.8),
            vector(U0, 0, 0) + V, V, 0.05, Zero, 0, 0.5*rho*Cd*d*0.6*U0*U0
        );
    }

    // 4. Across a linear shear flow: the midpoint rule of the integral
    {
        const scalar c = 8, z0 = 0.2, L = 0.6, spacing = 0.055;
        const label n = 11;     // ceil(0.6/0.055)
        const scalar h = L/n;
        volVectorField Ushear("Ushear", U);
        forAll(Ushear, i)
        {
            Ushear[i] = vector(c*(mesh.C()[i].z() - z0), 0, 0);
        }
        forAll(Ushear.boundaryField(), patchi)
        {
            fvPatchVectorField& pf = Ushear.boundaryFieldRef()[patchi];
            forAll(pf, facei)
            {
                pf[facei] =
                    vector(c*(mesh.C().boundaryField()[patchi][facei].z() - z0), 0, 0);
            }
        }
        const vector expected
        (
            0.5*rho*Cd*d*c*c*(pow3(L)/3 - L*h*h/12), 0, 0
        );
        checkLine
        (
            "4. line across a linear shear flow (11 pieces)", mesh, kernel(),
            Ushear, point(0.5, 0.5, z0), point(0.5, 0.5, z0 + L), Zero, Zero,
            spacing, expected, 0, mag(expected)
        );
    }

    // 5. Half outside the mesh
    {
        const scalar L = 1.0;
        const vector expected(0.5*rho*Cd*d*0.5*L*U0*U0, 0, 0);
        checkLine
        (
            "5. line half outside the mesh (10 pieces, 5 outside)", mesh,
            kernel(), U, point(0.5, 0.5, 0.5), point(0.5, 0.5, 1.5), Zero,
            Zero, 0.1, expected, 5, mag(expected)
        );
    }

    // 6. Bad entries
    Info<< "6. bad entries name the entry" << nl;
    {
        FatalIOError.throwExceptions();
        oneLine line(point(0.5, 0.5, 0.2), point(0.5, 0.5, 0.8), Zero);

        dictionary noDiameter(dragDict(0.1));
        noDiameter.remove("diameter");
        expectBadEntry
        (
            "missing diameter", noDiameter, mesh, kernel(), line.model,
            "coupling.lineDrag.diameter"
        );
        dictionary negativeCd(dragDict(0.1));
        negativeCd.set("Cd", -1.0);
        expectBadEntry
        (
            "Cd -1", negativeCd, mesh, kernel(), line.model,
            "coupling.lineDrag.Cd"
        );
        dictionary negativeCf(dragDict(0.1));
        negativeCf.set("Cf", -0.01);
        expectBadEntry
        (
            "Cf -0.01", negativeCf, mesh, kernel(), line.model,
            "coupling.lineDrag.Cf"
        );
        dictionary unknownEntry(dragDict(0.1));
        unknownEntry.add("Cdd", 1.0);
        expectBadEntry
        (
            "unknown Cdd", unknownEntry, mesh, kernel(), line.model,
            "coupling.lineDrag.Cdd"
        );
        dictionary zeroSpacing(dragDict(0.1));
        zeroSpacing.set("spacing", 0.0);
        expectBadEntry
        (
            "spacing 0", zeroSpacing, mesh, kernel(), line.model,
            "coupling.lineDrag.spacing"
        );

        // A model with no line springs (one fabric spring)
        canopy_model* fabric = nullptr;
        canopy_model_create(&fabric);
        const double xa[3] = {0.5, 0.5, 0.2}, xb[3] = {0.5, 0.5, 0.8};
        canopy_model_add_node(fabric, xa, 0.01, CANOPY_GROUP_FABRIC, nullptr);
        canopy_model_add_node(fabric, xb, 0.01, CANOPY_GROUP_FABRIC, nullptr);
        canopy_model_add_spring
        (
            fabric, 0, 1, 1000, 0, CANOPY_SPRING_MODEL_II,
            CANOPY_GROUP_FABRIC, nullptr
        );
        expectBadEntry
        (
            "no suspension lines", dragDict(0.1), mesh, kernel(), fabric,
            "coupling.lineDrag"
        );
        canopy_model_destroy(&fabric);
        FatalIOError.dontThrowExceptions();
    }

    Info<< nl << nChecks << " checks, " << nFailed << " failed" << nl;
    if (nFailed)
    {
        FatalErrorInFunction
            << "Test-lineDrag: FAILED (" << nFailed << " of " << nChecks
            << " checks)" << exit(FatalError);
    }
    Info<< "Test-lineDrag: PASSED" << endl;
    return 0;
}
