/*---------------------------------------------------------------------------*\
    canopyFoam: lineDrag.C — drag of the suspension lines and its reaction.
\*---------------------------------------------------------------------------*/

#include "lineDrag.H"
#include "canopy.h"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::lineDrag::validKeys()
{
    return {"diameter", "Cd", "Cf", "spacing"};
}


Foam::lineDrag::lineDrag
(
    const scopedEntryReader& reader,
    const fvMesh& mesh,
    const deltaKernel& kernel,
    const canopy_model* model,
    const scalar defaultSpacing
)
:
    diameter_(0),
    Cd_(reader.nonNegative("Cd", "drag coefficient normal to the line", 1.1)),
    Cf_(reader.nonNegative("Cf", "skin-friction coefficient", 0)),
    stencil_(mesh, kernel)
{
    reader.rejectUnknown(validKeys());
    diameter_ = reader.positive("diameter", "the lines' diameter [m]");
    const scalar spacing = reader.positive
    (
        "spacing", "sample spacing along the lines [m]", defaultSpacing
    );

    // The line springs; each split by its rest length (fixed, so that a
    // restart from a stretched state makes the same sample points)
    const int ns = canopy_model_spring_count(model);
    List<int> ends(2*ns), group(ns);
    List<double> restLength(ns);
    canopy_model_get_springs
    (
        model, ends.data(), restLength.data(), nullptr, ns
    );
    canopy_model_get_spring_groups(model, group.data(), ns);

    DynamicList<label> node0, node1;
    DynamicList<scalar> fraction, share;
    for (int s = 0; s < ns; ++s)
    {
        if (group[s] != CANOPY_GROUP_LINE)
        {
            continue;
        }
        const int i = ends[2*s], j = ends[2*s + 1];
        const label pieces = max(1, label(std::ceil(restLength[s]/spacing)));
        for (label k = 0; k < pieces; ++k)
        {
            node0.append(i);
            node1.append(j);
            fraction.append((k + 0.5)/pieces);
            share.append(1.0/pieces);
        }
    }
    if (node0.empty())
    {
        FatalIOErrorInFunction(reader.dict())
            << "Entry 'coupling.lineDrag' is given, but the structure has no"
            << " suspension lines" << exit(FatalIOError);
    }
    node0_.transfer(node0);
    node1_.transfer(node1);
    fraction_.transfer(fraction);
    share_.transfer(share);
    points_.setSize(node0_.size(), Zero);
    force_.setSize(node0_.size(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::lineDrag::nOutside() const
{
    label count = 0;
    for (const bool found : stencil_.found())
    {
        if (!found)
        {
            ++count;
        }
    }
    return count;
}


void Foam::lineDrag::writeInfo(Ostream& os) const
{
    os  << ", line drag at " << size() << " points (" << nOutside()
        << " outside the mesh)";
}


void Foam::lineDrag::place(const canopy_model* model, const vector& origin)
{
    const int n = canopy_model_node_count(model);
    List<double> x(3*n);
    canopy_model_get_positions(model, x.data(), n);
    forAll(points_, k)
    {
        const label i = node0_[k], j = node1_[k];
        const scalar s = fraction_[k];
        points_[k] =
            (1 - s)*point(x[3*i], x[3*i+1], x[3*i+2])
          + s*point(x[3*j], x[3*j+1], x[3*j+2])
          - origin;
    }
    stencil_.update(points_);
}


void Foam::lineDrag::compute
(
    const volVectorField& U,
    const canopy_model* model,
    const vector& frameVelocity,
    const scalar rho
)
{
    const int n = canopy_model_node_count(model);
    List<double> x(3*n), v(3*n);
    canopy_model_get_positions(model, x.data(), n);
    canopy_model_get_velocities(model, v.data(), n);
    const vectorField Us(stencil_.interpolate(U));
    const boolList& found = stencil_.found();
    const scalar pi = constant::mathematical::pi;

    forAll(force_, k)
    {
        force_[k] = Zero;
        if (!found[k])
        {
            continue;
        }
        const label i = node0_[k], j = node1_[k];
        const scalar s = fraction_[k];
        const vector xi(x[3*i], x[3*i+1], x[3*i+2]);
        const vector xj(x[3*j], x[3*j+1], x[3*j+2]);
        const vector vi(v[3*i], v[3*i+1], v[3*i+2]);
        const vector vj(v[3*j], v[3*j+1], v[3*j+2]);
        const scalar length = mag(xj - xi);
        if (length < VSMALL)
        {
            continue;
        }
        const vector t = (xj - xi)/length;
        const vector w = Us[k] - ((1 - s)*vi + s*vj - frameVelocity);
        const vector wt = (w & t)*t;
        const vector wn = w - wt;
        const scalar piece = share_[k]*length;
        force_[k] =
            0.5*rho*diameter_*piece*(Cd_*mag(wn)*wn + Cf_*pi*mag(wt)*wt);
    }
}


void Foam::lineDrag::nodalForces
(
    labelList& nodes,
    vectorField& forces
) const
{
    nodes.setSize(2*force_.size());
    forces.setSize(2*force_.size());
    forAll(force_, k)
    {
        nodes[2*k] = node0_[k];
        forces[2*k] = (1 - fraction_[k])*force_[k];
        nodes[2*k + 1] = node1_[k];
        forces[2*k + 1] = fraction_[k]*force_[k];
    }
}


void Foam::lineDrag::spreadReaction
(
    vectorField& cellForce,
    const scalar rho
) const
{
    const vectorField reaction(-force_/rho);
    stencil_.spread(reaction, cellForce);
}


void Foam::lineDrag::setForces(const vectorField& f)
{
    if (f.size() != force_.size())
    {
        FatalErrorInFunction
            << f.size() << " line-drag forces for " << force_.size()
            << " sample points" << abort(FatalError);
    }
    force_ = f;
}


void Foam::lineDrag::writeState(dictionary& state) const
{
    state.add("lineDragForce", force_);
}


void Foam::lineDrag::readState(const dictionary& state)
{
    const vectorField f
    (
        state.lookupOrDefault<vectorField>("lineDragForce", vectorField())
    );
    if (f.size() != size())
    {
        FatalIOErrorInFunction(state)
            << "Entry 'lineDragForce' holds " << f.size() << " forces,"
            << " but the lines have " << size() << " sample points (was"
            << " coupling.lineDrag added or changed since it was written?)"
            << exit(FatalIOError);
    }
    setForces(f);
}
