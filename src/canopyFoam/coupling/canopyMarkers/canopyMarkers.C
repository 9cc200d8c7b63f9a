/*---------------------------------------------------------------------------*\
    canopyFoam: canopyMarkers.C — immersed-boundary markers on canopy triangles.
\*---------------------------------------------------------------------------*/

#include "canopyMarkers.H"
#include "canopy.h"
#include "error.H"
#include "freeEdgeRetraction.H"

namespace
{

// Barycentric centroids of the 4^level sub-triangles of (a, b, c), given as
// barycentric corner coordinates, appended to `out`.
void subdivide
(
    const Foam::FixedList<Foam::scalar, 3>& a,
    const Foam::FixedList<Foam::scalar, 3>& b,
    const Foam::FixedList<Foam::scalar, 3>& c,
    const int level,
    Foam::DynamicList<Foam::FixedList<Foam::scalar, 3>>& out
)
{
    using Foam::FixedList;
    using Foam::scalar;
    if (level == 0)
    {
        FixedList<scalar, 3> g;
        for (int d = 0; d < 3; ++d)
        {
            g[d] = (a[d] + b[d] + c[d])/3.0;
        }
        out.append(g);
        return;
    }
    FixedList<scalar, 3> ab, bc, ca;
    for (int d = 0; d < 3; ++d)
    {
        ab[d] = 0.5*(a[d] + b[d]);
        bc[d] = 0.5*(b[d] + c[d]);
        ca[d] = 0.5*(c[d] + a[d]);
    }
    subdivide(a, ab, ca, level - 1, out);
    subdivide(ab, b, bc, level - 1, out);
    subdivide(ca, bc, c, level - 1, out);
    subdivide(ab, bc, ca, level - 1, out);
}

} // End anonymous namespace


Foam::labelList Foam::canopyMarkers::levels
(
    const canopy_model* model,
    const scalarField& triangleSpacing
)
{
    const int n = canopy_model_node_count(model);
    const int nt = canopy_model_triangle_count(model);
    if (triangleSpacing.size() != nt)
    {
        FatalErrorInFunction
            << triangleSpacing.size() << " marker spacings for " << nt
            << " canopy triangles" << exit(FatalError);
    }
    List<double> x(3*n);
    List<int> tri(3*nt);
    canopy_model_get_positions(model, x.data(), n);
    canopy_model_get_triangles(model, tri.data(), nt);

    labelList result(nt, 0);
    for (int t = 0; t < nt; ++t)
    {
        if (!(triangleSpacing[t] > 0))
        {
            FatalErrorInFunction
                << "marker spacing " << triangleSpacing[t] << " of canopy"
                << " triangle " << t << " must be > 0" << exit(FatalError);
        }
        scalar longest = 0;
        for (int k = 0; k < 3; ++k)
        {
            const int i = tri[3*t + k], j = tri[3*t + (k + 1) % 3];
            const vector d(x[3*j] - x[3*i], x[3*j+1] - x[3*i+1], x[3*j+2] - x[3*i+2]);
            longest = max(longest, mag(d));
        }
        label level = 0;
        while
        (
            level < 5
         && longest/Foam::pow(2.0, level) > 1.5*triangleSpacing[t]
        )
        {
            ++level;
        }
        result[t] = level;
    }
    return result;
}


Foam::canopyMarkers::canopyMarkers
(
    const canopy_model* model,
    const labelList& levels,
    const freeEdgeRetraction* retraction
)
:
    levels_(levels),
    nNodes_(canopy_model_node_count(model))
{
    const int nt = canopy_model_triangle_count(model);
    if (levels.size() != nt)
    {
        FatalErrorInFunction
            << levels.size() << " subdivision levels for " << nt
            << " canopy triangles" << exit(FatalError);
    }
    List<int> tri(3*nt);
    canopy_model_get_triangles(model, tri.data(), nt);

    // Each node as the markers see it: itself, or with the free edges
    // retracted its view (freeEdgeRetraction)
    auto nodeShare = [&]
    (
        const label i,
        const scalar b,
        DynamicList<label>& nodes,
        DynamicList<scalar>& weights
    )
    {
        if (!retraction)
        {
            nodes.append(i);
            weights.append(b);
            return;
        }
        const labelList& view = retraction->viewNodes(i);
        const scalarList& share = retraction->viewWeights(i);
        forAll(view, k)
        {
            nodes.append(view[k]);
            weights.append(b*share[k]);
        }
    };

    DynamicList<label> parent, start, node;
    DynamicList<scalar> weight, fraction;
    triangleStart_.setSize(nt + 1);

    const FixedList<scalar, 3> e0({1, 0, 0}), e1({0, 1, 0}), e2({0, 0, 1});
    for (int t = 0; t < nt; ++t)
    {
        triangleStart_[t] = parent.size();
        if (levels[t] < 0 || levels[t] > 5)
        {
            FatalErrorInFunction
                << "subdivision level " << levels[t] << " of canopy triangle "
                << t << " is not in 0 .. 5" << exit(FatalError);
        }
        DynamicList<FixedList<scalar, 3>> sub;
        subdivide(e0, e1, e2, levels[t], sub);
        forAll(sub, s)
        {
            parent.append(t);
            fraction.append(1.0/sub.size());
            start.append(node.size());
            for (int k = 0; k < 3; ++k)
            {
                nodeShare(tri[3*t + k], sub[s][k], node, weight);
            }
        }
    }
    triangleStart_[nt] = parent.size();
    start.append(node.size());

    triangle_.transfer(parent);
    weightStart_.transfer(start);
    weightNode_.transfer(node);
    weight_.transfer(weight);
    fraction_.transfer(fraction);
    points_.setSize(triangle_.size());
    normals_.setSize(triangle_.size());
    areas_.setSize(triangle_.size());
    update(model);
}


void Foam::canopyMarkers::update
(
    const canopy_model* model,
    const vector& origin
)
{
    const int n = canopy_model_node_count(model);
    const int nt = canopy_model_triangle_count(model);
    List<double> x(3*n);
    List<double> normal(3*nt), area(nt);
    canopy_model_get_positions(model, x.data(), n);
    canopy_model_get_triangle_geometry
    (
        model, nullptr, normal.data(), area.data(), nt
    );

    forAll(triangle_, m)
    {
        const label t = triangle_[m];
        point p(Zero);
        for (label w = weightStart_[m]; w < weightStart_[m + 1]; ++w)
        {
            const label i = weightNode_[w];
            p += weight_[w]*point(x[3*i], x[3*i+1], x[3*i+2]);
        }
        points_[m] = p - origin;
        normals_[m] = vector(normal[3*t], normal[3*t+1], normal[3*t+2]);
        areas_[m] = fraction_[m]*area[t];
    }
}


void Foam::canopyMarkers::moveTo
(
    const pointField& points,
    const vectorField& normals,
    const scalarField& areas
)
{
    if
    (
        points.size() != size() || normals.size() != size()
     || areas.size() != size()
    )
    {
        FatalErrorInFunction
            << points.size() << " positions, " << normals.size()
            << " normals and " << areas.size() << " areas for " << size()
            << " markers" << exit(FatalError);
    }
    points_ = points;
    normals_ = normals/max(mag(normals), VSMALL);
    areas_ = areas;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::canopyMarkers::areaMean
(
    const Field<Type>& markerValues
) const
{
    const label nt = triangleStart_.size() - 1;
    tmp<Field<Type>> tresult(new Field<Type>(nt, Zero));
    Field<Type>& result = tresult.ref();
    for (label t = 0; t < nt; ++t)
    {
        scalar sumA = 0;
        Type sumV(Zero);
        for (label m = triangleStart_[t]; m < triangleStart_[t + 1]; ++m)
        {
            sumA += areas_[m];
            sumV += areas_[m]*markerValues[m];
        }
        result[t] = sumA > VSMALL ? sumV/sumA : Zero;
    }
    return tresult;
}


Foam::tmp<Foam::scalarField> Foam::canopyMarkers::triangleAverage
(
    const scalarField& markerValues
) const
{
    return areaMean(markerValues);
}


Foam::tmp<Foam::vectorField> Foam::canopyMarkers::triangleAverage
(
    const vectorField& markerValues
) const
{
    return areaMean(markerValues);
}


Foam::tmp<Foam::scalarField> Foam::canopyMarkers::toMarkers
(
    const scalarField& triangleValues
) const
{
    tmp<scalarField> tresult(new scalarField(triangle_.size()));
    scalarField& result = tresult.ref();
    forAll(triangle_, m)
    {
        result[m] = triangleValues[triangle_[m]];
    }
    return tresult;
}


Foam::tmp<Foam::vectorField> Foam::canopyMarkers::toMarkers
(
    const vectorField& triangleValues
) const
{
    tmp<vectorField> tresult(new vectorField(triangle_.size()));
    vectorField& result = tresult.ref();
    forAll(triangle_, m)
    {
        result[m] = triangleValues[triangle_[m]];
    }
    return tresult;
}


Foam::tmp<Foam::vectorField> Foam::canopyMarkers::toNodes
(
    const vectorField& markerForces
) const
{
    if (markerForces.size() != triangle_.size())
    {
        FatalErrorInFunction
            << markerForces.size() << " marker forces for "
            << triangle_.size() << " markers" << exit(FatalError);
    }
    tmp<vectorField> tresult(new vectorField(nNodes_, Zero));
    vectorField& result = tresult.ref();
    forAll(triangle_, m)
    {
        for (label w = weightStart_[m]; w < weightStart_[m + 1]; ++w)
        {
            result[weightNode_[w]] += weight_[w]*markerForces[m];
        }
    }
    return tresult;
}
