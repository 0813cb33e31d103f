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

#include "polygon.H"
#include "planarArea.H"
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
    defineTypeNameAndDebug(polygon, 0);
    addToRunTimeSelectionTable(bodyShape, polygon, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShapes::polygon::polygon
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    axes_(direction(0)),
    vertices_(),
    centroid_(Zero),
    area_(0),
    Suu_(0),
    Svv_(0),
    Suv_(0),
    radius_(0),
    labVertices_(),
    labMin_(Zero),
    labMax_(Zero),
    labOrient_(1)
{
    checkDimension(mesh, dict, 2, axes_);
    setVertices(dict.get<List<vector2D>>("vertices"), dict);
    setLabVertices();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::bodyShapes::polygon::setVertices
(
    const List<vector2D>& p,
    const dictionary& dict
)
{
    const label n = p.size();
    const word body(dict.dictName());

    if (n < 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'vertices' of body " << body << ": a polygon needs at"
            << " least 3 vertices, got " << n << exit(FatalIOError);
    }

    // Size for the round-off limits
    scalar size = 0;
    for (const vector2D& q : p)
    {
        size = max(size, mag(q - p[0]));
    }

    // Distinct, every turn to the left, winding once
    scalar turning = 0;
    for (label i = 0; i < n; ++i)
    {
        const vector2D e0(p[(i + 1) % n] - p[i]);
        const vector2D e1(p[(i + 2) % n] - p[(i + 1) % n]);
        if (mag(e0) <= 1e-12*size)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'vertices' of body " << body << ": vertices " << i
                << " and " << (i + 1) % n << " coincide at " << p[i]
                << exit(FatalIOError);
        }
        const scalar cross = e0.x()*e1.y() - e0.y()*e1.x();
        if (cross <= 1e-12*mag(e0)*mag(e1))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'vertices' of body " << body << ": the polygon "
                << p << " is not convex and counter-clockwise: the turn at"
                << " vertex " << (i + 1) % n << " " << p[(i + 1) % n]
                << " is " << (cross < 0 ? "to the right" : "straight")
                << " (list the vertices of a convex polygon"
                << " counter-clockwise in the plane's (u v))"
                << exit(FatalIOError);
        }
        turning += std::atan2(cross, e0 & e1);
    }
    if (mag(turning - constant::mathematical::twoPi) > 1e-6)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'vertices' of body " << body << ": the polygon " << p
            << " winds " << turning/constant::mathematical::twoPi
            << " times around its interior (it crosses itself); a convex"
            << " polygon winds once" << exit(FatalIOError);
    }

    // Area and centroid (about p[0] for round-off)
    scalar A2 = 0;
    vector2D C(Zero);
    for (label i = 0; i < n; ++i)
    {
        const vector2D a(p[i] - p[0]);
        const vector2D b(p[(i + 1) % n] - p[0]);
        const scalar c = a.x()*b.y() - b.x()*a.y();
        A2 += c;
        C += (a + b)*c;
    }
    area_ = 0.5*A2;
    C /= 3*A2;
    centroid_ = p[0] + C;

    // Vertices about the centroid and the second moments there
    vertices_.setSize(n);
    radius_ = 0;
    for (label i = 0; i < n; ++i)
    {
        vertices_[i] = p[i] - centroid_;
        radius_ = max(radius_, mag(vertices_[i]));
    }
    Suu_ = Svv_ = Suv_ = 0;
    for (label i = 0; i < n; ++i)
    {
        const vector2D& a = vertices_[i];
        const vector2D& b = vertices_[(i + 1) % n];
        const scalar c = a.x()*b.y() - b.x()*a.y();
        Suu_ += c*(sqr(a.x()) + a.x()*b.x() + sqr(b.x()));
        Svv_ += c*(sqr(a.y()) + a.y()*b.y() + sqr(b.y()));
        Suv_ +=
            c*(2*a.x()*a.y() + a.x()*b.y() + b.x()*a.y() + 2*b.x()*b.y());
    }
    Suu_ /= 12;
    Svv_ /= 12;
    Suv_ /= 24;
}


Foam::vector2D Foam::fbm::bodyShapes::polygon::toPlane
(
    const vector& r
) const
{
    const vector rb(toBody(inPlane(r)));
    return vector2D(rb[axes_[0]], rb[axes_[1]]);
}


Foam::scalar Foam::fbm::bodyShapes::polygon::distance
(
    const vector2D& p,
    vector2D& nOut
) const
{
    const label n = vertices_.size();

    // Largest signed distance to the edges' lines (outward normals of a
    // counter-clockwise polygon point to the right of its edges)
    scalar sMax = -GREAT;
    label iMax = 0;
    for (label i = 0; i < n; ++i)
    {
        const vector2D e(vertices_[(i + 1) % n] - vertices_[i]);
        const vector2D nrm(vector2D(e.y(), -e.x())/mag(e));
        const scalar s = nrm & (p - vertices_[i]);
        if (s > sMax)
        {
            sMax = s;
            iMax = i;
        }
    }
    if (sMax <= 0)
    {
        const vector2D e(vertices_[(iMax + 1) % n] - vertices_[iMax]);
        nOut = vector2D(e.y(), -e.x())/mag(e);
        return sMax;
    }

    // Outside: the nearest edge segment
    scalar d2Min = GREAT;
    for (label i = 0; i < n; ++i)
    {
        const vector2D& a = vertices_[i];
        const vector2D e(vertices_[(i + 1) % n] - a);
        const scalar t = max(scalar(0), min(scalar(1), ((p - a) & e)/(e & e)));
        const vector2D q(a + t*e);
        const scalar d2 = magSqr(p - q);
        if (d2 < d2Min)
        {
            d2Min = d2;
            nOut = p - q;
        }
    }
    const scalar d = Foam::sqrt(d2Min);
    nOut /= max(d, VSMALL);
    return d;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::polygon::signedDistance
(
    const vector& r
) const
{
    vector2D n;
    return distance(toPlane(r), n);
}


Foam::vector Foam::fbm::bodyShapes::polygon::normal(const vector& r) const
{
    vector2D n2;
    distance(toPlane(r), n2);
    vector nb(Zero);
    nb[axes_[0]] = n2.x();
    nb[axes_[1]] = n2.y();
    return inPlane(toLab(nb));
}


Foam::vector Foam::fbm::bodyShapes::polygon::halfExtent() const
{
    vector h(Zero);
    for (const vector2D& p : vertices_)
    {
        vector pb(Zero);
        pb[axes_[0]] = p.x();
        pb[axes_[1]] = p.y();
        h = max(h, cmptMag(toLab(pb)));
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD_[d] < 0) h[d] = GREAT;
    }
    return h;
}


void Foam::fbm::bodyShapes::polygon::setLabVertices()
{
    const direction i = axes_[0], j = axes_[1];
    labVertices_.resize(vertices_.size());
    labMin_ = vector2D::uniform(GREAT);
    labMax_ = -labMin_;
    forAll(vertices_, k)
    {
        vector pb(Zero);
        pb[i] = vertices_[k].x();
        pb[j] = vertices_[k].y();
        const vector pl(toLab(pb));
        labVertices_[k] = vector2D(pl[i], pl[j]);
        labMin_ = min(labMin_, labVertices_[k]);
        labMax_ = max(labMax_, labVertices_[k]);
    }
    labOrient_ = planarArea::area(labVertices_) < 0 ? -1 : 1;
}


void Foam::fbm::bodyShapes::polygon::setOrientation(const tensor& Q)
{
    bodyShape::setOrientation(Q);
    setLabVertices();
}


Foam::scalar Foam::fbm::bodyShapes::polygon::boxFraction
(
    const boundBox& bb,
    const label
) const
{
    const direction i = axes_[0], j = axes_[1];
    const vector2D lo(bb.min()[i], bb.min()[j]);
    const vector2D hi(bb.max()[i], bb.max()[j]);
    const scalar boxArea = (hi.x() - lo.x())*(hi.y() - lo.y());
    if (!(hi.x() > lo.x() && hi.y() > lo.y()))
    {
        return 0;
    }

    // Apart from the turned polygon's bounding box: 0
    if
    (
        labMax_.x() <= lo.x() || labMin_.x() >= hi.x()
     || labMax_.y() <= lo.y() || labMin_.y() >= hi.y()
    )
    {
        return 0;
    }

    // Every corner of the box on the inner side of every edge: 1
    const List<vector2D>& p = labVertices_;
    const label n = p.size();
    bool inside = true;
    for (label k = 0; k < n && inside; ++k)
    {
        const vector2D& a = p[k];
        const vector2D e(p[(k + 1) % n] - a);
        for (label c = 0; c < 4 && inside; ++c)
        {
            const vector2D q
            (
                (c == 1 || c == 2) ? hi.x() : lo.x(),
                c < 2 ? lo.y() : hi.y()
            );
            const vector2D r(q - a);
            inside = labOrient_*(e.x()*r.y() - e.y()*r.x()) >= 0;
        }
    }
    if (inside)
    {
        return 1;
    }

    return max
    (
        scalar(0),
        min(scalar(1), planarArea::boxPolygon(p, lo, hi)/boxArea)
    );
}


Foam::scalar Foam::fbm::bodyShapes::polygon::volume() const
{
    return area_*depth_;
}


Foam::symmTensor Foam::fbm::bodyShapes::polygon::inertiaPerDensity() const
{
    const scalar L = depth_;
    const scalar V = volume();
    const direction u = axes_[0], v = axes_[1];
    const direction w = 3 - u - v;

    tensor I(Zero);
    I(u, u) = L*Svv_ + V*sqr(L)/12;
    I(v, v) = L*Suu_ + V*sqr(L)/12;
    I(w, w) = L*(Suu_ + Svv_);
    I(u, v) = I(v, u) = -L*Suv_;
    return symm(I);
}


Foam::vector Foam::fbm::bodyShapes::polygon::centroid() const
{
    vector c(Zero);
    c[axes_[0]] = centroid_.x();
    c[axes_[1]] = centroid_.y();
    return c;
}


Foam::scalar Foam::fbm::bodyShapes::polygon::diameter() const
{
    return 2*Foam::sqrt(area_/constant::mathematical::pi);
}


Foam::vector Foam::fbm::bodyShapes::polygon::support
(
    const tensor& Q,
    const vector& d
) const
{
    const vector db(Q.T() & inPlane(d));
    const vector2D d2(db[axes_[0]], db[axes_[1]]);
    const vector2D& v = supportPoint(vertices_, d2);
    vector pb(Zero);
    pb[axes_[0]] = v.x();
    pb[axes_[1]] = v.y();
    return Q & pb;
}


Foam::vector Foam::fbm::bodyShapes::polygon::planeContact
(
    const tensor& Q,
    const vector& d,
    const scalar band
) const
{
    const vector db(Q.T() & inPlane(d));
    const vector2D d2(db[axes_[0]], db[axes_[1]]);
    const vector2D m(bandMiddle(vertices_, d2, band));
    vector pb(Zero);
    pb[axes_[0]] = m.x();
    pb[axes_[1]] = m.y();
    return Q & pb;
}



void Foam::fbm::bodyShapes::polygon::supportBand
(
    const tensor& Q,
    const vector& d,
    const scalar band,
    DynamicList<vector>& pts,
    DynamicList<scalar>& weights
) const
{
    const vector db(Q.T() & inPlane(d));
    const vector2D d2(db[axes_[0]], db[axes_[1]]);
    DynamicList<vector2D> sel;
    bandPoints(vertices_, d2, band, sel, weights);
    for (const vector2D& v : sel)
    {
        vector pb(Zero);
        pb[axes_[0]] = v.x();
        pb[axes_[1]] = v.y();
        pts.append(Q & pb);
    }
}

// ************************************************************************* //
