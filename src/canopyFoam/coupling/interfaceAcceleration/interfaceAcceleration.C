/*---------------------------------------------------------------------------*\
    canopyFoam: interfaceAcceleration.C — type name, run-time selection
    table and the vector-field secondary data of the interface accelerations.
\*---------------------------------------------------------------------------*/

#include "interfaceAcceleration.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(interfaceAcceleration, 0);
    defineRunTimeSelectionTable(interfaceAcceleration, dictionary);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The components of a and b one after another
Foam::scalarField packVectors
(
    const Foam::vectorField& a,
    const Foam::vectorField& b
)
{
    Foam::scalarField s(3*(a.size() + b.size()));
    Foam::label i = 0;
    for (const Foam::vectorField* f : {&a, &b})
    {
        for (const Foam::vector& v : *f)
        {
            for (Foam::direction d = 0; d < 3; ++d)
            {
                s[i++] = v[d];
            }
        }
    }
    return s;
}


// The inverse of packVectors (a and b keep their sizes)
void unpackVectors
(
    const Foam::scalarField& s,
    Foam::vectorField& a,
    Foam::vectorField& b
)
{
    Foam::label i = 0;
    for (Foam::vectorField* f : {&a, &b})
    {
        for (Foam::vector& v : *f)
        {
            for (Foam::direction d = 0; d < 3; ++d)
            {
                v[d] = s[i++];
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::interfaceAcceleration::relax
(
    scalarField& x,
    const scalarField& target,
    vectorField& a,
    vectorField& b,
    const vectorField& aTarget,
    const vectorField& bTarget
)
{
    scalarField s(packVectors(a, b));
    relax(x, target, s, packVectors(aTarget, bTarget));
    unpackVectors(s, a, b);
}


// ************************************************************************* //
