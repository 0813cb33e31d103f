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
    defineTypeNameAndDebug(ellipsoid, 0);
    addToRunTimeSelectionTable(bodyShape, ellipsoid, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShapes::ellipsoid::ellipsoid
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    e_(Zero)
{
    // The mesh first: the message for a 2D mesh names the shape
    FixedList<direction, 2> axes;
    checkDimension(mesh, dict, 3, axes);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const word key(d == 0 ? "a" : d == 1 ? "b" : "c");
        e_[d] = readLength(dict, key, mesh);
    }
}


Foam::fbm::bodyShapes::ellipsoid::ellipsoid
(
    const vector& semiAxes,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    e_(semiAxes)
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::ellipsoid::distance
(
    const vector& e,
    const vector& y,
    vector& n
)
{
    // By symmetry: the point's mirror image in the first octant
    vector z(Zero), sgn(Zero);
    label k = -1;
    scalar g = -1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (e[d] > 0)
        {
            z[d] = mag(y[d]);
            sgn[d] = (y[d] < 0) ? -1 : 1;
            g += sqr(z[d]/e[d]);
            if (k < 0 || e[d] < e[k])
            {
                k = d;
            }
        }
    }

    // Off the plane of the smallest axis (the root then lies near the
    // pole, found wherever the closest point is)
    z[k] = max(z[k], 1e-15*e[k]);

    // Newton from the left of the root: F convex and decreasing. The
    // unknown is the distance from the pole, s = t + e_k^2 (t itself would
    // lose the digits of a root near the pole)
    const scalar ek2 = sqr(e[k]);
    scalar s = e[k]*z[k];
    for (label iter = 0; iter < 200; ++iter)
    {
        scalar F = -1, dF = 0;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (e[d] > 0)
            {
                const scalar p = (d == k) ? s : s + (sqr(e[d]) - ek2);
                const scalar q = sqr(e[d]*z[d]/p);
                F += q;
                dF -= 2*q/p;
            }
        }
        if (F <= 0 || dF >= 0)
        {
            break;
        }
        const scalar ds = -F/dF;
        s += ds;
        if (ds <= 1e-15*s)
        {
            break;
        }
    }

    // The closest point, the distance and the normal there
    scalar dist2 = 0;
    n = Zero;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (e[d] > 0)
        {
            const scalar p = (d == k) ? s : s + (sqr(e[d]) - ek2);
            const scalar x = sqr(e[d])*z[d]/p;
            dist2 += sqr(z[d] - x);
            n[d] = sgn[d]*x/sqr(e[d]);
        }
    }
    n /= max(mag(n), VSMALL);

    const scalar dist = Foam::sqrt(dist2);
    return (g < 0) ? -dist : dist;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::ellipsoid::signedDistance
(
    const vector& r
) const
{
    vector n;
    return distance(e_, toBody(r), n);
}


Foam::vector Foam::fbm::bodyShapes::ellipsoid::normal(const vector& r) const
{
    vector n;
    distance(e_, toBody(r), n);
    return toLab(n);
}


Foam::vector Foam::fbm::bodyShapes::ellipsoid::halfExtent() const
{
    return rotatedHalfExtent(e_);
}


Foam::scalar Foam::fbm::bodyShapes::ellipsoid::mappedFraction
(
    const vector& m,
    const tensor& E,
    const label nSubdivision
)
{
    const scalar mm = mag(m);
    const scalar d = mm - 1;
    const scalar reach = mag(E.x()) + mag(E.y()) + mag(E.z());

    if (d <= -reach)
    {
        return 1;
    }
    if (d >= reach)
    {
        return 0;
    }

    if (nSubdivision <= 0)
    {
        // Leaf: the share behind the tangent plane at the centre
        if (mm < VSMALL)
        {
            return 1;
        }
        const vector n(m/mm);
        const scalar width =
            2*(mag(n & E.x()) + mag(n & E.y()) + mag(n & E.z()));
        if (width < VSMALL)
        {
            return d < 0 ? 1 : 0;
        }
        return max(scalar(0), min(scalar(1), 0.5 - d/width));
    }

    const tensor Eh(0.5*E);
    scalar sum = 0;
    for (label child = 0; child < 8; ++child)
    {
        const vector mc
        (
            m
          + ((child & 1) ? Eh.x() : -Eh.x())
          + ((child & 2) ? Eh.y() : -Eh.y())
          + ((child & 4) ? Eh.z() : -Eh.z())
        );
        sum += mappedFraction(mc, Eh, nSubdivision - 1);
    }
    return sum/8;
}


Foam::scalar Foam::fbm::bodyShapes::ellipsoid::boxFraction
(
    const boundBox& bb,
    const label nSubdivision
) const
{
    // x' = S Q^T x, S = diag(1/a, 1/b, 1/c): the box's centre and its
    // half edges (the rows of E: S Q^T e_i h_i)
    const tensor SQt
    (
        tensor(1/e_.x(), 0, 0, 0, 1/e_.y(), 0, 0, 0, 1/e_.z())
      & Q_.T()
    );
    const vector h(0.5*bb.span());
    const tensor E
    (
        SQt.cx()*h.x(),
        SQt.cy()*h.y(),
        SQt.cz()*h.z()
    );
    return mappedFraction(SQt & bb.centre(), E, nSubdivision);
}


Foam::scalar Foam::fbm::bodyShapes::ellipsoid::volume() const
{
    return 4.0/3.0*constant::mathematical::pi*e_.x()*e_.y()*e_.z();
}


Foam::symmTensor Foam::fbm::bodyShapes::ellipsoid::inertiaPerDensity() const
{
    const scalar V = volume();
    const vector e2(cmptMultiply(e_, e_));
    symmTensor I(Zero);
    I.xx() = V*(e2.y() + e2.z())/5;
    I.yy() = V*(e2.x() + e2.z())/5;
    I.zz() = V*(e2.x() + e2.y())/5;
    return I;
}


Foam::scalar Foam::fbm::bodyShapes::ellipsoid::diameter() const
{
    return 2*Foam::cbrt(e_.x()*e_.y()*e_.z());
}


Foam::vector Foam::fbm::bodyShapes::ellipsoid::supportPoint
(
    const vector& e,
    const tensor& Q,
    const vector& d
)
{
    // Body frame: x.d largest on x^T diag(e)^-2 x = 1 at
    // x = E db/sqrt(db.E db), E = diag(e^2), db = Q^T d
    const vector db(Q.T() & d);
    const vector Edb(sqr(e.x())*db.x(), sqr(e.y())*db.y(), sqr(e.z())*db.z());
    const scalar s = db & Edb;
    return s > 0 ? (Q & Edb)/Foam::sqrt(s) : vector::zero;
}


Foam::vector Foam::fbm::bodyShapes::ellipsoid::support
(
    const tensor& Q,
    const vector& d
) const
{
    return supportPoint(e_, Q, d);
}


// ************************************************************************* //
