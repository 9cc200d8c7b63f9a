// canopyStructureBuild.C: canopyStructure::build, reading and validating canopyProperties and building the model with libcanopy's builders.
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

Description
    Every entry is read and checked before anything is built, except the
    line length, which is checked against the skirt radius of the canopy
    once it exists. All errors in the dictionary are FatalIOError on the
    (sub-)dictionary holding the entry and name it by its scoped name.

\*---------------------------------------------------------------------------*/

#include "canopyStructure.H"
#include "OStringStream.H"
#include "scopedEntryReader.H"
#include "prescribedRotation.H"

#include "canopy.h"

#include <cmath>
#include <map>
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Spring laws by dictionary name
const wordList lawNames{"modelII", "modelI", "tensionOnly"};

canopy_spring_law lawFromName(const word& name)
{
    if (name == "modelI") return CANOPY_SPRING_MODEL_I;
    if (name == "tensionOnly") return CANOPY_SPRING_TENSION_ONLY;
    return CANOPY_SPRING_MODEL_II;
}

word lawName(const canopy_spring_law law)
{
    switch (law)
    {
        case CANOPY_SPRING_MODEL_I: return "modelI";
        case CANOPY_SPRING_TENSION_ONLY: return "tensionOnly";
        default: return "modelII";
    }
}


// The entries of a material, names by family
struct materialKeys
{
    word density;       // arealDensity | linearDensity
    word modulus;       // tensileStiffness | EA
    std::string densityWhat;
    std::string modulusWhat;
};

const materialKeys sheetKeys
{
    "arealDensity", "tensileStiffness",
    "cloth mass per area [kg/m^2]",
    "2-D modulus E t [N/m]"
};

const materialKeys lineKeys
{
    "linearDensity", "EA",
    "mass per length [kg/m]",
    "axial stiffness E A [N]"
};

// Read a material over the given defaults
void readMaterial
(
    const scopedEntryReader& r,
    const materialKeys& keys,
    canopy_material& mat
)
{
    mat.density = r.nonNegative(keys.density, keys.densityWhat, mat.density);

    if (r.found("stiffness") && r.found(keys.modulus))
    {
        r.fail
        (
            keys.modulus,
            "and '" + r.name("stiffness") + "' are both given: give one of "
            "them"
        );
    }
    if (r.found("stiffness"))
    {
        mat.stiffness = r.positive("stiffness", "spring constant k [N/m]");
    }
    else if (r.found(keys.modulus))
    {
        mat.stiffness = 0;      // derived from the modulus by the builder
        mat.modulus = r.positive(keys.modulus, keys.modulusWhat);
    }

    mat.damping = r.nonNegative
    (
        "damping", "dashpot coefficient [N s/m]", mat.damping
    );
    mat.law = lawFromName
    (
        r.choice("law", lawNames, "spring law", lawName(mat.law))
    );
}


// Everything canopyProperties says, read and checked: libcanopy's build
// specifications complete, and the settings applied to the model after
struct structureSpec
{
    // canopy
    word type;
    bool circular = false;
    canopy_circular_spec circ = canopy_circular_spec_default();
    canopy_cross_spec cross = canopy_cross_spec_default();
    canopy_rectangle_spec rect = canopy_rectangle_spec_default();
    scalar edge = 0;
    vector centre = Zero;
    label nAttach = 0;

    // fabric
    canopy_material fabric = canopy_material_fabric_default();
    scalar alpha = 0;
    scalar beta = 0;
    scalar bendingDamping = 0;
    scalar bendingDampingUntil = VGREAT;
    word bendingDampingScheme = "explicit";
    word bendingDampingFilter = "none";
    scalar compressionRatio = 1;

    // radial tapes
    bool tapes = false;

    // lines and payload
    const dictionary* linesDict = nullptr;
    label nLines = 0;
    canopy_lines_spec lines = canopy_lines_spec_default();
    bool payloadFixed = false;

    // guide wire
    bool guidePayload = false;
    bool guideApex = false;
    vector guideDirection = Zero;

    // model
    vector g = Zero;
    vector initialVelocity = Zero;
    word integratorName = "rk4";
    scalar maxOmegaDt = 0.1;
    scalar hhtAlpha = -0.1;
    scalar newtonTol = 1e-10;
    label newtonIter = 25;
    scalar speedLimit = 1e4;
    bool fixSkirt = false;
    bool fixAll = false;
    const dictionary* motionDict = nullptr;
};


// The entries a material reads (radial tapes, lines)
const wordList lineMaterialEntries
{
    "linearDensity", "stiffness", "EA", "damping", "law"
};


// canopy: type, size and shape; returns the entries read
wordList readCanopyShape(const scopedEntryReader& cr, structureSpec& s)
{
    const wordList types{"flatCircular", "parabolic", "cross", "rectangle"};
    s.type = cr.choice("type", types, "canopy type");
    s.circular = (s.type == "flatCircular" || s.type == "parabolic");

    s.edge = cr.positive("edgeLength", "target triangle edge length [m]");
    s.centre = cr.vectorValue("centre", "canopy centre [m]", Zero);

    wordList used{"type", "edgeLength", "centre"};
    if (s.circular)
    {
        canopy_circular_spec& circ = s.circ;
        circ.diameter = cr.positive("diameter", "skirt diameter [m]");
        circ.vent_diameter = cr.nonNegative("ventDiameter", "vent diameter [m]", 0);
        if (!(circ.vent_diameter < circ.diameter))
        {
            cr.fail
            (
                "ventDiameter",
                "= " + scopedEntryReader::format(circ.vent_diameter)
              + " must be smaller than " + cr.name("diameter") + " = "
              + scopedEntryReader::format(circ.diameter)
            );
        }
        used.append
        (
            wordList
            {
                "diameter", "ventDiameter", "height", "extendedSkirt",
                "nominalDiameter"
            }
        );
        // The nominal diameter (of the nominal area, the cloth's with its
        // vent) is the output's reference length: the diameter unless an
        // extended skirt makes the hem narrower than the rim
        if (cr.found("nominalDiameter") || cr.found("extendedSkirt"))
        {
            cr.positive("nominalDiameter", "nominal diameter [m]");
        }
        if (const dictionary* sd = cr.optionalDict("extendedSkirt"))
        {
            // A band from the rim down and inwards to a narrower hem
            const scopedEntryReader sr(*sd, cr.name("extendedSkirt"));
            circ.skirt_length = sr.positive("length", "slant length [m]");
            circ.skirt_diameter =
                sr.positive("hemDiameter", "hem diameter [m]");
            if (!(circ.skirt_diameter < circ.diameter))
            {
                sr.fail
                (
                    "hemDiameter",
                    "= " + scopedEntryReader::format(circ.skirt_diameter)
                  + " must be smaller than " + cr.name("diameter") + " = "
                  + scopedEntryReader::format(circ.diameter)
                  + " (the hem is narrower than the rim)"
                );
            }
            if (!(0.5*(circ.diameter - circ.skirt_diameter) < circ.skirt_length))
            {
                sr.fail
                (
                    "length",
                    "= " + scopedEntryReader::format(circ.skirt_length)
                  + " must exceed the radial step from the rim to the hem, ("
                  + cr.name("diameter") + " - " + sr.name("hemDiameter")
                  + ")/2 = "
                  + scopedEntryReader::format
                    (
                        0.5*(circ.diameter - circ.skirt_diameter)
                    )
                );
            }
            sr.warnUnused(wordList{"length", "hemDiameter"});
        }
        if (s.type == "parabolic")
        {
            circ.height = cr.positive("height", "apex height above the rim [m]");
        }
        else
        {
            // A flat canopy: a height other than 0 is a mistake
            circ.height = cr.nonNegative("height", "apex height [m]", 0);
            if (circ.height != 0)
            {
                cr.fail
                (
                    "height",
                    "= " + scopedEntryReader::format(circ.height)
                  + ", but a flatCircular canopy is flat (use canopy type"
                    " parabolic for a height)"
                );
            }
        }
    }
    else if (s.type == "cross")
    {
        s.cross.span = cr.positive("span", "tip-to-tip arm length [m]");
        s.cross.arm_width = cr.positive("armWidth", "arm width [m]");
        if (!(s.cross.arm_width < s.cross.span))
        {
            cr.fail
            (
                "armWidth",
                "= " + scopedEntryReader::format(s.cross.arm_width)
              + " must be smaller than " + cr.name("span") + " = "
              + scopedEntryReader::format(s.cross.span)
            );
        }
        used.append(wordList{"span", "armWidth"});
    }
    else
    {
        s.rect.width = cr.positive("width", "extent along x [m]");
        s.rect.length = cr.positive("length", "extent along y [m]");
        used.append(wordList{"width", "length"});
    }
    return used;
}


// lines.number (read before the attachments: nAttachments defaults to it)
void readLineCount(const scopedEntryReader& top, structureSpec& s)
{
    s.linesDict = top.optionalDict("lines");
    if (!s.linesDict)
    {
        return;
    }
    const scopedEntryReader lr(*s.linesDict, "lines");
    s.nLines = lr.integer("number", "the number of suspension lines");
    if (s.nLines < 0 || (s.nLines > 0 && s.nLines < 3))
    {
        lr.fail
        (
            "number",
            "= " + std::to_string(s.nLines) + " must be 0 (no lines) or >= 3"
        );
    }
}


// canopy.nAttachments, checked against the canopy type and lines.number;
// then the canopy's unused entries (used: those read so far)
void readAttachments
(
    const scopedEntryReader& cr,
    structureSpec& s,
    wordList used
)
{
    const scopedEntryReader lr
    (
        s.linesDict ? *s.linesDict : dictionary::null, "lines"
    );
    if (s.type == "rectangle")
    {
        if (s.nLines > 0)
        {
            lr.fail
            (
                "number",
                "= " + std::to_string(s.nLines) + ": a rectangle canopy has "
                "no attachment points for lines; use lines { number 0; } or "
                "remove lines"
            );
        }
        cr.warnUnused(used, " by canopy type " + s.type);
        return;
    }
    used.append("nAttachments");

    // The entry that sets the attachment count, for the messages
    const scopedEntryReader* src = &cr;
    word srcKey = "nAttachments";
    std::string note;
    if (cr.found("nAttachments"))
    {
        s.nAttach = cr.integer("nAttachments", "the number of attachment points");
    }
    else if (s.nLines > 0)
    {
        s.nAttach = s.nLines;
        src = &lr;
        srcKey = "number";
        note = " (canopy.nAttachments defaults to lines.number)";
    }
    else
    {
        s.nAttach = s.circular ? s.circ.n_attachments : s.cross.n_attachments;
    }

    if (s.circular && s.nAttach < 3)
    {
        src->fail
        (
            srcKey,
            "= " + std::to_string(s.nAttach) + " must be >= 3" + note
        );
    }
    if (s.type == "cross" && (s.nAttach < 4 || s.nAttach % 4 != 0))
    {
        src->fail
        (
            srcKey,
            "= " + std::to_string(s.nAttach) + " must be a positive "
            "multiple of 4 for a cross canopy (the attachment points are "
            "spread evenly over the four arm tips)" + note
        );
    }
    if (s.nLines > 0 && s.nAttach != s.nLines)
    {
        cr.fail
        (
            "nAttachments",
            "= " + std::to_string(s.nAttach) + " must equal "
          + lr.name("number") + " = " + std::to_string(s.nLines)
          + " (one line per attachment point)"
        );
    }
    cr.warnUnused(used, " by canopy type " + s.type);
}


// fabric: material, hinge dashpots, compression, porosity
void readFabric(const scopedEntryReader& top, structureSpec& s)
{
    const dictionary* d = top.optionalDict("fabric");
    if (!d)
    {
        return;
    }
    const scopedEntryReader fr(*d, "fabric");
    readMaterial(fr, sheetKeys, s.fabric);
    s.bendingDamping = fr.nonNegative
    (
        "bendingDamping", "decay rate of each hinge's bending [1/s]", 0
    );
    if (fr.found("bendingDampingUntil"))
    {
        s.bendingDampingUntil = fr.nonNegative
        (
            "bendingDampingUntil",
            "time from which the hinge dashpots are off [s]", 0
        );
        if (s.bendingDamping == 0)
        {
            fr.fail
            (
                "bendingDampingUntil",
                "needs hinge dashpots to switch off (bendingDamping > 0)"
            );
        }
    }
    s.bendingDampingScheme = fr.choice
    (
        "bendingDampingScheme", wordList{"explicit", "implicit"},
        "hinge dashpot scheme", s.bendingDampingScheme
    );
    s.bendingDampingFilter = fr.choice
    (
        "bendingDampingFilter", wordList{"none", "highPass"},
        "hinge dashpot filter", s.bendingDampingFilter
    );
    if (s.bendingDampingFilter == "highPass" && s.bendingDampingScheme != "implicit")
    {
        fr.fail
        (
            "bendingDampingFilter",
            "highPass needs bendingDampingScheme implicit"
        );
    }
    s.compressionRatio = fr.inRange
    (
        "compressionRatio",
        "the springs' stiffness in compression over their stiffness",
        0, 1, s.compressionRatio
    );
    if (fr.found("compressionRatio") && s.fabric.law != CANOPY_SPRING_MODEL_II)
    {
        fr.fail
        (
            "compressionRatio",
            "needs law modelII (the law is " + lawName(s.fabric.law) + ")"
        );
    }
    if (const dictionary* pd = fr.optionalDict("porosity"))
    {
        const scopedEntryReader pr(*pd, "fabric.porosity");
        s.alpha = pr.nonNegative("alpha", "Darcy coefficient [Pa s/m]", 0);
        s.beta = pr.nonNegative("beta", "Forchheimer coefficient [Pa s^2/m^2]", 0);
        pr.warnUnused(wordList{"alpha", "beta"});
    }
    fr.warnUnused
    (
        wordList
        {
            "arealDensity", "stiffness", "tensileStiffness", "damping",
            "bendingDamping", "bendingDampingUntil", "bendingDampingScheme",
            "bendingDampingFilter", "compressionRatio", "law", "porosity"
        }
    );
}


// radialTapes: enabled (circular canopies only) and their material
void readRadialTapes(const scopedEntryReader& top, structureSpec& s)
{
    const dictionary* d = top.optionalDict("radialTapes");
    if (!d)
    {
        return;
    }
    const scopedEntryReader tr(*d, "radialTapes");
    s.tapes = tr.flag("enabled", false);
    if (s.tapes && !s.circular)
    {
        tr.fail
        (
            "enabled",
            "= true, but radial tapes need a circular canopy "
            "(flatCircular or parabolic), not canopy type " + s.type
        );
    }
    if (s.tapes)
    {
        readMaterial(tr, lineKeys, s.circ.tape);
    }
    wordList used(lineMaterialEntries);
    used.append("enabled");
    tr.warnUnused(used);
}


// lines: length, segment length and material (when there are lines)
void readLines(structureSpec& s)
{
    const scopedEntryReader lr
    (
        s.linesDict ? *s.linesDict : dictionary::null, "lines"
    );
    if (s.nLines > 0)
    {
        s.lines.line_length = lr.positive
        (
            "length",
            "the suspension line length [m] when lines.number > 0"
        );
        s.lines.edge_length = lr.positive
        (
            "edgeLength", "target line segment length [m]", s.edge
        );
        readMaterial(lr, lineKeys, s.lines.line);
    }
    if (s.linesDict)
    {
        wordList used(lineMaterialEntries);
        used.append(wordList{"number", "length", "edgeLength"});
        lr.warnUnused(used);
    }
}


// payload: required with lines, ignored (with a warning) without
void readPayload(const scopedEntryReader& top, structureSpec& s)
{
    if (s.nLines > 0)
    {
        const scopedEntryReader pr
        (
            top.subReader
            (
                "payload",
                "payload { mass <kg>; } (there are suspension lines)"
            )
        );
        s.lines.payload_mass = pr.nonNegative("mass", "payload mass [kg]");
        s.payloadFixed = pr.flag("fixed", false);
        pr.warnUnused(wordList{"mass", "fixed"});
    }
    else if (top.found("payload"))
    {
        IOWarningInFunction(top.dict())
            << "Sub-dictionary 'payload' is ignored: there are no suspension "
            << "lines (lines.number = 0 or no lines)" << endl;
    }
}


// guideWire: which nodes slide on a wire, and its direction
void readGuideWire(const scopedEntryReader& top, structureSpec& s)
{
    const dictionary* d = top.optionalDict("guideWire");
    if (!d)
    {
        return;
    }
    const scopedEntryReader gr(*d, "guideWire");
    s.guidePayload = gr.flag("payload", true);
    s.guideApex = gr.flag("apex", true);
    s.guideDirection = gr.nonZeroVector("direction", "the wire's direction", Zero);
    if (s.guidePayload && s.nLines == 0)
    {
        gr.fail("payload", "= true needs suspension lines and a payload");
    }
    gr.warnUnused(wordList{"payload", "apex", "direction"});
}


// integrator: libcanopy's time integrator and its controls
void readIntegrator(const scopedEntryReader& top, structureSpec& s)
{
    const dictionary* d = top.optionalDict("integrator");
    if (!d)
    {
        return;
    }
    wordList integrators(canopy_integrator_count());
    forAll(integrators, i)
    {
        integrators[i] = word(canopy_integrator_name(i));
    }
    const scopedEntryReader ir(*d, "integrator");
    s.integratorName = ir.choice("type", integrators, "integrator", s.integratorName);
    s.maxOmegaDt = ir.positive("maxOmegaDt", "sub-step bound omega dt", s.maxOmegaDt);
    s.hhtAlpha = ir.inRange("hhtAlpha", "HHT alpha", -1.0/3.0, 0, s.hhtAlpha);
    s.newtonTol = ir.positive("tolerance", "Newton relative tolerance", s.newtonTol);
    s.newtonIter = ir.integerAtLeast
    (
        "maxIterations", "Newton iteration limit", 1, s.newtonIter
    );
    s.speedLimit = ir.positive("speedLimit", "runaway speed [m/s]", s.speedLimit);
    ir.warnUnused
    (
        wordList
        {
            "type", "maxOmegaDt", "hhtAlpha", "tolerance",
            "maxIterations", "speedLimit"
        }
    );
}


// fixedNodes: the rim, or every cloth node (read after guideWire)
void readFixedNodes(const scopedEntryReader& top, structureSpec& s)
{
    const dictionary* d = top.optionalDict("fixedNodes");
    if (!d)
    {
        return;
    }
    const scopedEntryReader fr(*d, "fixedNodes");
    s.fixSkirt = fr.flag("skirt", false);
    s.fixAll = fr.flag("all", false);
    if (s.fixAll && s.guideApex)
    {
        fr.fail
        (
            "all",
            "= true pins the apex, which guideWire.apex = true (the default"
            " when guideWire is given) puts on the wire: set"
            " guideWire.apex false"
        );
    }
    s.motionDict = fr.optionalDict("motion");
    if (s.motionDict && !s.fixAll && !s.fixSkirt)
    {
        fr.fail
        (
            "motion",
            "turns the fixed nodes, and there are none: set fixedNodes.all"
            " or fixedNodes.skirt true"
        );
    }
    fr.warnUnused(wordList{"skirt", "all", "motion"});
}


// The builder specifications from what was read
void completeBuildSpecs(structureSpec& s)
{
    s.circ.edge_length = s.edge;
    s.cross.edge_length = s.edge;
    s.rect.edge_length = s.edge;
    for (direction d = 0; d < 3; ++d)
    {
        s.circ.center[d] = s.centre[d];
        s.cross.center[d] = s.centre[d];
    }
    s.rect.origin[0] = s.centre.x() - 0.5*s.rect.width;
    s.rect.origin[1] = s.centre.y() - 0.5*s.rect.length;
    s.rect.origin[2] = s.centre.z();
    s.circ.n_attachments = s.nAttach;
    s.cross.n_attachments = s.nAttach;
    s.circ.radial_tapes = s.tapes ? 1 : 0;
    s.circ.fabric = s.fabric;
    s.cross.fabric = s.fabric;
    s.rect.fabric = s.fabric;
}


// Every entry of canopyProperties, in the order the errors are reported
structureSpec readStructure
(
    const dictionary& dict,
    const vector& defaultGravity
)
{
    structureSpec s;
    const scopedEntryReader top(dict, "");
    const scopedEntryReader cr
    (
        top.subReader("canopy", "canopy { type ...; }")
    );
    const wordList canopyUsed(readCanopyShape(cr, s));
    readLineCount(top, s);
    readAttachments(cr, s, canopyUsed);
    readFabric(top, s);
    readRadialTapes(top, s);
    readLines(s);
    readPayload(top, s);
    readGuideWire(top, s);
    s.g = top.vectorValue("gravity", "gravity [m/s^2]", defaultGravity);
    s.initialVelocity = top.vectorValue
    (
        "initialVelocity", "velocity of every node at the start [m/s]", Zero
    );
    readIntegrator(top, s);
    readFixedNodes(top, s);
    completeBuildSpecs(s);
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::canopyStructure::build(const vector& defaultGravity)
{
    // ---- read: every entry checked before anything is built ----------------

    const structureSpec s(readStructure(dict_, defaultGravity));
    initialVelocity_ = s.initialVelocity;

    // ---- build ---------------------------------------------------------------

    {
        canopy_model* m = nullptr;
        if (canopy_model_create(&m) != CANOPY_OK || !m)
        {
            FatalErrorInFunction
                << "libcanopy canopy_model_create failed (out of memory)"
                << exit(FatalError);
        }
        model_.reset(m);
    }
    canopy_model* m = model_.get();

    std::vector<int> attach(s.nAttach > 0 ? s.nAttach : 1, -1);
    int st = CANOPY_OK;
    if (s.circular)
    {
        st = canopy_build_circular(m, &s.circ, attach.data());
    }
    else if (s.type == "cross")
    {
        st = canopy_build_cross(m, &s.cross, attach.data());
    }
    else
    {
        st = canopy_build_rectangle(m, &s.rect);
    }
    if (st != CANOPY_OK)
    {
        FatalErrorInFunction
            << "libcanopy could not build the " << s.type << " canopy of "
            << dict_.name() << ": " << canopy_model_message(m) << nl
            << exit(FatalError);
    }

    attachments_.setSize(s.nAttach);
    forAll(attachments_, k)
    {
        attachments_[k] = attach[k];
    }

    // Pin the rim: nodes on boundary edges (edges of one triangle only),
    // without a vent's
    if (s.fixAll)
    {
        // A rigid, immobile structure (verification cases: fixed plates)
        for (label i = 0; i < nNodes(); ++i)
        {
            check(canopy_model_set_fixed(m, i, 1), "build", "set_fixed");
        }
    }
    else if (s.fixSkirt)
    {
        const triFaceList tris(triangles());
        std::map<std::pair<label, label>, label> edgeCount;
        for (const triFace& f : tris)
        {
            for (label e = 0; e < 3; ++e)
            {
                const label a = f[e];
                const label b = f[(e + 1) % 3];
                ++edgeCount[std::make_pair(min(a, b), max(a, b))];
            }
        }
        const pointField x(points());
        const scalar rCut = 0.25*(s.circ.diameter + s.circ.vent_diameter);
        for (const auto& ec : edgeCount)
        {
            if (ec.second != 1) continue;
            for (const label i : {ec.first.first, ec.first.second})
            {
                if (s.circular)
                {
                    const scalar r = std::hypot
                    (
                        x[i].x() - s.centre.x(), x[i].y() - s.centre.y()
                    );
                    if (r < rCut) continue;     // a vent node
                }
                check
                (
                    canopy_model_set_fixed(m, i, 1),
                    FUNCTION_NAME, "canopy_model_set_fixed"
                );
            }
        }
    }

    // Lines: the length must exceed the attachments' radius (as libcanopy
    // requires), reported here on the entry
    if (s.nLines > 0)
    {
        const pointField x(points());
        scalar cx = 0, cy = 0;
        for (const int i : attach)
        {
            cx += x[i].x()/s.nAttach;
            cy += x[i].y()/s.nAttach;
        }
        scalar rho = 0;
        for (const int i : attach)
        {
            rho += std::hypot(x[i].x() - cx, x[i].y() - cy)/s.nAttach;
        }
        if (!(s.lines.line_length > rho))
        {
            OStringStream os;
            os  << "= " << s.lines.line_length << " must exceed the skirt radius "
                << rho << " m (mean distance of the " << s.nAttach
                << " attachment points from their centroid)";
            scopedEntryReader(*s.linesDict, "lines").fail("length", os.str());
        }

        int payload = -1;
        st = canopy_build_suspension_lines
        (
            m, attach.data(), s.nAttach, &s.lines, &payload
        );
        if (st != CANOPY_OK)
        {
            FatalErrorInFunction
                << "libcanopy could not build the suspension lines of "
                << dict_.name() << ": " << canopy_model_message(m) << nl
                << exit(FatalError);
        }
        payloadNode_ = payload;
        if (s.payloadFixed)
        {
            check
            (
                canopy_model_set_fixed(m, payload, 1),
                FUNCTION_NAME, "canopy_model_set_fixed"
            );
        }
    }

    // ---- model settings ------------------------------------------------------

    const double gArr[3] = {s.g.x(), s.g.y(), s.g.z()};
    check(canopy_model_set_gravity(m, gArr), FUNCTION_NAME, "canopy_model_set_gravity");
    check(canopy_model_set_porosity(m, s.alpha, s.beta), FUNCTION_NAME, "canopy_model_set_porosity");
    check
    (
        canopy_model_set_bending_damping(m, s.bendingDamping),
        FUNCTION_NAME, "canopy_model_set_bending_damping"
    );
    check
    (
        canopy_model_set_bending_damping_implicit
        (
            m, s.bendingDampingScheme == "implicit"
        ),
        FUNCTION_NAME, "canopy_model_set_bending_damping_implicit"
    );
    check
    (
        canopy_model_set_bending_damping_filter
        (
            m, s.bendingDampingFilter == "highPass"
        ),
        FUNCTION_NAME, "canopy_model_set_bending_damping_filter"
    );
    check
    (
        canopy_model_set_fabric_compression(m, s.compressionRatio),
        FUNCTION_NAME, "canopy_model_set_fabric_compression"
    );
    check
    (
        canopy_model_set_integrator(m, s.integratorName.c_str()),
        FUNCTION_NAME, "canopy_model_set_integrator"
    );
    check(canopy_model_set_max_omega_dt(m, s.maxOmegaDt), FUNCTION_NAME, "canopy_model_set_max_omega_dt");
    check(canopy_model_set_hht_alpha(m, s.hhtAlpha), FUNCTION_NAME, "canopy_model_set_hht_alpha");
    check
    (
        canopy_model_set_implicit_controls(m, s.newtonTol, s.newtonIter),
        FUNCTION_NAME, "canopy_model_set_implicit_controls"
    );
    check(canopy_model_set_speed_limit(m, s.speedLimit), FUNCTION_NAME, "canopy_model_set_speed_limit");

    bendingDampingUntil_ = s.bendingDampingUntil;
    if (bendingDampingUntil_ < VGREAT)
    {
        Info<< "canopyStructure: the hinge dashpots ("
            << Foam::name(s.bendingDamping) << " /s) are off from t = "
            << Foam::name(bendingDampingUntil_) << endl;
    }

    if (s.motionDict)
    {
        motion_.reset(new prescribedRotation(*s.motionDict, m, payloadNode_));
        Info<< "canopyStructure: ";
        motion_->writeInfo(Info);
        Info<< endl;
    }

    if (s.guidePayload || s.guideApex)
    {
        setGuideWire(s.guidePayload, s.guideApex, s.guideDirection, s.g, s.centre);
    }

    if (initialVelocity_ != vector::zero)
    {
        List<scalar> v(3*nNodes());
        for (label i = 0; i < nNodes(); ++i)
        {
            for (direction d = 0; d < 3; ++d)
            {
                v[3*i + d] = initialVelocity_[d];
            }
        }
        check
        (
            canopy_model_set_velocities(m, v.cdata(), nNodes()),
            FUNCTION_NAME, "canopy_model_set_velocities"
        );
    }

    // The cloth's area as built, before an initial state (e.g. a fold)
    // or a restart moves it: the nominal area
    builtCanopyArea_ = canopyArea();

    if (debug)
    {
        Info<< "canopyStructure: " << s.type << " canopy, " << nNodes()
            << " nodes, " << nSprings() << " springs, " << nTriangles()
            << " triangles, " << s.nLines << " lines, integrator "
            << s.integratorName << endl;
    }
}


void Foam::canopyStructure::setGuideWire
(
    const bool payload,
    const bool apex,
    const vector& direction,
    const vector& gravity,
    const vector& centre
)
{
    canopy_model* m = model();
    const vector e = mag(direction) > 0 ? direction : gravity;
    if (!(mag(e) > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'guideWire.direction' is missing and gravity is zero:"
            << " give the wire's direction" << exit(FatalIOError);
    }
    const double axis[3] = {e.x(), e.y(), e.z()};
    if (payload)
    {
        check
        (
            canopy_model_set_guide(m, payloadNode_, axis),
            FUNCTION_NAME, "canopy_model_set_guide"
        );
    }
    label apexNode = -1;
    if (apex)
    {
        // The cloth's node nearest the canopy's centre
        const label n = nNodes();
        const pointField x(points());
        List<int> group(n);
        check
        (
            canopy_model_get_node_groups(m, group.data(), n),
            FUNCTION_NAME, "canopy_model_get_node_groups"
        );
        scalar best = GREAT;
        for (label i = 0; i < n; ++i)
        {
            if (group[i] != CANOPY_GROUP_FABRIC)
            {
                continue;
            }
            const scalar d = mag(x[i] - centre);
            if (d < best)
            {
                best = d;
                apexNode = i;
            }
        }
        if (apexNode < 0)
        {
            FatalIOErrorInFunction(dict_)
                << "Entry 'guideWire.apex' = true: the canopy has no cloth"
                << " node" << exit(FatalIOError);
        }
        check
        (
            canopy_model_set_guide(m, apexNode, axis),
            FUNCTION_NAME, "canopy_model_set_guide"
        );
    }
    Info<< "canopyStructure: guide wire along " << e/mag(e) << " through"
        << (payload ? " the payload" : "") << (payload && apex ? " and" : "");
    if (apex)
    {
        Info<< " the canopy's apex (node " << apexNode << ")";
    }
    Info<< endl;
}


// ************************************************************************* //
