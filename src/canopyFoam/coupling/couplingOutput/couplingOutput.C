/*---------------------------------------------------------------------------*\
    canopyFoam: couplingOutput.C — the canopy's time series, the structure's
    output steps, the coupling's restart state and the iteration's log.
\*---------------------------------------------------------------------------*/

#include "couplingOutput.H"
#include "canopy.h"
#include "mathematicalConstants.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::couplingOutput::stateIO
(
    const IOobject::readOption r
) const
{
    return IOobject
    (
        "canopyCoupling",
        canopyCompat::timeName(mesh_.time()),
        "uniform",
        mesh_,
        r,
        IOobject::NO_WRITE,
        false
    );
}


void Foam::couplingOutput::openSeries()
{
    const Time& runTime = mesh_.time();
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"canopy"
       /runTime.timeName(runTime.startTime().value())
    );
    mkDir(dir);
    series_.reset(new OFstream(dir/"canopy.dat"));
    double g[3] = {0, 0, 0};
    canopy_model_get_gravity(structure_.model(), g);
    series_()
        << "# canopyFoam time series of the canopy (ground frame)" << nl
        << "# nominalDiameter " << nominalDiameter_ << nl
        << "# totalMass " << structure_.totalMass() << nl
        << "# rho " << rho_ << nl
        << "# gravity " << g[0] << ' ' << g[1] << ' ' << g[2] << nl
        << "# time payload_x payload_y payload_z payload_Ux payload_Uy"
        << " payload_Uz force_x force_y force_z projected_diameter"
        << " canopy_area kinetic spring gravity coupling_iterations"
        << " residual slip substeps frame_x frame_y frame_z"
        << " line_drag_x line_drag_y line_drag_z"
        << " canopy_x canopy_y canopy_z" << nl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::couplingOutput::couplingOutput
(
    const fvMesh& mesh,
    canopyStructure& structure,
    const scalar rho
)
:
    mesh_(mesh),
    structure_(structure),
    rho_(rho),
    nominalDiameter_(0)
{
    // A restart continues from the structure's state at the start time
    // (canopyStructure::startsFrom decides; the structure's constructor
    // has read an initial state otherwise)
    const Time& runTime = mesh.time();
    if (structure.startsFrom(runTime) == canopyStructure::origin::restart)
    {
        Info<< "canopyCoupling: restarting the structure from its state"
            << " at t = " << canopyCompat::timeName(runTime) << " in "
            << canopyStructure::outputPath(runTime) << ".h5" << endl;
        structure.readState(runTime);
    }
    else if (runTime.value() != 0)
    {
        WarningInFunction
            << "No structure state at the start time " << canopyCompat::timeName(runTime)
            << " in " << canopyStructure::outputPath(runTime) << ".h5:"
            << " the canopy starts from its initial shape" << endl;
    }
    // The parachute's nominal diameter as its specification states it
    // (canopy.nominalDiameter, required with an extended skirt, whose rim
    // is not it), else the canopy's diameter, else a disc of its area as
    // built: the nominal area, which a fold or the inflated shape reached
    // by a restart does not change
    const dictionary canopyDict(structure.dict().subOrEmptyDict("canopy"));
    nominalDiameter_ = canopyDict.lookupOrDefault<scalar>
    (
        "nominalDiameter",
        canopyDict.lookupOrDefault<scalar>
        (
            "diameter",
            Foam::sqrt
            (
                4*structure.builtCanopyArea()/constant::mathematical::pi
            )
        )
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::couplingOutput::statePath() const
{
    return canopyCompat::objectPath(stateIO(IOobject::NO_READ));
}


Foam::autoPtr<Foam::localIOdictionary> Foam::couplingOutput::readState() const
{
    IOobject io(stateIO(IOobject::MUST_READ));
    if (mesh_.time().value() == 0)
    {
        return autoPtr<localIOdictionary>();
    }
    if (!canopyCompat::headerOk<localIOdictionary>(io))
    {
        WarningInFunction
            << "No " << statePath() << ": the immersed-boundary"
            << " force restarts from zero and the frame from the payload"
            << endl;
        return autoPtr<localIOdictionary>();
    }
    return autoPtr<localIOdictionary>(new localIOdictionary(io));
}


void Foam::couplingOutput::write
(
    const vector* frameOrigin,
    const std::function<void(dictionary&)>& addState
)
{
    structure_.write(mesh_.time(), frameOrigin);

    // ASCII (a dictionary cannot hold binary fields) with every digit, so
    // that a restart continues exactly: the precision is set before the
    // entries are added, because an entry is formatted when it is added
    const unsigned precision = IOstream::defaultPrecision(17);
    localIOdictionary state(stateIO(IOobject::NO_READ));
    addState(state);
    state.writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
    IOstream::defaultPrecision(precision);
}


void Foam::couplingOutput::writeSeries(const stepSummary& step)
{
    if (!Pstream::master())
    {
        return;
    }
    if (!series_.valid())
    {
        openSeries();
    }
    const point x
    (
        structure_.hasPayload() ? structure_.payloadPosition() : point::zero
    );
    const vector v
    (
        structure_.hasPayload() ? structure_.payloadVelocity() : vector::zero
    );
    const scalar diameter = structure_.projectedDiameter();
    const scalar area = structure_.canopyArea();
    const canopyStructure::energy e(structure_.energies());
    // The canopy's area-weighted centre (ground frame): with the payload,
    // the suspension's direction
    const scalarField areas(structure_.triangleAreas());
    const point centre
    (
        sum(areas*structure_.triangleCentres())/max(sum(areas), VSMALL)
    );
    const vector& f = step.load;
    const vector& o = step.frameOrigin;
    const vector& l = step.lineDrag;
    series_()
        << mesh_.time().value() << ' ' << x.x() << ' ' << x.y() << ' '
        << x.z() << ' ' << v.x() << ' ' << v.y() << ' ' << v.z()
        << ' ' << f.x() << ' ' << f.y() << ' ' << f.z()
        << ' ' << diameter << ' ' << area
        << ' ' << e.kinetic << ' ' << e.spring << ' ' << e.gravity
        << ' ' << step.iterations << ' ' << step.residual << ' '
        << step.slip << ' ' << step.subSteps
        << ' ' << o.x() << ' ' << o.y() << ' ' << o.z()
        << ' ' << l.x() << ' ' << l.y() << ' ' << l.z()
        << ' ' << centre.x() << ' ' << centre.y() << ' ' << centre.z()
        << endl;
}


void Foam::couplingOutput::writeInfo(Ostream& os) const
{
    os  << "canopyCoupling: structure of " << structure_.nNodes()
        << " nodes, total mass " << structure_.totalMass() << " kg, canopy"
        << " area " << structure_.canopyArea() << " m^2, nominal diameter "
        << nominalDiameter_ << " m" << nl;
}


void Foam::couplingOutput::logIteration
(
    const stepSummary& step,
    const label worst,
    const string& acceleration,
    const bool tangentialLoad,
    const vector& ibForce,
    const vector* lineDrag
) const
{
    Info<< "canopyCoupling: iteration " << step.iterations
        << ", interface residual " << step.velocityResidual;
    if (worst >= 0)
    {
        Info<< " (largest at " << structure_.triangleCentres()()[worst]
            << ")";
    }
    if (step.balanceResidual >= 0)
    {
        Info<< ", balance residual " << step.balanceResidual;
    }
    Info<< ", slip " << step.slip
        << ", " << acceleration.c_str()
        << ", structure sub-steps " << step.subSteps
        << (tangentialLoad ? ", load on the cloth " : ", pressure force ")
        << step.load << ", IB force " << ibForce;
    if (lineDrag)
    {
        Info<< ", line drag " << *lineDrag;
    }
    Info<< endl;
}


Foam::string Foam::couplingOutput::notConverged
(
    const stepSummary& step,
    const scalar tolerance
) const
{
    return
        "the coupling did not converge at t = " + canopyCompat::timeName(mesh_.time())
      + " in " + Foam::name(step.iterations) + " iterations (residual "
      + Foam::name(step.residual)
      + (
            step.balanceResidual >= 0
          ? " of velocity " + Foam::name(step.velocityResidual)
          + " and balance " + Foam::name(step.balanceResidual)
          : string()
        )
      + ", slip " + Foam::name(step.slip)
      + ", tolerance " + Foam::name(tolerance) + ")";
}


// ************************************************************************* //
