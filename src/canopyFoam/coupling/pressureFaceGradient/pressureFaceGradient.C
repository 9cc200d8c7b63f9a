/*---------------------------------------------------------------------------*\
    canopyFoam: pressureFaceGradient.C — snGrad(p)|Sf| without the
    non-orthogonal correction's gradient on orthogonal meshes.
\*---------------------------------------------------------------------------*/

#include "pressureFaceGradient.H"
#include "snGradScheme.H"
#include "canopyFoamCompat.H"

Foam::scalar Foam::largestNonOrthCorrection(const fvMesh& mesh)
{
    const surfaceVectorField& k = mesh.nonOrthCorrectionVectors();
    scalar largest = k.primitiveField().size() ? max(mag(k.primitiveField())) : 0;
    for (const fvsPatchVectorField& kp : k.boundaryField())
    {
        if (kp.size())
        {
            largest = max(largest, max(mag(kp)));
        }
    }
    reduce(largest, maxOp<scalar>());
    return largest;
}


bool Foam::meshNeedsNonOrthCorrection(const fvMesh& mesh)
{
    return largestNonOrthCorrection(mesh) > orthogonalityTolerance;
}


Foam::tmp<Foam::surfaceScalarField> Foam::pressureFaceGradient
(
    const volScalarField& p,
    const bool needsNonOrthCorrection
)
{
    const fvMesh& mesh = p.mesh();
    const word name("snGrad(" + p.name() + ')');
    tmp<fv::snGradScheme<scalar>> scheme
    (
        fv::snGradScheme<scalar>::New
        (
            mesh, canopyCompat::snGradScheme(mesh, name)
        )
    );

    // snGradScheme::snGrad(p) is this uncorrected part plus, for a
    // corrected scheme, correction(p)
    tmp<surfaceScalarField> tsnGrad =
    (
        needsNonOrthCorrection || !scheme().corrected()
      ? scheme().snGrad(p)
      : fv::snGradScheme<scalar>::snGrad(p, scheme().deltaCoeffs(p), "snGrad")
    );
    return tsnGrad*mesh.magSf();
}
