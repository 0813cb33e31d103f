/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "bodyShape.H"
#include "polyMesh.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(bodyShape, 0);
    defineRunTimeSelectionTable(bodyShape, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShape::bodyShape(const polyMesh& mesh)
:
    solutionD_(mesh.solutionD()),
    depth_(1),
    Q_(tensor::I)
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD_[d] < 0)
        {
            depth_ = mesh.bounds().span()[d];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fbm::bodyShape::support
(
    const tensor&,
    const vector&
) const
{
    FatalErrorInFunction
        << "The shape " << type() << " has no support function"
        << abort(FatalError);
    return Zero;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::vector Foam::fbm::bodyShape::rotatedHalfExtent(const vector& e) const
{
    // The support of the ellipsoid in direction d: |diag(e) Q^T e_d|
    vector h(Zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        scalar s = 0;
        for (direction k = 0; k < vector::nComponents; ++k)
        {
            s += sqr(Q_(d, k)*e[k]);
        }
        h[d] = Foam::sqrt(s);
    }
    return h;
}


void Foam::fbm::bodyShape::checkDimension
(
    const polyMesh& mesh,
    const dictionary& dict,
    const label nDim,
    FixedList<direction, 2>& axes
) const
{
    if (mesh.nSolutionD() != nDim)
    {
        FatalIOErrorInFunction(dict)
            << "Body shape " << dict.get<word>("type") << " (body "
            << dict.dictName() << ") needs a " << nDim << "D mesh"
            << (nDim == 2 ? " (one cell thick, empty front and back)" : "")
            << ", this mesh has " << mesh.nSolutionD()
            << " solution directions" << exit(FatalIOError);
    }
    axes = direction(0);
    label n = 0;
    for (direction d = 0; d < vector::nComponents && n < 2; ++d)
    {
        if (solutionD_[d] >= 0)
        {
            axes[n++] = d;
        }
    }
}


Foam::scalar Foam::fbm::bodyShape::readLength
(
    const dictionary& dict,
    const word& key,
    const polyMesh& mesh
)
{
    // (OpenFOAM reads magnitudes below 1e-300 as 0)
    const scalar L = dict.getCheck<scalar>(key, [](scalar r){ return r >= 0; });
    const scalar d = mag(mesh.bounds().span());
    if (!(L <= d && L >= 1e-6*d))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' " << L << " in " << dict.name()
            << " is out of range for this mesh: a body's " << key
            << " lies between 1e-6 d and d, d = " << d << " the diagonal"
            << " of the mesh's bounding box (magnitudes below 1e-300 are"
            << " read as 0)" << exit(FatalIOError);
    }
    return L;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShape::sampleFraction
(
    const boundBox& bb,
    const label nSubdivision
) const
{
    const vector c(inPlane(bb.centre()));
    const vector half(inPlane(0.5*bb.span()));
    const scalar d = signedDistance(c);
    const scalar halfDiag = mag(half);

    if (d <= -halfDiag)
    {
        return 1;
    }
    if (d >= halfDiag)
    {
        return 0;
    }

    if (nSubdivision <= 0)
    {
        // Leaf: fraction of the box behind the tangent plane at the centre
        const vector n(normal(c));
        scalar width = 0;
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            width += 2*half[i]*mag(n[i]);
        }
        if (width < VSMALL)
        {
            return d < 0 ? 1 : 0;
        }
        return max(scalar(0), min(scalar(1), 0.5 - d/width));
    }

    // Split along every solution direction and average the children
    scalar sum = 0;
    label nChildren = 0;
    const point& lo = bb.min();
    const point mid(bb.centre());
    const point& hi = bb.max();

    for (label child = 0; child < 8; ++child)
    {
        point cMin(lo), cMax(hi);
        bool used = true;
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            const bool upper = (child >> i) & 1;
            if (solutionD_[i] < 0)
            {
                // Empty direction: not split, only the first half is used
                if (upper) used = false;
                continue;
            }
            if (upper) cMin[i] = mid[i]; else cMax[i] = mid[i];
        }
        if (used)
        {
            sum += sampleFraction(boundBox(cMin, cMax), nSubdivision - 1);
            ++nChildren;
        }
    }

    return sum/nChildren;
}


// ************************************************************************* //
