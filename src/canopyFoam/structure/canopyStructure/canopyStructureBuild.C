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
#include "switchToken.H"
#include "FlatOutput.H"

#include "canopy.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Function name shown in the dictionary errors and warnings
const char* const whereName = "Foam::canopyStructure::build";


// A number as OpenFOAM writes it (2.134, not 2.134000)
std::string toStr(const scalar x)
{
    OStringStream os;
    os << x;
    return os.str();
}


// Reads the entries of one (sub-)dictionary with type and range checks.
// Errors are FatalIOError on that dictionary and name the entry by its
// scoped name ("payload.mass").
class entryReader
{
    const dictionary& dict_;
    const std::string scope_;

    static std::string describe(const token& tok)
    {
        OStringStream os;
        os << tok.info();
        return os.str();
    }

    const entry* find(const word& key) const
    {
        return dict_.findEntry(key, keyType::LITERAL);
    }

    // The entry's stream; fails if it is missing or a sub-dictionary
    ITstream& stream(const word& key, const std::string& expected) const
    {
        const entry* e = find(key);
        if (!e)
        {
            fail(key, "is missing (required: " + expected + ")");
        }
        if (e->isDict())
        {
            fail(key, "must be a value (" + expected + "), not a sub-dictionary");
        }
        return e->stream();
    }

    // The single token of a one-token entry
    const token& single(const word& key, const std::string& expected) const
    {
        ITstream& is = stream(key, expected);
        if (is.size() != 1)
        {
            fail
            (
                key,
                "must be a single value (" + expected + "), found "
              + std::to_string(is.size()) + " tokens: " + is.toString()
            );
        }
        return is[0];
    }


public:

    entryReader(const dictionary& dict, const std::string& scope)
    :
        dict_(dict),
        scope_(scope)
    {}

    const dictionary& dict() const
    {
        return dict_;
    }

    //- Scoped name of an entry: "payload.mass"
    std::string name(const word& key) const
    {
        return scope_.empty() ? std::string(key) : scope_ + '.' + key;
    }

    bool found(const word& key) const
    {
        return find(key) != nullptr;
    }

    //- FatalIOError "Entry '<scope.key>' <what>"
    [[noreturn]] void fail(const word& key, const std::string& what) const
    {
        FatalIOErrorIn(whereName, dict_)
            << "Entry '" << name(key).c_str() << "' " << what.c_str() << nl
            << exit(FatalIOError);
        std::abort();   // not reached: FatalIOError exits or throws
    }

    //- A number (finite)
    scalar getScalar(const word& key, const std::string& what) const
    {
        const token& tok = single(key, what);
        if (!tok.isNumber())
        {
            fail
            (
                key,
                "must be a number (" + what + "), found " + describe(tok)
            );
        }
        const scalar x = tok.number();
        if (!std::isfinite(x))
        {
            fail(key, "= " + toStr(x) + " must be finite");
        }
        return x;
    }

    //- A number > 0
    scalar positive(const word& key, const std::string& what) const
    {
        const scalar x = getScalar(key, what);
        if (!(x > 0))
        {
            fail(key, "= " + toStr(x) + " must be > 0 (" + what + ")");
        }
        return x;
    }

    scalar positive
    (
        const word& key,
        const std::string& what,
        const scalar deflt
    ) const
    {
        return found(key) ? positive(key, what) : deflt;
    }

    //- A number >= 0
    scalar nonNegative(const word& key, const std::string& what) const
    {
        const scalar x = getScalar(key, what);
        if (x < 0)
        {
            fail(key, "= " + toStr(x) + " must be >= 0 (" + what + ")");
        }
        return x;
    }

    scalar nonNegative
    (
        const word& key,
        const std::string& what,
        const scalar deflt
    ) const
    {
        return found(key) ? nonNegative(key, what) : deflt;
    }

    //- A number in [lo, hi]
    scalar inRange
    (
        const word& key,
        const std::string& what,
        const scalar lo,
        const scalar hi,
        const scalar deflt
    ) const
    {
        if (!found(key))
        {
            return deflt;
        }
        const scalar x = getScalar(key, what);
        if (x < lo || x > hi)
        {
            fail
            (
                key,
                "= " + toStr(x) + " must be in [" + toStr(lo) + ", " + toStr(hi)
              + "] (" + what + ")"
            );
        }
        return x;
    }

    //- An integer
    label getLabel(const word& key, const std::string& what) const
    {
        const token& tok = single(key, what);
        if (!tok.isLabel())
        {
            fail
            (
                key,
                "must be an integer (" + what + "), found " + describe(tok)
            );
        }
        return tok.labelToken();
    }

    //- A switch: true/false, on/off, yes/no, ...
    bool getBool(const word& key, const bool deflt) const
    {
        if (!found(key))
        {
            return deflt;
        }
        const token& tok = single(key, "true or false");
        bool value = deflt;
        if (readSwitchToken(tok, value))
        {
            return value;
        }
        fail
        (
            key,
            "must be a switch (true/false, on/off, yes/no), found "
          + describe(tok)
        );
    }

    //- A vector (x y z), finite
    vector getVector(const word& key, const vector& deflt) const
    {
        if (!found(key))
        {
            return deflt;
        }
        ITstream& is = stream(key, "a vector (x y z)");
        const bool ok =
            is.size() == 5
         && is[0].isPunctuation() && is[0].pToken() == token::BEGIN_LIST
         && is[1].isNumber() && is[2].isNumber() && is[3].isNumber()
         && is[4].isPunctuation() && is[4].pToken() == token::END_LIST;
        if (!ok)
        {
            fail(key, "must be a vector (x y z), found " + is.toString());
        }
        const vector v(is[1].number(), is[2].number(), is[3].number());
        if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z()))
        {
            fail(key, "must be finite");
        }
        return v;
    }

    //- One of the given names; a missing entry gives deflt if that is not
    //- empty, else is an error
    word select
    (
        const word& key,
        const wordList& valid,
        const std::string& what,
        const word& deflt = word::null
    ) const
    {
        if (!found(key) && !deflt.empty())
        {
            return deflt;
        }
        std::string list;
        for (const word& w : valid)
        {
            list += (list.empty() ? "" : " ") + w;
        }
        const token& tok = single(key, "the " + what + ", one of: " + list);
        if (!tok.isWord())
        {
            fail
            (
                key,
                "must be a " + what + " name, found " + describe(tok)
              + ". Valid " + what + "s: " + list
            );
        }
        const word& w = tok.wordToken();
        if (!valid.found(w))
        {
            fail
            (
                key,
                "= " + w + " is not a known " + what + ". Valid " + what
              + "s: " + list
            );
        }
        return w;
    }

    //- A sub-dictionary, or nullptr when absent (an entry that is not a
    //- dictionary is an error)
    const dictionary* optionalDict(const word& key) const
    {
        const entry* e = find(key);
        if (!e)
        {
            return nullptr;
        }
        if (!e->isDict())
        {
            fail(key, "must be a sub-dictionary { ... }");
        }
        return &e->dict();
    }

    const dictionary& requiredDict(const word& key, const std::string& what)
        const
    {
        const dictionary* d = optionalDict(key);
        if (!d)
        {
            fail(key, "is missing: a sub-dictionary " + what + " is required");
        }
        return *d;
    }

    //- Warn about the entries not in 'used'
    void warnUnused(const wordList& used, const std::string& context) const
    {
        for (const word& key : dict_.toc())
        {
            if (!used.found(key))
            {
                IOWarningIn(whereName, dict_)
                    << "Entry '" << name(key).c_str() << "' is not used"
                    << context.c_str() << " and is ignored. Valid entries here: "
                    << flatOutput(used) << endl;
            }
        }
    }
};


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
    const entryReader& r,
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
        r.select("law", lawNames, "spring law", lawName(mat.law))
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::canopyStructure::build(const vector& defaultGravity)
{
    const entryReader top(dict_, "");

    // ---- canopy ------------------------------------------------------------

    const entryReader cr(top.requiredDict("canopy", "canopy { type ...; }"), "canopy");

    const wordList types{"flatCircular", "parabolic", "cross", "rectangle"};
    const word type = cr.select("type", types, "canopy type");
    const bool circular = (type == "flatCircular" || type == "parabolic");

    canopy_circular_spec circ = canopy_circular_spec_default();
    canopy_cross_spec cross = canopy_cross_spec_default();
    canopy_rectangle_spec rect = canopy_rectangle_spec_default();

    const scalar edge = cr.positive("edgeLength", "target triangle edge length [m]");
    const vector centre = cr.getVector("centre", Zero);

    wordList canopyUsed{"type", "edgeLength", "centre"};
    if (circular)
    {
        circ.diameter = cr.positive("diameter", "skirt diameter [m]");
        circ.vent_diameter = cr.nonNegative("ventDiameter", "vent diameter [m]", 0);
        if (!(circ.vent_diameter < circ.diameter))
        {
            cr.fail
            (
                "ventDiameter",
                "= " + toStr(circ.vent_diameter)
              + " must be smaller than " + cr.name("diameter") + " = "
              + toStr(circ.diameter)
            );
        }
        canopyUsed.append(wordList{"diameter", "ventDiameter"});
        if (type == "parabolic")
        {
            circ.height = cr.positive("height", "apex height above the skirt [m]");
            canopyUsed.append("height");
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
                    "= " + toStr(circ.height) + ", but a flatCircular canopy "
                    "is flat (use canopy type parabolic for a height)"
                );
            }
            canopyUsed.append("height");
        }
    }
    else if (type == "cross")
    {
        cross.span = cr.positive("span", "tip-to-tip arm length [m]");
        cross.arm_width = cr.positive("armWidth", "arm width [m]");
        if (!(cross.arm_width < cross.span))
        {
            cr.fail
            (
                "armWidth",
                "= " + toStr(cross.arm_width) + " must be smaller than "
              + cr.name("span") + " = " + toStr(cross.span)
            );
        }
        canopyUsed.append(wordList{"span", "armWidth"});
    }
    else
    {
        rect.width = cr.positive("width", "extent along x [m]");
        rect.length = cr.positive("length", "extent along y [m]");
        canopyUsed.append(wordList{"width", "length"});
    }

    // ---- lines (read first: nAttachments defaults to lines.number) --------

    const dictionary* linesDict = top.optionalDict("lines");
    const entryReader lr(linesDict ? *linesDict : dictionary::null, "lines");
    label nLines = 0;
    if (linesDict)
    {
        nLines = lr.getLabel("number", "the number of suspension lines");
        if (nLines < 0 || (nLines > 0 && nLines < 3))
        {
            lr.fail
            (
                "number",
                "= " + std::to_string(nLines) + " must be 0 (no lines) or >= 3"
            );
        }
    }

    // ---- attachments ---------------------------------------------------------

    label nAttach = 0;
    if (type == "rectangle")
    {
        if (nLines > 0)
        {
            lr.fail
            (
                "number",
                "= " + std::to_string(nLines) + ": a rectangle canopy has no "
                "attachment points for lines; use lines { number 0; } or "
                "remove lines"
            );
        }
    }
    else
    {
        canopyUsed.append("nAttachments");

        // The entry that sets the attachment count, for the messages
        const entryReader* src = &cr;
        word srcKey = "nAttachments";
        std::string note;
        if (cr.found("nAttachments"))
        {
            nAttach = cr.getLabel("nAttachments", "the number of attachment points");
        }
        else if (nLines > 0)
        {
            nAttach = nLines;
            src = &lr;
            srcKey = "number";
            note = " (canopy.nAttachments defaults to lines.number)";
        }
        else
        {
            nAttach = circular ? circ.n_attachments : cross.n_attachments;
        }

        if (circular && nAttach < 3)
        {
            src->fail
            (
                srcKey,
                "= " + std::to_string(nAttach) + " must be >= 3" + note
            );
        }
        if (type == "cross" && (nAttach < 4 || nAttach % 4 != 0))
        {
            src->fail
            (
                srcKey,
                "= " + std::to_string(nAttach) + " must be a positive "
                "multiple of 4 for a cross canopy (the attachment points are "
                "spread evenly over the four arm tips)" + note
            );
        }
        if (nLines > 0 && nAttach != nLines)
        {
            cr.fail
            (
                "nAttachments",
                "= " + std::to_string(nAttach) + " must equal "
              + lr.name("number") + " = " + std::to_string(nLines)
              + " (one line per attachment point)"
            );
        }
    }
    cr.warnUnused(canopyUsed, " by canopy type " + type);

    // ---- fabric --------------------------------------------------------------

    canopy_material fabric = canopy_material_fabric_default();
    scalar alpha = 0;
    scalar beta = 0;
    scalar bendingDamping = 0;
    word bendingDampingScheme("explicit");
    word bendingDampingFilter("none");
    scalar compressionRatio = 1;
    if (const dictionary* d = top.optionalDict("fabric"))
    {
        const entryReader fr(*d, "fabric");
        readMaterial(fr, sheetKeys, fabric);
        bendingDamping = fr.nonNegative
        (
            "bendingDamping", "decay rate of each hinge's bending [1/s]", 0
        );
        bendingDampingScheme = fr.select
        (
            "bendingDampingScheme", wordList{"explicit", "implicit"},
            "hinge dashpot scheme", bendingDampingScheme
        );
        bendingDampingFilter = fr.select
        (
            "bendingDampingFilter", wordList{"none", "highPass"},
            "hinge dashpot filter", bendingDampingFilter
        );
        if
        (
            bendingDampingFilter == "highPass"
         && bendingDampingScheme != "implicit"
        )
        {
            fr.fail
            (
                "bendingDampingFilter",
                "highPass needs bendingDampingScheme implicit"
            );
        }
        compressionRatio = fr.inRange
        (
            "compressionRatio",
            "the springs' stiffness in compression over their stiffness",
            0, 1, compressionRatio
        );
        if (fr.found("compressionRatio") && fabric.law != CANOPY_SPRING_MODEL_II)
        {
            fr.fail
            (
                "compressionRatio",
                "needs law modelII (the law is " + lawName(fabric.law) + ")"
            );
        }
        if (const dictionary* pd = fr.optionalDict("porosity"))
        {
            const entryReader pr(*pd, "fabric.porosity");
            alpha = pr.nonNegative("alpha", "Darcy coefficient [Pa s/m]", 0);
            beta = pr.nonNegative("beta", "Forchheimer coefficient [Pa s^2/m^2]", 0);
            pr.warnUnused(wordList{"alpha", "beta"}, "");
        }
        fr.warnUnused
        (
            wordList
            {
                "arealDensity", "stiffness", "tensileStiffness", "damping",
                "bendingDamping", "bendingDampingScheme",
                "bendingDampingFilter", "compressionRatio", "law", "porosity"
            },
            ""
        );
    }

    // ---- radial tapes --------------------------------------------------------

    const wordList materialUsed
    {
        "linearDensity", "stiffness", "EA", "damping", "law"
    };

    bool tapes = false;
    if (const dictionary* d = top.optionalDict("radialTapes"))
    {
        const entryReader tr(*d, "radialTapes");
        tapes = tr.getBool("enabled", false);
        if (tapes && !circular)
        {
            tr.fail
            (
                "enabled",
                "= true, but radial tapes need a circular canopy "
                "(flatCircular or parabolic), not canopy type " + type
            );
        }
        if (tapes)
        {
            readMaterial(tr, lineKeys, circ.tape);
        }
        wordList used(materialUsed);
        used.append("enabled");
        tr.warnUnused(used, "");
    }

    // ---- lines ---------------------------------------------------------------

    canopy_lines_spec lines = canopy_lines_spec_default();
    if (nLines > 0)
    {
        lines.line_length = lr.positive
        (
            "length",
            "the suspension line length [m] when lines.number > 0"
        );
        lines.edge_length = lr.positive
        (
            "edgeLength", "target line segment length [m]", edge
        );
        readMaterial(lr, lineKeys, lines.line);
    }
    if (linesDict)
    {
        wordList used(materialUsed);
        used.append(wordList{"number", "length", "edgeLength"});
        lr.warnUnused(used, "");
    }

    // ---- payload -------------------------------------------------------------

    bool payloadFixed = false;
    if (nLines > 0)
    {
        const entryReader pr
        (
            top.requiredDict
            (
                "payload",
                "payload { mass <kg>; } (there are suspension lines)"
            ),
            "payload"
        );
        lines.payload_mass = pr.nonNegative("mass", "payload mass [kg]");
        payloadFixed = pr.getBool("fixed", false);
        pr.warnUnused(wordList{"mass", "fixed"}, "");
    }
    else if (top.found("payload"))
    {
        IOWarningIn(whereName, dict_)
            << "Sub-dictionary 'payload' is ignored: there are no suspension "
            << "lines (lines.number = 0 or no lines)" << endl;
    }

    // ---- guide wire ----------------------------------------------------------

    bool guidePayload = false;
    bool guideApex = false;
    vector guideDirection(Zero);
    const dictionary* guideDict = top.optionalDict("guideWire");
    if (guideDict)
    {
        const entryReader gr(*guideDict, "guideWire");
        guidePayload = gr.getBool("payload", true);
        guideApex = gr.getBool("apex", true);
        guideDirection = gr.getVector("direction", Zero);
        if (gr.found("direction") && !(mag(guideDirection) > 0))
        {
            gr.fail("direction", "must be a non-zero vector");
        }
        if (guidePayload && nLines == 0)
        {
            gr.fail("payload", "= true needs suspension lines and a payload");
        }
        gr.warnUnused(wordList{"payload", "apex", "direction"}, "");
    }

    // ---- gravity, integrator, fixed nodes ------------------------------------

    const vector g = top.getVector("gravity", defaultGravity);
    initialVelocity_ = top.getVector("initialVelocity", Zero);

    wordList integrators(canopy_integrator_count());
    forAll(integrators, i)
    {
        integrators[i] = word(canopy_integrator_name(i));
    }

    word integratorName("rk4");
    scalar maxOmegaDt = 0.1;
    scalar hhtAlpha = -0.1;
    scalar newtonTol = 1e-10;
    label newtonIter = 25;
    scalar speedLimit = 1e4;
    if (const dictionary* d = top.optionalDict("integrator"))
    {
        const entryReader ir(*d, "integrator");
        integratorName = ir.select("type", integrators, "integrator", integratorName);
        maxOmegaDt = ir.positive("maxOmegaDt", "sub-step bound omega dt", maxOmegaDt);
        hhtAlpha = ir.inRange("hhtAlpha", "HHT alpha", -1.0/3.0, 0, hhtAlpha);
        newtonTol = ir.positive("tolerance", "Newton relative tolerance", newtonTol);
        if (ir.found("maxIterations"))
        {
            newtonIter = ir.getLabel("maxIterations", "Newton iteration limit");
            if (newtonIter < 1)
            {
                ir.fail
                (
                    "maxIterations",
                    "= " + std::to_string(newtonIter) + " must be > 0"
                );
            }
        }
        speedLimit = ir.positive("speedLimit", "runaway speed [m/s]", speedLimit);
        ir.warnUnused
        (
            wordList
            {
                "type", "maxOmegaDt", "hhtAlpha", "tolerance",
                "maxIterations", "speedLimit"
            },
            ""
        );
    }

    bool fixSkirt = false;
    bool fixAll = false;
    if (const dictionary* d = top.optionalDict("fixedNodes"))
    {
        const entryReader fr(*d, "fixedNodes");
        fixSkirt = fr.getBool("skirt", false);
        fixAll = fr.getBool("all", false);
        fr.warnUnused(wordList{"skirt", "all"}, "");
    }


    // ---- build -------------------------------------------------------------

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

    std::vector<int> attach(nAttach > 0 ? nAttach : 1, -1);
    int st = CANOPY_OK;
    if (circular)
    {
        circ.edge_length = edge;
        for (direction d = 0; d < 3; ++d) circ.center[d] = centre[d];
        circ.n_attachments = nAttach;
        circ.radial_tapes = tapes ? 1 : 0;
        circ.fabric = fabric;
        st = canopy_build_circular(m, &circ, attach.data());
    }
    else if (type == "cross")
    {
        cross.edge_length = edge;
        for (direction d = 0; d < 3; ++d) cross.center[d] = centre[d];
        cross.n_attachments = nAttach;
        cross.fabric = fabric;
        st = canopy_build_cross(m, &cross, attach.data());
    }
    else
    {
        rect.edge_length = edge;
        rect.origin[0] = centre.x() - 0.5*rect.width;
        rect.origin[1] = centre.y() - 0.5*rect.length;
        rect.origin[2] = centre.z();
        rect.fabric = fabric;
        st = canopy_build_rectangle(m, &rect);
    }
    if (st != CANOPY_OK)
    {
        FatalErrorInFunction
            << "libcanopy could not build the " << type << " canopy of "
            << dict_.name() << ": " << canopy_model_message(m) << nl
            << exit(FatalError);
    }

    attachments_.setSize(nAttach);
    forAll(attachments_, k)
    {
        attachments_[k] = attach[k];
    }

    // Pin the rim: nodes on boundary edges (edges of one triangle only),
    // without a vent's
    if (fixAll)
    {
        // A rigid, immobile structure (verification cases: fixed plates)
        for (label i = 0; i < nNodes(); ++i)
        {
            check(canopy_model_set_fixed(m, i, 1), "build", "set_fixed");
        }
    }
    else if (fixSkirt)
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
        const scalar rCut = 0.25*(circ.diameter + circ.vent_diameter);
        for (const auto& ec : edgeCount)
        {
            if (ec.second != 1) continue;
            for (const label i : {ec.first.first, ec.first.second})
            {
                if (circular)
                {
                    const scalar r = std::hypot
                    (
                        x[i].x() - centre.x(), x[i].y() - centre.y()
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
    if (nLines > 0)
    {
        const pointField x(points());
        scalar cx = 0, cy = 0;
        for (const int i : attach)
        {
            cx += x[i].x()/nAttach;
            cy += x[i].y()/nAttach;
        }
        scalar rho = 0;
        for (const int i : attach)
        {
            rho += std::hypot(x[i].x() - cx, x[i].y() - cy)/nAttach;
        }
        if (!(lines.line_length > rho))
        {
            OStringStream os;
            os  << "= " << lines.line_length << " must exceed the skirt radius "
                << rho << " m (mean distance of the " << nAttach
                << " attachment points from their centroid)";
            lr.fail("length", os.str());
        }

        int payload = -1;
        st = canopy_build_suspension_lines
        (
            m, attach.data(), nAttach, &lines, &payload
        );
        if (st != CANOPY_OK)
        {
            FatalErrorInFunction
                << "libcanopy could not build the suspension lines of "
                << dict_.name() << ": " << canopy_model_message(m) << nl
                << exit(FatalError);
        }
        payloadNode_ = payload;
        if (payloadFixed)
        {
            check
            (
                canopy_model_set_fixed(m, payload, 1),
                FUNCTION_NAME, "canopy_model_set_fixed"
            );
        }
    }

    // ---- model settings ------------------------------------------------------

    const double gArr[3] = {g.x(), g.y(), g.z()};
    check(canopy_model_set_gravity(m, gArr), FUNCTION_NAME, "canopy_model_set_gravity");
    check(canopy_model_set_porosity(m, alpha, beta), FUNCTION_NAME, "canopy_model_set_porosity");
    check
    (
        canopy_model_set_bending_damping(m, bendingDamping),
        FUNCTION_NAME, "canopy_model_set_bending_damping"
    );
    check
    (
        canopy_model_set_bending_damping_implicit
        (
            m, bendingDampingScheme == "implicit"
        ),
        FUNCTION_NAME, "canopy_model_set_bending_damping_implicit"
    );
    check
    (
        canopy_model_set_bending_damping_filter
        (
            m, bendingDampingFilter == "highPass"
        ),
        FUNCTION_NAME, "canopy_model_set_bending_damping_filter"
    );
    check
    (
        canopy_model_set_fabric_compression(m, compressionRatio),
        FUNCTION_NAME, "canopy_model_set_fabric_compression"
    );
    check
    (
        canopy_model_set_integrator(m, integratorName.c_str()),
        FUNCTION_NAME, "canopy_model_set_integrator"
    );
    check(canopy_model_set_max_omega_dt(m, maxOmegaDt), FUNCTION_NAME, "canopy_model_set_max_omega_dt");
    check(canopy_model_set_hht_alpha(m, hhtAlpha), FUNCTION_NAME, "canopy_model_set_hht_alpha");
    check
    (
        canopy_model_set_implicit_controls(m, newtonTol, newtonIter),
        FUNCTION_NAME, "canopy_model_set_implicit_controls"
    );
    check(canopy_model_set_speed_limit(m, speedLimit), FUNCTION_NAME, "canopy_model_set_speed_limit");

    if (guidePayload || guideApex)
    {
        setGuideWire(guidePayload, guideApex, guideDirection, g, centre);
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

    if (debug)
    {
        Info<< "canopyStructure: " << type << " canopy, " << nNodes()
            << " nodes, " << nSprings() << " springs, " << nTriangles()
            << " triangles, " << nLines << " lines, integrator "
            << integratorName << endl;
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
