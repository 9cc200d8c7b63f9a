/*---------------------------------------------------------------------------*\
    canopyFoam: restoreExactTime.C — the restart's exact time value from
    <time>/uniform/time.
\*---------------------------------------------------------------------------*/

#include "restoreExactTime.H"
#include "IOdictionary.H"
#include "canopyFoamCompat.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::restoreExactTime(Time& runTime)
{
    if (runTime.timeIndex() == 0)
    {
        return false;
    }
    const word name(canopyCompat::timeName(runTime));
    const IOdictionary timeDict
    (
        IOobject
        (
            "time",
            name,
            "uniform",
            runTime,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    scalar written = runTime.value();
    if
    (
        timeDict.readIfPresent("value", written)
     && written != runTime.value()
     && Time::timeName(runTime.timeToUserTime(written)) == name
    )
    {
        Info<< "Continuing from the written time value " << written
            << " (the directory's name rounds it)" << nl << endl;
        runTime.setTime(runTime.userTimeToTime(written), runTime.timeIndex());
        return true;
    }
    return false;
}


// ************************************************************************* //
