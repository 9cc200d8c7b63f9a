// Test-canopyInitialState.C: reads a case's folded initial state (canopyProperties initialState, written by canopyFold) through canopyStructure and checks it against the file, the flat canopy and the geometry of the fold; exits non-zero on any failure.
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
    Test-canopyInitialState

Description
    Builds the structure of constant/canopyProperties twice: flat
    (canopyStructure(runTime, false)) and as a solver does, with the entry
    initialState applied (a bad or incompatible initialState stops there
    with FatalIOError naming the entry: exit status 1). The master reads
    the file's first and last steps with libcanopy's reader
    (canopy_reader_read_state, the call a restart makes, not the
    canopy_reader_read_motion the structure's initial state is read
    with) into two more structures built flat. Exits 1 unless:

    The file and the restore
    - the file holds the model's structure: node, spring and triangle
      counts, triangles, spring ends and rest lengths (the reader's
      checks: the fold changed no connectivity and no rest length);
    - its first step is the flat canopy, bit for bit;
    - the structure's positions are the file's last step bit for bit, its
      velocities are the file's, and all zero;
    - rest lengths, stiffnesses and masses are the flat structure's bit for
      bit (the folded canopy keeps the flat rest lengths), and the time is
      the run's start time.

    The fold (system/canopyFoldDict, read here with plain lookups)
    - every canopy node inside the region of seed 000 eq. 5.3 at t = 0
      (not fixed, innerRadius <= r < radius) moved by v0 T to 1e-9 m, and
      there is at least one;
    - a held payload has not moved;
    - springs: largest stretch (l - l0)/l0 of any spring <= -maxStretch,
      largest compression of a canopy spring <= -maxCompression;
    - the projected diameter D about the fold axis (the line from the
      displaced region centre A = c + v0 T to the held payload P, else the
      region axis through A) is at most the bound the velocity field
      prescribes for an inextensible structure, relaxed by the measured
      largest stretch eps:
          every node i lies within rho_A(i) = max_d |x0_d - c|
          + (1 + eps) g_D(i) of A (g_D: shortest rest-length path through
          the springs to a driven node d, which moved by v0 T) and within
          rho_P(i) = (1 + eps) g_P(i) of P (path to the payload); its
          distance from the line AP is at most that of the lens the two
          balls make, and D <= 2 max_i of it.
      This needs only the triangle inequality: a fold that drove the wrong
      nodes, or drove them too little, breaks it.

    In parallel the checks run on the master and the structure must be
    identical on all ranks.

Usage
    Test-canopyInitialState [-case dir] [-maxStretch 0.01]
        [-maxCompression 0.01] [-parallel]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "canopyStructure.H"

#include "canopy.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <queue>
#include <string>
#include <utility>
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


// ---- reading the file (libcanopy's reader) ----------------------------------

// A canopy_reader, destroyed with the object
class reader
{
    canopy_reader* r_;

public:

    reader()
    :
        r_(nullptr)
    {
        canopy_reader_create(&r_);
    }

    ~reader()
    {
        canopy_reader_destroy(&r_);
    }

    reader(const reader&) = delete;
    void operator=(const reader&) = delete;

    canopy_reader* get() const { return r_; }

    std::string message() const
    {
        return r_ ? canopy_reader_message(r_) : "out of memory";
    }
};


// The group name NNNNNN of step number `number`
std::string stepName(const int number)
{
    char name[32];
    std::snprintf(name, sizeof name, "%06d", number);
    return name;
}


// A structure's positions or velocities as 3 n doubles
std::vector<double> flatten(const vectorField& v)
{
    std::vector<double> d(3*v.size());
    forAll(v, i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            d[3*i + c] = v[i][c];
        }
    }
    return d;
}


// Shortest rest-length paths through the springs from a set of sources
std::vector<double> pathLengths
(
    const label n,
    const std::vector<int>& ends,
    const std::vector<double>& rest,
    const std::vector<label>& sources
)
{
    std::vector<std::vector<std::pair<label, double>>> adj(n);
    for (std::size_t k = 0; k < rest.size(); ++k)
    {
        adj[ends[2*k]].push_back({ends[2*k + 1], rest[k]});
        adj[ends[2*k + 1]].push_back({ends[2*k], rest[k]});
    }
    std::vector<double> g(n, GREAT);
    typedef std::pair<double, label> item;
    std::priority_queue<item, std::vector<item>, std::greater<item>> queue;
    for (const label s : sources)
    {
        g[s] = 0;
        queue.push({0.0, s});
    }
    while (!queue.empty())
    {
        const item top = queue.top();
        queue.pop();
        if (top.first > g[top.second]) continue;
        for (const auto& e : adj[top.second])
        {
            const double d = top.first + e.second;
            if (d < g[e.first])
            {
                g[e.first] = d;
                queue.push({d, e.first});
            }
        }
    }
    return g;
}


// Largest distance from the axis (through o along the unit vector e) of a
// point in the intersection of the balls (c1, r1) and (c2, r2); -1 when
// they do not intersect. The distance is a convex function, so its
// largest value on the lens is at the farthest point of one ball (when
// that lies in the other ball) or on the circle where the spheres meet,
// which is sampled finely (the margin covers the sampling).
scalar lensMaxRadius
(
    const point& c1, const scalar r1,
    const point& c2, const scalar r2,
    const point& o, const vector& e
)
{
    auto radial = [&](const point& q)
    {
        const vector d = q - o;
        return d - (d & e)*e;
    };
    const scalar d12 = mag(c2 - c1);
    if (d12 > r1 + r2) return -1;

    scalar best = -1;

    // The farthest point of each ball from the axis (towards the other
    // centre's side when the centre lies on the axis)
    const point centres[2] = {c1, c2};
    const scalar radii[2] = {r1, r2};
    for (int b = 0; b < 2; ++b)
    {
        const point& c = centres[b];
        const point& other = centres[1 - b];
        vector dir = radial(c);
        if (mag(dir) < SMALL*max(r1, r2)) dir = radial(other);
        if (mag(dir) < SMALL*max(r1, r2))
        {
            // Both centres on the axis: any radial direction
            dir = (mag(e ^ vector(1, 0, 0)) > 0.5 ? vector(1, 0, 0) : vector(0, 1, 0));
            dir -= (dir & e)*e;
        }
        dir /= mag(dir);
        const point far = c + radii[b]*dir;
        if (mag(far - other) <= radii[1 - b])
        {
            best = max(best, mag(radial(far)));
        }
    }

    // The circle where the spheres meet
    if (d12 > 0 && d12 >= mag(r1 - r2))
    {
        const vector n = (c2 - c1)/d12;
        const scalar l = (r1*r1 - r2*r2 + d12*d12)/(2*d12);
        const scalar rho = std::sqrt(max(r1*r1 - l*l, scalar(0)));
        const point m = c1 + l*n;
        vector u = (mag(n ^ e) > 1e-6 ? (n ^ e) : (n ^ vector(1, 0, 0)));
        if (mag(u) < 1e-6) u = n ^ vector(0, 1, 0);
        u /= mag(u);
        const vector w = n ^ u;
        const label nSample = 3600;
        for (label k = 0; k < nSample; ++k)
        {
            const scalar phi = constant::mathematical::twoPi*k/nSample;
            const point q = m + rho*(std::cos(phi)*u + std::sin(phi)*w);
            best = max(best, mag(radial(q)));
        }
        // Between samples the distance can exceed the sampled value by at
        // most rho (1 - cos(pi/nSample)) + ...; a margin of rho 1e-5 covers it
        best += 1e-5*rho;
    }
    return best;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Read the folded initial state of constant/canopyProperties"
        " (initialState, from canopyFold) and check it; exit 1 on failure"
    );
    canopyCompat::noFunctionObjects();
    argList::addOption
    (
        "maxStretch", "eps", "Largest spring stretch allowed (default 0.01)"
    );
    argList::addOption
    (
        "maxCompression", "eps",
        "Largest canopy spring compression allowed (default 0.01)"
    );
    argList::addOption
    (
        "minMouthReduction", "fraction",
        "The mouth bound must be below (1 - fraction) x the flat mouth"
        " diameter (default 0)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    const scalar maxStretch = canopyCompat::argOrDefault<scalar>(args, "maxStretch", 0.01);
    const scalar maxCompression =
        canopyCompat::argOrDefault<scalar>(args, "maxCompression", 0.01);
    const scalar minReduction =
        canopyCompat::argOrDefault<scalar>(args, "minMouthReduction", 0);

    canopyStructure flat(runTime, false);
    canopyStructure folded(runTime);

    // The file's first and last steps are read into these (master only)
    canopyStructure firstStep(runTime, false);
    canopyStructure lastStep(runTime, false);

    const fileName h5(folded.initialStateFile(runTime));
    if (h5.empty())
    {
        FatalErrorInFunction
            << "constant/canopyProperties has no entry initialState"
            << exit(FatalError);
    }

    const label n = folded.nNodes();
    const label ns = folded.nSprings();
    const label nt = folded.nTriangles();
    canopy_model* mf = folded.model();
    canopy_model* m0 = flat.model();

    Info<< nl << "Initial state " << h5 << nl
        << "    nodes " << n << ", springs " << ns << ", triangles " << nt
        << nl << endl;

    // The fold's controls (read on every rank: reading is collective)
    const IOdictionary foldDict
    (
        IOobject
        (
            "canopyFoldDict", runTime.system(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );

    // ---- parallel: every rank holds the same state -------------------------

    if (Pstream::parRun())
    {
        report(folded.identicalOnAllRanks(), "identical on all ranks");
    }

    if (Pstream::master())
    {
        // ---- the file, read independently ------------------------------------

        Info<< "The file and the restore:" << endl;

        const reader file;
        int count = 0, firstNumber = -1, lastNumber = -1;
        bool read =
            file.get()
         && canopy_reader_open(file.get(), h5.lessExt().c_str()) == CANOPY_OK
         && (count = canopy_reader_step_count(file.get())) >= 2
         && canopy_reader_step(file.get(), 0, &firstNumber, nullptr)
         == CANOPY_OK
         && canopy_reader_step(file.get(), count - 1, &lastNumber, nullptr)
         == CANOPY_OK;
        report
        (
            read, "the file holds at least two steps",
            read ? std::to_string(count) + " steps" : file.message()
        );
        if (!read)
        {
            FatalErrorInFunction
                << "Test-canopyInitialState: cannot read " << h5 << ": "
                << file.message().c_str() << exit(FatalError);
        }

        // canopy_reader_read_state fails with the first difference unless
        // the file holds this structure
        std::string why;
        read =
            canopy_reader_read_state(file.get(), 0, firstStep.model())
         == CANOPY_OK;
        if (read)
        {
            read =
                canopy_reader_read_state
                (
                    file.get(), count - 1, lastStep.model()
                )
             == CANOPY_OK;
        }
        if (!read)
        {
            why = file.message();
        }
        report
        (
            read,
            "the file holds this structure (node, spring and triangle counts,"
            " triangles, spring ends, rest lengths)",
            read
          ? std::to_string(n) + ", " + std::to_string(ns) + ", "
          + std::to_string(nt)
          : why
        );
        if (!read)
        {
            FatalErrorInFunction
                << "Test-canopyInitialState: cannot read " << h5 << ": "
                << why.c_str() << exit(FatalError);
        }

        std::vector<int> ends(2*ns);
        canopy_model_get_springs(m0, ends.data(), nullptr, nullptr, ns);

        const pointField x0(flat.points());
        const pointField x(folded.points());
        const vectorField v(folded.velocities());

        report
        (
            flatten(firstStep.points()) == flatten(x0),
            "step " + stepName(firstNumber) + " is the flat canopy, bit for bit"
        );
        report
        (
            flatten(lastStep.points()) == flatten(x),
            "positions = step " + stepName(lastNumber)
          + " of the file, bit for bit"
        );
        report
        (
            flatten(lastStep.velocities()) == flatten(v),
            "velocities = the file's, bit for bit"
        );
        report(max(mag(v)) == 0, "velocities all zero");

        std::vector<double> r0(ns), k0(ns), r1(ns), k1(ns);
        canopy_model_get_springs(m0, nullptr, r0.data(), k0.data(), ns);
        canopy_model_get_springs(mf, nullptr, r1.data(), k1.data(), ns);
        report(r0 == r1, "rest lengths of the flat canopy, bit for bit");
        report(k0 == k1, "stiffnesses unchanged");
        const scalarField m0Mass(flat.masses()), m1Mass(folded.masses());
        report(m0Mass == m1Mass, "masses unchanged");
        report
        (
            folded.time() == runTime.value(),
            "time = the run's start time",
            "t = " + str(folded.time())
        );

        // ---- the fold ------------------------------------------------------

        Info<< nl << "The fold (system/canopyFoldDict):" << endl;

        const dictionary& region = foldDict.subDict("region");
        const vector v0(canopyCompat::readValue<vector>(foldDict, "velocity"));
        const scalar T = canopyCompat::readValue<scalar>(foldDict, "duration");
        const scalar a = canopyCompat::readValue<scalar>(region, "radius");
        const scalar aIn = region.lookupOrDefault<scalar>("innerRadius", 0);
        point c = flat.dict().subOrEmptyDict("canopy")
            .lookupOrDefault<point>("centre", Zero);
        region.readIfPresent("centre", c);
        vector e = region.lookupOrDefault<vector>("axis", vector(0, 0, 1));
        e /= mag(e);
        const bool hold = foldDict.lookupOrDefault<bool>("holdPayload", true);

        // The driven nodes: canopy nodes, not fixed, inside at t = 0
        std::vector<int> groups(n), fixed(n);
        canopy_model_get_node_groups(m0, groups.data(), n);
        canopy_model_get_fixed(m0, fixed.data(), n);
        std::vector<label> driven, canopyNodes;
        scalar rDriven = 0;
        for (label i = 0; i < n; ++i)
        {
            if (groups[i] != CANOPY_GROUP_FABRIC && groups[i] != CANOPY_GROUP_TAPE)
            {
                continue;
            }
            canopyNodes.push_back(i);
            const vector d = x0[i] - c;
            const scalar r = mag(d - (d & e)*e);
            if (!fixed[i] && r < a && r >= aIn)
            {
                driven.push_back(i);
                rDriven = max(rDriven, mag(d));
            }
        }
        scalar shift = 0;
        for (const label i : driven)
        {
            shift = max(shift, mag(x[i] - x0[i] - v0*T));
        }
        report
        (
            !driven.empty() && shift <= 1e-9,
            "the " + std::to_string(driven.size()) + " canopy nodes inside "
            "the region at t = 0 moved by v0 T",
            "|v0 T| = " + str(mag(v0*T)) + " m, largest error "
          + str(shift) + " m, limit 1e-9 m"
        );

        const label p = folded.payloadNode();
        const bool anchor = hold && p >= 0;
        if (anchor)
        {
            report(x[p] == x0[p], "the held payload has not moved");
        }

        // Strains
        std::vector<int> sGroups(ns);
        canopy_model_get_spring_groups(m0, sGroups.data(), ns);
        scalar stretch = 0, compression = 0;
        for (label k = 0; k < ns; ++k)
        {
            const scalar s = mag(x[ends[2*k]] - x[ends[2*k + 1]])/r0[k] - 1;
            stretch = max(stretch, s);
            if (sGroups[k] == CANOPY_GROUP_FABRIC || sGroups[k] == CANOPY_GROUP_TAPE)
            {
                compression = max(compression, -s);
            }
        }
        report
        (
            stretch <= maxStretch,
            "largest spring stretch (l - l0)/l0 <= " + str(maxStretch),
            str(100*stretch) + " %"
        );
        report
        (
            compression <= maxCompression,
            "largest canopy spring compression <= " + str(maxCompression),
            str(100*compression) + " %"
        );
        const canopyStructure::energy en(folded.energies());
        Info<< "    (spring energy of the folded state " << en.spring
            << " J)" << endl;

        // Projected diameters about the fold axis (the region axis moved by
        // v0 T) and the bound the field prescribes: node i lies within
        // (1 + eps) g(i, d) of every driven node d, which moved by v0 T,
        // and within (1 + eps) g(i, P) of the held payload P
        const point A = c + v0*T;
        auto axisDistance = [&](const point& q)
        {
            const vector d = q - A;
            return mag(d - (d & e)*e);
        };
        std::vector<std::vector<double>> gD;
        for (const label d : driven)
        {
            gD.push_back(pathLengths(n, ends, r0, {d}));
        }
        const std::vector<double> gP =
            anchor ? pathLengths(n, ends, r0, {p}) : std::vector<double>();
        auto bound = [&](const label i)
        {
            scalar b = GREAT;
            for (std::size_t k = 0; k < driven.size(); ++k)
            {
                const point xd = x0[driven[k]] + v0*T;
                const scalar rd = (1 + stretch)*gD[k][i];
                if (anchor && gP[i] < GREAT)
                {
                    const scalar r = lensMaxRadius
                    (
                        xd, rd, x0[p], (1 + stretch)*gP[i], A, e
                    );
                    if (r >= 0) b = min(b, r);
                }
                else
                {
                    b = min(b, axisDistance(xd) + rd);
                }
            }
            return b;
        };

        scalar r0Max = 0, rMax = 0;
        for (const label i : canopyNodes)
        {
            r0Max = max(r0Max, axisDistance(x0[i] + v0*T));
            rMax = max(rMax, axisDistance(x[i]));
        }

        // The mouth: the circle of the lines' attachment points
        scalar rMouth0 = 0, rMouth = 0, rMouthBound = 0;
        for (const label i : flat.attachmentNodes())
        {
            rMouth0 = max(rMouth0, axisDistance(x0[i] + v0*T));
            rMouth = max(rMouth, axisDistance(x[i]));
            rMouthBound = max(rMouthBound, bound(i));
        }
        const scalar D0 = 2*r0Max, D = 2*rMax;
        const scalar M0 = 2*rMouth0, M = 2*rMouth, Mbound = 2*rMouthBound;
        const scalar Dlib0 = flat.projectedDiameter();
        const scalar Dlib = folded.projectedDiameter();

        Info<< "    lift v0 T                        " << mag(v0*T) << " m"
            << nl
            << "    projected diameter (fold axis)   " << D0 << " -> " << D
            << " m (" << 100*D/D0 << " %)" << nl
            << "    projected diameter (libcanopy)   " << Dlib0 << " -> "
            << Dlib << " m (" << 100*Dlib/Dlib0 << " %)" << nl
            << "    mouth diameter (attachments)     " << M0 << " -> " << M
            << " m (" << 100*M/M0 << " %)" << nl
            << "    mouth bound for the lift         " << Mbound << " m ("
            << 100*Mbound/M0 << " %; slack: largest stretch "
            << 100*stretch << " %)" << endl;

        if (flat.attachmentNodes().size() && anchor)
        {
            report
            (
                M <= Mbound,
                "mouth diameter <= the bound the lift v0 T prescribes",
                str(M) + " <= " + str(Mbound) + " m"
            );
            report
            (
                Mbound <= (1 - minReduction)*M0,
                "the bound closes the mouth by >= " + str(100*minReduction)
              + " % (the check has teeth)",
                str(100*(1 - Mbound/M0)) + " %"
            );
        }
        report
        (
            Dlib < Dlib0 && D < D0,
            "the projected diameter decreased",
            str(Dlib) + " < " + str(Dlib0) + " m"
        );
        report
        (
            D >= 2*rDriven*(1 - 1e-12),
            "the driven nodes keep their distance from the axis"
            " (D >= 2 x the largest)",
            str(D) + " >= " + str(2*rDriven) + " m"
        );
    }

    // ---- result --------------------------------------------------------------

    // Not "return 1": FatalError gives a non-zero exit status (v1912's
    // argList destructor would replace main's return value by 0).
    reduce(nFailed, sumOp<label>());
    if (nFailed)
    {
        FatalErrorInFunction
            << "Test-canopyInitialState: FAILED " << nFailed << " check(s)"
            << nl << exit(FatalError);
    }

    Info<< nl << "Test-canopyInitialState: PASSED" << nl << endl;

    return 0;
}


// ************************************************************************* //
