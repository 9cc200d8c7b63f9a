// canopyFold.C: folds the canopy of constant/canopyProperties before a run (Foam::canopyFold, system/canopyFoldDict) and writes the initial state canopyStructure reads (entry initialState).
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

Application
    canopyFold

Description
    Folds the canopy of constant/canopyProperties with the singular velocity
    field of seed 000 eq. 5.3 (structure only) and writes the folded state
    for canopyProperties' entry initialState. The fold, its dictionary
    system/canopyFoldDict and its output are documented in canopyFold.H
    (src/canopyFoam/structure/canopyFold).

Usage
    canopyFold [-case dir] [-dict file]

See also
    applications/utilities/canopyFold/README.md, Foam::canopyFold,
    Foam::canopyStructure (entry initialState).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "canopyStructure.H"
#include "canopyFold.H"
#include "canopyFoamCompat.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Fold the canopy of constant/canopyProperties with the singular"
        " velocity field of seed 000 eq. 5.3 (structure only) and write the"
        " folded state for canopyProperties' initialState"
    );
    argList::noParallel();
    canopyCompat::noFunctionObjects();
    #include "addDictOption.H"

    #include "setRootCase.H"
    #include "createTime.H"

    // The flat canopy, as built from canopyProperties (its own initialState
    // entry, which may name the file written here, is not applied)
    canopyStructure structure(runTime, false);

    // system/canopyFoldDict, or the file (or the folder's canopyFoldDict)
    // that -dict names
    const word dictName("canopyFoldDict");
    fileName dictPath;
    if (canopyCompat::argFound(args, "dict"))
    {
        dictPath = canopyCompat::argRead<fileName>(args, "dict");
        dictPath.expand();
        if (isDir(dictPath))
        {
            dictPath = dictPath/dictName;
        }
    }
    const IOdictionary foldDict
    (
        dictPath.empty()
      ? IOobject
        (
            dictName, runTime.system(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
      : IOobject
        (
            dictPath.isAbsolute() ? dictPath : runTime.path()/dictPath,
            runTime, IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );

    canopyFold fold(structure, foldDict, runTime);
    fold.run();

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //
