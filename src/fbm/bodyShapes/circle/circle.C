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
#include "planarArea.H"

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
    bodyShape(mesh),
    radius_(readLength(dict, "radius", mesh)),
    axes_(direction(0))
{
    setAxes(mesh, &dict);
}


Foam::fbm::bodyShapes::circle::circle
(
    const scalar radius,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    radius_(radius),
    axes_(direction(0))
{
    setAxes(mesh, nullptr);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::bodyShapes::circle::setAxes
(
    const polyMesh& mesh,
    const dictionary* dict
)
{
    if (mesh.nSolutionD() != 2)
    {
        const string msg
        (
            "A circle needs a 2D mesh (one cell thick, empty front and back),"
            " this mesh has " + Foam::name(mesh.nSolutionD())
          + " solution directions: use 'type sphere;' in 3D"
        );
        if (dict)
        {
            FatalIOErrorInFunction(*dict) << msg.c_str() << exit(FatalIOError);
        }
        FatalErrorInFunction << msg.c_str() << exit(FatalError);
    }

    label n = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD()[d] >= 0)
        {
            axes_[n++] = d;
        }
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


Foam::scalar Foam::fbm::bodyShapes::circle::boxFraction
(
    const boundBox& bb,
    const label
) const
{
    const direction i = axes_[0], j = axes_[1];
    const scalar x0 = bb.min()[i], x1 = bb.max()[i];
    const scalar y0 = bb.min()[j], y1 = bb.max()[j];
    const scalar boxArea = (x1 - x0)*(y1 - y0);
    const scalar R2 = sqr(radius_);

    // Wholly outside: the nearest point of the box; wholly inside: the
    // farthest corner
    const scalar nx = max(x0, min(scalar(0), x1));
    const scalar ny = max(y0, min(scalar(0), y1));
    if (boxArea <= 0 || sqr(nx) + sqr(ny) >= R2)
    {
        return 0;
    }
    if (sqr(max(mag(x0), mag(x1))) + sqr(max(mag(y0), mag(y1))) <= R2)
    {
        return 1;
    }

    // The corners counter-clockwise
    const vector2D c[4] =
    {
        vector2D(x0, y0), vector2D(x1, y0), vector2D(x1, y1), vector2D(x0, y1)
    };
    scalar area = 0;
    for (label k = 0; k < 4; ++k)
    {
        area += planarArea::diskTriangle(c[k], c[(k + 1) % 4], radius_);
    }

    return max(scalar(0), min(scalar(1), area/boxArea));
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


Foam::vector Foam::fbm::bodyShapes::circle::support
(
    const tensor&,
    const vector& d
) const
{
    const vector dp(inPlane(d));
    const scalar m = mag(dp);
    return m > 0 ? (radius_/m)*dp : vector::zero;
}


// ************************************************************************* //
