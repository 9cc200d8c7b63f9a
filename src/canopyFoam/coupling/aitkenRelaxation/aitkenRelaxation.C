/*---------------------------------------------------------------------------*\
    canopyFoam: aitkenRelaxation.C — Aitken's dynamic under-relaxation.
\*---------------------------------------------------------------------------*/

#include "aitkenRelaxation.H"
#include "addToRunTimeSelectionTable.H"
#include "readEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(aitkenRelaxation, 0);
    addToRunTimeSelectionTable
    (
        interfaceAcceleration,
        aitkenRelaxation,
        dictionary
    );
}


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// maxRelaxation, checked to lie in [omega0, 1]
Foam::scalar readMaxRelaxation
(
    const Foam::dictionary& dict,
    const Foam::scalar omega0
)
{
    const Foam::scalar omegaMax = Foam::canopyEntry::number
    (
        dict, "maxRelaxation", "coupling.maxRelaxation", 1
    );
    if (omegaMax > 1 || omegaMax < omega0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.maxRelaxation' = " << omegaMax
            << " must lie in [initialRelaxation, 1] = [" << omega0
            << ", 1]" << Foam::exit(Foam::FatalIOError);
    }
    return omegaMax;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::aitkenRelaxation::aitkenRelaxation
(
    scalar omega0,
    scalar omegaMin,
    scalar omegaMax
)
:
    omega0_(omega0),
    omegaMin_(omegaMin),
    omegaMax_(omegaMax),
    omega_(omega0),
    previousResidual_()
{}


Foam::aitkenRelaxation::aitkenRelaxation
(
    const dictionary& coupling,
    const scalar omega0
)
:
    aitkenRelaxation
    (
        omega0, min(0.05, omega0), readMaxRelaxation(coupling, omega0)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


void Foam::aitkenRelaxation::reset()
{
    previousResidual_.clear();
    omega_ = omega0_;
}


void Foam::aitkenRelaxation::relax
(
    scalarField& x,
    const scalarField& target,
    scalarField& s,
    const scalarField& sTarget
)
{
    const scalarField r(target - x);

    if (previousResidual_.size() == r.size())
    {
        const scalarField dr(r - previousResidual_);
        const scalar drdr = sum(dr*dr);
        const scalar next =
            drdr > VSMALL ? -omega_*sum(previousResidual_*dr)/drdr : omega_;
        // A non-positive factor means the residual grew along the last
        // update (the fluid moved under the interface): start afresh
        omega_ = next > 0 ? min(max(next, omegaMin_), omegaMax_) : omega0_;
    }
    else
    {
        omega_ = omega0_;
    }

    x += omega_*r;
    // The secondary data take the last evaluation's values (the factor is
    // the interface velocity's): measured on the 7 ft canopy, moving them
    // with the factor as well left the residual at 0.79-0.90 of the last
    // after a factor below 1 and needed 0.1 more iterations per step
    // (issue 31); IQN-ILS, which needs one map of its iterate, moves them
    s = sTarget;
    previousResidual_ = r;
}


Foam::string Foam::aitkenRelaxation::describe() const
{
    return "relaxation " + Foam::name(omega_);
}
