// Test-couplingKeys.C: prints the entries every part of the coupling accepts in its sub-dictionary, one header per line, for tests/openfoam/couplingKeys.
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
    Test-couplingKeys

Description
    Each class of the coupling reads its own sub-dictionary of
    constant/canopyProperties and rejects every entry not in its list of
    valid entries (validKeys()); its header documents them in a property
    table. This program prints, one line per header, the header's file name
    and the entries its class accepts:

    \verbatim
    aitkenRelaxation.H type initial max
    \endverbatim

    tests/openfoam/couplingKeys compares each line with the rows of the
    header's property tables, so that an entry a class reads cannot be
    left out of its documentation (nor a documented one go unread).

Usage
    Test-couplingKeys

SourceFiles
    Test-couplingKeys.C

\*---------------------------------------------------------------------------*/

#include "canopyCoupling.H"
#include "ibForcing.H"
#include "clothLoad.H"
#include "aitkenRelaxation.H"
#include "interfaceQuasiNewton.H"
#include "addedMassStabiliser.H"
#include "lineDrag.H"
#include "fixed.H"
#include "payload.H"

#include <iostream>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main()
{
    const struct { const char* header; wordList keys; } parts[] =
    {
        {"canopyCoupling.H", canopyCoupling::validKeys()},
        {"ibForcing.H", ibForcing::validKeys()},
        {"clothLoad.H", clothLoad::validKeys()},
        {"sampled.H", clothLoad::validKeys()},
        {"ibForce.H", clothLoad::validKeys()},
        {"aitkenRelaxation.H", aitkenRelaxation::validKeys()},
        {"interfaceQuasiNewton.H", interfaceQuasiNewton::validKeys()},
        {"addedMassStabiliser.H", addedMassStabiliser::validKeys()},
        {"lineDrag.H", lineDrag::validKeys()},
        {"fixed.H", canopyFrames::fixed::validKeys()},
        {"payload.H", canopyFrames::payload::validKeys()},
    };
    for (const auto& part : parts)
    {
        std::cout << part.header;
        for (const word& key : part.keys)
        {
            std::cout << ' ' << key;
        }
        std::cout << '\n';
    }
    return 0;
}


// ************************************************************************* //
