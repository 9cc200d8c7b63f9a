/*---------------------------------------------------------------------------*\
    canopyFoam: canopyImmersedBoundary.C — fvOption coupling a stock solver
    with the libcanopy canopy (explicit coupling).
\*---------------------------------------------------------------------------*/

#include "canopyImmersedBoundary.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(canopyImmersedBoundary, 0);
    addToRunTimeSelectionTable(option, canopyImmersedBoundary, dictionary);
}
}


Foam::fv::canopyImmersedBoundary::canopyImmersedBoundary
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    pName_(dict.getOrDefault<word>("pName", "p")),
    coupling_(mesh, true),
    timeIndex_(-1)
{
    if (coupling_.followsPayload())
    {
        FatalIOErrorInFunction
        (
            coupling_.structure().dict().subDict("coupling").subDict("frame")
        )   << "Entry 'coupling.frame.type' = payload needs canopyPimpleFoam"
            << " (the fvOption cannot set the inlet velocity); use"
            << " frame { type fixed; } with the fvOption"
            << exit(FatalIOError);
    }
    fieldNames_.setSize(1, "U");
    applied_.setSize(1, false);
}


void Foam::fv::canopyImmersedBoundary::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    const label index = mesh_.time().timeIndex();
    if (index != timeIndex_)
    {
        // A new time step: the structure takes it with the latest pressure
        coupling_.beginTimeStep();
        coupling_.correctStructure
        (
            mesh_.lookupObject<volScalarField>(pName_)
        );
        if (!coupling_.endTimeStep())
        {
            FatalErrorInFunction
                << "Stopping: " << coupling_.failure().c_str()
                << exit(FatalError);
        }
        timeIndex_ = index;
    }
    eqn += coupling_.force();
}


void Foam::fv::canopyImmersedBoundary::correct(volVectorField& U)
{
    coupling_.forcingIncrement(U);
    coupling_.addForcingIncrement
    (
        mesh_.time().deltaTValue(),
        U.primitiveFieldRef()
    );
    U.correctBoundaryConditions();
}


bool Foam::fv::canopyImmersedBoundary::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        dict.readIfPresent("pName", pName_);
        return true;
    }
    return false;
}
