/*---------------------------------------------------------------------------*\
    canopyFoam: Test-canopyMarkers.C — verification of the canopy's IB
    markers (canopyMarkers): the free edges' retraction, exact placement and
    the adjoint force split.
-------------------------------------------------------------------------------
Application
    Test-canopyMarkers

Description
    Without a mesh, on libcanopy cloths:

    1. A flat rectangle W x L (rows of nodes along x, H = L/ny apart), every
       triangle subdivided once. Markers without a retraction and with an
       all-zero one are placed identically (bitwise). With the free edges
       retracted by d (> H, so that the band 2 d spans rows): every
       marker in the middle half of the width lies where the band's map
       rho -> d + rho/2 (rho < 2 d, rho the distance from the nearest long
       side), interpolated linearly between the rows of nodes, puts the
       marker without the retraction, x unchanged; to 1e-12 m (round-off:
       the row spacings come from the springs' rest lengths by Heron's
       formula). The cloth's half-width (the largest distance of a node
       from a free edge, against which ibForcing checks the band) is L/2.
    2. The force split (toNodes), with and without the retraction: each
       marker's unit force goes to nodes with non-negative shares summing
       to one; for arbitrary forces the nodal total is the markers' and
       sum_n f_n . x_n = sum_m F_m . p_m (the split is the exact adjoint of
       placing the markers), to 1e-12 relative.
    3. A flat circular canopy with a vent: exactly the nodes on the hem
       (r = R) and the vent's edge (r = r_v) and within the band of them
       move; the hem's nodes are seen d inside it, to the sag of a chord
       of the next ring (the view is a mean of that ring's nodes).

    Option -perturb places the retracted markers 1e-9 m off (the expected
    positions shifted): the run must fail (a check of the checks).

    A passing run prints "Test-canopyMarkers: PASSED".

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "canopyMarkers.H"
#include "freeEdgeRetraction.H"
#include "canopy.h"
#include "testCheck.H"

#include <cmath>

using namespace Foam;

namespace
{

// Node positions of a model
pointField nodePositions(const canopy_model* model)
{
    const int n = canopy_model_node_count(model);
    List<double> x(3*n);
    canopy_model_get_positions(model, x.data(), n);
    pointField p(n);
    forAll(p, i)
    {
        p[i] = point(x[3*i], x[3*i + 1], x[3*i + 2]);
    }
    return p;
}


// Checks of the force split: shares non-negative, summing to one; total and
// moment-like sum sum_n f_n . x_n kept
void checkSplit(const word& name, const canopy_model* model, const canopyMarkers& mk)
{
    const pointField x(nodePositions(model));
    scalar worstSum = 0, mostNegative = 0;
    vectorField unit(mk.size(), Zero);
    forAll(unit, m)
    {
        unit[m] = vector(1, 0, 0);
        const vectorField f(mk.toNodes(unit));
        unit[m] = Zero;
        worstSum = max(worstSum, mag(sum(f.component(0)) - 1));
        mostNegative = max(mostNegative, -min(f.component(0)));
    }
    check(name + ": |sum of a marker's shares - 1|, worst", worstSum, 1e-12);
    check(name + ": most negative share", mostNegative, 0);

    vectorField F(mk.size());
    forAll(F, m)
    {
        F[m] = vector(Foam::sin(1.3*m), Foam::cos(0.7*m), Foam::sin(0.11*m + 2));
    }
    const vectorField f(mk.toNodes(F));
    const scalar scale = sum(mag(F));
    check(name + ": |sum f_n - sum F_m| / sum |F_m|", mag(sum(f) - sum(F))/scale, 1e-12);
    scalar work = 0, markerWork = 0;
    forAll(f, i)
    {
        work += f[i] & x[i];
    }
    forAll(F, m)
    {
        markerWork += F[m] & mk.points()[m];
    }
    check
    (
        name + ": |sum f_n.x_n - sum F_m.p_m| / sum |F_m||p_m|",
        mag(work - markerWork)/sum(mag(F)*mag(mk.points())), 1e-12
    );
}

// The position of node i's view
point viewPosition
(
    const freeEdgeRetraction& r,
    const pointField& x,
    const label i
)
{
    point p(Zero);
    forAll(r.viewNodes(i), k)
    {
        p += r.viewWeights(i)[k]*x[r.viewNodes(i)[k]];
    }
    return p;
}


// The band's map of the distance from the edge
scalar bandMap(const scalar rho, const scalar d)
{
    return rho < 2*d ? d + 0.5*rho : rho;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Verify canopyMarkers: the free edges' retraction and the force split"
    );
    argList::noParallel();
    argList::addBoolOption
    (
        "perturb",
        "Compare the retracted markers with positions 1e-9 m off (the run"
        " must fail)"
    );
    argList args(argc, argv);
    const scalar offset = args.found("perturb") ? 1e-9 : 0;

    // ---- 1. the rectangle -------------------------------------------------

    const scalar W = 1, L = 0.6, edge = 0.05;
    canopy_model* rect = nullptr;
    canopy_model_create(&rect);
    canopy_rectangle_spec spec = canopy_rectangle_spec_default();
    spec.width = W;
    spec.length = L;
    spec.edge_length = edge;
    if (canopy_build_rectangle(rect, &spec) != CANOPY_OK)
    {
        FatalErrorInFunction
            << "canopy_build_rectangle: " << canopy_model_message(rect)
            << exit(FatalError);
    }
    const pointField x(nodePositions(rect));
    scalar H = L;
    forAll(x, i)
    {
        if (x[i].y() > 1e-9)
        {
            H = min(H, x[i].y());
        }
    }
    const label nt = canopy_model_triangle_count(rect);
    const labelList levels(nt, 1);
    const scalar d = 0.06;
    Info<< "rectangle " << W << " x " << L << " m, edge " << edge << " m: "
        << x.size() << " nodes, " << nt << " triangles, rows " << H
        << " m apart; retraction " << d << " m (band " << 2*d << " m)"
        << nl;

    const canopyMarkers plain(rect, levels);
    const freeEdgeRetraction none(rect, 0);
    const canopyMarkers zero(rect, levels, &none);
    check
    (
        "rectangle: zero retraction against none, largest position difference",
        max(mag(zero.points() - plain.points())), 0
    );

    const freeEdgeRetraction retraction(rect, d);
    Info<< "    " << retraction.nMoved() << " nodes moved, "
        << retraction.nStopped() << " stopped at the corners' ridges; "
        << "half-width " << retraction.halfWidth() << " m" << nl;
    check("rectangle: |half-width - L/2| [m]", mag(retraction.halfWidth() - 0.5*L), 1e-12);

    const canopyMarkers retracted(rect, levels, &retraction);
    scalar placeError = 0, moved = 0;
    label nBand = 0, nKept = 0;
    forAll(plain.points(), m)
    {
        const point& p0 = plain.points()[m];
        if (p0.x() < 0.25*W || p0.x() > 0.75*W)
        {
            continue;
        }
        // Distance from the nearer long side, the rows of nodes around it
        const bool bottom = p0.y() < 0.5*L;
        const scalar rho = bottom ? p0.y() : L - p0.y();
        const scalar lo = H*std::floor(rho/H + 1e-12);
        const scalar eta = (rho - lo)/H;
        const scalar mapped =
            (1 - eta)*bandMap(lo, d) + eta*bandMap(lo + H, d);
        point expected = p0;
        expected.y() = (bottom ? mapped : L - mapped) + offset;
        (mapped > rho + 1e-12 ? nBand : nKept) += 1;
        placeError = max(placeError, mag(retracted.points()[m] - expected));
        moved = max(moved, mag(retracted.points()[m] - p0));
    }
    Info<< "    middle half: " << nBand << " markers in the bands, " << nKept
        << " inside; the largest move " << moved << " m" << nl;
    check("rectangle: largest |marker - mapped marker| [m]", placeError, 1e-12);

    checkSplit("rectangle, no retraction", rect, plain);
    checkSplit("rectangle, retracted", rect, retracted);
    canopy_model_destroy(&rect);

    // ---- 3. the circular canopy with a vent --------------------------------

    canopy_model* disc = nullptr;
    canopy_model_create(&disc);
    canopy_circular_spec cspec = canopy_circular_spec_default();
    const scalar R = 1, Rv = 0.2;
    cspec.diameter = 2*R;
    cspec.vent_diameter = 2*Rv;
    cspec.edge_length = 0.1;
    cspec.n_attachments = 16;
    if (canopy_build_circular(disc, &cspec, nullptr) != CANOPY_OK)
    {
        FatalErrorInFunction
            << "canopy_build_circular: " << canopy_model_message(disc)
            << exit(FatalError);
    }
    const pointField xc(nodePositions(disc));
    const label ntc = canopy_model_triangle_count(disc);
    const scalar dc = 0.06;
    const freeEdgeRetraction cr(disc, dc);
    label wrong = 0, hem = 0, vent = 0;
    scalar hemError = 0, sag = 0;
    forAll(xc, i)
    {
        const scalar r = mag(vector(xc[i].x(), xc[i].y(), 0));
        const bool onHem = mag(r - R) < 1e-9, onVent = mag(r - Rv) < 1e-9;
        const bool inBand = r > R - 2*dc - 1e-9 || r < Rv + 2*dc + 1e-9;
        hem += onHem;
        vent += onVent;
        const bool isMoved = cr.viewNodes(i).size() > 1;
        if ((onHem || onVent) && !isMoved)
        {
            ++wrong;
        }
        if (!inBand && isMoved)
        {
            ++wrong;
        }
        if (onHem)
        {
            const point v(viewPosition(cr, xc, i));
            hemError =
                max(hemError, mag(mag(vector(v.x(), v.y(), 0)) - (R - dc)));
            // the sag of the chord between the view's nodes next to it
            forAll(cr.viewNodes(i), k)
            {
                for (const label j : cr.viewNodes(i))
                {
                    const scalar c = mag(xc[cr.viewNodes(i)[k]] - xc[j]);
                    sag = max(sag, c*c/(8*R));
                }
            }
        }
    }
    Info<< "circular canopy R = " << R << " m, vent " << Rv << " m: " << hem
        << " hem nodes, " << vent << " vent nodes; retraction " << dc
        << " m: " << cr.nMoved() << " nodes moved, the hem seen "
        << hemError << " m off R - d (a chord's sag " << sag << " m)" << nl;
    check("circle: nodes moved that should not be, or not that should", wrong, 0);
    check("circle: hem's view's radius - (R - d) [m], worst", hemError, sag);

    const canopyMarkers cretracted(disc, labelList(ntc, 1), &cr);
    checkSplit("circle, retracted", disc, cretracted);
    canopy_model_destroy(&disc);

    Info<< nl << nChecks << " checks, " << nFailed << " failed" << nl;
    if (nFailed)
    {
        FatalErrorInFunction
            << nFailed << " of " << nChecks << " checks failed"
            << exit(FatalError);
    }
    Info<< "Test-canopyMarkers: PASSED" << endl;
    return 0;
}
