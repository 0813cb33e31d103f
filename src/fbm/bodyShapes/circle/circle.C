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

#include "circle.H"
#include "polyMesh.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace bodyShapes
{
    defineTypeNameAndDebug(circle, 0);
    addToRunTimeSelectionTable(bodyShape, circle, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShapes::circle::circle
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    bodyShape(dict, mesh),
    radius_(dict.getCheck<scalar>("radius", [](scalar r){ return r > 0; }))
{
    if (mesh.nSolutionD() != 2)
    {
        FatalIOErrorInFunction(dict)
            << "A circle needs a 2D mesh (one cell thick, empty front and"
            << " back), this mesh has " << mesh.nSolutionD()
            << " solution directions: use 'type sphere;' in 3D"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::circle::signedDistance
(
    const vector& r
) const
{
    return mag(inPlane(r)) - radius_;
}


Foam::vector Foam::fbm::bodyShapes::circle::normal(const vector& r) const
{
    const vector rp(inPlane(r));
    const scalar m = mag(rp);
    if (m < VSMALL)
    {
        return inPlane(vector(1, 1, 1))/mag(inPlane(vector(1, 1, 1)));
    }
    return rp/m;
}


Foam::vector Foam::fbm::bodyShapes::circle::halfExtent() const
{
    vector h(radius_, radius_, radius_);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD_[d] < 0) h[d] = GREAT;
    }
    return h;
}


Foam::scalar Foam::fbm::bodyShapes::circle::volume() const
{
    return constant::mathematical::pi*sqr(radius_)*depth_;
}


Foam::symmTensor Foam::fbm::bodyShapes::circle::inertiaPerDensity() const
{
    // Cylinder of length depth: 1/2 m R^2 about the axis,
    // m (3 R^2 + L^2)/12 about the in-plane axes
    const scalar m = volume();
    const scalar Iaxis = 0.5*m*sqr(radius_);
    const scalar Iperp = m*(3*sqr(radius_) + sqr(depth_))/12;

    symmTensor I(Zero);
    I.xx() = (solutionD_.x() < 0) ? Iaxis : Iperp;
    I.yy() = (solutionD_.y() < 0) ? Iaxis : Iperp;
    I.zz() = (solutionD_.z() < 0) ? Iaxis : Iperp;
    return I;
}


// ************************************************************************* //
