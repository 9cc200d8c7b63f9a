/*---------------------------------------------------------------------------*\
    canopyFoam: couplingForce.C — the immersed-boundary force field and its
    face flux.
\*---------------------------------------------------------------------------*/

#include "couplingForce.H"
#include "surfaceInterpolate.H"
#include "sectionTimer.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingForce::couplingForce
(
    const fvMesh& mesh,
    ibForcing& ib,
    const lineDrag* lines,
    const canopyFrame& frame,
    const scalar rho,
    scalar& seconds
)
:
    mesh_(mesh),
    ib_(ib),
    lines_(lines),
    frame_(frame),
    rho_(rho),
    seconds_(seconds),
    force_
    (
        IOobject
        (
            "canopyForce",
            canopyCompat::timeName(mesh.time()),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity/dimTime, Zero)
    ),
    faceForce_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::surfaceScalarField& Foam::couplingForce::faceForce() const
{
    if (!faceForce_.valid())
    {
        sectionTimer timer(seconds_);
        faceForce_.reset
        (
            new surfaceScalarField
            (
                "canopyFaceForce",
                (
                    fvc::interpolate(force_)
                  - dimensionedVector
                    (
                        "A", force_.dimensions(), frame_.acceleration()
                    )
                ) & mesh_.Sf()
            )
        );
        frame_.zeroFictitiousFlux(faceForce_->boundaryFieldRef());
    }
    return faceForce_();
}


void Foam::couplingForce::spread()
{
    sectionTimer timer(seconds_);
    vectorField f(mesh_.nCells(), Zero);
    ib_.spread(f);
    if (lines_)
    {
        lines_->spreadReaction(f, rho_);
    }
    force_.primitiveFieldRef() = f;
    force_.correctBoundaryConditions();
    faceForce_.clear();
}


Foam::scalar Foam::couplingForce::forcingIncrement
(
    const volVectorField& U,
    const scalarField& normalVelocity,
    const vectorField& triangleVelocity,
    const scalar Uref
)
{
    sectionTimer timer(seconds_);
    const scalar slip =
        ib_.forcingIncrement(U, normalVelocity, triangleVelocity, Uref, force_);
    force_.correctBoundaryConditions();
    faceForce_.clear();
    return slip;
}


// ************************************************************************* //
