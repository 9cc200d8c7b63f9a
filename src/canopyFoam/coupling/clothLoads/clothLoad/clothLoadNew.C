/*---------------------------------------------------------------------------*\
    canopyFoam: clothLoadNew.C — run-time selection of the load on the cloth
    from the coupling dictionary.
\*---------------------------------------------------------------------------*/

#include "clothLoad.H"
#include "readEntry.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::clothLoad> Foam::clothLoad::New
(
    const dictionary& coupling,
    const scalar rho,
    const bool tangential
)
{
    const word type
    (
        canopyEntry::wordValue
        (
            coupling, "pressureJump", "coupling.pressureJump", "sampled"
        )
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(coupling)
            << "Entry 'coupling.pressureJump' = " << type
            << " is not valid; valid:";
        for (const word& valid : dictionaryConstructorTablePtr_->sortedToc())
        {
            FatalIOError << ' ' << valid;
        }
        FatalIOError << exit(FatalIOError);
    }
    return cstrIter()(coupling, rho, tangential);
}


// ************************************************************************* //
