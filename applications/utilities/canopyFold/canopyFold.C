// canopyFold.C: folds the canopy of constant/canopyProperties before a run: a structure-only pre-simulation driven by the singular velocity field of seed 000 eq. 5.3, written as the initial state canopyStructure reads (entry initialState).
/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | canopyFoam: parachute fluid-structure interaction
   \\    /   O peration     | for OpenFOAM v1912
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of canopyFoam, a plugin for OpenFOAM, and like OpenFOAM
    is distributed under the GNU General Public License version 3 or later.

Application
    canopyFold

Description
    Deforms the fully extended canopy of constant/canopyProperties into a
    folded state, as seed 000 does before its inflation runs (section 5.8,
    Figs. 5.17 and 5.18): a pre-simulation of the spring system alone (no
    fluid; gravity off, no pressure jump) in which chosen canopy nodes are
    moved by the singular velocity field of seed 000 eq. 5.3,

        v = v0   if x^2 + y^2 < a^2,      v = 0   otherwise,

    with x^2 + y^2 read as the squared distance r^2 from an axis through a
    centre (a ring innerRadius <= r < a when innerRadius > 0), and the rest
    of the structure is dragged along through the springs ("even though
    only a few points are driven by the external velocity field, the
    entire fabric surface feels the dragging force by the moving points
    through the spring system", seed 000 section 5.4).

    - The driven nodes are the canopy nodes (cloth and radial tapes; not
      line nodes, not the payload, not nodes fixed in canopyProperties)
      inside the region at t = 0. They move kinematically with v0 for the
      time T (duration): libcanopy's fixed nodes ignore forces and keep the
      velocity they are given, so they move by v0 T exactly.
    - region.capture true applies eq. 5.3 as a field instead: a canopy
      node the springs pull into the region is driven from then on
      (checked at the start of each chunk, below). A captured node keeps
      the strain its springs had when it was caught (the driven nodes move
      rigidly), so capture locks stress into the fold; the default is
      false.
    - holdPayload (default true) pins the payload during the fold. Lifting
      the canopy centre away from it pulls on the lines, which draw the
      skirt towards the axis: the canopy closes around its axis above the
      payload, wrinkling where the cloth has to gather. With holdPayload
      false the whole system is towed and only the drag shapes it.
    - damping zeta: a drag per unit mass, f_i = -zeta m_i v_i, on every
      free node: an artificial quiescent medium that makes the fold
      quasi-static and lets it settle (libcanopy's dashpots act on
      relative velocities only and leave the cloth's zero-stiffness
      folding motions undamped). While the centre is driven, the drag on
      the trailing cloth acts like gravity along -v0 (of size zeta |v0|),
      so the cloth drapes behind the driven nodes as seed 000's cloth does
      under gravity (Fig. 5.11). It is applied by operator splitting: after
      each chunk of duration dt the free nodes' velocities are scaled by
      exp(-zeta dt), the exact solution of dv/dt = -zeta v. It is not part
      of the model and not written to the file.
    - After the drive the driven nodes stop and are held while the rest
      settles for the time relaxation (default 0). The last state is
      written with all velocities zero.
    - Chunks: time advances in chunks of at most
      min(0.05/zeta, 0.1 edge/|v0|, (T + relaxation)/nOutput), edge the
      mean rest length of the cloth springs; libcanopy sub-cycles each at
      its stable step (canopyProperties' integrator and maxOmegaDt, or the
      entries integrator and maxOmegaDt here). The
      drive ends exactly at T.
    - Rest lengths are never changed: the folded canopy is stressed only
      where the fold left a spring longer or shorter than its flat length.
      The progress table shows the largest cloth stretch and compression
      and the spring energy; a Model-II cloth under compression buckles
      into wrinkles (no bending stiffness), and a settled fold is nearly
      stress-free. A spring stretched by more than maxStrain (default 0.1)
      stops the run with FatalError after writing that state: the lift
      v0 T was too large for the lines and cloth.
    - Collisions of the fabric with itself are not handled (seed 000 uses
      the front tracking library's). The column "closest" of the table is
      the closest approach of two canopy nodes that share no spring, in
      units of the mean edge: near 0 the cloth has folded onto itself and
      may interpenetrate (a gentler or shorter fold avoids it).

    Output: one HDF5 file with its XDMF sidecar through libcanopy's
    canopy_output (layout in canopy.h): the flat canopy first, then
    nOutput states spread evenly over the fold, the last the folded state
    at rest. Open the .xdmf in ParaView to watch the fold. The file defaults
    to canopyProperties' initialState, else constant/canopyInitialState.h5;
    with initialState naming it, the solver starts from its last step (see
    canopyStructure.H).

Usage
    canopyFold [-case dir] [-dict file]

    \c system/canopyFoldDict (the test case's, tests/openfoam/canopyFold):
    \verbatim
    velocity        (0 0 1);        // v0 [m/s]
    duration        0.4;            // T [s]: lift v0 T = 0.4 m
    region
    {
        centre      (0 0 0);        // on the axis; default canopy.centre
        axis        (0 0 1);
        radius      0.15;           // a [m]
        innerRadius 0;              // > 0: a ring innerRadius <= r < a
        capture     false;
    }
    damping         20;             // zeta [1/s]
    relaxation      0.2;            // [s] after T, driven nodes held
    nOutput         12;
    holdPayload     true;
    maxStrain       0.1;
    // output       "constant/canopyInitialState.h5";
    \endverbatim

    \table
        Property           | Description                          | Required | Default
        velocity           | v0 of eq. 5.3 [m/s], not zero         | yes | -
        duration           | driving time T [s], > 0               | yes | -
        region.radius      | a of eq. 5.3 [m], > 0                 | yes | -
        region.centre      | a point on the axis of the region     | no  | canopy.centre of canopyProperties, else (0 0 0)
        region.axis        | axis direction (normalised), not zero | no  | (0 0 1)
        region.innerRadius | inner radius of a ring, in [0, radius) | no | 0
        region.capture     | nodes the springs pull into the region are driven too | no | false
        damping            | drag zeta [1/s] per unit mass, >= 0   | no  | 20
        relaxation         | time after T with the driven nodes held [s], >= 0 | no | 0
        nOutput            | states written after the flat one, >= 1 | no | 10
        holdPayload        | pin the payload during the fold       | no  | true
        maxStrain          | largest spring stretch (l - l0)/l0 allowed, > 0 | no | 0.1
        integrator         | libcanopy integrator of the fold (e.g. rk4 when the run uses one large hht step) | no | canopyProperties' integrator.type
        maxOmegaDt         | the fold's sub-step bound Lambda dt, > 0 | no | canopyProperties' integrator.maxOmegaDt
        output             | HDF5 file to write (ending in .h5), relative to the case | no | canopyProperties initialState, else constant/canopyInitialState.h5
    \endtable

    A bad entry stops with FatalIOError naming it, as in canopyProperties.

See also
    applications/utilities/canopyFold/README.md,
    Foam::canopyStructure (entry initialState).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "Switch.H"
#include "FlatOutput.H"
#include "canopyStructure.H"

#include "canopy.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

// Reads and checks the entries of one (sub-)dictionary; errors are
// FatalIOError on it naming the entry by its scoped name ("region.radius")
class foldReader
{
    const dictionary& dict_;
    const std::string scope_;

    std::string name(const word& key) const
    {
        return scope_.empty() ? std::string(key) : scope_ + '.' + key;
    }

    ITstream& stream(const word& key, const std::string& what) const
    {
        const entry* e = dict_.findEntry(key, keyType::LITERAL);
        if (!e)
        {
            fail(key, "is missing (required: " + what + ")");
        }
        if (e->isDict())
        {
            fail(key, "must be a value (" + what + "), not a sub-dictionary");
        }
        return e->stream();
    }

    static std::string str(const scalar x)
    {
        OStringStream os;
        os << x;
        return os.str();
    }


public:

    foldReader(const dictionary& dict, const std::string& scope)
    :
        dict_(dict),
        scope_(scope)
    {}

    bool found(const word& key) const
    {
        return dict_.findEntry(key, keyType::LITERAL) != nullptr;
    }

    [[noreturn]] void fail(const word& key, const std::string& what) const
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << name(key).c_str() << "' " << what.c_str() << nl
            << exit(FatalIOError);
        std::abort();   // not reached
    }

    //- A finite number, >= lo (or > lo when strict)
    scalar number
    (
        const word& key,
        const std::string& what,
        const scalar lo,
        const bool strict
    ) const
    {
        ITstream& is = stream(key, what);
        if (is.size() != 1 || !is[0].isNumber())
        {
            fail(key, "must be a number (" + what + "), found " + is.toString());
        }
        const scalar x = is[0].number();
        if (!std::isfinite(x))
        {
            fail(key, "= " + str(x) + " must be finite");
        }
        if (strict ? !(x > lo) : !(x >= lo))
        {
            fail
            (
                key,
                "= " + str(x) + " must be " + (strict ? "> " : ">= ") + str(lo)
              + " (" + what + ")"
            );
        }
        return x;
    }

    scalar number
    (
        const word& key,
        const std::string& what,
        const scalar lo,
        const bool strict,
        const scalar deflt
    ) const
    {
        return found(key) ? number(key, what, lo, strict) : deflt;
    }

    //- An integer >= lo
    label integer(const word& key, const std::string& what, const label lo,
        const label deflt) const
    {
        if (!found(key)) return deflt;
        ITstream& is = stream(key, what);
        if (is.size() != 1 || !is[0].isLabel())
        {
            fail(key, "must be an integer (" + what + "), found " + is.toString());
        }
        const label n = is[0].labelToken();
        if (n < lo)
        {
            fail
            (
                key,
                "= " + std::to_string(n) + " must be >= " + std::to_string(lo)
              + " (" + what + ")"
            );
        }
        return n;
    }

    //- A finite vector (x y z); nonZero: not (0 0 0)
    vector vec(const word& key, const std::string& what, const bool nonZero,
        const bool required, const vector& deflt) const
    {
        if (!required && !found(key)) return deflt;
        ITstream& is = stream(key, what);
        const bool ok =
            is.size() == 5
         && is[0].isPunctuation() && is[0].pToken() == token::BEGIN_LIST
         && is[1].isNumber() && is[2].isNumber() && is[3].isNumber()
         && is[4].isPunctuation() && is[4].pToken() == token::END_LIST;
        if (!ok)
        {
            fail(key, "must be a vector (x y z) (" + what + "), found " + is.toString());
        }
        const vector v(is[1].number(), is[2].number(), is[3].number());
        if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z()))
        {
            fail(key, "must be finite");
        }
        if (nonZero && mag(v) == 0)
        {
            fail(key, "= (0 0 0) must not be zero (" + what + ")");
        }
        return v;
    }

    //- A switch
    bool flag(const word& key, const bool deflt) const
    {
        if (!found(key)) return deflt;
        ITstream& is = stream(key, "true or false");
        if (is.size() == 1 && is[0].isBool()) return is[0].boolToken();
        if (is.size() == 1 && is[0].isWord())
        {
            const Switch sw(is[0].wordToken(), true);
            if (sw.valid()) return bool(sw);
        }
        fail(key, "must be a switch (true/false, on/off, yes/no), found " + is.toString());
    }

    //- One of the words in 'choices'
    word select(const word& key, const wordList& choices) const
    {
        std::string list;
        for (const word& w : choices)
        {
            list += (list.empty() ? "" : " ") + w;
        }
        ITstream& is = stream(key, "one of " + list);
        if (is.size() != 1 || !is[0].isWord() || !choices.found(is[0].wordToken()))
        {
            fail(key, "= " + is.toString() + " must be one of: " + list);
        }
        return is[0].wordToken();
    }

    //- A file name ending in .h5
    fileName h5(const word& key) const
    {
        ITstream& is = stream(key, "an HDF5 file name");
        if (is.size() != 1 || !is[0].isStringType())
        {
            fail(key, "must be a single file name, found " + is.toString());
        }
        fileName f(is[0].stringToken());
        f.expand();
        if (f.ext() != "h5")
        {
            fail(key, "= " + f + " must name an HDF5 file ending in .h5");
        }
        return f;
    }

    //- Warn about entries not in 'used' (typos)
    void warnUnused(const wordList& used) const
    {
        for (const word& key : dict_.toc())
        {
            if (!used.found(key))
            {
                IOWarningInFunction(dict_)
                    << "Entry '" << name(key).c_str() << "' is not used and is"
                    << " ignored. Valid entries here: " << flatOutput(used)
                    << endl;
            }
        }
    }
};


// The fold's controls (system/canopyFoldDict)
struct foldControls
{
    vector velocity;
    scalar duration;
    point centre;
    vector axis;            // unit
    scalar radius;
    scalar innerRadius;
    bool capture;
    scalar damping;
    scalar relaxation;
    label nOutput;
    bool holdPayload;
    scalar maxStrain;
    word integrator;        // empty: canopyProperties'
    scalar maxOmegaDt;      // <= 0: canopyProperties'
    fileName output;        // absolute
};


foldControls readControls
(
    const dictionary& dict,
    const canopyStructure& structure,
    const Time& runTime
)
{
    foldControls c;
    const foldReader top(dict, "");

    c.velocity = top.vec("velocity", "v0 of seed 000 eq. 5.3 [m/s]", true, true, Zero);
    c.duration = top.number("duration", "driving time T [s]", 0, true);

    const entry* re = dict.findEntry("region", keyType::LITERAL);
    if (!re || !re->isDict())
    {
        top.fail
        (
            "region",
            re ? "must be a sub-dictionary { radius ...; }"
               : "is missing: a sub-dictionary region { radius <a>; } is required"
        );
    }
    const foldReader rr(re->dict(), "region");

    // Default centre: the canopy's centre in canopyProperties
    point canopyCentre(Zero);
    const dictionary& canopyDict = structure.dict().subOrEmptyDict("canopy");
    canopyDict.readIfPresent("centre", canopyCentre);

    c.centre = rr.vec("centre", "a point on the axis [m]", false, false, canopyCentre);
    c.axis = rr.vec("axis", "axis direction", true, false, vector(0, 0, 1));
    c.axis /= mag(c.axis);
    c.radius = rr.number("radius", "radius a of the driven region [m]", 0, true);
    c.innerRadius = rr.number("innerRadius", "inner radius of a ring [m]", 0, false, 0);
    if (!(c.innerRadius < c.radius))
    {
        OStringStream os;
        os  << "= " << c.innerRadius << " must be smaller than region.radius = "
            << c.radius;
        rr.fail("innerRadius", os.str());
    }
    c.capture = rr.flag("capture", false);
    rr.warnUnused(wordList{"centre", "axis", "radius", "innerRadius", "capture"});

    c.damping = top.number("damping", "drag per unit mass zeta [1/s]", 0, false, 20);
    c.relaxation = top.number("relaxation", "relaxation time after the drive [s]", 0, false, 0);
    c.nOutput = top.integer("nOutput", "number of states written", 1, 10);
    c.holdPayload = top.flag("holdPayload", true);
    c.maxStrain = top.number("maxStrain", "largest spring stretch allowed", 0, true, 0.1);
    if (top.found("integrator"))
    {
        wordList names(canopy_integrator_count());
        forAll(names, i)
        {
            names[i] = word(canopy_integrator_name(i));
        }
        c.integrator = top.select("integrator", names);
    }
    c.maxOmegaDt = top.number("maxOmegaDt", "sub-step bound omega dt", 0, true, -1);

    if (top.found("output"))
    {
        c.output = top.h5("output");
        if (!c.output.isAbsolute())
        {
            c.output = runTime.globalPath()/c.output;
        }
    }
    else
    {
        c.output = structure.initialStateFile(runTime);
        if (c.output.empty())
        {
            c.output =
                runTime.globalPath()/canopyStructure::defaultInitialStateName;
        }
    }

    top.warnUnused
    (
        wordList
        {
            "velocity", "duration", "region", "damping", "relaxation",
            "nOutput", "holdPayload", "maxStrain", "integrator",
            "maxOmegaDt", "output"
        }
    );
    return c;
}


// Distance of x from the axis of the region
scalar axisDistance(const foldControls& c, const point& x)
{
    const vector d = x - c.centre;
    return mag(d - (d & c.axis)*c.axis);
}


// Inside the region of eq. 5.3 (a disc, or a ring with innerRadius > 0)
bool inside(const foldControls& c, const point& x)
{
    const scalar r = axisDistance(c, x);
    return r < c.radius && r >= c.innerRadius;
}


// Spring strains (l - l0)/l0: largest stretch of any spring (and which),
// of a canopy (cloth or tape) spring and of a line spring; largest
// compression of a canopy spring
struct strainSummary
{
    scalar maxStretch;
    label stretchSpring;
    scalar maxCanopyStretch;
    scalar maxLineStretch;
    scalar maxCanopyCompression;
};

strainSummary strains
(
    const pointField& x,
    const std::vector<int>& ends,
    const std::vector<double>& rest,
    const std::vector<int>& groups
)
{
    strainSummary s{0, -1, 0, 0, 0};
    for (std::size_t k = 0; k < rest.size(); ++k)
    {
        const scalar e = mag(x[ends[2*k]] - x[ends[2*k + 1]])/rest[k] - 1;
        if (e > s.maxStretch)
        {
            s.maxStretch = e;
            s.stretchSpring = label(k);
        }
        const bool canopy =
            groups[k] == CANOPY_GROUP_FABRIC || groups[k] == CANOPY_GROUP_TAPE;
        if (canopy)
        {
            if (e > s.maxCanopyStretch) s.maxCanopyStretch = e;
            if (-e > s.maxCanopyCompression) s.maxCanopyCompression = -e;
        }
        else if (e > s.maxLineStretch)
        {
            s.maxLineStretch = e;
        }
    }
    return s;
}


// Closest approach of two canopy nodes that share no spring, found with a
// uniform grid of cell size h; returns h when no such pair is closer
scalar closestApproach
(
    const pointField& x,
    const std::vector<label>& canopyNodes,
    const std::vector<std::vector<label>>& neighbours,
    const scalar h
)
{
    typedef std::tuple<long, long, long> cellKey;
    std::map<cellKey, std::vector<label>> grid;
    auto keyOf = [h](const point& p)
    {
        return cellKey
        (
            long(std::floor(p.x()/h)),
            long(std::floor(p.y()/h)),
            long(std::floor(p.z()/h))
        );
    };
    for (const label i : canopyNodes)
    {
        grid[keyOf(x[i])].push_back(i);
    }

    scalar closest = h;
    for (const label i : canopyNodes)
    {
        const cellKey k = keyOf(x[i]);
        for (long a = -1; a <= 1; ++a)
        for (long b = -1; b <= 1; ++b)
        for (long c = -1; c <= 1; ++c)
        {
            const auto it = grid.find
            (
                cellKey
                (
                    std::get<0>(k) + a, std::get<1>(k) + b, std::get<2>(k) + c
                )
            );
            if (it == grid.end()) continue;
            for (const label j : it->second)
            {
                if (j <= i) continue;
                const std::vector<label>& nb = neighbours[i];
                if (std::find(nb.begin(), nb.end(), j) != nb.end()) continue;
                closest = min(closest, mag(x[i] - x[j]));
            }
        }
    }
    return closest;
}

// FatalError quoting libcanopy's message when a call failed
void check(const int status, const canopy_model* m, const char* call)
{
    if (status != CANOPY_OK)
    {
        FatalErrorInFunction
            << "libcanopy " << call << " failed: " << canopy_model_message(m)
            << nl << exit(FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Fold the canopy of constant/canopyProperties with the singular"
        " velocity field of seed 000 eq. 5.3 (structure only) and write the"
        " folded state for canopyProperties' initialState"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    #include "addDictOption.H"

    #include "setRootCase.H"
    #include "createTime.H"

    // The flat canopy, as built from canopyProperties (its own initialState
    // entry, which may name the file written here, is not applied)
    canopyStructure structure(runTime, false);
    canopy_model* m = structure.model();

    const word dictName("canopyFoldDict");
    #include "setSystemRunTimeDictionaryIO.H"
    const IOdictionary foldDict(dictIO);
    const foldControls c = readControls(foldDict, structure, runTime);

    // ---- the model as the fold needs it -------------------------------------

    const label n = structure.nNodes();
    const label ns = structure.nSprings();

    const double zero3[3] = {0, 0, 0};
    check(canopy_model_set_gravity(m, zero3), m, "set_gravity");  // g off
    if (!c.integrator.empty())
    {
        check(canopy_model_set_integrator(m, c.integrator.c_str()), m, "set_integrator");
    }
    if (c.maxOmegaDt > 0)
    {
        check(canopy_model_set_max_omega_dt(m, c.maxOmegaDt), m, "set_max_omega_dt");
    }
    // (pressure jumps are zero: nothing sets them)
    structure.setTime(0);

    std::vector<int> fixed0(n), groups(n), springEnds(2*ns), springGroups(ns);
    std::vector<double> rest(ns);
    check(canopy_model_get_fixed(m, fixed0.data(), n), m, "get_fixed");
    check
    (
        canopy_model_get_node_groups(m, groups.data(), n), m, "get_node_groups"
    );
    check
    (
        canopy_model_get_springs
        (
            m, springEnds.data(), rest.data(), nullptr, ns
        ),
        m, "get_springs"
    );
    check
    (
        canopy_model_get_spring_groups(m, springGroups.data(), ns),
        m, "get_spring_groups"
    );

    // Canopy nodes: cloth and tapes; those not fixed may be driven
    std::vector<label> canopyNodes;
    std::vector<bool> drivable(n, false);
    for (label i = 0; i < n; ++i)
    {
        if (groups[i] == CANOPY_GROUP_FABRIC || groups[i] == CANOPY_GROUP_TAPE)
        {
            canopyNodes.push_back(i);
            drivable[i] = !fixed0[i];
        }
    }

    // Spring neighbours, and the mean cloth edge
    std::vector<std::vector<label>> neighbours(n);
    scalar edgeSum = 0;
    label nEdge = 0;
    for (label k = 0; k < ns; ++k)
    {
        neighbours[springEnds[2*k]].push_back(springEnds[2*k + 1]);
        neighbours[springEnds[2*k + 1]].push_back(springEnds[2*k]);
        if (springGroups[k] == CANOPY_GROUP_FABRIC)
        {
            edgeSum += rest[k];
            ++nEdge;
        }
    }
    const scalar edge = nEdge ? edgeSum/nEdge : 0;
    if (!(edge > 0))
    {
        FatalErrorInFunction
            << "The structure of " << structure.dict().name()
            << " has no canopy cloth to fold" << exit(FatalError);
    }

    // The driven nodes at t = 0
    const pointField x0(structure.points());
    std::vector<bool> initiallyInside(n, false);
    label nInitial = 0;
    for (label i = 0; i < n; ++i)
    {
        if (drivable[i] && inside(c, x0[i]))
        {
            initiallyInside[i] = true;
            ++nInitial;
        }
    }
    if (nInitial == 0)
    {
        scalar rMin = GREAT;
        for (const label i : canopyNodes) rMin = min(rMin, axisDistance(c, x0[i]));
        FatalIOErrorInFunction(foldDict.subDict("region"))
            << "Entry 'region.radius' = " << c.radius << ": no free canopy"
            << " node lies inside the region (innerRadius " << c.innerRadius
            << ", centre " << c.centre << ", axis " << c.axis << "); the"
            << " nearest canopy node is " << rMin << " m from the axis"
            << nl << exit(FatalIOError);
    }

    // ---- chunks ----------------------------------------------------------------

    const scalar tEnd = c.duration + c.relaxation;
    scalar dtMax = min(0.1*edge/mag(c.velocity), tEnd/c.nOutput);
    if (c.damping > 0)
    {
        dtMax = min(dtMax, 0.05/c.damping);
    }
    const label nDrive = label(std::ceil(c.duration/dtMax - 1e-9));
    const label nRelax =
        c.relaxation > 0 ? label(std::ceil(c.relaxation/dtMax - 1e-9)) : 0;
    const label nChunks = nDrive + nRelax;

    const scalar d0 = structure.projectedDiameter();

    Info<< "canopyFold: " << structure.dict().name() << nl
        << "    structure          " << n << " nodes (" << canopyNodes.size()
        << " canopy), " << ns << " springs, " << structure.nTriangles()
        << " triangles, mean cloth edge " << edge << " m" << nl
        << "    field (eq. 5.3)    v0 = " << c.velocity << " m/s inside r < "
        << c.radius;
    if (c.innerRadius > 0)
    {
        Info<< " and r >= " << c.innerRadius;
    }
    Info<< " m of the axis " << c.axis << " through " << c.centre
        << (c.capture ? ", capturing" : ", initial nodes only") << nl
        << "    driven at t = 0    " << nInitial << " canopy nodes" << nl
        << "    drive              " << c.duration << " s (displacement "
        << mag(c.velocity)*c.duration << " m), then " << c.relaxation
        << " s held" << nl
        << "    damping            " << c.damping << " 1/s per unit mass"
        << nl
        << "    payload            "
        << (structure.hasPayload() ? (c.holdPayload ? "held" : "free") : "none")
        << nl
        << "    chunks             " << nDrive << " + " << nRelax
        << " (at most " << dtMax << " s; stable sub-step "
        << structure.stableStep() << " s)" << nl
        << "    output             " << c.output.c_str() << " (+ .xdmf)" << nl
        << "    flat projected diameter " << d0 << " m" << nl << endl;

    mkDir(c.output.path());
    canopy_output* outRaw = nullptr;
    if
    (
        canopy_output_create
        (
            m, c.output.lessExt().c_str(), CANOPY_OUTPUT_CREATE, &outRaw
        )
     != CANOPY_OK
    )
    {
        FatalErrorInFunction
            << "libcanopy cannot create " << c.output << ": "
            << canopy_model_message(m) << exit(FatalError);
    }
    std::unique_ptr<canopy_output, void(*)(canopy_output*)> out
    (
        outRaw, [](canopy_output* o) { canopy_output_destroy(&o); }
    );

    // Pinned only now, so that the file's /mesh/node_fixed holds the flags
    // of canopyProperties (those the solver runs with)
    if (c.holdPayload && structure.hasPayload())
    {
        check
        (
            canopy_model_set_fixed(m, structure.payloadNode(), 1),
            m, "set_fixed"
        );
    }

    auto writeState = [&]()
    {
        if (canopy_output_write(out.get(), m) != CANOPY_OK)
        {
            FatalErrorInFunction
                << "libcanopy cannot write to " << c.output << ": "
                << canopy_output_message(out.get()) << exit(FatalError);
        }
    };

    std::vector<bool> driven(n, false);
    label nDriven = 0;

    // One line of the progress table
    auto progress = [&](const scalar t, const strainSummary& s)
    {
        const pointField x(structure.points());
        const canopyStructure::energy e(structure.energies());
        char line[160];
        std::snprintf
        (
            line, sizeof line,
            "    %9.4g %7d %10.5g %9.3g %9.3g %9.3g %11.3g %11.3g %8.3g",
            t, int(nDriven), structure.projectedDiameter(),
            100*s.maxCanopyStretch, 100*s.maxCanopyCompression,
            100*s.maxLineStretch, e.kinetic, e.spring,
            closestApproach(x, canopyNodes, neighbours, edge)/edge
        );
        Info<< line << endl;
    };

    auto currentStrains = [&]()
    {
        return strains(structure.points(), springEnds, rest, springGroups);
    };

    // Strains in %: cloth (and tapes) stretched / compressed, lines
    // stretched; closest: of two canopy nodes sharing no spring / edge
    Info<< "     time [s]  driven  diam. [m]  cloth +%  cloth -%  lines +%"
        << "  kinetic [J]  spring [J]  closest" << endl;
    writeState();
    progress(0, currentStrains());

    // ---- the fold ---------------------------------------------------------------

    vectorField v(n, Zero);
    label written = 0;
    for (label j = 1; j <= nChunks; ++j)
    {
        const bool drive = j <= nDrive;
        const scalar dt = drive ? c.duration/nDrive : c.relaxation/nRelax;

        // The field of eq. 5.3 at the chunk's start: driven nodes are fixed
        // in libcanopy and move with the velocity they are given
        {
            const pointField x(structure.points());
            v = structure.velocities();
            for (label i = 0; i < n; ++i)
            {
                if (!drivable[i]) continue;
                const bool want =
                    drive
                 && (c.capture ? inside(c, x[i]) : initiallyInside[i]);
                if (want)
                {
                    v[i] = c.velocity;
                    if (!driven[i])
                    {
                        check(canopy_model_set_fixed(m, i, 1), m, "set_fixed");
                        driven[i] = true;
                        ++nDriven;
                    }
                }
                else if (driven[i])
                {
                    if (drive)
                    {
                        // Left the region (v0 not along the axis): free again
                        check(canopy_model_set_fixed(m, i, 0), m, "set_fixed");
                        driven[i] = false;
                        --nDriven;
                    }
                    else
                    {
                        v[i] = Zero;    // relaxation: held where they are
                    }
                }
            }
            check
            (
                canopy_model_set_velocities
                (
                    m, reinterpret_cast<const double*>(v.cdata()), n
                ),
                m, "set_velocities"
            );
        }

        label nSub = 0;
        string message;
        if (!structure.tryAdvance(dt, nSub, message))
        {
            FatalErrorInFunction
                << "The fold failed at t = " << structure.time() << ": "
                << message.c_str() << nl << exit(FatalError);
        }

        // Drag on the free nodes: dv/dt = -zeta v over the chunk, exactly
        {
            v = structure.velocities();
            std::vector<int> fixedNow(n);
            check(canopy_model_get_fixed(m, fixedNow.data(), n), m, "get_fixed");
            const scalar factor = std::exp(-c.damping*dt);
            for (label i = 0; i < n; ++i)
            {
                if (!fixedNow[i]) v[i] *= factor;
            }
            if (j == nChunks)
            {
                v = Zero;       // the folded state starts at rest
            }
            check
            (
                canopy_model_set_velocities
                (
                    m, reinterpret_cast<const double*>(v.cdata()), n
                ),
                m, "set_velocities"
            );
        }

        // nOutput states, about evenly spaced, the last at the end; and a
        // spring stretched beyond maxStrain stops the fold (written first)
        const strainSummary s = currentStrains();
        const bool torn = s.maxStretch > c.maxStrain;
        const label due = (j*c.nOutput)/nChunks;
        if (due > written || torn)
        {
            written = due;
            writeState();
            progress(structure.time(), s);
        }
        if (torn)
        {
            FatalErrorInFunction
                << "At t = " << structure.time() << " spring "
                << s.stretchSpring << " (nodes "
                << springEnds[2*s.stretchSpring] << " and "
                << springEnds[2*s.stretchSpring + 1] << ") is stretched by "
                << 100*s.maxStretch << " %, more than maxStrain = "
                << 100*c.maxStrain << " % (this state is the last in "
                << c.output.c_str() << "). Drive less far (velocity x"
                << " duration), or release the payload (holdPayload false)"
                << exit(FatalError);
        }
    }

    // ---- summary ---------------------------------------------------------------

    const pointField x(structure.points());
    scalar maxShift = 0;
    for (label i = 0; i < n; ++i)
    {
        if (!initiallyInside[i]) continue;
        const scalar d = mag((x[i] - x0[i]) - c.velocity*c.duration);
        maxShift = max(maxShift, d);
    }
    const scalar d1 = structure.projectedDiameter();
    Info<< nl << "canopyFold: folded in " << nChunks << " chunks, "
        << canopy_output_step_count(out.get()) << " states written" << nl
        << "    projected diameter " << d0 << " m -> " << d1 << " m ("
        << 100*d1/d0 << " %)" << nl
        << "    canopy area        " << structure.canopyArea() << " m^2" << nl
        << "    nodes driven at the end of the drive " << nDriven << nl
        << "    initially driven nodes moved by v0 T = "
        << c.velocity*c.duration << " m to within " << maxShift << " m" << nl
        << "    folded state       " << c.output.c_str() << nl
        << "    view               " << c.output.lessExt().c_str() << ".xdmf"
        << nl
        << "    use                initialState \""
        << c.output.relative(runTime.globalPath()).c_str() << "\"; in "
        << "constant/canopyProperties" << nl << endl;

    out.reset();

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
