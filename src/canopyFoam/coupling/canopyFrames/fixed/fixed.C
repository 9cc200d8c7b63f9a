/*---------------------------------------------------------------------------*\
    canopyFoam: fixed.C — the frame of a mesh at rest.
\*---------------------------------------------------------------------------*/

#include "fixed.H"
#include "readEntry.H"
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

Foam::canopyFrames::fixed::fixed
(
    const dictionary& dict,
    const fvMesh& mesh,
    const canopyStructure& structure
)
:
    canopyFrame(mesh)
{
    // Checked like payload's, so that a malformed entry stops either way
    canopyEntry::vectorValue(dict, "wind", "coupling.frame.wind", Zero);
}


// ************************************************************************* //
