/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceAcceleration.C — selection of the coupling's
    acceleration from the coupling dictionary.
\*---------------------------------------------------------------------------*/

#include "interfaceAcceleration.H"
#include "aitkenRelaxation.H"
#include "interfaceQuasiNewton.H"
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
    if (type != "aitken" && type != "IQN-ILS")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.acceleration' = " << type
            << " is not valid; valid: aitken IQN-ILS" << exit(FatalIOError);
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

    if (type == "aitken")
    {
        const scalar omegaMax = canopyEntry::number
        (
            dict, "maxRelaxation", "coupling.maxRelaxation", 1
        );
        if (omegaMax > 1 || omegaMax < omega0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'coupling.maxRelaxation' = " << omegaMax
                << " must lie in [initialRelaxation, 1] = [" << omega0
                << ", 1]" << exit(FatalIOError);
        }
        return autoPtr<interfaceAcceleration>
        (
            new aitkenRelaxation(omega0, min(0.05, omega0), omegaMax)
        );
    }

    const label reuse =
        canopyEntry::integer(dict, "reuse", "coupling.reuse", 8);
    if (reuse < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.reuse' = " << reuse << " must be >= 0"
            << exit(FatalIOError);
    }
    const scalar filter =
        canopyEntry::number(dict, "filter", "coupling.filter", 1e-3);
    if (!(filter > 0) || !(filter < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.filter' = " << filter
            << " must lie in (0, 1)" << exit(FatalIOError);
    }
    return autoPtr<interfaceAcceleration>
    (
        new interfaceQuasiNewton(omega0, reuse, filter)
    );
}


// ************************************************************************* //
