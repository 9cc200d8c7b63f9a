/*---------------------------------------------------------------------------*\
    canopyFoam: deltaKernelNew.C — run-time selection of a delta kernel by
    name or from a dictionary entry.
\*---------------------------------------------------------------------------*/

#include "deltaKernel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::deltaKernel> Foam::deltaKernel::New
(
    const word& kernelType
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kernelType);

    if (!cstrIter.found())
    {
        FatalErrorInFunction
            << "Unknown delta kernel '" << kernelType << "'" << nl << nl
            << "Valid delta kernels :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalError);
    }

    return cstrIter()(dictionary::null);
}


Foam::autoPtr<Foam::deltaKernel> Foam::deltaKernel::New
(
    const dictionary& dict,
    const word& entryName,
    const word& defaultType
)
{
    const word kernelType
    (
        defaultType.empty()
      ? dict.get<word>(entryName)
      : dict.getOrDefault<word>(entryName, defaultType)
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(kernelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown delta kernel '" << kernelType << "' in entry '"
            << entryName << "' of dictionary " << dict.name() << nl << nl
            << "Valid delta kernels :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(dict.optionalSubDict(kernelType + "Coeffs"));
}


// ************************************************************************* //
