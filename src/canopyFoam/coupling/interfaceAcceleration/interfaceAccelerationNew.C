/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceAccelerationNew.C — run-time selection of the
    interface acceleration from the coupling dictionary.
\*---------------------------------------------------------------------------*/

#include "interfaceAcceleration.H"
#include "error.H"
#include "readEntry.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::interfaceAcceleration> Foam::interfaceAcceleration::New
(
    const dictionary& dict
)
{
    const word type
    (
        canopyEntry::wordValue(dict, "acceleration", "coupling.acceleration", "aitken")
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.acceleration' = " << type
            << " is not valid; valid:";
        for (const word& valid : dictionaryConstructorTablePtr_->sortedToc())
        {
            FatalIOError << ' ' << valid;
        }
        FatalIOError << exit(FatalIOError);
    }

    const scalar omega0 = canopyEntry::number
    (
        dict, "initialRelaxation", "coupling.initialRelaxation", 0.5
    );
    if (!(omega0 > 0) || omega0 > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.initialRelaxation' = " << omega0
            << " must lie in (0, 1]" << exit(FatalIOError);
    }

    return cstrIter()(dict, omega0);
}


// ************************************************************************* //
