// Test-canopyProperties.C: builds a case's canopy from constant/canopyProperties (canopyStructure) and checks it against libcanopy's C API, known totals, output and restart; exits non-zero on any mismatch.
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
    Test-canopyProperties

Description
    Constructs Foam::canopyStructure from the case's constant/canopyProperties
    (an invalid dictionary stops there with FatalIOError naming the entry:
    exit status 1), prints its counts and totals, and checks, exiting 1 when
    any check fails:
    - the same canopy built directly through the C API (canopy.h) from the
      same dictionary, read here with plain dictionary lookups, is
      identical: node positions, masses, groups, fixed flags, guides, springs (ends,
      rest lengths, stiffnesses, groups), triangles, integrator, stable
      step, gravity energy and seepage velocity;
    - known totals: total mass = areal density x canopy area + linear
      densities x line and tape rest lengths + payload mass; canopy area of
      a rectangle (w l), a cross (2 S w - w^2) and a flat circle (pi R^2
      less the vent, within 1 %);
    - both models, loaded with the same uniform pressure jump, advance
      -steps steps of -deltaT identically (sub-step counts, positions,
      velocities);
    - every step is written to postProcessing/canopy/canopy.h5 (+ .xdmf);
      a second structure restarted from the file at the final time
      (readState) equals the first, does not write that step again, and
      restarting at a time the file does not hold fails naming the file
      and the time;
    - fixedNodes.skirt pins exactly the nodes on the geometric rim;
    - in parallel, the structure is identical on all ranks.

Usage
    Test-canopyProperties [-case dir] [-steps N] [-deltaT dt] [-dp Pa]
        [-perturbReference] [-parallel]

    -perturbReference makes the reference differ by 1e-9 kg at one node:
    the run must then fail (a check of the checks).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "uniformDimensionedFields.H"
#include "canopyStructure.H"

#include "canopy.h"

#include <cctype>
#include <cmath>
#include <vector>
#include "canopyFoamCompat.H"

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

label nFailed = 0;

void report(const bool ok, const std::string& what, const std::string& detail = "")
{
    if (!ok)
    {
        ++nFailed;
    }
    Info<< (ok ? "    ok    " : "    FAIL  ") << what.c_str();
    if (!detail.empty())
    {
        Info<< "  (" << detail.c_str() << ")";
    }
    Info<< endl;
}

std::string str(const scalar x)
{
    OStringStream os;
    os << x;
    return os.str();
}

// Exact comparison of two arrays; the detail names the first difference
template<class T>
void same
(
    const std::vector<T>& a,
    const std::vector<T>& b,
    const std::string& what
)
{
    if (a.size() != b.size())
    {
        report(false, what, "sizes " + std::to_string(a.size()) + " and "
            + std::to_string(b.size()));
        return;
    }
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        if (!(a[i] == b[i]))
        {
            OStringStream os;
            os  << "first difference at " << label(i) << ": " << a[i]
                << " vs " << b[i];
            report(false, what, os.str());
            return;
        }
    }
    report(true, what, std::to_string(a.size()) + " values identical");
}

canopy_spring_law lawOf(const word& name)
{
    if (name == "modelI") return CANOPY_SPRING_MODEL_I;
    if (name == "tensionOnly") return CANOPY_SPRING_TENSION_ONLY;
    return CANOPY_SPRING_MODEL_II;
}

// A material from a dictionary over libcanopy's defaults; the modulus key is
// tensileStiffness (fabric) or EA (lines, tapes)
canopy_material materialOf
(
    const dictionary& d,
    canopy_material m,
    const word& densityKey,
    const word& modulusKey
)
{
    m.density = d.lookupOrDefault<scalar>(densityKey, m.density);
    if (d.found("stiffness"))
    {
        m.stiffness = canopyCompat::readValue<scalar>(d, "stiffness");
    }
    else if (d.found(modulusKey))
    {
        m.stiffness = 0;
        m.modulus = canopyCompat::readValue<scalar>(d, modulusKey);
    }
    m.damping = d.lookupOrDefault<scalar>("damping", m.damping);
    if (d.found("law"))
    {
        m.law = lawOf(canopyCompat::readValue<word>(d, "law"));
    }
    return m;
}

void ok(canopy_model* m, const canopy_status st, const char* call)
{
    if (st != CANOPY_OK)
    {
        FatalErrorInFunction
            << "reference build: " << call << " failed: "
            << canopy_model_message(m) << exit(FatalError);
    }
}

// Expected totals of the dictionary, for the known-answer checks
struct expected
{
    word type;
    scalar arealDensity = 0;
    scalar lineDensity = 0;
    scalar tapeDensity = 0;
    scalar payloadMass = 0;
    scalar area = -1;           // < 0: no closed form
    scalar areaTolerance = 0;
};

// The canopy of the dictionary, built directly with the C API
canopy_model* buildReference
(
    const dictionary& props,
    const vector& gDefault,
    expected& e
)
{
    canopy_model* m = nullptr;
    canopy_model_create(&m);

    const dictionary& c = props.subDict("canopy");
    const word type = canopyCompat::readValue<word>(c, "type");
    const scalar edge = canopyCompat::readValue<scalar>(c, "edgeLength");
    const vector centre = c.lookupOrDefault<vector>("centre", Zero);
    const dictionary lines = props.subOrEmptyDict("lines");
    const label nLines = lines.lookupOrDefault<label>("number", 0);
    const dictionary fabricDict = props.subOrEmptyDict("fabric");
    const canopy_material fabric = materialOf
    (
        fabricDict, canopy_material_fabric_default(), "arealDensity",
        "tensileStiffness"
    );
    const dictionary tapesDict = props.subOrEmptyDict("radialTapes");
    const bool tapes = tapesDict.lookupOrDefault<bool>("enabled", false);

    e.type = type;
    e.arealDensity = fabric.density;

    std::vector<int> attach;
    if (type == "flatCircular" || type == "parabolic")
    {
        canopy_circular_spec s = canopy_circular_spec_default();
        s.diameter = canopyCompat::readValue<scalar>(c, "diameter");
        s.vent_diameter = c.lookupOrDefault<scalar>("ventDiameter", 0);
        s.height = type == "parabolic" ? canopyCompat::readValue<scalar>(c, "height") : 0;
        const dictionary skirt = c.subOrEmptyDict("extendedSkirt");
        s.skirt_length = skirt.lookupOrDefault<scalar>("length", 0);
        s.skirt_diameter = skirt.lookupOrDefault<scalar>("hemDiameter", 0);
        s.edge_length = edge;
        for (direction d = 0; d < 3; ++d) s.center[d] = centre[d];
        s.n_attachments = c.lookupOrDefault<label>
        (
            "nAttachments", nLines > 0 ? nLines : s.n_attachments
        );
        s.radial_tapes = tapes;
        s.fabric = fabric;
        if (tapes)
        {
            s.tape = materialOf
            (
                tapesDict, canopy_material_line_default(), "linearDensity", "EA"
            );
            e.tapeDensity = s.tape.density;
        }
        attach.resize(s.n_attachments);
        ok(m, canopy_build_circular(m, &s, attach.data()), "canopy_build_circular");
        if (type == "flatCircular")
        {
            // the flat disc and the extended skirt's frustum
            e.area = constant::mathematical::pi/4
                *(sqr(s.diameter) - sqr(s.vent_diameter))
              + constant::mathematical::pi/2
                *(s.diameter + s.skirt_diameter)*s.skirt_length;
            e.areaTolerance = 0.01;
        }
    }
    else if (type == "cross")
    {
        canopy_cross_spec s = canopy_cross_spec_default();
        s.span = canopyCompat::readValue<scalar>(c, "span");
        s.arm_width = canopyCompat::readValue<scalar>(c, "armWidth");
        s.edge_length = edge;
        for (direction d = 0; d < 3; ++d) s.center[d] = centre[d];
        s.n_attachments = c.lookupOrDefault<label>
        (
            "nAttachments", nLines > 0 ? nLines : s.n_attachments
        );
        s.fabric = fabric;
        attach.resize(s.n_attachments);
        ok(m, canopy_build_cross(m, &s, attach.data()), "canopy_build_cross");
        e.area = 2*s.span*s.arm_width - sqr(s.arm_width);
        e.areaTolerance = 1e-9;
    }
    else
    {
        canopy_rectangle_spec s = canopy_rectangle_spec_default();
        s.width = canopyCompat::readValue<scalar>(c, "width");
        s.length = canopyCompat::readValue<scalar>(c, "length");
        s.edge_length = edge;
        s.origin[0] = centre.x() - s.width/2;
        s.origin[1] = centre.y() - s.length/2;
        s.origin[2] = centre.z();
        s.fabric = fabric;
        ok(m, canopy_build_rectangle(m, &s), "canopy_build_rectangle");
        e.area = s.width*s.length;
        e.areaTolerance = 1e-9;
    }

    // fixedNodes.all: every node the canopy's builder made (not the lines)
    if (props.subOrEmptyDict("fixedNodes").lookupOrDefault<bool>("all", false))
    {
        for (int i = 0; i < canopy_model_node_count(m); ++i)
        {
            ok(m, canopy_model_set_fixed(m, i, 1), "canopy_model_set_fixed");
        }
    }
    // Rim: nodes of edges that belong to one triangle only, without a vent's
    else if (props.subOrEmptyDict("fixedNodes").lookupOrDefault<bool>("skirt", false))
    {
        const int nt = canopy_model_triangle_count(m);
        const int n = canopy_model_node_count(m);
        std::vector<int> tri(3*nt);
        std::vector<double> x(3*n);
        canopy_model_get_triangles(m, tri.data(), nt);
        canopy_model_get_positions(m, x.data(), n);
        // count triangles per edge in a per-node adjacency list
        std::vector<std::vector<std::pair<int, int>>> adj(n);
        for (int t = 0; t < nt; ++t)
        {
            for (int k = 0; k < 3; ++k)
            {
                int a = tri[3*t + k], b = tri[3*t + (k + 1)%3];
                if (a > b) std::swap(a, b);
                bool seen = false;
                for (auto& p : adj[a])
                {
                    if (p.first == b) { ++p.second; seen = true; }
                }
                if (!seen) adj[a].push_back({b, 1});
            }
        }
        const bool circ = (type == "flatCircular" || type == "parabolic");
        const scalar rCut = circ
            ? 0.25*(canopyCompat::readValue<scalar>(c, "diameter") + c.lookupOrDefault<scalar>("ventDiameter", 0))
            : 0;
        for (int a = 0; a < n; ++a)
        {
            for (const auto& p : adj[a])
            {
                if (p.second != 1) continue;
                for (const int i : {a, p.first})
                {
                    const scalar r = std::hypot
                    (
                        x[3*i] - centre.x(), x[3*i + 1] - centre.y()
                    );
                    if (!circ || r >= rCut)
                    {
                        canopy_model_set_fixed(m, i, 1);
                    }
                }
            }
        }
    }

    int payloadNode = -1;
    if (nLines > 0)
    {
        canopy_lines_spec ls = canopy_lines_spec_default();
        ls.line_length = canopyCompat::readValue<scalar>(lines, "length");
        ls.edge_length = lines.lookupOrDefault<scalar>("edgeLength", edge);
        ls.line = materialOf
        (
            lines, canopy_material_line_default(), "linearDensity", "EA"
        );
        const dictionary& payload = props.subDict("payload");
        ls.payload_mass = canopyCompat::readValue<scalar>(payload, "mass");
        e.lineDensity = ls.line.density;
        e.payloadMass = ls.payload_mass;
        int pn = -1;
        ok
        (
            m,
            canopy_build_suspension_lines
            (
                m, attach.data(), int(attach.size()), &ls, &pn
            ),
            "canopy_build_suspension_lines"
        );
        if (payload.lookupOrDefault<bool>("fixed", false))
        {
            canopy_model_set_fixed(m, pn, 1);
        }
        payloadNode = pn;
    }

    const vector g = props.lookupOrDefault<vector>("gravity", gDefault);
    const double ga[3] = {g.x(), g.y(), g.z()};
    ok(m, canopy_model_set_gravity(m, ga), "canopy_model_set_gravity");

    // guideWire: the payload and the cloth node nearest canopy.centre
    // slide along the wire (default direction: gravity's)
    const dictionary guide = props.subOrEmptyDict("guideWire");
    if (props.found("guideWire"))
    {
        const vector dir = guide.lookupOrDefault<vector>("direction", g);
        const double axis[3] = {dir.x(), dir.y(), dir.z()};
        if (guide.lookupOrDefault<bool>("payload", true) && payloadNode >= 0)
        {
            ok(m, canopy_model_set_guide(m, payloadNode, axis),
               "canopy_model_set_guide");
        }
        if (guide.lookupOrDefault<bool>("apex", true))
        {
            const vector c =
                props.subDict("canopy").lookupOrDefault<vector>("centre", Zero);
            const int n = canopy_model_node_count(m);
            List<double> x(3*n);
            List<int> group(n);
            canopy_model_get_positions(m, x.data(), n);
            canopy_model_get_node_groups(m, group.data(), n);
            int apex = -1;
            scalar best = GREAT;
            for (int i = 0; i < n; ++i)
            {
                const scalar d =
                    mag(vector(x[3*i], x[3*i + 1], x[3*i + 2]) - c);
                if (group[i] == CANOPY_GROUP_FABRIC && d < best)
                {
                    best = d;
                    apex = i;
                }
            }
            ok(m, canopy_model_set_guide(m, apex, axis),
               "canopy_model_set_guide");
        }
    }
    const dictionary por = fabricDict.subOrEmptyDict("porosity");
    ok
    (
        m,
        canopy_model_set_porosity
        (
            m, por.lookupOrDefault<scalar>("alpha", 0),
            por.lookupOrDefault<scalar>("beta", 0)
        ),
        "canopy_model_set_porosity"
    );
    ok
    (
        m,
        canopy_model_set_bending_damping
        (
            m, fabricDict.lookupOrDefault<scalar>("bendingDamping", 0)
        ),
        "canopy_model_set_bending_damping"
    );
    ok
    (
        m,
        canopy_model_set_bending_damping_implicit
        (
            m,
            fabricDict.lookupOrDefault<word>("bendingDampingScheme", "explicit")
         == "implicit"
        ),
        "canopy_model_set_bending_damping_implicit"
    );
    ok
    (
        m,
        canopy_model_set_bending_damping_filter
        (
            m,
            fabricDict.lookupOrDefault<word>("bendingDampingFilter", "none")
         == "highPass"
        ),
        "canopy_model_set_bending_damping_filter"
    );
    ok
    (
        m,
        canopy_model_set_fabric_compression
        (
            m, fabricDict.lookupOrDefault<scalar>("compressionRatio", 1)
        ),
        "canopy_model_set_fabric_compression"
    );
    const dictionary integ = props.subOrEmptyDict("integrator");
    ok
    (
        m,
        canopy_model_set_integrator
        (
            m, integ.lookupOrDefault<word>("type", "rk4").c_str()
        ),
        "canopy_model_set_integrator"
    );
    ok
    (
        m,
        canopy_model_set_max_omega_dt
        (
            m, integ.lookupOrDefault<scalar>("maxOmegaDt", 0.1)
        ),
        "canopy_model_set_max_omega_dt"
    );
    ok
    (
        m,
        canopy_model_set_hht_alpha(m, integ.lookupOrDefault<scalar>("hhtAlpha", -0.1)),
        "canopy_model_set_hht_alpha"
    );
    ok
    (
        m,
        canopy_model_set_implicit_controls
        (
            m, integ.lookupOrDefault<scalar>("tolerance", 1e-10),
            integ.lookupOrDefault<label>("maxIterations", 25)
        ),
        "canopy_model_set_implicit_controls"
    );
    ok
    (
        m,
        canopy_model_set_speed_limit
        (
            m, integ.lookupOrDefault<scalar>("speedLimit", 1e4)
        ),
        "canopy_model_set_speed_limit"
    );
    return m;
}


std::vector<double> positionsOf(const canopy_model* m)
{
    const int n = canopy_model_node_count(m);
    std::vector<double> x(3*n);
    canopy_model_get_positions(m, x.data(), n);
    return x;
}

std::vector<double> velocitiesOf(const canopy_model* m)
{
    const int n = canopy_model_node_count(m);
    std::vector<double> v(3*n);
    canopy_model_get_velocities(m, v.data(), n);
    return v;
}


// Compare everything the two models expose
void compareModels(const canopy_model* a, canopy_model* b)
{
    const int n = canopy_model_node_count(a);
    const int ns = canopy_model_spring_count(a);
    const int nt = canopy_model_triangle_count(a);
    report(n == canopy_model_node_count(b), "node count",
        std::to_string(n) + " vs " + std::to_string(canopy_model_node_count(b)));
    report(ns == canopy_model_spring_count(b), "spring count",
        std::to_string(ns) + " vs " + std::to_string(canopy_model_spring_count(b)));
    report(nt == canopy_model_triangle_count(b), "triangle count",
        std::to_string(nt) + " vs " + std::to_string(canopy_model_triangle_count(b)));
    if
    (
        n != canopy_model_node_count(b) || ns != canopy_model_spring_count(b)
     || nt != canopy_model_triangle_count(b)
    )
    {
        return;
    }

    same(positionsOf(a), positionsOf(b), "node positions");

    std::vector<double> da(n), db(n);
    canopy_model_get_masses(a, da.data(), n);
    canopy_model_get_masses(b, db.data(), n);
    same(da, db, "node masses");

    std::vector<int> ia(n), ib(n);
    canopy_model_get_fixed(a, ia.data(), n);
    canopy_model_get_fixed(b, ib.data(), n);
    same(ia, ib, "fixed flags");
    canopy_model_get_node_groups(a, ia.data(), n);
    canopy_model_get_node_groups(b, ib.data(), n);
    same(ia, ib, "node groups");

    std::vector<double> guideA(3*n), guideB(3*n);
    for (int i = 0; i < n; ++i)
    {
        canopy_model_get_guide(a, i, guideA.data() + 3*i);
        canopy_model_get_guide(b, i, guideB.data() + 3*i);
    }
    same(guideA, guideB, "guides (guideWire)");

    std::vector<int> ea(2*ns), eb(2*ns);
    std::vector<double> ra(ns), rb(ns), ka(ns), kb(ns);
    canopy_model_get_springs(a, ea.data(), ra.data(), ka.data(), ns);
    canopy_model_get_springs(b, eb.data(), rb.data(), kb.data(), ns);
    same(ea, eb, "spring ends");
    same(ra, rb, "spring rest lengths");
    same(ka, kb, "spring stiffnesses");
    std::vector<int> ga(ns), gb(ns);
    canopy_model_get_spring_groups(a, ga.data(), ns);
    canopy_model_get_spring_groups(b, gb.data(), ns);
    same(ga, gb, "spring groups");

    std::vector<int> ta(3*nt), tb(3*nt);
    canopy_model_get_triangles(a, ta.data(), nt);
    canopy_model_get_triangles(b, tb.data(), nt);
    same(ta, tb, "triangles");

    const word intA(canopy_model_integrator(a)), intB(canopy_model_integrator(b));
    report(intA == intB, "integrator", intA + " vs " + intB);

    double sa = 0, sb = 0;
    canopy_model_stable_step(const_cast<canopy_model*>(a), &sa);
    canopy_model_stable_step(b, &sb);
    report(sa == sb, "stable sub-step (masses, springs, dashpots, maxOmegaDt)",
        str(sa) + " vs " + str(sb));

    canopy_energies ena, enb;
    canopy_model_energies(a, &ena);
    canopy_model_energies(b, &enb);
    report(ena.gravity == enb.gravity, "gravity energy (gravity vector)",
        str(ena.gravity) + " vs " + str(enb.gravity));

    // Every spring 1 % shorter (the structure shrunk about the origin): the
    // spring energy holds the cloth's stiffness in compression
    {
        std::vector<double> xa(3*n), xb(3*n), shrunk(3*n);
        canopy_model_get_positions(a, xa.data(), n);
        canopy_model_get_positions(b, xb.data(), n);
        for (int i = 0; i < 3*n; ++i) shrunk[i] = 0.99*xa[i];
        canopy_model* am = const_cast<canopy_model*>(a);
        canopy_model_set_positions(am, shrunk.data(), n);
        canopy_model_set_positions(b, shrunk.data(), n);
        canopy_energies ca, cb;
        canopy_model_energies(a, &ca);
        canopy_model_energies(b, &cb);
        canopy_model_set_positions(am, xa.data(), n);
        canopy_model_set_positions(b, xb.data(), n);
        report(ca.spring == cb.spring,
            "spring energy 1 % compressed (fabric.compressionRatio, law)",
            str(ca.spring) + " vs " + str(cb.spring));
    }

    const scalar wa = canopy_model_seepage_velocity(a, 100);
    const scalar wb = canopy_model_seepage_velocity(b, 100);
    report(wa == wb, "seepage velocity at 100 Pa (porosity)",
        str(wa) + " vs " + str(wb));
}


// fixedNodes.skirt: the fixed fabric nodes must be exactly the nodes on the
// geometric rim of the shape (a vent's edge excluded); returns their number
label checkRim(const canopyStructure& structure, const dictionary& props)
{
    const dictionary& c = props.subDict("canopy");
    const word type = canopyCompat::readValue<word>(c, "type");
    const vector o = c.lookupOrDefault<vector>("centre", Zero);
    const pointField x(structure.points());
    std::vector<int> fixed(x.size()), group(x.size());
    canopy_model_get_fixed(structure.model(), fixed.data(), x.size());
    canopy_model_get_node_groups(structure.model(), group.data(), x.size());

    auto near = [](const scalar a, const scalar b)
    {
        return mag(a - b) <= 1e-9*max(1.0, mag(b));
    };

    label nFixed = 0, nWrong = 0;
    forAll(x, i)
    {
        if (group[i] != CANOPY_GROUP_FABRIC) continue;
        const scalar dx = x[i].x() - o.x(), dy = x[i].y() - o.y();
        bool rim = false;
        if (type == "flatCircular" || type == "parabolic")
        {
            rim = near(std::hypot(dx, dy), canopyCompat::readValue<scalar>(c, "diameter")/2);
        }
        else if (type == "rectangle")
        {
            const scalar w = canopyCompat::readValue<scalar>(c, "width")/2;
            const scalar l = canopyCompat::readValue<scalar>(c, "length")/2;
            rim = near(mag(dx), w) || near(mag(dy), l);
        }
        else
        {
            const scalar s = canopyCompat::readValue<scalar>(c, "span")/2;
            const scalar w = canopyCompat::readValue<scalar>(c, "armWidth")/2;
            const scalar ax = mag(dx), ay = mag(dy);
            rim =
                near(ax, s) || near(ay, s)
             || (near(ax, w) && ay >= w) || (near(ay, w) && ax >= w);
        }
        if (fixed[i]) ++nFixed;
        if (bool(fixed[i]) != rim) ++nWrong;
    }
    report
    (
        nWrong == 0 && nFixed > 0,
        "fixedNodes.skirt pins exactly the rim of the " + type,
        std::to_string(nFixed) + " fixed, " + std::to_string(nWrong)
      + " nodes wrongly fixed or free"
    );
    return nFixed;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Build the canopy of constant/canopyProperties and check it against"
        " libcanopy's C API; exit 1 on any mismatch"
    );
    canopyCompat::noFunctionObjects();
    argList::addOption("steps", "N", "Steps to advance (default 3)");
    argList::addOption("deltaT", "dt", "Step [s] (default 1e-3)");
    argList::addOption("dp", "Pa", "Uniform pressure jump (default 40)");
    argList::addBoolOption
    (
        "perturbReference",
        "Add 1e-9 kg to node 0 of the C API reference (checks that the"
        " comparison catches a difference: the run must fail)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    const label nSteps = canopyCompat::argOrDefault<label>(args, "steps", 3);
    const scalar dt = canopyCompat::argOrDefault<scalar>(args, "deltaT", 1e-3);
    const scalar dpValue = canopyCompat::argOrDefault<scalar>(args, "dp", 40);

    // ---- the structure, as a solver builds it ------------------------------

    // Its state after each step, kept for the restart checks
    std::vector<scalar> stepTimes, runTimes;
    std::vector<std::vector<double>> stepX, stepV;
    scalarField dp;

    {
        canopyStructure structure(runTime);
        structure.setTime(runTime.value());

        Info<< nl << "canopyStructure from "
            << structure.dict().name() << nl
            << "    nodes              " << structure.nNodes() << nl
            << "    springs            " << structure.nSprings() << nl
            << "    triangles          " << structure.nTriangles() << nl
            << "    attachment points  " << structure.attachmentNodes().size()
            << nl
            << "    payload node       " << structure.payloadNode() << nl
            << "    integrator         " << structure.integrator() << nl
            << "    total mass         " << structure.totalMass() << " kg" << nl
            << "    canopy area        " << structure.canopyArea() << " m^2"
            << nl
            << "    projected diameter " << structure.projectedDiameter()
            << " m" << nl
            << "    stable sub-step    " << structure.stableStep() << " s"
            << nl;
        if (structure.hasPayload())
        {
            Info<< "    payload position   " << structure.payloadPosition()
                << nl;
        }
        Info<< endl;

        // ---- the same canopy through the C API -----------------------------

        vector gDefault(0, 0, -9.81);
        {
            IOobject gIO
            (
                "g", runTime.constant(), runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            );
            if
            (
                canopyCompat::headerOk<uniformDimensionedVectorField>(gIO)
            )
            {
                gDefault = uniformDimensionedVectorField(gIO).value();
            }
        }
        const IOdictionary props
        (
            IOobject
            (
                canopyStructure::propertiesName, runTime.constant(), runTime,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            )
        );
        expected e;
        canopy_model* ref = buildReference(props, gDefault, e);
        if (canopyCompat::argFound(args, "perturbReference"))
        {
            Info<< "(-perturbReference: node 0 of the reference is 1e-9 kg"
                << " heavier)" << endl;
            canopy_model_add_node_mass(ref, 0, 1e-9);
        }

        Info<< "Same canopy as the C API:" << endl;
        compareModels(structure.model(), ref);

        // ---- known totals ----------------------------------------------------

        Info<< "Known totals:" << endl;
        {
            const label ns = structure.nSprings();
            std::vector<int> groups(ns);
            std::vector<double> rest(ns);
            canopy_model_get_springs
            (
                structure.model(), nullptr, rest.data(), nullptr, ns
            );
            canopy_model_get_spring_groups(structure.model(), groups.data(), ns);
            scalar lineLength = 0, tapeLength = 0;
            for (label k = 0; k < ns; ++k)
            {
                if (groups[k] == CANOPY_GROUP_LINE) lineLength += rest[k];
                if (groups[k] == CANOPY_GROUP_TAPE) tapeLength += rest[k];
            }
            const scalar area = structure.canopyArea();
            const scalar mExpected =
                e.arealDensity*area + e.lineDensity*lineLength
              + e.tapeDensity*tapeLength + e.payloadMass;
            const scalar mTotal = structure.totalMass();
            report
            (
                mag(mTotal - mExpected) <= 1e-12*max(1.0, mExpected),
                "total mass = arealDensity A + linearDensity L + payload",
                str(mTotal) + " vs " + str(mExpected) + " kg"
            );
            if (e.area > 0)
            {
                report
                (
                    mag(area - e.area) <= e.areaTolerance*e.area,
                    "canopy area of the " + e.type + " shape",
                    str(area) + " vs " + str(e.area) + " m^2, tolerance "
                  + str(100*e.areaTolerance) + " %"
                );
            }
            if
            (
                props.subOrEmptyDict("fixedNodes")
                    .lookupOrDefault<bool>("skirt", false)
            )
            {
                checkRim(structure, props);
            }
            report(structure.identicalOnAllRanks(), "identical on all ranks");
        }

        // ---- motion and output -------------------------------------------

        Info<< "Advance " << nSteps << " steps of " << dt << " s under "
            << dpValue << " Pa, writing each:" << endl;
        dp.setSize(structure.nTriangles(), dpValue);
        structure.setPressureJump(dp);
        canopy_model_set_pressure_jump(ref, dp.cdata(), dp.size());
        canopy_model_set_time(ref, runTime.value());

        runTime.setDeltaT(dt);
        bool sameSubSteps = true;
        bool wroteAll = true;
        label subSteps = 0;
        for (label s = 0; s < nSteps; ++s)
        {
            ++runTime;
            int refSub = 0;
            subSteps = structure.advance(dt);
            ok(ref, canopy_model_advance(ref, dt, &refSub), "canopy_model_advance");
            sameSubSteps = sameSubSteps && subSteps == refSub;
            wroteAll = structure.write(runTime) && wroteAll;
            stepTimes.push_back(structure.time());
            runTimes.push_back(runTime.value());
            stepX.push_back(positionsOf(structure.model()));
            stepV.push_back(velocitiesOf(structure.model()));
        }
        report(sameSubSteps, "sub-steps per step", std::to_string(subSteps));
        same(positionsOf(structure.model()), positionsOf(ref), "positions after the steps");
        same(velocitiesOf(structure.model()), velocitiesOf(ref), "velocities after the steps");
        report(structure.identicalOnAllRanks(), "identical on all ranks after the steps");
        report(wroteAll, "every step written");
        canopy_model_destroy(&ref);
    }   // the structure and its output handle are gone: as after a run

    // ---- restart from the output -------------------------------------------

    const fileName h5(canopyStructure::outputPath(runTime) + ".h5");
    Info<< "Output " << h5 << " and restarts:" << endl;
    if (Pstream::master())
    {
        report(isFile(h5), "the HDF5 file exists");
        report
        (
            isFile(canopyStructure::outputPath(runTime) + ".xdmf"),
            "the XDMF sidecar exists"
        );
    }
    const label last = label(stepTimes.size()) - 1;
    if (last >= 0)
    {
        // Restart at the final time (startFrom latestTime)
        canopyStructure restarted(runTime);
        report(restarted.stateAvailable(runTime), "a step at the final time");
        restarted.readState(runTime);
        report(restarted.time() == stepTimes[last], "restarted time",
            str(restarted.time()) + " vs " + str(stepTimes[last]));
        same(positionsOf(restarted.model()), stepX[last], "restarted positions");
        same(velocitiesOf(restarted.model()), stepV[last], "restarted velocities");
        const scalarField rdp(restarted.pressureJump());
        report(rdp == dp, "restarted pressure jumps");
        report(!restarted.write(runTime), "the restart step is not written twice");
        report(restarted.identicalOnAllRanks(), "restart identical on all ranks");
    }
    if (last >= 1)
    {
        // Restart one step earlier, redo the last step: the same state, and
        // the file's later step is replaced (APPEND mode)
        runTime.setTime(runTimes[last - 1], runTime.timeIndex() + 1);
        canopyStructure restarted(runTime);
        restarted.readState(runTime);
        same(positionsOf(restarted.model()), stepX[last - 1],
            "positions restarted one step earlier");
        restarted.advance(dt);
        same(positionsOf(restarted.model()), stepX[last],
            "positions after redoing the last step (exact restart)");
        same(velocitiesOf(restarted.model()), stepV[last],
            "velocities after redoing the last step");
        runTime.setTime(runTimes[last], runTime.timeIndex() + 1);
        report(restarted.write(runTime), "the redone step is appended");
    }
    if (last >= 0)
    {
        canopyStructure again(runTime);
        again.readState(runTime);
        same(positionsOf(again.model()), stepX[last],
            "positions read back from the appended step");

        // A time the file does not hold: FatalError naming file and time
        const scalar tBad = 1234.5;
        runTime.setTime(tBad, runTime.timeIndex() + 1);
        report(!again.stateAvailable(runTime), "no step at t = 1234.5");
        canopyCompat::throwExceptions(FatalError, true);
        bool threw = false;
        std::string text;
        try
        {
            again.readState(runTime);
        }
        catch (const Foam::error& err)
        {
            threw = true;
            text = err.message();
            while (!text.empty() && std::isspace(text.back()))
            {
                text.pop_back();
            }
        }
        canopyCompat::throwExceptions(FatalError, false);
        report
        (
            threw && text.find("canopy.h5") != std::string::npos
         && text.find("1234.5") != std::string::npos,
            "restart at a missing time fails naming the file and the time",
            text
        );

        // The message counts the file's steps: the redone step replaced
        // the old one, it did not add a duplicate
        const std::string count = std::to_string(stepTimes.size()) + " steps";
        report
        (
            text.find(count) != std::string::npos,
            "the file holds " + count + " after the restarts"
        );
    }

    // ---- result --------------------------------------------------------------

    // Not "return 1": Debian's v1912 argList destructor ends the process
    // through UPstream::exit(0), which would replace main's return value.
    // FatalError exits with status 1 (serial) or aborts MPI (parallel).
    reduce(nFailed, sumOp<label>());
    if (nFailed)
    {
        FatalErrorInFunction
            << "Test-canopyProperties: FAILED " << nFailed << " check(s)"
            << nl << exit(FatalError);
    }

    Info<< nl << "Test-canopyProperties: PASSED" << nl << endl;

    return 0;
}


// ************************************************************************* //
