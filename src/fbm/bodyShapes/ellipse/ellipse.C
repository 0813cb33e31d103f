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
#include "planarArea.H"
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


Foam::scalar Foam::fbm::bodyShapes::ellipse::boxFraction
(
    const boundBox& bb,
    const label
) const
{
    const direction i = axes_[0], j = axes_[1];
    const scalar x[2] = {bb.min()[i], bb.max()[i]};
    const scalar y[2] = {bb.min()[j], bb.max()[j]};
    if (!(x[1] > x[0] && y[1] > y[0]))
    {
        return 0;
    }

    // The rectangle's corners counter-clockwise, mapped to the frame where
    // the ellipse is the unit disk
    const label cx[4] = {0, 1, 1, 0}, cy[4] = {0, 0, 1, 1};
    vector2D corners[4];
    UList<vector2D> p(corners, 4);
    for (label k = 0; k < 4; ++k)
    {
        vector r(Zero);
        r[i] = x[cx[k]];
        r[j] = y[cy[k]];
        const vector rb(toBody(r));
        p[k] = vector2D(rb[i]/a_, rb[j]/b_);
    }

    // A rotation that turns the plane over reverses the corners' order
    scalar A = planarArea::area(p);
    if (A < 0)
    {
        Swap(p[1], p[3]);
        A = -A;
    }

    return max(scalar(0), min(scalar(1), planarArea::diskPolygon(p, 1)/A));
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
