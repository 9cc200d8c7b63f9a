/*---------------------------------------------------------------------------*\
    canopyFoam: Test-ibStencil.C — verification of the immersed-boundary
    stencils: exact interpolation of constant and linear fields, one-sided
    stencils, conservation and adjointness of spreading.
-------------------------------------------------------------------------------
Application
    Test-ibStencil

Description
    Checks libcanopyImmersedBoundary (deltaKernel, ibStencil) on the mesh
    of the case, serial or parallel, and exits non-zero (FatalError) when a
    check fails. For each kernel:

    - the kernel's identities on a uniform grid: sum_j phi(r - j) = 1,
      sum_j (r - j) phi(r - j) = 0, phi = 0 outside the support;
    - random markers (deterministic generator, the same on every rank) at
      least 3 of the largest cells away from the boundary, two-sided
      stencils: every marker found and solvable; interpolation of a
      constant and of a linear vector field U = a + B.x, and of a linear
      scalar field, exact to tol relative to the field's scale;
    - one-sided stencils at reference + side*delta*n, delta = 1.5 cells
      along a random normal n, for side = +1 and -1: no cell on the wrong
      side, the same exactness checks;
    - interpolateSpread(F) = interpolate(spread(F));
    - shareSpread(F, s): the total of F kept; F_m = s_m c (c constant)
      shared back as s_m c exactly where every weight is non-negative;
      opposite forces on coincident markers (a pattern that spreads to
      nothing) shared back as nothing;
    - spreading of random marker forces F_m: sum_i f_i V_i = sum_m F_m and
      sum_i f_i.q_i V_i = sum_m F_m.q(X_m) (adjointness, q a smooth
      nonlinear field) to tol relative;
    - the interpolation error of q (second-order accurate) below a loose
      bound;
    - markers anywhere (down to the walls) plus one outside the mesh: the
      outside one flagged, without stencil, the others exact;
    - a stencil updated twice (moved markers) equals a new one; an update
      with no markers works (collectively);
    - on a mesh with refinement levels (refineMesh: neighbouring cells with
      volumes differing by more than a factor 1.5), markers at the centres
      of faces between levels (on the interface: the point lies in cells of
      both sizes), markers within one small cell of them, and one-sided
      stencils across them: the same checks, and a marker moved onto or
      off an interface gets the stencil a new one gets. Every check prints
      how many stencils straddle an interface (hold cells of two levels).

    Unknown kernel names must be refused, by name and from a dictionary
    entry, with a message listing the valid kernels.

    The interpolated values, spacings and global sums are written (master,
    17 digits) to a text file in the case directory, so that serial and
    parallel runs can be compared.

    Option -perturb adds 1e-6 times a smooth nonlinear field to the linear
    fields: the run must then fail (a check of the checks, and of the exit
    status, serial and parallel).

    Option -timing N instead times update, interpolate and spread for N
    markers on a sphere in the middle of the domain (no checks).

    Note: v1912's argList destructor ends every run with Pstream::exit(0),
    so "return 1" from main exits with status 0: failures stop through
    FatalError instead.

Usage
    \b Test-ibStencil [OPTIONS]

    Options:
      - \par -kernel \<name\>   only this kernel (default: all)
      - \par -markers \<N\>     number of random markers (default 1000)
      - \par -seed \<N\>        random seed (default 1912)
      - \par -tol \<value\>     relative tolerance (default 1e-10)
      - \par -output \<file\>   results file (default
            Test-ibStencil.np\<nProcs\>.dat in the case directory)
      - \par -straddle \<f\>     require at least the fraction f of the
            random two-sided and of the interface markers to have stencils
            that straddle a refinement interface (a check that the mesh
            tests what it is meant to)
      - \par -timing \<N\>      time the operations for N markers instead
      - \par -perturb          perturb the linear fields (must fail)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "testCheck.H"
#include "OFstream.H"
#include "deltaKernel.H"
#include "ibStencil.H"
#include "syncTools.H"
#include "processorPolyPatch.H"
#include "ListListOps.H"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <numeric>
#include <random>
#include "canopyFoamCompat.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Uniform random vectors in [0, 1)^3 from a seed (the C++ library's
// generator: the same markers with either OpenFOAM flavour)
class uniformSampler
{
    std::mt19937 generator_;
    std::uniform_real_distribution<double> uniform_;

public:

    explicit uniformSampler(const label seed)
    :
        generator_(seed),
        uniform_(0, 1)
    {}

    vector sample01()
    {
        const scalar x = uniform_(generator_);
        const scalar y = uniform_(generator_);
        const scalar z = uniform_(generator_);
        return vector(x, y, z);
    }
};


namespace
{

// Linear fields with known values
const vector a0(1.0, -2.0, 0.5);
const tensor B0(0.3, -1.2, 0.7, 2.0, 0.1, -0.4, -0.6, 0.9, 1.5);
const vector g0(-1.1, 0.4, 2.3);

vector linearU(const point& x)
{
    return a0 + (B0 & x);
}

scalar linearP(const point& x)
{
    return 3.0 + (g0 & x);
}

// A smooth nonlinear vector field, one period over the box
vector smoothQ(const point& x, const boundBox& bb)
{
    const vector s(cmptDivide(x - bb.min(), bb.span()));
    const scalar w = constant::mathematical::twoPi;
    return vector
    (
        Foam::sin(w*s.x() + 0.3)*Foam::cos(w*s.y()),
        Foam::cos(w*s.z() - 0.2) + s.x()*s.y(),
        Foam::exp(s.z())*Foam::sin(w*s.y())
    );
}


// Largest bounding-box extent of the cells, per direction (global)
vector maxCellSpan(const fvMesh& mesh)
{
    vector span(Zero);
    forAll(mesh.cells(), celli)
    {
        const boundBox bb(mesh.points(), mesh.cellPoints()[celli], false);
        span = max(span, bb.span());
    }
    reduce(span, maxOp<vector>());
    return span;
}


// Global maximum of |f| over the cells
template<class Type>
scalar fieldScale(const UList<Type>& f)
{
    scalar s = 0;
    forAll(f, i)
    {
        s = max(s, mag(f[i]));
    }
    return returnReduce(s, maxOp<scalar>());
}


// Cells whose volumes differ by more than this factor lie on different
// refinement levels (a 2:1 split: 8 in 3-D, 4 in 2-D; grading changes
// neighbouring volumes by a few per cent)
const scalar levelRatio = 1.5;


// Per marker: the ratio of the largest to the smallest cell volume of its
// stencil, over all ranks (0 for an empty stencil)
scalarList stencilVolumeRatio(const ibStencil& st)
{
    const scalarField& V = st.mesh().cellVolumes();
    scalarList vMin(st.size(), GREAT);
    scalarList vMax(st.size(), Zero);
    forAll(vMin, m)
    {
        for (const label celli : st.cells(m))
        {
            vMin[m] = min(vMin[m], V[celli]);
            vMax[m] = max(vMax[m], V[celli]);
        }
    }
    Pstream::listCombineGather(vMin, minEqOp<scalar>());
    Pstream::listCombineScatter(vMin);
    Pstream::listCombineGather(vMax, maxEqOp<scalar>());
    Pstream::listCombineScatter(vMax);

    scalarList ratio(st.size(), Zero);
    forAll(ratio, m)
    {
        if (vMax[m] > 0)
        {
            ratio[m] = vMax[m]/vMin[m];
        }
    }
    return ratio;
}


// The faces between cells on different refinement levels (volume ratio
// above levelRatio), internal and processor faces (once, from the owner
// side): their centres, unit normals (towards the smaller cell) and the
// smaller cell's size
// (cube root of its volume). The same list on every rank, in an order that
// does not depend on the decomposition (lexicographic in the centres),
// thinned to at most nMax faces (every k-th).
void interfaceFaces
(
    const fvMesh& mesh,
    const label nMax,
    pointField& centres,
    vectorField& normals,
    scalarField& sizes
)
{
    const scalarField& V = mesh.cellVolumes();
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const vectorField& Sf = mesh.faceAreas();
    const pointField& Cf = mesh.faceCentres();

    scalarField nbrV;
    syncTools::swapBoundaryCellList(mesh, V, nbrV);

    DynamicList<point> myC;
    DynamicList<vector> myN;
    DynamicList<scalar> myH;

    // The normal points to the smaller cell (the owner side of a face
    // depends on the decomposition)
    const auto add = [&](const label facei, const scalar v0, const scalar v1)
    {
        if (max(v0, v1) > levelRatio*min(v0, v1))
        {
            myC.append(Cf[facei]);
            myN.append((v1 < v0 ? 1 : -1)*Sf[facei]/mag(Sf[facei]));
            myH.append(Foam::cbrt(min(v0, v1)));
        }
    };

    forAll(nei, facei)
    {
        add(facei, V[own[facei]], V[nei[facei]]);
    }
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const processorPolyPatch* procPtr =
            isA<processorPolyPatch>(pp)
          ? &refCast<const processorPolyPatch>(pp)
          : nullptr;
        if (procPtr && procPtr->owner())
        {
            forAll(pp, i)
            {
                const label facei = pp.start() + i;
                add(facei, V[own[facei]], nbrV[facei - mesh.nInternalFaces()]);
            }
        }
    }

    // Every rank's faces on every rank
    List<pointField> allC(Pstream::nProcs());
    List<vectorField> allN(Pstream::nProcs());
    List<scalarField> allH(Pstream::nProcs());
    allC[Pstream::myProcNo()] = myC;
    allN[Pstream::myProcNo()] = myN;
    allH[Pstream::myProcNo()] = myH;
    Pstream::gatherList(allC);
    Pstream::scatterList(allC);
    Pstream::gatherList(allN);
    Pstream::scatterList(allN);
    Pstream::gatherList(allH);
    Pstream::scatterList(allH);

    const pointField C(ListListOps::combine<pointField>
    (
        allC, accessOp<pointField>()
    ));
    const vectorField N(ListListOps::combine<vectorField>
    (
        allN, accessOp<vectorField>()
    ));
    const scalarField H(ListListOps::combine<scalarField>
    (
        allH, accessOp<scalarField>()
    ));

    // Lexicographic order of the centres rounded to 1e-9 of the box (the
    // same face may differ in the last bits between decompositions)
    const boundBox& bb = mesh.bounds();
    const scalar quantum = 1e-9*cmptMax(bb.span());
    List<FixedList<double, 3>> keys(C.size());
    forAll(keys, i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            keys[i][d] = std::round((C[i][d] - bb.min()[d])/quantum);
        }
    }
    labelList order(C.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort
    (
        order.begin(),
        order.end(),
        [&keys](const label i, const label j)
        {
            return std::lexicographical_compare
            (
                keys[i].begin(), keys[i].end(), keys[j].begin(), keys[j].end()
            );
        }
    );

    const label stride = max(label(1), (C.size() + nMax - 1)/max(nMax, 1));
    const label n = (C.size() + stride - 1)/stride;
    centres.setSize(n);
    normals.setSize(n);
    sizes.setSize(n);
    for (label k = 0; k < n; ++k)
    {
        const label i = order[k*stride];
        centres[k] = C[i];
        normals[k] = N[i];
        sizes[k] = H[i];
    }
}


// Do two stencils hold the same cells, spacings and weights (all ranks)?
scalar stencilDifference(const ibStencil& a, const ibStencil& b)
{
    scalar diff = 0;
    if
    (
        a.offsets() != b.offsets()
     || a.cells() != b.cells()
     || a.spacing() != b.spacing()
    )
    {
        diff = GREAT;
    }
    else
    {
        forAll(a.weights(), k)
        {
            diff = max(diff, mag(a.weights()[k] - b.weights()[k]));
        }
    }
    return returnReduce(diff, maxOp<scalar>());
}


// Refused names: by name and from a dictionary entry
void checkSelectionErrors()
{
    Info<< "Kernel selection" << nl;

    canopyCompat::throwExceptions(FatalError, true);
    canopyCompat::throwExceptions(FatalIOError, true);

    scalar bad = 0;
    try
    {
        deltaKernel::New("noSuchKernel");
        bad += 1;
    }
    catch (const Foam::error& err)
    {
        const string msg(err.message());
        if
        (
            msg.find("noSuchKernel") == string::npos
         || msg.find("roma3") == string::npos
         || msg.find("peskin4") == string::npos
        )
        {
            bad += 1;
        }
    }
    check("unknown name not refused or valid names not listed", bad, 0);

    bad = 0;
    dictionary dict;
    dict.name() = "testDict";
    dict.add("ibKernel", word("noSuchKernel"));
    try
    {
        deltaKernel::New(dict, "ibKernel");
        bad += 1;
    }
    catch (const Foam::IOerror& err)
    {
        const string msg(err.message());
        if
        (
            msg.find("ibKernel") == string::npos
         || msg.find("noSuchKernel") == string::npos
         || msg.find("roma3") == string::npos
        )
        {
            bad += 1;
        }
    }
    check("unknown entry not refused or entry not named", bad, 0);

    bad = 1;
    try
    {
        deltaKernel::New(dictionary(), "ibKernel");
    }
    catch (const Foam::IOerror& err)
    {
        bad = (string(err.message()).find("ibKernel") == string::npos);
    }
    check("missing entry (no default) not refused", bad, 0);

    // Valid selections: from an entry, and the default for a missing one
    dictionary dict2;
    dict2.add("kernel", word("roma3"));
    const bool ok =
    (
        deltaKernel::New(dict2, "kernel", "peskin4")->type() == "roma3"
     && deltaKernel::New(dictionary(), "kernel", "peskin4")->type()
            == "peskin4"
     && deltaKernel::New("peskin4")->support() == 2
     && deltaKernel::New("roma3")->support() == 1.5
    );
    check("wrong kernel selected from entry, default or name", ok ? 0 : 1, 0);

    canopyCompat::throwExceptions(FatalError, false);
    canopyCompat::throwExceptions(FatalIOError, false);
}


// The kernel's identities on a uniform grid
void checkKernelIdentities(const deltaKernel& kernel)
{
    scalar err0 = 0;
    scalar err1 = 0;
    const label nj = label(kernel.support()) + 2;
    for (label s = 0; s <= 200; ++s)
    {
        const scalar r = s/200.0;
        scalar sum0 = 0;
        scalar sum1 = 0;
        for (label j = -nj; j <= nj; ++j)
        {
            const scalar phi = kernel.phi(r - j);
            sum0 += phi;
            sum1 += (r - j)*phi;
        }
        err0 = max(err0, mag(sum0 - 1));
        err1 = max(err1, mag(sum1));
    }
    check("1-D: max |sum_j phi(r-j) - 1|", err0, 1e-14);
    check("1-D: max |sum_j (r-j) phi(r-j)|", err1, 1e-14);

    const scalar s = kernel.support();
    scalar outside = 0;
    for (const scalar r : {s, s + 1e-3, s + 0.5, 10*s})
    {
        outside = max(outside, max(mag(kernel.phi(r)), mag(kernel.phi(-r))));
    }
    check("1-D: max |phi| outside the support", outside, 0);
}


// Collected exact fields of the test
struct testFields
{
    volVectorField Uconst;
    volVectorField Ulin;
    volScalarField plin;
    volVectorField q;
    scalar UconstScale;
    scalar UlinScale;
    scalar plinScale;

    //- With perturb, add 1e-6*q to the linear fields: a check of the
    //  checks (the exactness checks must then fail)
    testFields(const fvMesh& mesh, const bool perturb)
    :
        Uconst
        (
            IOobject("Uconst", canopyCompat::timeName(mesh.time()), mesh),
            mesh,
            dimensionedVector("Uconst", dimless, vector(1.3, -0.7, 2.1))
        ),
        Ulin
        (
            IOobject("Ulin", canopyCompat::timeName(mesh.time()), mesh),
            mesh,
            dimensionedVector("zero", dimless, Zero)
        ),
        plin
        (
            IOobject("plin", canopyCompat::timeName(mesh.time()), mesh),
            mesh,
            dimensionedScalar("zero", dimless, Zero)
        ),
        q
        (
            IOobject("q", canopyCompat::timeName(mesh.time()), mesh),
            mesh,
            dimensionedVector("zero", dimless, Zero)
        )
    {
        const pointField& C = mesh.cellCentres();
        forAll(C, celli)
        {
            Ulin.primitiveFieldRef()[celli] = linearU(C[celli]);
            plin.primitiveFieldRef()[celli] = linearP(C[celli]);
            q.primitiveFieldRef()[celli] = smoothQ(C[celli], mesh.bounds());
        }
        UconstScale = mag(Uconst.primitiveField()[0]);
        UlinScale = fieldScale(Ulin.primitiveField());
        plinScale = fieldScale(plin.primitiveField());

        if (perturb)
        {
            Ulin.primitiveFieldRef() += 1e-6*UlinScale*q.primitiveField();
            plin.primitiveFieldRef() +=
                1e-6*plinScale*q.primitiveField().component(vector::X);
        }
    }
};


// Checks of one stencil; writes its per-marker results. Exactly
// nInvalidExpected markers (the last ones) must be invalid; the checks use
// the valid ones. With minStraddle > 0, at least that fraction of the
// valid markers must have stencils across a refinement interface (cells of
// volume ratio above levelRatio).
void checkStencil
(
    const word& kernelName,
    const word& tag,
    const ibStencil& st,
    const pointField& X,
    const label nInvalidExpected,
    const testFields& tf,
    const scalar tol,
    const scalar minStraddle,
    uniformSampler& rnd,
    OFstream* osPtr
)
{
    const fvMesh& mesh = st.mesh();
    const label N = X.size();
    const boolList& valid = st.valid();

    label wrongFlags = 0;
    forAll(valid, m)
    {
        if (valid[m] != (m < N - nInvalidExpected))
        {
            ++wrongFlags;
        }
    }
    check("markers wrongly flagged (found and solvable)", wrongFlags, 0);
    check
    (
        "|nInvalid - " + Foam::name(nInvalidExpected) + "|",
        mag(st.nInvalid() - nInvalidExpected),
        0
    );

    // Stencil sizes, and how many stencils span more than one rank
    labelList nCells(N);
    labelList nRanks(N);
    forAll(nCells, m)
    {
        nCells[m] = st.cells(m).size();
        nRanks[m] = (nCells[m] ? 1 : 0);
    }
    Pstream::listCombineGather(nCells, plusEqOp<label>());
    Pstream::listCombineScatter(nCells);
    Pstream::listCombineGather(nRanks, plusEqOp<label>());
    Pstream::listCombineScatter(nRanks);

    label minCells = labelMax;
    label maxCells = 0;
    label nShared = 0;
    scalar minRcond = GREAT;
    forAll(nCells, m)
    {
        if (valid[m])
        {
            minCells = min(minCells, nCells[m]);
            maxCells = max(maxCells, nCells[m]);
            minRcond = min(minRcond, st.rcond()[m]);
            nShared += (nRanks[m] > 1);
        }
        else if (nCells[m])
        {
            ++wrongFlags;
        }
    }
    Info<< "    (cells per marker " << minCells << " .. " << maxCells
        << ", min rcond " << minRcond << ", " << nShared
        << " stencils on 2+ ranks)" << nl;
    check("stencil entries of markers that are not found", wrongFlags, 0);

    // Stencils across refinement interfaces
    {
        const scalarList ratio(stencilVolumeRatio(st));
        label nStraddle = 0;
        label nValid = 0;
        scalar maxRatio = 0;
        forAll(ratio, m)
        {
            if (valid[m])
            {
                ++nValid;
                nStraddle += (ratio[m] > levelRatio);
                maxRatio = max(maxRatio, ratio[m]);
            }
        }
        Info<< "    (" << nStraddle << " of " << nValid
            << " stencils straddle a refinement interface, largest cell"
            << " volume ratio in a stencil " << maxRatio << ")" << nl;
        if (minStraddle > 0)
        {
            check
            (
                "1 - straddling fraction (1 - " + Foam::name(minStraddle)
              + " at most)",
                1 - scalar(nStraddle)/max(nValid, 1),
                1 - minStraddle
            );
        }
    }
    if (Pstream::parRun() && N - nInvalidExpected >= 100)
    {
        // Otherwise serial = parallel would prove little
        check
        (
            "parallel split not exercised (1: no stencil spans two ranks)",
            nShared ? 0 : 1,
            0
        );
    }

    // Interpolation of constant and linear fields: exact
    const vectorField Uc(st.interpolate(tf.Uconst));
    const vectorField Ul(st.interpolate(tf.Ulin));
    const scalarField pl(st.interpolate(tf.plin));
    const vectorField qi(st.interpolate(tf.q));

    const boundBox& bb = mesh.bounds();
    const scalar qScale = fieldScale(tf.q.primitiveField());

    scalar errC = 0, errL = 0, errP = 0, errQ = 0;
    forAll(X, m)
    {
        if (valid[m])
        {
            errC = max(errC, mag(Uc[m] - tf.Uconst.primitiveField()[0]));
            errL = max(errL, mag(Ul[m] - linearU(X[m])));
            errP = max(errP, mag(pl[m] - linearP(X[m])));
            errQ = max(errQ, mag(qi[m] - smoothQ(X[m], bb)));
        }
        else if (mag(Uc[m]) + mag(qi[m]) != 0)
        {
            errC = GREAT;
        }
    }
    check("max |U - U_exact|/|U|, constant U", errC/tf.UconstScale, tol);
    check("max |U - U_exact|/max|U|, U = a + B.x", errL/tf.UlinScale, tol);
    check("max |p - p_exact|/max|p|, p = p0 + g.x", errP/tf.plinScale, tol);
    // Second order: loose bound, catches gross errors only
    check("max |q - q_exact|/max|q|, smooth q (2nd order)", errQ/qScale, 0.1);

    // Spreading: conservation and adjointness (markers without stencil
    // spread nothing)
    vectorField F(N);
    forAll(F, m)
    {
        F[m] = 2*rnd.sample01() - vector::one;
    }
    vectorField f(mesh.nCells(), Zero);
    st.spread(F, f);

    vector sumF(Zero);
    scalar normF = 0;
    scalar rhs = 0;
    scalar normFq = 0;
    label nValid = 0;
    forAll(F, m)
    {
        if (valid[m])
        {
            sumF += F[m];
            normF += mag(F[m]);
            rhs += F[m] & qi[m];
            normFq += mag(F[m])*mag(qi[m]);
            ++nValid;
        }
    }

    const scalarField& V = mesh.cellVolumes();
    const vector sumFV = gSum(V*f);
    check
    (
        "|sum_i f_i V_i - sum_m F_m|/sum_m |F_m|",
        mag(sumFV - sumF)/normF,
        tol
    );

    const scalar lhs = gSum(V*(f & tf.q.primitiveField()));
    check
    (
        "|sum_i f_i.q_i V_i - sum_m F_m.q_m|/sum_m |F_m||q_m|",
        mag(lhs - rhs)/normFq,
        tol
    );

    // interpolateSpread = interpolate after spread (on the stencils' cells
    // only; the forcing iterations use it)
    {
        vectorField viaMesh;
        st.interpolate(f, viaMesh);
        List<vector> direct;
        st.interpolateSpread(F, direct);
        scalar diff = 0;
        scalar scale = VSMALL;
        forAll(viaMesh, m)
        {
            diff = max(diff, mag(direct[m] - viaMesh[m]));
            scale = max(scale, mag(viaMesh[m]));
        }
        check
        (
            "max |interpolateSpread(F) - interpolate(spread(F))|/max",
            diff/scale,
            tol
        );
    }

    // Scalar spreading
    scalarField fs(mesh.nCells(), Zero);
    st.spread(scalarField(N, 1.0), fs);
    check
    (
        "|sum_i s_i V_i - N|/N, unit scalar per valid marker",
        mag(gSum(V*fs) - nValid)/max(nValid, 1),
        tol
    );

    // Sharing the spread back among the markers (shareSpread, the cloth's
    // load as the reaction of the force in the cells): the total kept, a
    // load proportional to the shares given back exactly where no weight
    // is negative, and a pattern that spreads to nothing shares back
    // nothing
    vectorField shared;
    {
        scalarField shares(N);
        forAll(shares, m)
        {
            shares[m] = 0.5 + rnd.sample01().x();
        }
        st.shareSpread(F, shares, shared);
        vector sumShared(Zero);
        forAll(shared, m)
        {
            sumShared += shared[m];
        }
        check
        (
            "|sum_m shared_m - sum_m F_m|/sum_m |F_m|, shareSpread",
            mag(sumShared - sumF)/normF,
            tol
        );

        // F_m = s_m c (one load per share): where every weight is
        // non-negative (a symmetric stencil whose kernel already has zero
        // first moments, e.g. the uniform mesh's interior) each marker
        // gets back exactly its own; negative weights (moment
        // corrections) spread it somewhat among neighbours
        scalar minWeight = GREAT;
        forAll(st.weights(), k)
        {
            minWeight = min(minWeight, st.weights()[k]);
        }
        reduce(minWeight, minOp<scalar>());
        const vector c(0.3, -1.1, 0.7);
        vectorField Fc(N, Zero);
        forAll(Fc, m)
        {
            if (valid[m])
            {
                Fc[m] = shares[m]*c;
            }
        }
        List<vector> sharedC;
        st.shareSpread(Fc, shares, sharedC);
        scalar errShareC = 0;
        forAll(X, m)
        {
            if (valid[m])
            {
                errShareC = max(errShareC, mag(sharedC[m]/shares[m] - c));
            }
        }
        if (minWeight >= 0)
        {
            check
            (
                "max |shared_m/s_m - c|/|c|, shareSpread of s c (weights"
                " >= 0: exact)",
                errShareC/mag(c),
                tol
            );
        }
        else
        {
            Info<< "    (shareSpread of s c: max |shared_m/s_m - c|/|c| = "
                << errShareC/mag(c) << " with negative weights, smallest "
                << minWeight << ": not checked)" << nl;
        }

        // Every marker twice, with opposite forces: nothing in any cell
        pointField XX(2*N);
        vectorField G(2*N);
        scalarField sharesXX(2*N);
        forAll(X, m)
        {
            XX[m] = X[m];
            XX[m + N] = X[m];
            G[m] = F[m];
            G[m + N] = -F[m];
            sharesXX[m] = shares[m];
            sharesXX[m + N] = 0.5*shares[m];
        }
        ibStencil twice(mesh, st.kernel());
        twice.update(XX);
        List<vector> sharedG;
        twice.shareSpread(G, sharesXX, sharedG);
        scalar maxG = 0;
        forAll(sharedG, m)
        {
            maxG = max(maxG, mag(sharedG[m]));
        }
        check
        (
            "max |shared_m|/max |F_m|, opposite forces on coincident "
            "markers",
            maxG/max(gMax(mag(F)), VSMALL),
            tol
        );
    }

    if (osPtr)
    {
        OFstream& os = *osPtr;
        forAll(X, m)
        {
            os  << kernelName << ' ' << tag << " shared " << m << ' '
                << shared[m].x() << ' ' << shared[m].y() << ' '
                << shared[m].z() << nl;
        }
        forAll(X, m)
        {
            const vector& h = st.spacing()[m];
            os  << kernelName << ' ' << tag << ' ' << m << ' '
                << label(st.found()[m]) << ' ' << label(st.solvable()[m])
                << ' ' << nCells[m]
                << ' ' << h.x() << ' ' << h.y() << ' ' << h.z()
                << ' ' << st.rcond()[m]
                << ' ' << qi[m].x() << ' ' << qi[m].y() << ' ' << qi[m].z()
                << ' ' << Ul[m].x() << ' ' << Ul[m].y() << ' ' << Ul[m].z()
                << ' ' << pl[m] << nl;
        }
        os  << kernelName << ' ' << tag << " sumFV "
            << sumFV.x() << ' ' << sumFV.y() << ' ' << sumFV.z() << nl
            << kernelName << ' ' << tag << " adjoint " << lhs << ' ' << rhs
            << nl;
    }
}


void testKernel
(
    const fvMesh& mesh,
    const word& kernelName,
    const label nMarkers,
    const label seed,
    const scalar tol,
    const scalar minStraddle,
    const testFields& tf,
    OFstream* osPtr
)
{
    autoPtr<deltaKernel> kernelPtr(deltaKernel::New(kernelName));
    const deltaKernel& kernel = kernelPtr();

    Info<< nl << "Kernel " << kernelName << " (support "
        << kernel.support() << " cells)" << nl;

    checkKernelIdentities(kernel);

    // Random markers at least 3 of the largest cells from the boundary;
    // in empty/wedge directions on the mid-plane
    const boundBox& bb = mesh.bounds();
    const vector margin(3*maxCellSpan(mesh));
    const Vector<label>& geomD = mesh.geometricD();

    uniformSampler rnd(seed);
    pointField X(nMarkers);
    forAll(X, m)
    {
        const vector s(rnd.sample01());
        for (direction d = 0; d < 3; ++d)
        {
            X[m][d] =
            (
                geomD[d] == 1
              ? bb.min()[d] + margin[d] + s[d]*(bb.span()[d] - 2*margin[d])
              : bb.midpoint()[d]
            );
        }
    }

    ibStencil st(mesh, kernel);
    st.update(X);
    Info<< "  two-sided stencils, " << nMarkers << " markers" << nl;
    checkStencil
    (
        kernelName, "centre", st, X, 0, tf, tol, minStraddle, rnd, osPtr
    );

    // Re-using a stencil (previous cells as hints, kept work lists) must
    // give what a new one gives: move the markers by up to 0.4 cells
    {
        pointField Xm(X);
        forAll(Xm, m)
        {
            const vector s(2*rnd.sample01() - vector::one);
            Xm[m] += 0.4*cmptMultiply(s, st.spacing()[m]);
        }
        ibStencil fresh(mesh, kernel);
        fresh.update(Xm);

        ibStencil reused(mesh, kernel);
        reused.update(X);
        reused.update(Xm);

        Info<< "  re-used stencil, markers moved" << nl;
        check
        (
            "max |w_reused - w_new| (identical stencils)",
            stencilDifference(reused, fresh),
            0
        );
    }

    // One-sided stencils: at X + side*delta*n, delta = 1.5 cells along n
    vectorField n(nMarkers);
    forAll(n, m)
    {
        vector v(Zero);
        while (mag(v) < 0.1)
        {
            v = 2*rnd.sample01() - vector::one;
            for (direction d = 0; d < 3; ++d)
            {
                if (geomD[d] != 1)
                {
                    v[d] = 0;
                }
            }
        }
        n[m] = v/mag(v);
    }
    scalarField delta(nMarkers);
    forAll(delta, m)
    {
        delta[m] = 1.5*(cmptMag(n[m]) & st.spacing()[m]);
    }

    for (const label side : {1, -1})
    {
        const pointField Xs(X + side*delta*n);

        ibStencil one(mesh, kernel);
        one.update(Xs, n, X, side);

        Info<< "  one-sided stencils, side " << side << nl;

        // No cell on the wrong side
        label wrong = 0;
        const pointField& C = mesh.cellCentres();
        forAll(Xs, m)
        {
            for (const label celli : one.cells(m))
            {
                if (side*((C[celli] - X[m]) & n[m]) <= 0)
                {
                    ++wrong;
                }
            }
        }
        reduce(wrong, sumOp<label>());
        check("stencil cells on the wrong side", wrong, 0);

        checkStencil
        (
            kernelName,
            side > 0 ? "plus" : "minus",
            one, Xs, 0, tf, tol, -1, rnd, osPtr
        );
    }

    // No markers at all: still collective, nothing to do
    {
        ibStencil none(mesh, kernel);
        none.update(pointField());
        const vectorField Un(none.interpolate(tf.Ulin));
        vectorField f(mesh.nCells(), Zero);
        none.spread(vectorField(), f);
        check
        (
            "no markers: |results| + entries",
            Un.size() + none.cells().size() + none.nInvalid() + gMax(mag(f)),
            0
        );
    }

    // Markers anywhere, also in the cells next to the walls (truncated,
    // still moment-corrected stencils), and the last one outside the mesh
    {
        pointField Xw(nMarkers/4 + 1);
        forAll(Xw, m)
        {
            const vector s(rnd.sample01());
            for (direction d = 0; d < 3; ++d)
            {
                Xw[m][d] =
                (
                    geomD[d] == 1
                  ? bb.min()[d] + (0.001 + 0.998*s[d])*bb.span()[d]
                  : bb.midpoint()[d]
                );
            }
        }
        Xw.last() = bb.max() + 0.1*bb.span();

        ibStencil wall(mesh, kernel);
        wall.update(Xw);
        Info<< "  two-sided stencils anywhere (near walls), "
            << Xw.size() - 1 << " markers + 1 outside" << nl;
        checkStencil
        (
            kernelName, "anywhere", wall, Xw, 1, tf, tol, -1, rnd, osPtr
        );
    }

    // Markers on the refinement interfaces (faces between cells of
    // different levels: a marker on a face lies in the cells of both
    // sides), near them (within one small cell, every direction), and
    // one-sided stencils across them; none on a mesh without refinement
    pointField Xi;
    vectorField ni;
    scalarField hi;
    interfaceFaces(mesh, nMarkers/4, Xi, ni, hi);
    if (Xi.empty())
    {
        return;
    }

    pointField Xn(Xi);
    forAll(Xn, m)
    {
        Xn[m] += hi[m]*(2*rnd.sample01() - vector::one);
        for (direction d = 0; d < 3; ++d)
        {
            if (geomD[d] != 1)
            {
                Xn[m][d] = bb.midpoint()[d];
            }
        }
    }

    ibStencil on(mesh, kernel);
    on.update(Xi);
    Info<< "  two-sided stencils on refinement interfaces, " << Xi.size()
        << " markers at the centres of faces between levels" << nl;
    checkStencil
    (
        kernelName, "interfaceOn", on, Xi, 0, tf, tol, minStraddle, rnd, osPtr
    );

    ibStencil near(mesh, kernel);
    near.update(Xn);
    Info<< "  two-sided stencils near refinement interfaces, " << Xn.size()
        << " markers within one small cell of a face between levels" << nl;
    checkStencil
    (
        kernelName, "interfaceNear", near, Xn, 0, tf, tol, minStraddle, rnd,
        osPtr
    );

    // A marker that comes to lie on an interface (or leaves it) must get
    // the stencil a new one gets, whichever side it came from
    {
        ibStencil reused(mesh, kernel);
        reused.update(Xn);
        reused.update(Xi);
        const scalar diffOn = stencilDifference(reused, on);
        reused.update(Xn);
        const scalar diffNear = stencilDifference(reused, near);
        Info<< "  re-used stencil, markers moved onto and off the interfaces"
            << nl;
        check("max |w_reused - w_new|, moved onto an interface", diffOn, 0);
        check("max |w_reused - w_new|, moved off an interface", diffNear, 0);
    }

    // One-sided stencils on either side of the interfaces
    for (const label side : {1, -1})
    {
        scalarField delta(Xi.size());
        forAll(delta, m)
        {
            delta[m] = 1.5*(cmptMag(ni[m]) & on.spacing()[m]);
        }
        const pointField Xs(Xi + side*delta*ni);

        ibStencil one(mesh, kernel);
        one.update(Xs, ni, Xi, side);

        Info<< "  one-sided stencils across refinement interfaces, side "
            << side << nl;
        label wrong = 0;
        const pointField& C = mesh.cellCentres();
        forAll(Xs, m)
        {
            for (const label celli : one.cells(m))
            {
                if (side*((C[celli] - Xi[m]) & ni[m]) <= 0)
                {
                    ++wrong;
                }
            }
        }
        reduce(wrong, sumOp<label>());
        check("stencil cells on the wrong side", wrong, 0);

        checkStencil
        (
            kernelName,
            side > 0 ? "interfacePlus" : "interfaceMinus",
            one, Xs, 0, tf, tol, -1, rnd, osPtr
        );
    }
}


// Time update, interpolate and spread for N markers on a sphere
void timeOperations(const fvMesh& mesh, const label N, const testFields& tf)
{
    typedef std::chrono::steady_clock clock;
    const auto seconds = [](clock::time_point t0)
    {
        return std::chrono::duration<double>(clock::now() - t0).count();
    };

    const boundBox& bb = mesh.bounds();
    const point c(bb.midpoint());
    const scalar R = 0.3*cmptMin(bb.span());
    const scalar golden = constant::mathematical::pi*(3 - Foam::sqrt(5.0));

    // Fibonacci sphere: evenly spread, like canopy markers on a surface
    pointField X(N);
    vectorField n(N);
    forAll(X, m)
    {
        const scalar z = 1 - 2*(m + 0.5)/N;
        const scalar r = Foam::sqrt(max(1 - z*z, scalar(0)));
        n[m] = vector(r*Foam::cos(golden*m), r*Foam::sin(golden*m), z);
        X[m] = c + R*n[m];
    }

    const label nRep = 5;
    wordList names(deltaKernel::dictionaryConstructorTablePtr_->sortedToc());

    Info<< nl << "Timing, " << N << " markers, " << returnReduce
        (
            mesh.nCells(), sumOp<label>()
        ) << " cells, " << Pstream::nProcs() << " rank(s), ms per call"
        << nl;

    for (const word& name : names)
    {
        autoPtr<deltaKernel> kernel(deltaKernel::New(name));
        ibStencil st(mesh, kernel());

        // First update builds the cell tree and the tet decomposition
        clock::time_point t0 = clock::now();
        st.update(X);
        const double tFirst = seconds(t0);

        t0 = clock::now();
        for (label i = 0; i < nRep; ++i)
        {
            st.update(X);
        }
        const double tUpdate = seconds(t0)/nRep;

        const pointField Xs(X + 0.05*R*n);
        ibStencil one(mesh, kernel());
        t0 = clock::now();
        for (label i = 0; i < nRep; ++i)
        {
            one.update(Xs, n, X, 1);
        }
        const double tUpdate1 = seconds(t0)/nRep;

        vectorField Um;
        t0 = clock::now();
        for (label i = 0; i < 4*nRep; ++i)
        {
            st.interpolate(tf.Ulin.primitiveField(), Um);
        }
        const double tInterp = seconds(t0)/(4*nRep);

        vectorField F(N, vector(1, 2, 3));
        vectorField f(mesh.nCells(), Zero);
        t0 = clock::now();
        for (label i = 0; i < 4*nRep; ++i)
        {
            st.spread(F, f);
        }
        const double tSpread = seconds(t0)/(4*nRep);

        const label nEntries = returnReduce(st.cells().size(), sumOp<label>());

        Info<< "  " << name << ": first update " << 1e3*tFirst
            << ", update " << 1e3*tUpdate
            << ", one-sided update " << 1e3*tUpdate1
            << ", interpolate (vector) " << 1e3*tInterp
            << ", spread (vector) " << 1e3*tSpread
            << "; " << scalar(nEntries)/max(N, 1) << " cells per marker, "
            << st.nInvalid() << " invalid" << nl;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Verify the immersed-boundary stencils (deltaKernel, ibStencil);"
        " exits non-zero when a check fails"
    );
    canopyCompat::noFunctionObjects();
    argList::addOption("kernel", "name", "Test only this kernel");
    argList::addOption("markers", "N", "Number of random markers (1000)");
    argList::addOption("seed", "N", "Random seed (1912)");
    argList::addOption("tol", "value", "Relative tolerance (1e-10)");
    argList::addOption("output", "file", "Results file");
    argList::addOption
    (
        "straddle",
        "fraction",
        "Require at least this fraction of the random and the interface"
        " markers to have stencils across a refinement interface"
    );
    argList::addOption
    (
        "timing", "N", "Time the operations for N markers (no checks)"
    );
    argList::addBoolOption
    (
        "perturb",
        "Perturb the linear fields by 1e-6 (a check of the checks: must fail)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    Info<< "Create mesh for time = " << canopyCompat::timeName(runTime) << nl << endl;
    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            canopyCompat::timeName(runTime),
            runTime,
            IOobject::MUST_READ
        )
    );

    const testFields tf(mesh, canopyCompat::argFound(args, "perturb"));

    if (canopyCompat::argFound(args, "timing"))
    {
        timeOperations(mesh, canopyCompat::argRead<label>(args, "timing"), tf);
        Info<< nl << "End" << nl << endl;
        return 0;
    }

    const label nMarkers = canopyCompat::argOrDefault<label>(args, "markers", 1000);
    const label seed = canopyCompat::argOrDefault<label>(args, "seed", 1912);
    const scalar tol = canopyCompat::argOrDefault<scalar>(args, "tol", 1e-10);
    const scalar minStraddle = canopyCompat::argOrDefault<scalar>(args, "straddle", -1);

    wordList kernels;
    if (canopyCompat::argFound(args, "kernel"))
    {
        kernels = wordList(1, canopyCompat::argRead<word>(args, "kernel"));
    }
    else
    {
        kernels = deltaKernel::dictionaryConstructorTablePtr_->sortedToc();
    }

    const fileName outputName
    (
        canopyCompat::argOrDefault<fileName>
        (
            args, "output",
            runTime.globalPath()
           /("Test-ibStencil.np" + Foam::name(Pstream::nProcs()) + ".dat")
        )
    );

    autoPtr<OFstream> osPtr;
    if (Pstream::master())
    {
        osPtr.reset(new OFstream(outputName));
        osPtr->precision(17);
    }

    Info<< "Mesh: " << returnReduce(mesh.nCells(), sumOp<label>())
        << " cells, bounds " << mesh.bounds() << ", geometric directions "
        << mesh.geometricD() << nl
        << "Tolerance " << tol << ", " << nMarkers << " markers, seed "
        << seed << nl << nl;

    checkSelectionErrors();

    for (const word& kernelName : kernels)
    {
        testKernel
        (
            mesh, kernelName, nMarkers, seed, tol, minStraddle, tf,
            osPtr.valid() ? &osPtr() : nullptr
        );
    }

    reduce(nFailed, maxOp<label>());

    Info<< nl << "Results written to " << outputName << nl
        << nChecks << " checks, " << nFailed << " failed" << nl << endl;

    if (nFailed)
    {
        // Not "return 1": argList's destructor ends the run with
        // Pstream::exit(0), which would hide the failure
        FatalErrorInFunction
            << nFailed << " of " << nChecks << " checks failed"
            << exit(FatalError);
    }

    Info<< "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
