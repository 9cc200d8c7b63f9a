/*---------------------------------------------------------------------------*\
    canopyFoam: ibForcing.C — markers, stencils and multi-direct forcing of
    the canopy.
\*---------------------------------------------------------------------------*/

#include "ibForcing.H"
#include "treeDataCell.H"
#include "indexedOctree.H"
#include "canopyFoamCompat.H"
#include "freeEdgeRetraction.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::ibForcing::reportCoarseMarkers(const vectorField& h)
{
    // A marker in a cell more than 1.5 times the finest marker's cell lies
    // past the finest refinement level around the canopy (a nested mesh,
    // bin/canopy-mesh); said when the count changes (the same on every
    // rank: h is)
    scalar finest = GREAT;
    forAll(h, m)
    {
        if (cmptMax(h[m]) > 0)
        {
            finest = min(finest, cmptMax(h[m]));
        }
    }
    label coarse = 0;
    forAll(h, m)
    {
        coarse += (cmptMax(h[m]) > 1.5*finest);
    }
    if (coarse != coarseMarkers_)
    {
        Info<< "canopyCoupling: t = " << canopyCompat::timeName(mesh_.time()) << ": "
            << coarse << " of " << h.size() << " markers lie in cells"
            << " coarser than the finest at the canopy (" << finest
            << " m)" << (coarse ? ": the canopy reaches past the finest"
               " refinement level" : "") << endl;
        coarseMarkers_ = coarse;
    }
}


Foam::tmp<Foam::scalarField> Foam::ibForcing::markerVolumes() const
{
    const vectorField& h = velocityStencil_->spacing();
    tmp<scalarField> tdV(new scalarField(markers_->areas()));
    scalarField& dV = tdV.ref();
    forAll(dV, m)
    {
        dV[m] *= Foam::cbrt(h[m].x()*h[m].y()*h[m].z());
    }
    return tdV;
}


Foam::tmp<Foam::scalarField> Foam::ibForcing::localCellSizes
(
    const pointField& points,
    const scalar deflt
) const
{
    tmp<scalarField> tsize(new scalarField(points.size(), GREAT));
    scalarField& size = tsize.ref();
    const indexedOctree<treeDataCell>& tree = mesh_.cellTree();
    forAll(points, i)
    {
        const label celli = tree.findInside(points[i]);
        if (celli >= 0)
        {
            size[i] = Foam::cbrt(mesh_.V()[celli]);
        }
    }
    Pstream::listCombineGather(size, minEqOp<scalar>());
    Pstream::listCombineScatter(size);
    forAll(size, i)
    {
        if (size[i] >= GREAT)
        {
            size[i] = deflt;
        }
    }
    return tsize;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::ibForcing::validKeys()
{
    return
    {
        "kernel", "markerSpacing", "markerSpacingCells",
        "freeEdgeRetractionCells", "iterations", "tangential",
        "pressureOffset"
    };
}


Foam::ibForcing::ibForcing
(
    const scopedEntryReader& forcing,
    const fvMesh& mesh,
    const canopyStructure& structure,
    const labelList& restartLevels
)
:
    mesh_(mesh),
    forcingIterations_
    (
        forcing.integerAtLeast
        (
            "iterations", "multi-direct forcing iterations", 1, 2
        )
    ),
    noSlip_
    (
        forcing.choice
        (
            "tangential", {"noSlip", "free"}, "tangential condition", "noSlip"
        )
     == "noSlip"
    ),
    pressureOffset_
    (
        forcing.positive
        (
            "pressureOffset", "pressure sampling distance [cells]", 3
        )
    ),
    kernelName_
    (
        forcing.choice
        (
            "kernel", deltaKernel::dictionaryConstructorTablePtr_->sortedToc(),
            "delta kernel", "roma3"
        )
    ),
    uniformSpacing_(forcing.found("markerSpacing")),
    spacingCells_
    (
        forcing.positive
        (
            "markerSpacingCells", "marker spacing [local cell sizes]", 1
        )
    ),
    spacing_
    (
        forcing.positive
        (
            "markerSpacing", "marker spacing [m]",
            spacingCells_*Foam::cbrt(gMin(mesh.cellVolumes()))
        )
    ),
    retractionCells_
    (
        forcing.nonNegative
        (
            "freeEdgeRetractionCells",
            "free edges' retraction [finest cell sizes]", 0
        )
    ),
    totalForce_(Zero),
    coarseMarkers_(0)
{
    forcing.rejectUnknown(validKeys());
    if (uniformSpacing_ && forcing.found("markerSpacingCells"))
    {
        forcing.fail
        (
            "markerSpacingCells",
            "is given with markerSpacing: give the spacing in metres "
            "(markerSpacing) or in local cell sizes (markerSpacingCells), "
            "not both"
        );
    }
    kernel_ = deltaKernel::New(kernelName_);

    // The triangles' subdivision: a restart's own, else from the spacing
    labelList levels(restartLevels);
    const label nTriangles = structure.nTriangles();
    if (levels.size() != nTriangles)
    {
        const scalarField triangleSpacing
        (
            uniformSpacing_
          ? scalarField(nTriangles, spacing_)
          : scalarField
            (
                spacingCells_*localCellSizes
                (
                    structure.triangleCentres(), spacing_/spacingCells_
                )
            )
        );
        levels = canopyMarkers::levels(structure.model(), triangleSpacing);
    }

    // The free edges' retraction, in the finest cell's size (the canopy
    // lies in the finest level; one fixed length, so that a restart
    // retracts as the run did); its band (twice the retraction) must lie
    // within the cloth
    autoPtr<freeEdgeRetraction> retraction;
    if (retractionCells_ > 0)
    {
        retraction.reset
        (
            new freeEdgeRetraction
            (
                structure.model(),
                retractionCells_*Foam::cbrt(gMin(mesh.cellVolumes()))
            )
        );
        if (2*retraction->retraction() >= retraction->halfWidth())
        {
            forcing.fail
            (
                "freeEdgeRetractionCells",
                "retracts the cloth's free edges by "
              + Foam::name(retraction->retraction())
              + " m: the band of twice that reaches past the middle of "
                "the cloth, whose nodes lie at most "
              + Foam::name(retraction->halfWidth())
              + " m from a free edge; give a smaller retraction"
            );
        }
        Info<< "canopyCoupling: the free edges retracted by "
            << retraction->retraction() << " m: " << retraction->nMoved()
            << " nodes seen moved in, " << retraction->nStopped()
            << " of them stopped short at a ridge" << endl;
    }
    markers_.reset
    (
        new canopyMarkers(structure.model(), levels, retraction.get())
    );
    velocityStencil_.reset(new ibStencil(mesh, kernel_()));
    plusStencil_.reset(new ibStencil(mesh, kernel_()));
    minusStencil_.reset(new ibStencil(mesh, kernel_()));
    markerForce_.setSize(markers_->size(), Zero);
    markerForceStart_.setSize(markers_->size(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ibForcing::place(const canopy_model* model, const vector& origin)
{
    markers_->update(model, origin);
}


void Foam::ibForcing::moveMarkers
(
    const pointField& points,
    const vectorField& normals,
    const scalarField& areas
)
{
    markers_->moveTo(points, normals, areas);
}


Foam::string Foam::ibForcing::updateStencils()
{
    const canopyMarkers& mk = markers_();
    velocityStencil_->update(mk.points());

    // Pressure sampling points x -/+ delta n, delta in local cells along n
    const vectorField& h = velocityStencil_->spacing();
    const vectorField& n = mk.normals();
    scalarField delta(mk.size());
    forAll(delta, m)
    {
        const vector nn = cmptMag(n[m]);
        delta[m] = pressureOffset_*(nn & h[m]);
    }
    plusStencil_->update(mk.points() + delta*n, n, mk.points(), 1);
    minusStencil_->update(mk.points() - delta*n, n, mk.points(), -1);
    reportCoarseMarkers(h);

    // Every marker must have a stencil: a canopy leaving the mesh stops here
    const boolList* flags[3] =
    {
        &velocityStencil_->valid(),
        &plusStencil_->valid(),
        &minusStencil_->valid()
    };
    const char* names[3] = {"velocity", "pressure (+ side)", "pressure (- side)"};
    for (int s = 0; s < 3; ++s)
    {
        forAll(*flags[s], m)
        {
            if (!(*flags[s])[m])
            {
                OStringStream os;
                os  << "marker " << m << " at " << mk.points()[m]
                    << " has no " << names[s] << " stencil: the canopy is"
                    << " leaving the mesh (or the mesh is too coarse near it)";
                return os.str();
            }
        }
    }
    return string();
}


Foam::scalar Foam::ibForcing::forcingIncrement
(
    const volVectorField& U,
    const scalarField& normalVelocity,
    const vectorField& triangleVelocity,
    const scalar Uref,
    volVectorField& force
)
{
    const scalar dt = mesh_.time().deltaTValue();
    const canopyMarkers& mk = markers_();
    const scalarField dV(markerVolumes());
    const vectorField& n = mk.normals();
    const scalarField vn(mk.toMarkers(normalVelocity));
    const vectorField vt(mk.toMarkers(triangleVelocity));

    // The iterations work on the markers' velocities alone: spreading F
    // and advancing dt changes them by dt I S F (I interpolation, S
    // spreading), which the stencils give without touching the whole mesh
    vectorField Um(velocityStencil_->interpolate(U));
    vectorField increment(mk.size(), Zero);
    scalar slip = 0;

    for (label k = 0; k < forcingIterations_; ++k)
    {
        vectorField F(mk.size());
        forAll(F, m)
        {
            // Target: the normal velocity of the interface (canopy motion
            // + porous seepage); tangentially the canopy's own velocity
            // (no slip) or the fluid's (free slip).
            const vector tangent =
                noSlip_ ? (vt[m] - (vt[m] & n[m])*n[m])
                        : (Um[m] - (Um[m] & n[m])*n[m]);
            const vector target = tangent + vn[m]*n[m];
            F[m] = (target - Um[m])*dV[m]/dt;
            if (k == 0)
            {
                slip = max(slip, mag((Um[m] & n[m]) - vn[m]));
            }
        }
        increment += F;
        if (k + 1 < forcingIterations_)
        {
            List<vector> dUm;
            velocityStencil_->interpolateSpread(F, dUm);
            Um += dt*dUm;
        }
    }

    markerForce_ += increment;
    velocityStencil_->spread(increment, force.primitiveFieldRef());
    totalForce_ = sum(markerForce_);
    return slip/max(Uref, vn.size() ? max(mag(vn)) : 0);
}


Foam::tmp<Foam::vectorField> Foam::ibForcing::cellForceShares() const
{
    tmp<vectorField> tshares(new vectorField);
    velocityStencil_->shareSpread
    (
        markerForceStart_, markerVolumes(), tshares.ref()
    );
    tshares.ref() += markerForce_ - markerForceStart_;
    return tshares;
}


Foam::tmp<Foam::vectorField> Foam::ibForcing::kernelMean
(
    const vectorField& triangleValues
) const
{
    const scalarField dV(markerVolumes());
    vectorField shared;
    velocityStencil_->shareSpread
    (
        vectorField(dV*markers_->toMarkers(triangleValues)), dV, shared
    );
    forAll(shared, m)
    {
        shared[m] = dV[m] > VSMALL ? shared[m]/dV[m] : Zero;
    }
    return markers_->triangleAverage(shared);
}


void Foam::ibForcing::spread(vectorField& f) const
{
    velocityStencil_->spread(markerForce_, f);
}


void Foam::ibForcing::beginStep()
{
    markerForceStart_ = markerForce_;
}


void Foam::ibForcing::returnToStepStart()
{
    markerForce_ = markerForceStart_;
}


void Foam::ibForcing::writeState(dictionary& dict) const
{
    dict.add("markerForce", markerForce_);
    dict.add("markerLevels", markers_->levels());
}


void Foam::ibForcing::readState(const dictionary& dict)
{
    const vectorField F(canopyCompat::readValue<vectorField>(dict, "markerForce"));
    if (F.size() != markerForce_.size())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'markerForce' holds " << F.size() << " marker forces,"
            << " but the canopy has " << markerForce_.size()
            << " markers (were the canopy or coupling.forcing.markerSpacing"
            << " or markerSpacingCells changed"
            << " since it was written?)" << exit(FatalIOError);
    }
    markerForce_ = F;
    markerForceStart_ = F;
}


void Foam::ibForcing::writeInfo(Ostream& os) const
{
    os  << markers_->size() << " markers on " << markers_->levels().size()
        << " canopy triangles (spacing ";
    if (!uniformSpacing_)
    {
        os  << spacingCells_ << " local cell size, min ";
    }
    os  << spacing_ << " m), kernel " << kernelName_ << ", "
        << forcingIterations_ << " forcing iterations, "
        << (noSlip_ ? "noSlip" : "free");
    if (retractionCells_ > 0)
    {
        os  << ", free edges retracted by " << Foam::name(retractionCells_)
            << " finest cell";
    }
}


// ************************************************************************* //
