/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceAccelerationNew.C — run-time selection of the
    interface acceleration from the coupling's acceleration sub-dictionary.
\*---------------------------------------------------------------------------*/

#include "interfaceAcceleration.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::interfaceAcceleration> Foam::interfaceAcceleration::New
(
    const scopedEntryReader& acceleration
)
{
    const word type
    (
        acceleration.choice
        (
            "type", dictionaryConstructorTablePtr_->sortedToc(),
            "interface acceleration", "aitken"
        )
    );
    const scalar omega0 = acceleration.number
    (
        "initial", "the first relaxation factor, in (0, 1]", 0.5
    );
    if (!(omega0 > 0) || omega0 > 1)
    {
        acceleration.fail
        (
            "initial",
            "= " + scopedEntryReader::format(omega0) + " must lie in (0, 1]"
        );
    }
    return (*dictionaryConstructorTablePtr_)[type](acceleration, omega0);
}


// ************************************************************************* //
