/*---------------------------------------------------------------------------*\
    canopyFoam: Test-pressureFaceGradient.C — the predictor's face pressure
    gradient equals fvc::snGrad(p)*|Sf| on orthogonal and on sheared meshes.
-------------------------------------------------------------------------------
Application
    Test-pressureFaceGradient

Description
    On the case's mesh, serial or parallel, with p a smooth nonlinear field
    (not reproduced exactly by any face gradient, so that a dropped
    correction shows):

    - meshNeedsNonOrthCorrection(mesh) is what -nonOrthogonal says it must
      be (true or false);
    - pressureFaceGradient(p, flag) equals fvc::snGrad(p)*magSf on every
      internal and boundary face to within what the shortcut may drop:
      |k| |grad p| |S_f| at the largest correction vector k of the mesh
      (round-off, ~2e-14, on a box), plus 4 SMALL of the largest value;
    - on a non-orthogonal mesh, the uncorrected part alone
      (pressureFaceGradient(p, false)) differs from fvc::snGrad(p)*magSf by
      more than 1e-6 of its largest value: the correction matters there,
      and the flag is what keeps it.

    A failed check stops with FatalError (non-zero exit status).

Usage
    \b Test-pressureFaceGradient -nonOrthogonal \<true|false\> [-parallel]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "fvc.H"
#include "pressureFaceGradient.H"
#include "testCheck.H"
#include "canopyFoamCompat.H"

using namespace Foam;

// Largest |a - b| over internal and boundary faces, and largest |b|
static void compare
(
    const surfaceScalarField& a,
    const surfaceScalarField& b,
    scalar& difference,
    scalar& scale
)
{
    difference = gMax(mag(a.primitiveField() - b.primitiveField())());
    scale = gMax(mag(b.primitiveField())());
    forAll(a.boundaryField(), patchi)
    {
        const fvsPatchScalarField& ap = a.boundaryField()[patchi];
        const fvsPatchScalarField& bp = b.boundaryField()[patchi];
        if (ap.size())
        {
            difference = max(difference, max(mag(ap - bp)));
            scale = max(scale, max(mag(bp)));
        }
    }
    reduce(difference, maxOp<scalar>());
    reduce(scale, maxOp<scalar>());
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "pressureFaceGradient against fvc::snGrad(p)*magSf on the case's mesh"
    );
    argList::addOption
    (
        "nonOrthogonal",
        "true|false",
        "whether the mesh has non-orthogonal correction vectors"
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

    if (!canopyCompat::argFound(args, "nonOrthogonal"))
    {
        FatalErrorInFunction
            << "option -nonOrthogonal true|false is required" << exit(FatalError);
    }
    const bool expectNonOrth = canopyCompat::argRead<bool>(args, "nonOrthogonal");

    // A smooth nonlinear pressure, also on the boundary faces
    volScalarField p
    (
        IOobject("p", canopyCompat::timeName(runTime), mesh),
        mesh,
        dimensionedScalar(dimPressure, Zero),
        calculatedFvPatchScalarField::typeName
    );
    {
        const volVectorField& C = mesh.C();
        p.primitiveFieldRef() =
            sin(3*C.component(0)().primitiveField())
           *cos(2*C.component(1)().primitiveField())
          + sqr(C.component(2)().primitiveField());
        forAll(p.boundaryField(), patchi)
        {
            const vectorField& Cf = mesh.C().boundaryField()[patchi];
            p.boundaryFieldRef()[patchi] ==
                sin(3*Cf.component(0)())*cos(2*Cf.component(1)())
              + sqr(Cf.component(2)());
        }
        p.correctBoundaryConditions();
    }

    const bool needs = meshNeedsNonOrthCorrection(mesh);
    Info<< "mesh: " << returnReduce(mesh.nCells(), sumOp<label>())
        << " cells; meshNeedsNonOrthCorrection: " << needs
        << " (expected " << expectNonOrth << ")" << nl;
    check
    (
        "flag differs from -nonOrthogonal (0/1)",
        scalar(needs != expectNonOrth),
        0
    );

    const surfaceScalarField reference(fvc::snGrad(p)*mesh.magSf());
    scalar difference = 0, scale = 0;
    compare(pressureFaceGradient(p, needs)(), reference, difference, scale);

    // What the shortcut may drop: k.(grad p)_f |S_f| with |k| at most the
    // mesh's largest correction vector (below orthogonalityTolerance when
    // it is taken), plus round-off of the sums
    const scalar largestK = largestNonOrthCorrection(mesh);
    const scalar bound =
        (needs ? 0 : largestK*gMax(mag(fvc::grad(p))())*gMax(mesh.magSf()))
      + 4*SMALL*scale;
    Info<< "largest |snGrad(p)*magSf| " << scale << ", largest |k| "
        << largestK << ", bound on the difference " << bound << nl;
    check
    (
        "max |pressureFaceGradient - fvc::snGrad(p)*magSf| / bound",
        difference/bound,
        1
    );

    if (expectNonOrth)
    {
        compare(pressureFaceGradient(p, false)(), reference, difference, scale);
        check
        (
            "1e-6 scale / max |uncorrected - fvc::snGrad(p)*magSf|",
            1e-6*scale/max(difference, VSMALL),
            1
        );
    }

    Info<< nChecks - nFailed << " of " << nChecks << " checks passed" << nl;
    if (nFailed)
    {
        FatalErrorInFunction
            << nFailed << " check(s) failed" << exit(FatalError);
    }
    Info<< "End" << nl;
    return 0;
}
