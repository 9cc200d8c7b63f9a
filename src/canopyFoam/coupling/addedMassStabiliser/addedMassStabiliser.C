/*---------------------------------------------------------------------------*\
    canopyFoam: addedMassStabiliser.C — the strong coupling's added-mass
    stabiliser.
\*---------------------------------------------------------------------------*/

#include "addedMassStabiliser.H"
#include "canopyStructure.H"
#include "canopyFoamCompat.H"
#include "ibForcing.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::addedMassStabiliser::validKeys()
{
    return
    {
        "mass", "predictor", "balance", "direction", "filter", "distribution"
    };
}


Foam::addedMassStabiliser::addedMassStabiliser
(
    const scopedEntryReader& addedMass,
    const canopyStructure& structure
)
:
    triangles_(),
    mass_(),
    share_(),
    dt_(0),
    direction_(),
    stepStartVelocity_(),
    balanceAcceleration_(),
    stepMean_(),
    stepStartMean_(),
    fromLastStep_(false),
    fromStepMean_(false),
    endOfStep_(false),
    isotropic_(false),
    triangleMean_(false),
    kernel_(false),
    consistent_(false),
    forcing_(nullptr)
{
    addedMass.rejectUnknown(validKeys());

    // An absent sub-dictionary: off (any entry makes mass required)
    const scalar density =
        addedMass.dict().empty()
      ? 0
      : addedMass.nonNegative("mass", "added mass per area [kg/m^2]");
    const word predictor
    (
        addedMass.choice
        (
            "predictor", {"lastStep", "lastStepMean", "zero"}, "predictor",
            "lastStep"
        )
    );
    fromLastStep_ = predictor != "zero";
    fromStepMean_ = predictor == "lastStepMean";
    endOfStep_ =
        addedMass.choice
        (
            "balance", {"stepMean", "endOfStep"}, "balance", "stepMean"
        )
     == "endOfStep";
    isotropic_ =
        addedMass.choice
        (
            "direction", {"normal", "all"}, "direction", "normal"
        )
     == "all";
    const word filter
    (
        addedMass.choice
        (
            "filter", {"none", "triangleMean", "kernel"}, "filter", "none"
        )
    );
    kernel_ = filter == "kernel";
    triangleMean_ = filter != "none";
    consistent_ =
        addedMass.choice
        (
            "distribution", {"lumped", "consistent"}, "distribution",
            "lumped"
        )
     == "consistent";
    const word integrator(structure.integrator());
    if (consistent_)
    {
        if (!isotropic_)
        {
            addedMass.fail
            (
                "distribution",
                "= consistent acts in every direction: it needs direction"
                " all, not normal"
            );
        }
        if (addedMass.dict().found("filter") && !triangleMean_)
        {
            addedMass.fail
            (
                "filter",
                "= none contradicts distribution consistent, whose balance"
                " is the triangles' mean acceleration (filter triangleMean)"
            );
        }
        if (kernel_)
        {
            addedMass.fail
            (
                "filter",
                "= kernel leaves the motions finer than the IB kernel"
                " unbalanced, which distribution consistent gives added"
                " mass: use distribution lumped, or filter triangleMean"
            );
        }
        if (integrator != "hht" && integrator != "newmark")
        {
            addedMass.fail
            (
                "distribution",
                "= consistent couples the nodes and needs the structure's"
                " integrator.type hht or newmark, not " + integrator
            );
        }
        triangleMean_ = true;
    }
    if (kernel_ && !isotropic_)
    {
        addedMass.fail
        (
            "filter",
            "= kernel balances the whole acceleration as the IB kernel sees"
            " it: it needs direction all, not normal"
        );
    }
    if (endOfStep_ && integrator != "hht" && integrator != "newmark")
    {
        addedMass.fail
        (
            "balance",
            "= endOfStep needs the structure's integrator.type hht or"
            " newmark (an implicit integrator, which keeps the acceleration"
            " it ends a step with), not " + integrator
        );
    }
    if (density == 0)
    {
        return;
    }

    // A third of each canopy triangle's area to each of its nodes
    triangles_ = structure.triangles();
    mass_.setSize(structure.nNodes(), Zero);
    const scalarField areas(structure.triangleAreas());
    triangleMass_ = density*areas;
    forAll(triangles_, t)
    {
        for (const label node : triangles_[t])
        {
            mass_[node] += triangleMass_[t]/3;
        }
    }
    share_ = mass_/max(structure.masses() + mass_, VSMALL);
    direction_.setSize(structure.nNodes(), Zero);
    balanceAcceleration_.setSize(structure.nNodes(), Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::addedMassStabiliser::beginStep(canopyStructure& structure)
{
    if (!active())
    {
        return;
    }
    stepStartVelocity_ = structure.velocities();
    if (!fromLastStep_)
    {
        balanceAcceleration_ = Zero;
    }
    else if (fromStepMean_ && stepMean_.size())
    {
        balanceAcceleration_ = stepMean_;
    }
    stepStartBalance_ = balanceAcceleration_;
    stepStartMean_ = stepMean_;

    // The added mass acts along the nodes' normals at the step's start
    // (area-weighted over the adjacent triangles), or with
    // direction all in every direction (a zero direction)
    direction_ = Zero;
    if (consistent_)
    {
        structure.setDirectionalAddedMass
        (
            scalarField(mass_.size(), Zero), direction_
        );
        structure.setTriangleAddedMass(triangleMass_);
        return;
    }
    if (isotropic_)
    {
        structure.setDirectionalAddedMass(mass_, direction_);
        return;
    }
    const vectorField n(structure.triangleNormals());
    const scalarField areas(structure.triangleAreas());
    forAll(triangles_, t)
    {
        for (const label node : triangles_[t])
        {
            direction_[node] += areas[t]*n[t];
        }
    }
    forAll(direction_, node)
    {
        const scalar len = mag(direction_[node]);
        if (len > VSMALL)
        {
            direction_[node] /= len;
        }
    }
    structure.setDirectionalAddedMass(mass_, direction_);
}


Foam::tmp<Foam::vectorField>
Foam::addedMassStabiliser::balanceVelocities(const vectorField& abar) const
{
    tmp<vectorField> tvelocities(new vectorField(triangles_.size(), Zero));
    if (!active())
    {
        return tvelocities;
    }
    vectorField& velocities = tvelocities.ref();

    // Per node: abar along the added mass's directions, times the share
    // m_a/(m + m_a) of the node's mass the balance acts on
    vectorField nodal(abar);
    if (!isotropic_)
    {
        nodal = (direction_ & nodal)*direction_;
    }
    nodal *= share_;

    // Per triangle: the mean over its nodes, over the step (with filter
    // kernel: as the IB kernel sees it)
    forAll(triangles_, t)
    {
        const triFace& tri = triangles_[t];
        velocities[t] = dt_*(nodal[tri[0]] + nodal[tri[1]] + nodal[tri[2]])/3;
    }
    if (kernel_)
    {
        velocities = forcing().kernelMean(velocities);
    }
    return tvelocities;
}


Foam::tmp<Foam::vectorField>
Foam::addedMassStabiliser::balancingForces() const
{
    if (!triangleMean_)
    {
        if (isotropic_)
        {
            return mass_*balanceAcceleration_;
        }
        return mass_*(direction_ & balanceAcceleration_)*direction_;
    }

    // Each triangle's added mass m_t times its nodes' mean acceleration,
    // a third to each node: f = sum_t (m_t/9) 1_t 1_t^T abar (along the
    // normals, d_i sum_t (m_t/9) sum_j d_j.abar_j)
    tmp<vectorField> tforces(new vectorField(mass_.size(), Zero));
    vectorField& forces = tforces.ref();
    if (kernel_)
    {
        // Each triangle's added mass m_t times its nodes' mean
        // acceleration as the IB kernel sees it, a third to each node
        vectorField means(triangles_.size());
        forAll(triangles_, t)
        {
            const triFace& tri = triangles_[t];
            means[t] =
            (
                balanceAcceleration_[tri[0]]
              + balanceAcceleration_[tri[1]]
              + balanceAcceleration_[tri[2]]
            )/3;
        }
        const vectorField seen(forcing().kernelMean(means));
        forAll(triangles_, t)
        {
            const vector f = (triangleMass_[t]/3)*seen[t];
            for (const label node : triangles_[t])
            {
                forces[node] += f;
            }
        }
        return tforces;
    }
    forAll(triangles_, t)
    {
        const triFace& tri = triangles_[t];
        const scalar share = triangleMass_[t]/9;
        if (isotropic_)
        {
            const vector f =
                share
               *(
                    balanceAcceleration_[tri[0]]
                  + balanceAcceleration_[tri[1]]
                  + balanceAcceleration_[tri[2]]
                );
            for (const label node : tri)
            {
                forces[node] += f;
            }
        }
        else
        {
            scalar f = 0;
            for (const label node : tri)
            {
                f += direction_[node] & balanceAcceleration_[node];
            }
            for (const label node : tri)
            {
                forces[node] += share*f*direction_[node];
            }
        }
    }
    return tforces;
}


void Foam::addedMassStabiliser::filterThrough(const ibForcing& forcing)
{
    const label sampled = forcing.markers().levels().size();
    if (active() && sampled != triangles_.size())
    {
        FatalErrorInFunction
            << "The IB forcing's markers sample " << sampled
            << " triangles, the stabiliser acts on " << triangles_.size()
            << exit(FatalError);
    }
    forcing_ = &forcing;
}


const Foam::ibForcing& Foam::addedMassStabiliser::forcing() const
{
    if (!forcing_)
    {
        FatalErrorInFunction
            << "addedMass.filter kernel before the IB forcing was given"
            << " (filterThrough)" << exit(FatalError);
    }
    return *forcing_;
}


void Foam::addedMassStabiliser::update
(
    const canopyStructure& structure,
    const scalar dt
)
{
    if (!active())
    {
        return;
    }
    dt_ = dt;
    if (endOfStep_)
    {
        balanceAcceleration_ = structure.accelerationState();
    }
    else
    {
        balanceAcceleration_ = (structure.velocities() - stepStartVelocity_)/dt;
    }
    if (fromStepMean_)
    {
        stepMean_ = (structure.velocities() - stepStartVelocity_)/dt;
    }
}


void Foam::addedMassStabiliser::setBalanceAcceleration
(
    const vectorField& balance
)
{
    if (balance.size() != balanceAcceleration_.size())
    {
        FatalErrorInFunction
            << "The balancing acceleration has " << balance.size()
            << " values, the stabiliser acts on "
            << balanceAcceleration_.size() << " nodes" << exit(FatalError);
    }
    balanceAcceleration_ = balance;
}


void Foam::addedMassStabiliser::writeState(dictionary& state) const
{
    if (active())
    {
        state.add("addedMassBalance", balanceAcceleration_);
        if (fromStepMean_ && stepMean_.size())
        {
            state.add("addedMassStepMean", stepMean_);
        }
    }
}


bool Foam::addedMassStabiliser::readNodal
(
    const dictionary& state,
    const word& entry,
    const string& ifAbsent,
    vectorField& values
) const
{
    if (!state.found(entry))
    {
        WarningInFunction
            << "No entry '" << entry << "' in " << state.name()
            << ": the added-mass stabiliser's first balance after the"
            << " restart is " << ifAbsent.c_str() << endl;
        return false;
    }
    const vectorField read(canopyCompat::readValue<vectorField>(state, entry));
    if (read.size() != balanceAcceleration_.size())
    {
        FatalIOErrorInFunction(state)
            << "Entry '" << entry << "' holds " << read.size()
            << " accelerations, but the stabiliser acts on "
            << balanceAcceleration_.size() << " nodes (was coupling.addedMass"
            << " or the structure changed since it was written?)"
            << exit(FatalIOError);
    }
    values = read;
    return true;
}


void Foam::addedMassStabiliser::readState(const dictionary& state)
{
    if
    (
        active()
     && readNodal(state, "addedMassBalance", "zero", balanceAcceleration_)
     && fromStepMean_
    )
    {
        readNodal
        (
            state, "addedMassStepMean", "the last step's end acceleration",
            stepMean_
        );
    }
}


// ************************************************************************* //
