/*---------------------------------------------------------------------------*\
    canopyFoam: canopyFrameNew.C — run-time selection of the frame from the
    coupling dictionary's frame sub-dictionary.
\*---------------------------------------------------------------------------*/

#include "canopyFrame.H"
#include "readEntry.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::canopyFrame> Foam::canopyFrame::New
(
    const dictionary& coupling,
    const fvMesh& mesh,
    const canopyStructure& structure
)
{
    if (coupling.found("frame") && !coupling.isDict("frame"))
    {
        canopyEntry::fail
        (
            coupling, "frame", "coupling.frame",
            "must be a sub-dictionary { type ..; }"
        );
    }
    const dictionary& dict = coupling.subOrEmptyDict("frame");
    const word type
    (
        canopyEntry::wordValue(dict, "type", "coupling.frame.type", "fixed")
    );
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coupling.frame.type' = " << type
            << " is not valid; valid:";
        for (const word& valid : dictionaryConstructorTablePtr_->sortedToc())
        {
            FatalIOError << ' ' << valid;
        }
        FatalIOError << exit(FatalIOError);
    }
    canopyEntry::reportUnknown
    (
        dict, "coupling.frame.", {"type", "inletPatches", "wind"}
    );
    return cstrIter()(dict, mesh, structure);
}


// ************************************************************************* //
