/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceQuasiNewton.C — IQN-ILS acceleration of the strong
    coupling (Degroote, Bathe & Vierendeels 2009).
\*---------------------------------------------------------------------------*/

#include "interfaceQuasiNewton.H"
#include "UPtrList.H"
#include "SubList.H"
#include "addToRunTimeSelectionTable.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(interfaceQuasiNewton, 0);
    addToRunTimeSelectionTable
    (
        interfaceAcceleration,
        interfaceQuasiNewton,
        dictionary
    );
}


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// filter, checked to lie in (0, 1)
Foam::scalar readFilter(const Foam::scopedEntryReader& acceleration)
{
    const Foam::scalar filter =
        acceleration.number("filter", "relative QR filter, in (0, 1)", 1e-3);
    if (!(filter > 0) || !(filter < 1))
    {
        acceleration.fail
        (
            "filter",
            "= " + Foam::scopedEntryReader::format(filter)
          + " must lie in (0, 1)"
        );
    }
    return filter;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::SubList<Foam::List<Foam::scalarField>>
Foam::interfaceQuasiNewton::newest
(
    const List<List<scalarField>>& steps
) const
{
    const label drop = max(steps.size() - reuse_, 0);
    return SubList<List<scalarField>>(steps, steps.size() - drop, drop);
}


Foam::scalarField Foam::interfaceQuasiNewton::leastSquares
(
    const UPtrList<const scalarField>& V,
    const scalarField& r,
    boolList& keep
)
{
    // Modified Gram-Schmidt, column by column (newest first): Q R = V with
    // the filtered columns left out
    const label nc = V.size();
    keep.setSize(nc);
    keep = false;
    List<scalarField> Q;
    Q.setSize(nc);
    List<scalarField> R(nc, scalarField(nc, Zero));   // R[i][j], i <= j
    labelList accepted;
    accepted.setSize(0);
    label nq = 0;

    for (label j = 0; j < nc; ++j)
    {
        scalarField v(V[j]);
        const scalar length = Foam::sqrt(sum(v*v));
        scalarField proj(nq, Zero);
        for (label i = 0; i < nq; ++i)
        {
            proj[i] = sum(Q[i]*v);
            v -= proj[i]*Q[i];
        }
        const scalar rest = Foam::sqrt(sum(v*v));
        if (!(length > 0) || rest <= filter_*length)
        {
            continue;
        }
        for (label i = 0; i < nq; ++i)
        {
            R[i][nq] = proj[i];
        }
        R[nq][nq] = rest;
        Q[nq] = v/rest;
        accepted.append(j);
        keep[j] = true;
        ++nq;
    }

    // R c = Q^T (-r) by back substitution
    scalarField b(nq);
    for (label i = 0; i < nq; ++i)
    {
        b[i] = -sum(Q[i]*r);
    }
    scalarField cq(nq, Zero);
    for (label i = nq - 1; i >= 0; --i)
    {
        scalar s = b[i];
        for (label k = i + 1; k < nq; ++k)
        {
            s -= R[i][k]*cq[k];
        }
        cq[i] = s/R[i][i];
    }

    scalarField c(nc, Zero);
    forAll(accepted, i)
    {
        c[accepted[i]] = cq[i];
    }
    columnsUsed_ = nq;
    columnsDropped_ = nc - nq;
    return c;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::interfaceQuasiNewton::interfaceQuasiNewton
(
    scalar omega0,
    label reuse,
    scalar filter
)
:
    omega0_(omega0),
    reuse_(reuse),
    filter_(filter),
    V_(),
    W_(),
    Ws_(),
    pastV_(),
    pastW_(),
    pastWs_(),
    previousResidual_(),
    previousOutput_(),
    previousSecondary_(),
    columnsUsed_(0),
    columnsDropped_(0),
    firstResidual_(0),
    pastDropped_(false)
{}


Foam::wordList Foam::interfaceQuasiNewton::validKeys()
{
    return {"type", "initial", "reuse", "filter"};
}


Foam::interfaceQuasiNewton::interfaceQuasiNewton
(
    const scopedEntryReader& acceleration,
    const scalar omega0
)
:
    // reuse is read (and checked) before filter
    interfaceQuasiNewton
    (
        omega0,
        acceleration.integerAtLeast
        (
            "reuse", "past time steps whose columns are reused", 0, 8
        ),
        0
    )
{
    filter_ = readFilter(acceleration);
    acceleration.rejectUnknown(validKeys());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::interfaceQuasiNewton::reset()
{
    if (reuse_ > 0 && V_.size())
    {
        pastV_.append(List<scalarField>(V_));
        pastW_.append(List<scalarField>(W_));
        pastWs_.append(List<scalarField>(Ws_));
    }
    while (pastV_.size() > reuse_)
    {
        // Forget the oldest time step
        for (label s = 1; s < pastV_.size(); ++s)
        {
            pastV_[s - 1].transfer(pastV_[s]);
            pastW_[s - 1].transfer(pastW_[s]);
            pastWs_[s - 1].transfer(pastWs_[s]);
        }
        pastV_.setSize(pastV_.size() - 1);
        pastW_.setSize(pastW_.size() - 1);
        pastWs_.setSize(pastWs_.size() - 1);
    }
    discardStep();
}


void Foam::interfaceQuasiNewton::relax
(
    scalarField& x,
    const scalarField& target,
    scalarField& s,
    const scalarField& sTarget
)
{
    const scalarField r(target - x);
    const scalar residual = Foam::sqrt(sum(r*r));
    pastDropped_ = false;

    if (previousResidual_.size() != r.size())
    {
        // This time step's first iteration
        firstResidual_ = residual;
    }
    else
    {
        if (residual > firstResidual_ && pastV_.size())
        {
            // The update fitted to the past steps did worse than none:
            // their columns no longer describe the map
            pastV_.clear();
            pastW_.clear();
            pastWs_.clear();
            pastDropped_ = true;
        }
        V_.append(scalarField(r - previousResidual_));
        W_.append(scalarField(target - previousOutput_));
        Ws_.append
        (
            previousSecondary_.size() == sTarget.size()
          ? scalarField(sTarget - previousSecondary_)
          : scalarField()
        );
    }
    previousResidual_ = r;
    previousOutput_ = target;
    previousSecondary_ = sTarget;

    // Columns newest first: this step's, then the past steps'; a column
    // is used only with secondary differences of the secondary data's size
    UPtrList<const scalarField> V, W, Ws;
    const auto add = [&](const scalarField& v, const scalarField& w, const scalarField& ws)
    {
        if (v.size() == r.size() && ws.size() == sTarget.size())
        {
            V.append(&v);
            W.append(&w);
            Ws.append(&ws);
        }
    };
    for (label j = V_.size() - 1; j >= 0; --j)
    {
        add(V_[j], W_[j], Ws_[j]);
    }
    for (label p = pastV_.size() - 1; p >= 0; --p)
    {
        for (label j = pastV_[p].size() - 1; j >= 0; --j)
        {
            add(pastV_[p][j], pastW_[p][j], pastWs_[p][j]);
        }
    }

    if (V.empty())
    {
        x += omega0_*r;
        s += omega0_*(sTarget - s);
        columnsUsed_ = 0;
        columnsDropped_ = 0;
        return;
    }

    boolList keep;
    const scalarField c(leastSquares(V, r, keep));
    x = target;
    s = sTarget;
    forAll(W, j)
    {
        if (keep[j])
        {
            x += c[j]*W[j];
            s += c[j]*Ws[j];
        }
    }
}


void Foam::interfaceQuasiNewton::discardStep()
{
    V_.clear();
    W_.clear();
    Ws_.clear();
    previousResidual_.clear();
    previousOutput_.clear();
    previousSecondary_.clear();
}


void Foam::interfaceQuasiNewton::writeState(dictionary& dict) const
{
    // The past steps' columns as the next reset() leaves them: this step's
    // joined at the end, the oldest dropped beyond reuse_
    List<List<scalarField>> pastV(pastV_), pastW(pastW_), pastWs(pastWs_);
    if (reuse_ > 0 && V_.size())
    {
        pastV.append(List<scalarField>(V_));
        pastW.append(List<scalarField>(W_));
        pastWs.append(List<scalarField>(Ws_));
    }
    dict.add("quasiNewtonV", newest(pastV));
    dict.add("quasiNewtonW", newest(pastW));
    dict.add("quasiNewtonWs", newest(pastWs));
}


void Foam::interfaceQuasiNewton::readState(const dictionary& dict)
{
    // A restart written without them (or without IQN-ILS) starts with no
    // history, as the run's first step does
    if (!dict.found("quasiNewtonV") && !dict.found("quasiNewtonW"))
    {
        return;
    }
    const List<List<scalarField>> pastV
    (
        canopyCompat::readValue<List<List<scalarField>>>(dict, "quasiNewtonV")
    );
    const List<List<scalarField>> pastW
    (
        canopyCompat::readValue<List<List<scalarField>>>(dict, "quasiNewtonW")
    );
    // Written before the secondary data: empty columns, which only an
    // iteration without secondary data uses
    List<List<scalarField>> pastWs(pastW.size());
    forAll(pastWs, s)
    {
        pastWs[s].setSize(pastW[s].size());
    }
    if (dict.found("quasiNewtonWs"))
    {
        pastWs = canopyCompat::readValue<List<List<scalarField>>>(dict, "quasiNewtonWs");
    }
    bool fits =
        pastV.size() == pastW.size() && pastV.size() == pastWs.size();
    forAll(pastV, s)
    {
        fits =
            fits && pastV[s].size() == pastW[s].size()
         && pastV[s].size() == pastWs[s].size();
    }
    if (!fits)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'quasiNewtonV', 'quasiNewtonW' and 'quasiNewtonWs'"
            << " hold " << pastV.size() << ", " << pastW.size() << " and "
            << pastWs.size() << " time steps of columns that do not pair up"
            << exit(FatalIOError);
    }

    // A restart with a smaller coupling.acceleration.reuse keeps the
    // newest time steps
    pastV_ = newest(pastV);
    pastW_ = newest(pastW);
    pastWs_ = newest(pastWs);
    discardStep();
}


Foam::string Foam::interfaceQuasiNewton::describe() const
{
    if (columnsUsed_ == 0)
    {
        return "relaxation " + Foam::name(omega0_);
    }
    return
        "quasi-Newton columns " + Foam::name(columnsUsed_)
      + " (" + Foam::name(columnsDropped_) + " filtered"
      + (
            pastDropped_
          ? string("; the past steps' dropped: the residual rose above the "
                   "step's first)")
          : string(")")
        );
}


// ************************************************************************* //
