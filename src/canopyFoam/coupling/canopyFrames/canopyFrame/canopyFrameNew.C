/*---------------------------------------------------------------------------*\
    canopyFoam: canopyFrameNew.C — run-time selection of the frame from the
    coupling's frame sub-dictionary.
\*---------------------------------------------------------------------------*/

#include "canopyFrame.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::canopyFrame> Foam::canopyFrame::New
(
    const scopedEntryReader& frame,
    const fvMesh& mesh,
    const canopyStructure& structure
)
{
    const word type
    (
        frame.choice
        (
            "type", dictionaryConstructorTablePtr_->sortedToc(), "frame",
            "fixed"
        )
    );
    return (*dictionaryConstructorTablePtr_)[type]
    (
        frame, mesh, structure
    );
}


// ************************************************************************* //
