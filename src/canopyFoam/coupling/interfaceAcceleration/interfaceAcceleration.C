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

// The vector fields' components one after another, in list order, then
// the scalar fields' values
template<class VectorPtr, class ScalarPtr>
Foam::scalarField pack
(
    const Foam::UList<VectorPtr>& vectors,
    const Foam::UList<ScalarPtr>& scalars
)
{
    Foam::label n = 0;
    for (const VectorPtr f : vectors)
    {
        n += 3*f->size();
    }
    for (const ScalarPtr f : scalars)
    {
        n += f->size();
    }
    Foam::scalarField s(n);
    Foam::label i = 0;
    for (const VectorPtr f : vectors)
    {
        for (const Foam::vector& v : *f)
        {
            for (Foam::direction d = 0; d < 3; ++d)
            {
                s[i++] = v[d];
            }
        }
    }
    for (const ScalarPtr f : scalars)
    {
        for (const Foam::scalar v : *f)
        {
            s[i++] = v;
        }
    }
    return s;
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarField Foam::interfaceAcceleration::pack
(
    const UList<const vectorField*>& vectors,
    const UList<const scalarField*>& scalars
)
{
    return ::pack(vectors, scalars);
}


Foam::scalarField Foam::interfaceAcceleration::pack
(
    const UList<vectorField*>& vectors,
    const UList<scalarField*>& scalars
)
{
    return ::pack(vectors, scalars);
}


void Foam::interfaceAcceleration::unpack
(
    const scalarField& s,
    const UList<vectorField*>& vectors,
    const UList<scalarField*>& scalars
)
{
    label i = 0;
    for (vectorField* f : vectors)
    {
        for (vector& v : *f)
        {
            for (direction d = 0; d < 3; ++d)
            {
                v[d] = s[i++];
            }
        }
    }
    for (scalarField* f : scalars)
    {
        for (scalar& v : *f)
        {
            v = s[i++];
        }
    }
}


void Foam::interfaceAcceleration::relax
(
    scalarField& x,
    const scalarField& target,
    const UList<vectorField*>& held,
    const UList<const vectorField*>& targets,
    const UList<scalarField*>& heldScalars,
    const UList<const scalarField*>& scalarTargets
)
{
    scalarField s(pack(held, heldScalars));
    relax(x, target, s, pack(targets, scalarTargets));
    unpack(s, held, heldScalars);
}


// ************************************************************************* //
