/*---------------------------------------------------------------------------*\
    canopyFoam: ibStencilTemplates.C — interpolation to the markers and
    spreading from them, for any field type.
\*---------------------------------------------------------------------------*/

#include "ibStencil.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::ibStencil::sumToMarkers
(
    const UList<Type>& values,
    const labelUList& index,
    List<Type>& markerValues
) const
{
    markerValues.setSize(nMarkers_);

    for (label m = 0; m < nMarkers_; ++m)
    {
        Type sum(Zero);
        for (label k = offsets_[m]; k < offsets_[m + 1]; ++k)
        {
            sum += weights_[k]*values[index[k]];
        }
        markerValues[m] = sum;
    }

    // Every rank calls this, with or without local stencil entries
    Pstream::listCombineGather(markerValues, plusEqOp<Type>());
    Pstream::listCombineScatter(markerValues);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::ibStencil::interpolate
(
    const UList<Type>& cellValues,
    List<Type>& markerValues
) const
{
    if (cellValues.size() != mesh_.nCells())
    {
        FatalErrorInFunction
            << "Cell values of size " << cellValues.size()
            << " for a mesh of " << mesh_.nCells() << " cells"
            << exit(FatalError);
    }

    sumToMarkers(cellValues, cells_, markerValues);
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::ibStencil::interpolate
(
    const GeometricField<Type, fvPatchField, volMesh>& vf
) const
{
    tmp<Field<Type>> tresult(new Field<Type>(nMarkers_));
    interpolate(vf.primitiveField(), tresult.ref());
    return tresult;
}


template<class Type>
void Foam::ibStencil::spread
(
    const UList<Type>& markerValues,
    UList<Type>& cellField
) const
{
    checkMarkerCount(markerValues.size());
    if (cellField.size() != mesh_.nCells())
    {
        FatalErrorInFunction
            << "Cell field of size " << cellField.size()
            << " for a mesh of " << mesh_.nCells() << " cells"
            << exit(FatalError);
    }

    const scalarField& V = mesh_.cellVolumes();

    for (label m = 0; m < nMarkers_; ++m)
    {
        const Type& F = markerValues[m];
        for (label k = offsets_[m]; k < offsets_[m + 1]; ++k)
        {
            const label celli = cells_[k];
            cellField[celli] += (weights_[k]/V[celli])*F;
        }
    }
}


template<class Type>
void Foam::ibStencil::interpolateSpread
(
    const UList<Type>& markerValues,
    List<Type>& result
) const
{
    checkMarkerCount(markerValues.size());

    const scalarField& V = mesh_.cellVolumes();

    // The spread densities on the stencils' cells
    List<Type> density(stencilCells_.size(), Zero);
    for (label m = 0; m < nMarkers_; ++m)
    {
        const Type& F = markerValues[m];
        for (label k = offsets_[m]; k < offsets_[m + 1]; ++k)
        {
            density[entrySlot_[k]] += (weights_[k]/V[cells_[k]])*F;
        }
    }

    sumToMarkers(density, entrySlot_, result);
}


template<class Type>
void Foam::ibStencil::shareSpread
(
    const UList<Type>& markerValues,
    const scalarUList& shares,
    List<Type>& result
) const
{
    checkMarkerCount(markerValues.size());
    checkMarkerCount(shares.size());

    // Per stencil cell: the integrated value spread into it, and the sum of
    // the markers' claims s_m |w_mi| on it
    List<Type> cellValue(stencilCells_.size(), Zero);
    scalarList claims(stencilCells_.size(), Zero);
    for (label m = 0; m < nMarkers_; ++m)
    {
        for (label k = offsets_[m]; k < offsets_[m + 1]; ++k)
        {
            cellValue[entrySlot_[k]] += weights_[k]*markerValues[m];
            claims[entrySlot_[k]] += shares[m]*mag(weights_[k]);
        }
    }

    result.setSize(nMarkers_);
    for (label m = 0; m < nMarkers_; ++m)
    {
        Type sum(Zero);
        for (label k = offsets_[m]; k < offsets_[m + 1]; ++k)
        {
            const scalar claim = shares[m]*mag(weights_[k]);
            if (claim > 0)
            {
                sum += (claim/claims[entrySlot_[k]])*cellValue[entrySlot_[k]];
            }
        }
        result[m] = sum;
    }

    // Every rank calls this, with or without local stencil entries; a
    // cell's claims are all on the rank that holds it
    Pstream::listCombineGather(result, plusEqOp<Type>());
    Pstream::listCombineScatter(result);
}


// ************************************************************************* //
