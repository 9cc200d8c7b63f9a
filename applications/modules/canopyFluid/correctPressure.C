/*---------------------------------------------------------------------------*\
    canopyFoam: correctPressure.C — canopyFluid's pressure corrector, with
    the immersed-boundary force as a face flux ("balanced force").
\*---------------------------------------------------------------------------*/

#include "canopyFluid.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "adjustPhi.H"
#include "fvcFlux.H"
#include "fvcDdt.H"
#include "fvcDiv.H"
#include "fvmLaplacian.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solvers::canopyFluid::correctPressure()
{
    volScalarField& p(p_);
    volVectorField& U(U_);
    surfaceScalarField& phi(phi_);

    fvVectorMatrix& UEqn = tUEqn.ref();

    volScalarField rAU(1.0/UEqn.A());
    surfaceScalarField rAUf("rAUf", fvc::interpolate(rAU));
    volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p));

    // The force's share of the flux, treated exactly as the pressure
    // gradient's
    surfaceScalarField phiForce("phiForce", rAUf*coupling_.faceForce());
    surfaceScalarField phiHbyA
    (
        "phiHbyA",
        fvc::flux(HbyA)
      + rAUf*fvc::ddtCorr(U, phi, Uf)
      + phiForce
    );

    if (p.needReference())
    {
        adjustPhi(phiHbyA, U, p);
    }

    if (pimple.nCorrPiso() <= 1)
    {
        tUEqn.clear();
    }

    // The pressure's boundary conditions consistent with the flux
    constrainPressure(p, U, phiHbyA, rAUf);

    const fvScalarMatrix pEqnSource(fvModels().sourceProxy(p));

    while (pimple.correctNonOrthogonal())
    {
        fvScalarMatrix pEqn
        (
            fvm::laplacian(rAUf, p) == fvc::div(phiHbyA) - pEqnSource
        );
        pEqn.setReference
        (
            pressureReference.refCell(),
            pressureReference.refValue()
        );
        pEqn.solve();

        if (pimple.finalNonOrthogonalIter())
        {
            tmp<surfaceScalarField> pFlux(pEqn.flux());
            phi = phiHbyA - pFlux();

            // The velocity takes the relaxed pressure's flux (computed
            // again only when p is relaxed)
            if (p.relaxationFactor() < 1)
            {
                p.relax();
                pFlux = pEqn.flux();
            }
            U = HbyA + rAU*reconstruct_((phiForce - pFlux)/rAUf);
            U.correctBoundaryConditions();
            fvConstraints().constrain(U);
        }
    }

    continuityErrors();
}


// ************************************************************************* //
