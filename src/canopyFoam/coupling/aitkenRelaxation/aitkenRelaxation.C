/*---------------------------------------------------------------------------*\
    canopyFoam: aitkenRelaxation.C — Aitken's dynamic under-relaxation.
\*---------------------------------------------------------------------------*/

#include "aitkenRelaxation.H"
#include "addToRunTimeSelectionTable.H"

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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::aitkenRelaxation::validKeys()
{
    return {"type", "initial", "max"};
}


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
    const scopedEntryReader& acceleration,
    const scalar omega0
)
:
    aitkenRelaxation
    (
        omega0,
        min(0.05, omega0),
        acceleration.inRange
        (
            "max", "upper bound of Aitken's factor, in [initial, 1]",
            omega0, 1, 1
        )
    )
{
    acceleration.rejectUnknown(validKeys());
}


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

    // The secondary data move with the same factor, so that the whole
    // state the map reads is relaxed: the stabiliser's balance handed on
    // unrelaxed is a loop of its own that the factor does not reach (it
    // converges by no better than m_A/(m + m_A) per iteration;
    // docs/validation.md, "The stabiliser's balance under Aitken's
    // relaxation")
    x += omega_*r;
    s += omega_*(sTarget - s);
    previousResidual_ = r;
}


Foam::string Foam::aitkenRelaxation::describe() const
{
    return "relaxation " + Foam::name(omega_);
}
