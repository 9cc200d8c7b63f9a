/*---------------------------------------------------------------------------*\
    canopyFoam: freeEdgeRetraction.C — the nodes' views with the cloth's free
    edges retracted.
\*---------------------------------------------------------------------------*/

#include "freeEdgeRetraction.H"
#include "canopy.h"
#include "EdgeMap.H"
#include "DynamicList.H"
#include "error.H"
#include "Map.H"
#include "scalarField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::freeEdgeRetraction::freeEdgeRetraction
(
    const canopy_model* model,
    const scalar retraction
)
:
    viewNodes_(canopy_model_node_count(model)),
    viewWeights_(viewNodes_.size()),
    nMoved_(0),
    nStopped_(0),
    halfWidth_(0),
    retraction_(0)
{
    const label n = viewNodes_.size();
    const label nt = canopy_model_triangle_count(model);
    const label ns = canopy_model_spring_count(model);
    forAll(viewNodes_, i)
    {
        viewNodes_[i] = labelList(1, i);
        viewWeights_[i] = scalarList(1, 1.0);
    }
    if (!nt || !(retraction > 0))
    {
        return;
    }
    retraction_ = retraction;

    List<int> tri(3*nt), ends(2*ns);
    List<double> restLength(ns);
    canopy_model_get_triangles(model, tri.data(), nt);
    canopy_model_get_springs(model, ends.data(), restLength.data(), nullptr, ns);
    EdgeMap<scalar> rest(2*ns);
    for (label s = 0; s < ns; ++s)
    {
        rest.set(edge(ends[2*s], ends[2*s + 1]), restLength[s]);
    }
    auto length = [&](const label a, const label b)
    {
        const edge e(a, b);
        if (!rest.found(e))
        {
            FatalErrorInFunction
                << "canopy edge " << e << " has no spring: its rest length"
                << " is unknown" << exit(FatalError);
        }
        return rest[e];
    };
    // Height of c over the edge a-b (Heron)
    auto height = [&](const label a, const label b, const label c)
    {
        const scalar L0 = length(a, b), L1 = length(b, c), L2 = length(c, a);
        const scalar p = 0.5*(L0 + L1 + L2);
        return 2*Foam::sqrt(max(p*(p - L0)*(p - L1)*(p - L2), 0))/L0;
    };

    // Free edges and row 0
    EdgeMap<label> count(4*nt);
    for (label t = 0; t < nt; ++t)
    {
        for (int k = 0; k < 3; ++k)
        {
            const edge e(tri[3*t + k], tri[3*t + (k + 1) % 3]);
            if (count.found(e))
            {
                ++count[e];
            }
            else
            {
                count.insert(e, 1);
            }
        }
    }
    labelList row(n, -1);
    for (label t = 0; t < nt; ++t)
    {
        for (int k = 0; k < 3; ++k)
        {
            const edge e(tri[3*t + k], tri[3*t + (k + 1) % 3]);
            if (count[e] == 1)
            {
                row[e.first()] = row[e.second()] = 0;
            }
        }
    }

    // Neighbours through triangles, and the rows by breadth-first search
    List<DynamicList<label>> near(n);
    for (label t = 0; t < nt; ++t)
    {
        for (int k = 0; k < 3; ++k)
        {
            for (int l = 1; l < 3; ++l)
            {
                const label i = tri[3*t + k], j = tri[3*t + (k + l) % 3];
                if (!near[i].found(j))
                {
                    near[i].append(j);
                }
            }
        }
    }
    DynamicList<label> front;
    forAll(row, i)
    {
        if (row[i] == 0)
        {
            front.append(i);
        }
    }
    while (front.size())
    {
        DynamicList<label> next;
        for (const label i : front)
        {
            for (const label j : near[i])
            {
                if (row[j] < 0)
                {
                    row[j] = row[i] + 1;
                    next.append(j);
                }
            }
        }
        front.transfer(next);
    }

    // Each node's next row's neighbours and its row spacing
    labelListList inward(n);
    forAll(inward, i)
    {
        DynamicList<label> in;
        for (const label j : near[i])
        {
            if (row[i] >= 0 && row[j] == row[i] + 1)
            {
                in.append(j);
            }
        }
        Foam::sort(in);
        inward[i].transfer(in);
    }
    scalarField H(n, 0), hCount(n, 0);
    for (label t = 0; t < nt; ++t)
    {
        const label v[3] = {tri[3*t], tri[3*t + 1], tri[3*t + 2]};
        for (int k = 0; k < 3; ++k)
        {
            const label a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
            if (row[a] < 0 || row[a] != row[b] || row[c] == row[a])
            {
                continue;
            }
            // a-b in one row, c in the next or the previous one: the
            // height is the spacing between the two rows; it is the
            // spacing inwards of the nodes in the outer row
            const scalar h = height(a, b, c);
            if (row[c] == row[a] + 1)
            {
                H[a] += h; hCount[a] += 1;
                H[b] += h; hCount[b] += 1;
            }
            else
            {
                H[c] += h; hCount[c] += 1;
            }
        }
    }
    forAll(H, i)
    {
        if (hCount[i] > 0)
        {
            H[i] /= hCount[i];
        }
    }

    // Distances from the edge, row by row
    scalarField rho(n, 0);
    const label lastRow = max(row);
    for (label r = 1; r <= lastRow; ++r)
    {
        forAll(row, i)
        {
            if (row[i] != r)
            {
                continue;
            }
            scalar sumRho = 0;
            label nPrev = 0;
            for (const label j : near[i])
            {
                if (row[j] == r - 1)
                {
                    sumRho += rho[j] + H[j];
                    ++nPrev;
                }
            }
            rho[i] = sumRho/nPrev;
        }
    }

    forAll(rho, i)
    {
        if (row[i] >= 0)
        {
            halfWidth_ = max(halfWidth_, rho[i]);
        }
    }

    // Walk each node in the band inwards by d - rho/2
    forAll(viewNodes_, i)
    {
        if (row[i] < 0)
        {
            continue;
        }
        scalar remaining = retraction - 0.5*rho[i];
        if (!(remaining > 0))
        {
            continue;
        }
        Map<scalar> w;
        w.insert(i, 1.0);
        while (remaining > 0)
        {
            scalar step = 0;
            bool blocked = false;
            forAllConstIter(Map<scalar>, w, iter)
            {
                step += iter()*H[iter.key()];
                blocked = blocked || inward[iter.key()].empty()
                    || !(H[iter.key()] > 0);
            }
            if (blocked)
            {
                ++nStopped_;
                break;
            }
            Map<scalar> next;
            forAllConstIter(Map<scalar>, w, iter)
            {
                const labelList& in = inward[iter.key()];
                for (const label j : in)
                {
                    next(j) += iter()/in.size();
                }
            }
            const scalar f = min(remaining/step, 1.0);
            Map<scalar> mixed;
            forAllConstIter(Map<scalar>, w, iter)
            {
                mixed(iter.key()) += (1 - f)*iter();
            }
            forAllConstIter(Map<scalar>, next, iter)
            {
                mixed(iter.key()) += f*iter();
            }
            w.transfer(mixed);
            remaining -= f*step;
            if (f < 1)
            {
                break;
            }
        }
        labelList nodes(w.sortedToc());
        scalarList weights(nodes.size());
        forAll(nodes, k)
        {
            weights[k] = w[nodes[k]];
        }
        viewNodes_[i].transfer(nodes);
        viewWeights_[i].transfer(weights);
        ++nMoved_;
    }
}


// ************************************************************************* //
