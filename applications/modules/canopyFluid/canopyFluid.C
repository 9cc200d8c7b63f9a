/*---------------------------------------------------------------------------*\
    canopyFoam: canopyFluid.C — the canopyFluid module's construction, its
    checks, and the coupling's place among foamRun's hooks.
\*---------------------------------------------------------------------------*/

#include "canopyFluid.H"
#include "pressureFaceGradient.H"
#include "restoreExactTime.H"
#include "Residuals.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace solvers
{
    defineTypeNameAndDebug(canopyFluid, 0);
    addToRunTimeSelectionTable(solver, canopyFluid, fvMesh);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::solvers::canopyFluid::lastGoodIO
(
    const word& name
) const
{
    // Neither read, written nor registered: only the solver uses it
    return IOobject
    (
        name, runTime.name(), mesh, IOobject::NO_READ, IOobject::NO_WRITE,
        false
    );
}


void Foam::solvers::canopyFluid::checkSetUp() const
{
    if (!transient())
    {
        FatalIOErrorInFunction(mesh.schemes())
            << "canopyFluid needs a time-accurate run: ddtSchemes.default"
            << " must be a transient scheme (Euler, backward,"
            << " CrankNicolson), not steadyState or localEuler"
            << exit(FatalIOError);
    }
    if (MRF.size())
    {
        FatalIOErrorInFunction(MRF)
            << "canopyFluid does not support MRF zones: remove"
            << " constant/MRFProperties" << exit(FatalIOError);
    }
    if (mesh.dynamic())
    {
        FatalErrorInFunction
            << "canopyFluid needs a static mesh (its face-force numerics"
            << " are set up once): remove constant/dynamicMeshDict; the"
            << " frame that follows the payload is coupling.frame"
            << exit(FatalError);
    }

    const dictionary& pimpleDict = pimple.dict();
    if (pimpleDict.found("residualControl"))
    {
        FatalIOErrorInFunction(pimpleDict)
            << "Entry 'PIMPLE.residualControl' would end the whole run in"
            << " OpenFOAM-12; the coupling ends the outer loop through"
            << " PIMPLE.outerCorrectorResidualControl" << exit(FatalIOError);
    }
    if (pimple.consistent())
    {
        FatalIOErrorInFunction(pimpleDict)
            << "Entry 'PIMPLE.consistent' must be false: the coupling's"
            << " face force is balanced against the pressure gradient with"
            << " 1/A, not SIMPLEC's 1/(A - H1)" << exit(FatalIOError);
    }

    const word control("outerCorrectorResidualControl");
    const word field(canopyInterface_.name());
    const string form
    (
        control + " { " + field + " { tolerance 1; relTol 0; } }"
    );
    if (!coupling_.strong())
    {
        if
        (
            pimpleDict.isDict(control)
         && pimpleDict.subDict(control).found(field)
        )
        {
            FatalIOErrorInFunction(pimpleDict)
                << "Entry 'PIMPLE." << control << "." << field << "': with"
                << " explicit coupling (coupling.scheme explicit) the outer"
                << " loop runs nOuterCorrectors times; remove it"
                << exit(FatalIOError);
        }
        return;
    }
    if (!pimpleDict.isDict(control))
    {
        FatalIOErrorInFunction(pimpleDict)
            << "Strong coupling ends PIMPLE's outer loop through its"
            << " residual control: add to PIMPLE" << nl << "    "
            << form.c_str() << exit(FatalIOError);
    }
    const dictionary& controls = pimpleDict.subDict(control);
    for (const word& key : controls.toc())
    {
        if (key != field)
        {
            FatalIOErrorInFunction(controls)
                << "Entry 'PIMPLE." << control << "." << key << "': only "
                << field << " may end the outer loop, which the coupling"
                << " decides (the iteration after it has finished solves"
                << " nothing); PIMPLE must read" << nl << "    "
                << form.c_str() << exit(FatalIOError);
        }
    }
    if (!controls.isDict(field))
    {
        FatalIOErrorInFunction(controls)
            << "Entry 'PIMPLE." << control << "." << field << "' is missing"
            << " or not a dictionary; PIMPLE must read" << nl << "    "
            << form.c_str() << exit(FatalIOError);
    }
    const dictionary& interface = controls.subDict(field);
    const scalar tolerance = interface.lookupOrDefault<scalar>("tolerance", -1);
    const scalar relTol = interface.lookupOrDefault<scalar>("relTol", -1);
    if (!(tolerance > 0 && tolerance <= 1) || relTol != 0)
    {
        FatalIOErrorInFunction(interface)
            << "Entries 'PIMPLE." << control << "." << field
            << ".tolerance' and '.relTol' must be 1 and 0: the residual"
            << " reported is the coupling's relative to coupling.tolerance"
            << " in constant/canopyProperties, which decides convergence"
            << " (found tolerance " << tolerance << ", relTol " << relTol
            << ")" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solvers::canopyFluid::canopyFluid(fvMesh& mesh)
:
    incompressibleFluid(mesh),
    exactTimeRestored_(restoreExactTime(const_cast<Time&>(runTime))),
    coupling_(mesh),
    reconstruct_(mesh),
    pNeedsNonOrthCorrection_(meshNeedsNonOrthCorrection(mesh)),
    canopyInterface_
    (
        IOobject
        (
            "canopyInterface",
            runTime.name(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, 0)
    ),
    couplingDone_(false),
    lastGoodTime_(),
    lastGoodIndex_(0),
    lastGoodU_(lastGoodIO("lastGoodU"), U_),
    lastGoodp_(lastGoodIO("lastGoodp"), p_),
    lastGoodphi_(lastGoodIO("lastGoodphi"), phi_)
{
    checkSetUp();
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::solvers::canopyFluid::~canopyFluid()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solvers::canopyFluid::preSolve()
{
    incompressibleFluid::preSolve();

    // The state at the step's start (the time has not advanced yet)
    lastGoodTime_ = instant(runTime.value(), runTime.name());
    lastGoodIndex_ = runTime.timeIndex();
    lastGoodU_ == U_;
    lastGoodp_ == p_;
    lastGoodphi_ == phi_;
    couplingDone_ = false;
}


void Foam::solvers::canopyFluid::prePredictor()
{
    if (pimple.firstIter())
    {
        coupling_.beginTimeStep(U_);
    }
    else if (!couplingDone_ && coupling_.restartsFluid())
    {
        // coupling.restartFluid: every coupling iteration solves the fluid
        // from the step's start (the inlet keeps this step's frame velocity)
        U_.primitiveFieldRef() = lastGoodU_.primitiveField();
        U_.correctBoundaryConditions();
        p_ = lastGoodp_;
        phi_ = lastGoodphi_;
    }
    if (!couplingDone_)
    {
        incompressibleFluid::prePredictor();
    }
}


void Foam::solvers::canopyFluid::pressureCorrector()
{
    if (couplingDone_)
    {
        tUEqn.clear();
        return;
    }
    incompressibleFluid::pressureCorrector();
}


void Foam::solvers::canopyFluid::postCorrector()
{
    if (!couplingDone_)
    {
        couplingDone_ = coupling_.correctStructure(p);
        if (coupling_.strong())
        {
            // The coupling's residual as canopyInterface's, for PIMPLE's
            // outerCorrectorResidualControl (0 when the step failed, so
            // that the loop ends)
            const scalar r =
                coupling_.failed() ? 0 : coupling_.normalisedResidual();
            Residuals<scalar>::append
            (
                mesh,
                SolverPerformance<scalar>
                (
                    "canopyCoupling", canopyInterface_.name(), r, r,
                    coupling_.iteration(), couplingDone_
                )
            );
        }
    }
    incompressibleFluid::postCorrector();
}


void Foam::solvers::canopyFluid::postSolve()
{
    if (!coupling_.endTimeStep())
    {
        // Write the state at the step's start and stop with the reason
        Time& time = const_cast<Time&>(runTime);
        time.setTime(lastGoodTime_, lastGoodIndex_);
        U_ == lastGoodU_;
        p_ == lastGoodp_;
        phi_ == lastGoodphi_;
        time.writeNow();
        coupling_.stopAtLastGoodState();
    }
    incompressibleFluid::postSolve();
}


// ************************************************************************* //
