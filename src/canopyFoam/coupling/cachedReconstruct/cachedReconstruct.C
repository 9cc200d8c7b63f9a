/*---------------------------------------------------------------------------*\
    canopyFoam: cachedReconstruct.C — fvc::reconstruct with the static mesh's
    geometric inverse built once.
\*---------------------------------------------------------------------------*/

#include "cachedReconstruct.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "fvcSurfaceIntegrate.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cachedReconstruct::buildGeometry() const
{
    if (inverse_.valid())
    {
        return;
    }
    SfHat_.reset
    (
        new surfaceVectorField("canopySfHat", mesh_.Sf()/mesh_.magSf())
    );
    inverse_.reset
    (
        new volTensorField
        (
            "canopyReconstructInverse",
            inv(fvc::surfaceSum(SfHat_()*mesh_.Sf()))
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cachedReconstruct::cachedReconstruct(const fvMesh& mesh)
:
    mesh_(mesh)
{}


// * * * * * * * * * * * * * * * Member Operators  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField> Foam::cachedReconstruct::operator()
(
    const surfaceScalarField& ssf
) const
{
    buildGeometry();
    tmp<volVectorField> tfield
    (
        new volVectorField
        (
            IOobject
            (
                "reconstruct(" + ssf.name() + ')',
                ssf.instance(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh_,
            dimensioned<vector>(ssf.dimensions()/dimArea, Zero),
            extrapolatedCalculatedFvPatchField<vector>::typeName
        )
    );

    // inv(sum_f SfHat Sf) & sum_f SfHat ssf_f, summed face by face into
    // the cells (fvc::surfaceSum without the face field of the products)
    vectorField& result = tfield.ref().primitiveFieldRef();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& SfHat = SfHat_().primitiveField();
    const scalarField& values = ssf.primitiveField();
    forAll(own, facei)
    {
        const vector v(SfHat[facei]*values[facei]);
        result[own[facei]] += v;
        result[nei[facei]] += v;
    }
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
        const vectorField& pSfHat = SfHat_().boundaryField()[patchi];
        const scalarField& pValues = ssf.boundaryField()[patchi];
        forAll(faceCells, i)
        {
            result[faceCells[i]] += pSfHat[i]*pValues[i];
        }
    }
    const tensorField& inverse = inverse_().primitiveField();
    forAll(result, celli)
    {
        result[celli] = inverse[celli] & result[celli];
    }

    tfield.ref().correctBoundaryConditions();
    return tfield;
}


// ************************************************************************* //
