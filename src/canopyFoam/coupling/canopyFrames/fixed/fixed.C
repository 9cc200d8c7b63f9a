/*---------------------------------------------------------------------------*\
    canopyFoam: fixed.C — the frame of a mesh at rest.
\*---------------------------------------------------------------------------*/

#include "fixed.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace canopyFrames
{
    defineTypeNameAndDebug(fixed, 0);
    addToRunTimeSelectionTable(canopyFrame, fixed, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wordList Foam::canopyFrames::fixed::validKeys()
{
    return {"type", "wind"};
}


Foam::canopyFrames::fixed::fixed
(
    const scopedEntryReader& frame,
    const fvMesh& mesh,
    const canopyStructure& structure
)
:
    canopyFrame(mesh)
{
    // Checked like payload's, so that a malformed entry stops either way
    frame.vectorValue("wind", "ambient wind [m/s]", Zero);
    frame.rejectUnknown(validKeys());
}


// ************************************************************************* //
