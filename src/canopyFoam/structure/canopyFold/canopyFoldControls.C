// canopyFoldControls.C: canopyFold::controls, the entries of system/canopyFoldDict read and checked with scopedEntryReader.
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

\*---------------------------------------------------------------------------*/

#include "canopyFold.H"
#include "scopedEntryReader.H"
#include "Time.H"

#include "canopy.h"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::canopyFold::controls::controls
(
    const dictionary& foldDict,
    const canopyStructure& structure,
    const Time& runTime
)
{
    const scopedEntryReader top(foldDict, "");

    velocity = top.nonZeroVector("velocity", "v0 of seed 000 eq. 5.3 [m/s]");
    duration = top.positive("duration", "driving time T [s]");

    const scopedEntryReader rr
    (
        top.subReader("region", "region { radius <a>; }")
    );

    // Default centre: the canopy's centre in canopyProperties
    point canopyCentre(Zero);
    const dictionary& canopyDict = structure.dict().subOrEmptyDict("canopy");
    canopyDict.readIfPresent("centre", canopyCentre);

    centre = rr.vectorValue("centre", "a point on the axis [m]", canopyCentre);
    axis = rr.nonZeroVector("axis", "axis direction", vector(0, 0, 1));
    axis /= mag(axis);
    radius = rr.positive("radius", "radius a of the driven region [m]");
    innerRadius = rr.nonNegative("innerRadius", "inner radius of a ring [m]", 0);
    if (!(innerRadius < radius))
    {
        rr.fail
        (
            "innerRadius",
            "= " + scopedEntryReader::format(innerRadius) + " must be smaller"
            " than " + rr.name("radius") + " = "
          + scopedEntryReader::format(radius)
        );
    }
    capture = rr.flag("capture", false);
    rr.warnUnused
    (
        wordList{"centre", "axis", "radius", "innerRadius", "capture"}
    );

    damping = top.nonNegative("damping", "drag per unit mass zeta [1/s]", 20);
    relaxation = top.nonNegative
    (
        "relaxation", "relaxation time after the drive [s]", 0
    );
    nOutput = top.integerAtLeast("nOutput", "number of states written", 1, 10);
    holdPayload = top.flag("holdPayload", true);
    maxStrain = top.positive("maxStrain", "largest spring stretch allowed", 0.1);

    wordList integrators(canopy_integrator_count());
    forAll(integrators, i)
    {
        integrators[i] = word(canopy_integrator_name(i));
    }
    integrator = top.choice("integrator", integrators, "integrator", word::null);
    maxOmegaDt = top.positive("maxOmegaDt", "sub-step bound omega dt", -1);

    if (top.found("output"))
    {
        output = top.fileNameWithExt("output", "an HDF5 file name", "h5");
        if (!output.isAbsolute())
        {
            output = runTime.globalPath()/output;
        }
    }
    else
    {
        output = structure.initialStateFile(runTime);
        if (output.empty())
        {
            output =
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
}


// ************************************************************************* //
