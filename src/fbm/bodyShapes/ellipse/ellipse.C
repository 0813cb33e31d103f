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

#include "ellipse.H"
#include "ellipsoid.H"
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
    defineTypeNameAndDebug(ellipse, 0);
    addToRunTimeSelectionTable(bodyShape, ellipse, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShapes::ellipse::ellipse
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    a_(0),
    b_(0),
    axes_(direction(0)),
    e_(Zero)
{
    // The mesh first: the message for a 3D mesh names the shape
    checkDimension(mesh, dict, 2, axes_);
    a_ = readLength(dict, "a", mesh);
    b_ = readLength(dict, "b", mesh);
    setSemiAxes();
}


Foam::fbm::bodyShapes::ellipse::ellipse
(
    const scalar a,
    const scalar b,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    a_(a),
    b_(b),
    axes_(direction(0)),
    e_(Zero)
{
    label n = 0;
    for (direction d = 0; d < vector::nComponents && n < 2; ++d)
    {
        if (solutionD_[d] >= 0)
        {
            axes_[n++] = d;
        }
    }
    setSemiAxes();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::bodyShapes::ellipse::setSemiAxes()
{
    e_ = Zero;
    e_[axes_[0]] = a_;
    e_[axes_[1]] = b_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::ellipse::signedDistance
(
    const vector& r
) const
{
    vector n;
    return ellipsoid::distance(e_, toBody(inPlane(r)), n);
}


Foam::vector Foam::fbm::bodyShapes::ellipse::normal(const vector& r) const
{
    vector n;
    ellipsoid::distance(e_, toBody(inPlane(r)), n);
    return inPlane(toLab(n));
}


Foam::vector Foam::fbm::bodyShapes::ellipse::halfExtent() const
{
    vector h(rotatedHalfExtent(e_));
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD_[d] < 0) h[d] = GREAT;
    }
    return h;
}


Foam::scalar Foam::fbm::bodyShapes::ellipse::volume() const
{
    return constant::mathematical::pi*a_*b_*depth_;
}


Foam::symmTensor Foam::fbm::bodyShapes::ellipse::inertiaPerDensity() const
{
    const scalar V = volume();
    const scalar L2 = sqr(depth_);
    const direction u = axes_[0], v = axes_[1];
    const direction w = 3 - u - v;

    tensor I(Zero);
    I(u, u) = V*(sqr(b_)/4 + L2/12);
    I(v, v) = V*(sqr(a_)/4 + L2/12);
    I(w, w) = V*(sqr(a_) + sqr(b_))/4;
    return symm(I);
}


Foam::vector Foam::fbm::bodyShapes::ellipse::support
(
    const tensor& Q,
    const vector& d
) const
{
    // e_ is 0 in the empty direction: the point is in the plane
    return ellipsoid::supportPoint(e_, Q, inPlane(d));
}


// ************************************************************************* //
