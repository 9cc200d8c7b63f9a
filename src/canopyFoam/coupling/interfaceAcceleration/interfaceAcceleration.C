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

// The components of the fields one after another, in list order
template<class FieldPtr>
Foam::scalarField packVectors(const Foam::UList<FieldPtr>& fields)
{
    Foam::label n = 0;
    for (const FieldPtr f : fields)
    {
        n += 3*f->size();
    }
    Foam::scalarField s(n);
    Foam::label i = 0;
    for (const FieldPtr f : fields)
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


// The inverse of packVectors (the fields keep their sizes)
void unpackVectors
(
    const Foam::scalarField& s,
    const Foam::UList<Foam::vectorField*>& fields
)
{
    Foam::label i = 0;
    for (Foam::vectorField* f : fields)
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
    const UList<vectorField*>& held,
    const UList<const vectorField*>& targets
)
{
    scalarField s(packVectors(held));
    relax(x, target, s, packVectors(targets));
    unpackVectors(s, held);
}


// ************************************************************************* //
