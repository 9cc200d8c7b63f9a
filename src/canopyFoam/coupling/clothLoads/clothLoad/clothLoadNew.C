/*---------------------------------------------------------------------------*\
    canopyFoam: clothLoadNew.C — run-time selection of the load on the cloth
    from the coupling's load sub-dictionary.
\*---------------------------------------------------------------------------*/

#include "clothLoad.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::wordList Foam::clothLoad::validKeys()
{
    return {"type", "tangential", "pressureHeld", "reaction"};
}


Foam::autoPtr<Foam::clothLoad> Foam::clothLoad::New
(
    const scopedEntryReader& load,
    const scalar rho
)
{
    const word type
    (
        load.choice
        (
            "type", dictionaryConstructorTablePtr_->sortedToc(),
            "load on the cloth", "sampled"
        )
    );
    load.rejectUnknown(validKeys());
    return (*dictionaryConstructorTablePtr_)[type](load, rho);
}


// ************************************************************************* //
