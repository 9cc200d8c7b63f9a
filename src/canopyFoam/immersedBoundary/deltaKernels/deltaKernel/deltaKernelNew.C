/*---------------------------------------------------------------------------*\
    canopyFoam: deltaKernelNew.C — run-time selection of a delta kernel by
    name or from a dictionary entry.
\*---------------------------------------------------------------------------*/

#include "deltaKernel.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::deltaKernel> Foam::deltaKernel::New
(
    const word& kernelType
)
{
    const auto cstrIter = dictionaryConstructorTablePtr_->find(kernelType);

    if (cstrIter == dictionaryConstructorTablePtr_->end())
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
      ? canopyCompat::readValue<word>(dict, entryName)
      : dict.lookupOrDefault<word>(entryName, defaultType)
    );

    const auto cstrIter = dictionaryConstructorTablePtr_->find(kernelType);

    if (cstrIter == dictionaryConstructorTablePtr_->end())
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
