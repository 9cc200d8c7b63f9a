/*---------------------------------------------------------------------------*\
    canopyFoam: ibStencil.C — building the moment-corrected stencils of the
    immersed-boundary markers.
\*---------------------------------------------------------------------------*/

#include "ibStencil.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "treeDataPoint.H"
#include "treeBoundBox.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(ibStencil, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef Foam::indexedOctree<Foam::treeDataCell> cellTreeType;
typedef Foam::indexedOctree<Foam::treeDataPoint> pointTreeType;

// Cells whose kernel product is at most this are left out. Near the edge of
// the support phi falls as the square of the distance to it, so a cell
// centre on that edge to round-off (markers on mesh faces, cells of a
// regular grid) has phi ~ 1e-33 or 0 depending on the last bits of the
// centre, which differ between decompositions; its weight is immaterial
// either way, its presence in the stencil would not be
const Foam::scalar phiMin = 1e-12;

// Does p lie in the bounding box of cell celli's points, grown by tol?
bool inCellBox
(
    const Foam::polyMesh& mesh,
    const Foam::point& p,
    const Foam::label celli,
    const Foam::scalar tol
)
{
    const Foam::pointField& pts = mesh.points();
    const Foam::labelList& cellPts = mesh.cellPoints()[celli];
    Foam::point lo(pts[cellPts[0]]);
    Foam::point hi(lo);
    for (const Foam::label pointi : cellPts)
    {
        lo = Foam::min(lo, pts[pointi]);
        hi = Foam::max(hi, pts[pointi]);
    }
    for (Foam::direction d = 0; d < Foam::vector::nComponents; ++d)
    {
        if (p[d] < lo[d] - tol || p[d] > hi[d] + tol)
        {
            return false;
        }
    }
    return true;
}

// mesh.pointInCell(p, celli) (tet decomposition), after the cheap test
// that p lies in the bounding box of the cell's points (a cell lies in its
// box: the same answer, without the tets for the cells p is not near)
bool pointInCellFast
(
    const Foam::polyMesh& mesh,
    const Foam::point& p,
    const Foam::label celli
)
{
    return inCellBox(mesh, p, celli, 0) && mesh.pointInCell(p, celli);
}

// Does p lie within tol of cell celli: in its bounding box grown by tol,
// and at most tol outside the plane of each of its faces? For a convex cell
// this is the cell grown by tol; it accepts a point on a face, edge or
// corner whichever side's rounding says otherwise (mesh.pointInCell of a
// point on a face can be true for one of its cells and false for the other)
bool pointNearCell
(
    const Foam::polyMesh& mesh,
    const Foam::point& p,
    const Foam::label celli,
    const Foam::scalar tol
)
{
    if (!inCellBox(mesh, p, celli, tol))
    {
        return false;
    }

    const Foam::vectorField& Sf = mesh.faceAreas();
    const Foam::pointField& Cf = mesh.faceCentres();
    const Foam::labelUList& own = mesh.faceOwner();
    for (const Foam::label facei : mesh.cells()[celli])
    {
        // Outward from celli
        const Foam::scalar s = ((p - Cf[facei]) & Sf[facei])/mag(Sf[facei]);
        if ((own[facei] == celli ? s : -s) > tol)
        {
            return false;
        }
    }
    return true;
}

// Append to cells, once each, the shapes (cell centres) of the point tree
// inside box, searching the subtree of node nodei (whose box overlaps box).
// The traversal of indexedOctree::findBox, without its per-query hash set.
void pointsInBox
(
    const pointTreeType& tree,
    const Foam::label nodei,
    const Foam::boundBox& box,
    const Foam::pointField& centres,
    Foam::boolList& marked,
    Foam::DynamicList<Foam::label>& cells
)
{
    using namespace Foam;

    const pointTreeType::node& nod = tree.nodes()[nodei];
    const point mid(nod.bb_.midpoint());

    // Octant bit d set: upper half in direction d (treeBoundBox::RIGHTHALF,
    // TOPHALF, FRONTHALF). Which halves does the box reach?
    unsigned lower = 0;
    unsigned upper = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (box.min()[d] <= mid[d])
        {
            lower |= (1u << d);
        }
        if (box.max()[d] >= mid[d])
        {
            upper |= (1u << d);
        }
    }

    for (unsigned octant = 0; octant < 8; ++octant)
    {
        // Upper halves only where reached, lower halves only where reached
        if ((octant & ~upper) || (~octant & ~lower & 7u))
        {
            continue;
        }

        const labelBits index = nod.subNodes_[octant];

        if (pointTreeType::isNode(index))
        {
            pointsInBox
            (
                tree, pointTreeType::getNode(index), box, centres, marked, cells
            );
        }
        else if (pointTreeType::isContent(index))
        {
            // A point on a leaf boundary may sit in two leaves: marked
            for
            (
                const label celli
              : tree.contents()[pointTreeType::getContent(index)]
            )
            {
                if (!marked[celli] && box.contains(centres[celli]))
                {
                    marked[celli] = true;
                    cells.append(celli);
                }
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::ibStencil::cellSpan(const label celli) const
{
    const pointField& pts = mesh_.points();
    const faceList& faces = mesh_.faces();
    const cell& c = mesh_.cells()[celli];

    point lo(point::uniform(GREAT));
    point hi(point::uniform(-GREAT));

    for (const label facei : c)
    {
        for (const label pointi : faces[facei])
        {
            lo = min(lo, pts[pointi]);
            hi = max(hi, pts[pointi]);
        }
    }

    return hi - lo;
}


Foam::vector Foam::ibStencil::containingSpan
(
    const point& p,
    const label celli
) const
{
    // p lies in celli; any other cell holding p shares a point with it.
    // Within 1e-9 of the cell size counts as in: a point on a face is in
    // both of its cells, whichever the search found
    vector span(cellSpan(celli));
    const scalar tol = 1e-9*cmptMax(span);

    // More than tol inside the plane of every face (the cell's kernel, a
    // part of the cell): in no other cell. Most markers; saves the search
    {
        const vectorField& Sf = mesh_.faceAreas();
        const pointField& Cf = mesh_.faceCentres();
        const labelUList& own = mesh_.faceOwner();
        bool interior = true;
        for (const label facei : mesh_.cells()[celli])
        {
            const scalar s = ((p - Cf[facei]) & Sf[facei])/mag(Sf[facei]);
            if ((own[facei] == celli ? s : -s) >= -tol)
            {
                interior = false;
                break;
            }
        }
        if (interior)
        {
            return span;
        }
    }

    for (const label pointi : mesh_.cellPoints()[celli])
    {
        for (const label nbr : mesh_.pointCells()[pointi])
        {
            if
            (
                nbr != celli
             && (
                    pointNearCell(mesh_, p, nbr, tol)
                 || pointInCellFast(mesh_, p, nbr)
                )
            )
            {
                span = min(span, cellSpan(nbr));
            }
        }
    }
    return span;
}


const Foam::indexedOctree<Foam::treeDataPoint>&
Foam::ibStencil::centreTree()
{
    // Rebuild when the cell centres changed (mesh motion or a new mesh);
    // comparing them costs far less than the searches, and a mesh that
    // neither moves nor changes its topology is not compared at all
    if
    (
        !centreTree_.valid()
     || (mesh_.changing() && treeCentres_ != mesh_.cellCentres())
    )
    {
        centreTree_.clear();
        treeCentres_ = mesh_.cellCentres();

        // The centres' box, extended by 1e-4 of its diagonal by unequal
        // irrational multiples per side and axis, so that octant planes do
        // not fall on the cell centres of a regular mesh (which box the
        // tree has changes only its shape: the candidates are sorted)
        treeBoundBox bb(treeCentres_);
        const scalar delta = 1e-4*mag(bb.span()) + ROOTVSMALL;
        bb.min() -= delta*vector(1.6180339887, 1.4142135624, 1.3027756377);
        bb.max() += delta*vector(1.2360679775, 1.7320508076, 1.4494897428);

        centreTree_.reset
        (
            new indexedOctree<treeDataPoint>
            (
                treeDataPoint(treeCentres_),
                bb,
                10,         // maximum depth
                10,         // points per leaf
                3           // duplicity (points: ~1)
            )
        );
    }

    return *centreTree_;
}


void Foam::ibStencil::checkMarkerCount(const label n) const
{
    if (n != nMarkers_)
    {
        FatalErrorInFunction
            << "Marker values of size " << n
            << " for " << nMarkers_ << " markers" << exit(FatalError);
    }
}


void Foam::ibStencil::calcSpacing(const pointField& points)
{
    // Keep the previous cells as hints when the number of markers is the
    // same (every one is checked)
    if (markerCell_.size() != nMarkers_)
    {
        markerCell_.setSize(nMarkers_);
        markerCell_ = -1;
    }

    // Per marker, the smallest extents of the local cells containing it
    // (GREAT: none)
    spacing_.setSize(nMarkers_);
    spacing_ = vector::uniform(GREAT);

    if (mesh_.nCells())
    {
        const cellTreeType& tree = mesh_.cellTree();
        const labelList& shapeCells = tree.shapes().cellLabels();
        const label nCells = mesh_.nCells();
        const treeBoundBox& treeBb = tree.bb();

        forAll(points, m)
        {
            // The marker's cell of the previous update first, then its face
            // neighbours (markers move less than a cell between updates),
            // then the tree if the point is in its box (in parallel most
            // points are not)
            const label hint = markerCell_[m];
            label celli = -1;
            if (hint >= 0 && hint < nCells)
            {
                if (pointInCellFast(mesh_, points[m], hint))
                {
                    celli = hint;
                }
                else
                {
                    for (const label nbr : mesh_.cellCells()[hint])
                    {
                        if (pointInCellFast(mesh_, points[m], nbr))
                        {
                            celli = nbr;
                            break;
                        }
                    }
                }
            }
            if (celli < 0 && treeBb.contains(points[m]))
            {
                const label shapei = tree.findInside(points[m]);
                celli = (shapei < 0 ? -1 : shapeCells[shapei]);
            }
            markerCell_[m] = celli;

            // Which of the cells holding a point on a face (edge, corner)
            // the search returns depends on the hint and the tree: take
            // the smallest extents of them all
            if (celli >= 0)
            {
                spacing_[m] = containingSpan(points[m], celli);
            }
        }
    }
    else
    {
        markerCell_ = -1;
    }

    // The smallest extents over the ranks (min is per component), the same
    // on every rank and as in serial
    Pstream::listCombineGather(spacing_, minEqOp<vector>());
    Pstream::listCombineScatter(spacing_);

    found_.setSize(nMarkers_);
    forAll(found_, m)
    {
        found_[m] = (spacing_[m].x() < GREAT);
        if (!found_[m])
        {
            spacing_[m] = Zero;
        }
    }
}


Foam::scalar Foam::ibStencil::solveMoments
(
    const scalar* moments,
    const Vector<label>& geometricD,
    FixedList<scalar, 4>& coeffs
)
{
    // Moment matrix in rho = (C - X)/h:
    //     [ S    Sx   Sy   Sz  ]     S = sum b,  Sx = sum b rho_x,
    //     [ Sx   Sxx  Sxy  Sxz ]     Sxy = sum b rho_x rho_y, ...
    //     [ Sy   Sxy  Syy  Syz ]
    //     [ Sz   Sxz  Syz  Szz ]
    // moments = (S, Sx, Sy, Sz, Sxx, Sxy, Sxz, Syy, Syz, Szz)
    scalar A[4][4];
    A[0][0] = moments[0];
    A[0][1] = A[1][0] = moments[1];
    A[0][2] = A[2][0] = moments[2];
    A[0][3] = A[3][0] = moments[3];
    A[1][1] = moments[4];
    A[1][2] = A[2][1] = moments[5];
    A[1][3] = A[3][1] = moments[6];
    A[2][2] = moments[7];
    A[2][3] = A[3][2] = moments[8];
    A[3][3] = moments[9];

    // No moment condition in empty/wedge directions: beta_d = 0
    for (direction d = 0; d < 3; ++d)
    {
        if (geometricD[d] != 1)
        {
            for (label k = 0; k < 4; ++k)
            {
                A[d + 1][k] = A[k][d + 1] = 0;
            }
            A[d + 1][d + 1] = 1;
        }
    }

    coeffs = Zero;

    // Equilibrate to unit diagonal: Ahat = D A D
    scalar D[4];
    for (label k = 0; k < 4; ++k)
    {
        if (!(A[k][k] > 0))
        {
            return 0;
        }
        D[k] = 1/Foam::sqrt(A[k][k]);
    }
    for (label i = 0; i < 4; ++i)
    {
        for (label j = 0; j < 4; ++j)
        {
            A[i][j] *= D[i]*D[j];
        }
    }

    // Cholesky: Ahat = L L^T
    scalar L[4][4] = {};
    for (label j = 0; j < 4; ++j)
    {
        scalar s = A[j][j];
        for (label k = 0; k < j; ++k)
        {
            s -= L[j][k]*L[j][k];
        }
        if (!(s > SMALL))
        {
            return 0;
        }
        L[j][j] = Foam::sqrt(s);

        for (label i = j + 1; i < 4; ++i)
        {
            scalar t = A[i][j];
            for (label k = 0; k < j; ++k)
            {
                t -= L[i][k]*L[j][k];
            }
            L[i][j] = t/L[j][j];
        }
    }

    // Inverse of Ahat, column by column
    scalar Ainv[4][4];
    for (label c = 0; c < 4; ++c)
    {
        scalar y[4];
        for (label i = 0; i < 4; ++i)
        {
            scalar t = (i == c ? 1 : 0);
            for (label k = 0; k < i; ++k)
            {
                t -= L[i][k]*y[k];
            }
            y[i] = t/L[i][i];
        }
        for (label i = 3; i >= 0; --i)
        {
            scalar t = y[i];
            for (label k = i + 1; k < 4; ++k)
            {
                t -= L[k][i]*Ainv[k][c];
            }
            Ainv[i][c] = t/L[i][i];
        }
    }

    // Reciprocal 1-norm condition number
    scalar normA = 0;
    scalar normAinv = 0;
    for (label c = 0; c < 4; ++c)
    {
        scalar sA = 0;
        scalar sAinv = 0;
        for (label i = 0; i < 4; ++i)
        {
            sA += mag(A[i][c]);
            sAinv += mag(Ainv[i][c]);
        }
        normA = max(normA, sA);
        normAinv = max(normAinv, sAinv);
    }

    // A^-1 e0 = D Ahat^-1 D e0
    for (label k = 0; k < 4; ++k)
    {
        coeffs[k] = D[k]*Ainv[k][0]*D[0];
    }

    return 1/(normA*normAinv);
}


void Foam::ibStencil::calcStencils
(
    const pointField& points,
    const vectorField* normalsPtr,
    const pointField* referencesPtr,
    const label side
)
{
    nMarkers_ = points.size();

    // Every rank must pass the same markers: stop clearly, not in a
    // mismatched reduction
    if (Pstream::parRun())
    {
        const label nMin = returnReduce(nMarkers_, minOp<label>());
        const label nMax = returnReduce(nMarkers_, maxOp<label>());
        if (nMin != nMax)
        {
            FatalErrorInFunction
                << "The markers must be replicated on every rank: between "
                << nMin << " and " << nMax << " markers per rank"
                << exit(FatalError);
        }
    }

    // Collective, lazily evaluated mesh data: evaluate it on every rank
    // before any rank-dependent work (geometricD reduces over ranks, and
    // the tet decomposition behind the point-in-cell test synchronises
    // faces)
    const Vector<label>& geomD = mesh_.geometricD();
    (void)mesh_.tetBasePtIs();

    calcSpacing(points);

    const scalar support = kernel_.support();
    const pointField& C = mesh_.cellCentres();
    const scalarField& V = mesh_.cellVolumes();

    offsets_.setSize(nMarkers_ + 1);
    offsets_[0] = 0;
    cells_.clear();
    weights_.clear();
    moments_.setSize(10*nMarkers_);
    moments_ = 0;

    if (mesh_.nCells())
    {
        const pointTreeType& tree = centreTree();

        if (marked_.size() != mesh_.nCells())
        {
            marked_.setSize(mesh_.nCells());
            marked_ = false;
        }

        for (label m = 0; m < nMarkers_; ++m)
        {
            const point& X = points[m];
            const vector ext(support*spacing_[m]);
            const boundBox box(X - ext, X + ext);

            if (found_[m] && tree.nodes().size() && tree.bb().overlaps(box))
            {
                const vector& h = spacing_[m];

                candidates_.clear();
                pointsInBox(tree, 0, box, C, marked_, candidates_);
                for (const label celli : candidates_)
                {
                    marked_[celli] = false;
                }

                // A reproducible order, and cache-friendly sweeps
                Foam::sort(candidates_);

                scalar* mom = &moments_[10*m];

                for (const label celli : candidates_)
                {
                    if
                    (
                        normalsPtr
                     && side*((C[celli] - (*referencesPtr)[m])
                            & (*normalsPtr)[m]) <= 0
                    )
                    {
                        continue;
                    }

                    const vector r(C[celli] - X);
                    scalar rho[3];
                    scalar b = V[celli];
                    for (direction d = 0; d < 3; ++d)
                    {
                        if (geomD[d] == 1)
                        {
                            rho[d] = r[d]/h[d];
                            b *= kernel_.phi(rho[d]);
                        }
                        else
                        {
                            rho[d] = 0;
                        }
                    }

                    // Negligible at the edge of the support (see phiMin)
                    if (b <= phiMin*V[celli])
                    {
                        continue;
                    }

                    cells_.append(celli);
                    weights_.append(b);

                    mom[0] += b;
                    mom[1] += b*rho[0];
                    mom[2] += b*rho[1];
                    mom[3] += b*rho[2];
                    mom[4] += b*rho[0]*rho[0];
                    mom[5] += b*rho[0]*rho[1];
                    mom[6] += b*rho[0]*rho[2];
                    mom[7] += b*rho[1]*rho[1];
                    mom[8] += b*rho[1]*rho[2];
                    mom[9] += b*rho[2]*rho[2];
                }
            }

            offsets_[m + 1] = cells_.size();
        }
    }
    else
    {
        offsets_ = 0;
    }

    // Global moments: the same (a, beta) on every rank, as in serial
    Pstream::listCombineGather(moments_, plusEqOp<scalar>());
    Pstream::listCombineScatter(moments_);

    // Solve each marker's moment system; correct its local weights
    solvable_.setSize(nMarkers_);
    valid_.setSize(nMarkers_);
    rcond_.setSize(nMarkers_);
    nInvalid_ = 0;

    FixedList<scalar, 4> coeffs;

    for (label m = 0; m < nMarkers_; ++m)
    {
        const scalar* mom = &moments_[10*m];

        rcond_[m] = (found_[m] ? solveMoments(mom, geomD, coeffs) : 0);
        solvable_[m] = (found_[m] && rcond_[m] >= minRcond_);
        valid_[m] = solvable_[m];

        if (!valid_[m])
        {
            ++nInvalid_;

            // Fall back to the normalised kernel weights
            coeffs = Zero;
            if (mom[0] > 0)
            {
                coeffs[0] = 1/mom[0];
            }
        }

        const point& X = points[m];
        const vector& h = spacing_[m];

        for (label k = offsets_[m]; k < offsets_[m + 1]; ++k)
        {
            const vector r(C[cells_[k]] - X);
            scalar corr = coeffs[0];
            for (direction d = 0; d < 3; ++d)
            {
                if (geomD[d] == 1)
                {
                    corr += coeffs[d + 1]*r[d]/h[d];
                }
            }
            weights_[k] *= corr;
        }
    }

    // The stencils' distinct cells, for interpolateSpread
    if (cellSlot_.size() != mesh_.nCells())
    {
        cellSlot_.setSize(mesh_.nCells(), -1);
    }
    DynamicList<label> stencilCells(cells_.size());
    entrySlot_.setSize(cells_.size());
    forAll(cells_, k)
    {
        label& s = cellSlot_[cells_[k]];
        if (s < 0)
        {
            s = stencilCells.size();
            stencilCells.append(cells_[k]);
        }
        entrySlot_[k] = s;
    }
    stencilCells_.transfer(stencilCells);
    for (const label celli : stencilCells_)
    {
        cellSlot_[celli] = -1;
    }

    if (debug)
    {
        Info<< typeName << ": " << nMarkers_ << " markers, "
            << returnReduce(cells_.size(), sumOp<label>())
            << " stencil entries, " << nInvalid_ << " invalid, min rcond "
            << (nMarkers_ ? min(rcond_) : scalar(0)) << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ibStencil::ibStencil
(
    const fvMesh& mesh,
    const deltaKernel& kernel,
    const scalar minRcond
)
:
    mesh_(mesh),
    kernel_(kernel),
    minRcond_(minRcond),
    nMarkers_(0),
    found_(),
    solvable_(),
    valid_(),
    nInvalid_(0),
    spacing_(),
    rcond_(),
    offsets_(1, Zero),
    cells_(),
    weights_(),
    stencilCells_(),
    entrySlot_(),
    markerCell_(),
    moments_(),
    marked_(),
    candidates_(),
    cellSlot_(),
    treeCentres_(),
    centreTree_()
{
    // mesh.pointInCell needs the tet decomposition's base points, which
    // polyMesh computes collectively on first use: compute them on every
    // rank here, before any rank tests only the markers it holds
    (void)mesh_.tetBasePtIs();
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::ibStencil::~ibStencil()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ibStencil::update(const pointField& points)
{
    calcStencils(points, nullptr, nullptr, 1);
}


void Foam::ibStencil::update
(
    const pointField& points,
    const vectorField& normals,
    const pointField& references,
    const label side
)
{
    if (normals.size() != points.size() || references.size() != points.size())
    {
        FatalErrorInFunction
            << "One-sided stencils of " << points.size() << " points need as "
            << "many normals and references; got " << normals.size()
            << " normals and " << references.size() << " references"
            << exit(FatalError);
    }
    if (side != 1 && side != -1)
    {
        FatalErrorInFunction
            << "side must be +1 or -1, not " << side << exit(FatalError);
    }

    calcStencils(points, &normals, &references, side);
}


// ************************************************************************* //
