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

#include "contactPatch.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// z-component of (b - o) x (c - o)
inline Foam::scalar cross2
(
    const Foam::vector2D& o,
    const Foam::vector2D& b,
    const Foam::vector2D& c
)
{
    return (b.x() - o.x())*(c.y() - o.y()) - (b.y() - o.y())*(c.x() - o.x());
}

inline Foam::scalar cross2(const Foam::vector2D& a, const Foam::vector2D& b)
{
    return a.x()*b.y() - a.y()*b.x();
}

inline bool lexLess(const Foam::vector2D& a, const Foam::vector2D& b)
{
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

// The middle of the part of the segment p0-p1 inside the convex polygon
// P (counter-clockwise; Cyrus & Beck 1978); false where it misses P.
// region (if given) gets the part's two ends where it is longer than tol
bool clipSegment
(
    const Foam::vector2D& p0,
    const Foam::vector2D& p1,
    const Foam::List<Foam::vector2D>& P,
    const Foam::scalar tol,
    Foam::vector2D& middle,
    Foam::DynamicList<Foam::vector2D>* region
)
{
    using namespace Foam;
    const vector2D d(p1 - p0);
    scalar tIn = 0;
    scalar tOut = 1;
    forAll(P, i)
    {
        const vector2D& a = P[i];
        const vector2D e(P[P.fcIndex(i)] - a);
        const scalar magE = mag(e);
        // Inside: cross(e, q - a) >= 0
        const scalar N = cross2(e, p0 - a);
        const scalar D = cross2(e, d);
        if (mag(D) <= SMALL*magE*mag(d))
        {
            if (N < -tol*magE)
            {
                return false;
            }
            continue;
        }
        const scalar t = -N/D;
        if (D > 0)
        {
            tIn = max(tIn, t);
        }
        else
        {
            tOut = min(tOut, t);
        }
    }
    if (tIn > tOut)
    {
        return false;
    }
    middle = p0 + 0.5*(tIn + tOut)*d;
    if (region && (tOut - tIn)*mag(d) > tol)
    {
        region->append(p0 + tIn*d);
        region->append(p0 + tOut*d);
    }
    return true;
}

// The crossing or the middle of the overlap of the segments a0-a1 and
// b0-b1; false where they miss each other. region (if given) gets the
// overlap's two ends where the segments lie on one line and overlap by
// more than tol
bool segmentMiddle
(
    const Foam::vector2D& a0,
    const Foam::vector2D& a1,
    const Foam::vector2D& b0,
    const Foam::vector2D& b1,
    const Foam::scalar tol,
    Foam::vector2D& middle,
    Foam::DynamicList<Foam::vector2D>* region
)
{
    using namespace Foam;
    const vector2D da(a1 - a0);
    const vector2D db(b1 - b0);
    const scalar la = mag(da);
    const scalar lb = mag(db);
    const scalar denom = cross2(da, db);
    if (mag(denom) > SMALL*la*lb)
    {
        const scalar s = cross2(b0 - a0, db)/denom;
        const scalar u = cross2(b0 - a0, da)/denom;
        const scalar es = tol/la;
        const scalar eu = tol/lb;
        if (s < -es || s > 1 + es || u < -eu || u > 1 + eu)
        {
            return false;
        }
        middle = a0 + min(max(s, scalar(0)), scalar(1))*da;
        return true;
    }

    // Parallel: on one line, the middle of the overlap along it
    const vector2D ea(da/la);
    if (mag(cross2(ea, b0 - a0)) > tol)
    {
        return false;
    }
    const scalar s0 = (b0 - a0) & ea;
    const scalar s1 = (b1 - a0) & ea;
    const scalar lo = max(scalar(0), min(s0, s1));
    const scalar hi = min(la, max(s0, s1));
    if (lo > hi + tol)
    {
        return false;
    }
    middle = a0 + 0.5*(lo + hi)*ea;
    if (region && hi - lo > tol)
    {
        region->append(a0 + lo*ea);
        region->append(a0 + hi*ea);
    }
    return true;
}

// The area centroid of a polygon (its vertex mean if its area vanishes)
Foam::vector2D polygonCentroid
(
    const Foam::DynamicList<Foam::vector2D>& P,
    const Foam::scalar areaTol
)
{
    using namespace Foam;
    vector2D mean(Zero);
    for (const vector2D& p : P)
    {
        mean += p;
    }
    mean /= P.size();

    scalar A2 = 0;
    vector2D c(Zero);
    forAll(P, i)
    {
        const vector2D& p = P[i];
        const vector2D& q = P[P.fcIndex(i)];
        const scalar a = cross2(mean, p, q);
        A2 += a;
        c += a*(mean + p + q);
    }
    if (mag(A2) <= areaTol)
    {
        return mean;
    }
    return c/(3*A2);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::vector2D> Foam::fbm::contactPatch::project
(
    const point& c0,
    const UList<point>& pts,
    const UList<scalar>& weights
) const
{
    // The support point: the largest weight (1)
    label s = 0;
    forAll(weights, k)
    {
        if (weights[k] > weights[s])
        {
            s = k;
        }
    }
    List<vector2D> q(pts.size());
    forAll(pts, k)
    {
        const vector r(pts[s] + weights[k]*(pts[k] - pts[s]) - c0);
        q[k] = vector2D(r & t1_, planar_ ? 0 : (r & t2_));
    }
    return q;
}


Foam::scalar Foam::fbm::contactPatch::intervalMiddle
(
    const UList<vector2D>& a,
    const UList<vector2D>& b,
    scalar& lo,
    scalar& hi
) const
{
    scalar loA = GREAT, hiA = -GREAT, loB = GREAT, hiB = -GREAT;
    for (const vector2D& p : a)
    {
        loA = min(loA, p.x());
        hiA = max(hiA, p.x());
    }
    for (const vector2D& p : b)
    {
        loB = min(loB, p.x());
        hiB = max(hiB, p.x());
    }
    lo = max(loA, loB);
    hi = min(hiA, hiB);
    return 0.5*(lo + hi);
}


Foam::List<Foam::vector2D> Foam::fbm::contactPatch::hull
(
    List<vector2D> pts,
    const scalar tol
)
{
    const label n = pts.size();
    if (n < 2)
    {
        return pts;
    }
    std::sort(pts.begin(), pts.end(), lexLess);

    // Andrew's monotone chain: lower, then upper hull
    const scalar areaTol = tol*tol;
    List<vector2D> H(2*n);
    label k = 0;
    for (label i = 0; i < n; ++i)
    {
        while (k >= 2 && cross2(H[k-2], H[k-1], pts[i]) <= areaTol)
        {
            --k;
        }
        H[k++] = pts[i];
    }
    for (label i = n - 2, t = k + 1; i >= 0; --i)
    {
        while (k >= t && cross2(H[k-2], H[k-1], pts[i]) <= areaTol)
        {
            --k;
        }
        H[k++] = pts[i];
    }
    H.setSize(max(k - 1, label(1)));

    // Coincident neighbours merged (a segment of zero length is a point)
    DynamicList<vector2D> out(H.size());
    for (const vector2D& p : H)
    {
        if (out.empty() || mag(p - out.last()) > tol)
        {
            out.append(p);
        }
    }
    if (out.size() > 1 && mag(out.first() - out.last()) <= tol)
    {
        out.remove();
    }
    return List<vector2D>(std::move(out));
}


bool Foam::fbm::contactPatch::hullMiddle
(
    const List<vector2D>& a,
    const List<vector2D>& b,
    const scalar tol,
    vector2D& middle,
    DynamicList<vector2D>* region
)
{
    const label na = a.size();
    const label nb = b.size();
    if (na == 1 && nb == 1)
    {
        middle = 0.5*(a[0] + b[0]);
        return true;
    }
    if (na == 1 || nb == 1)
    {
        // A vertex (or a smooth body's point) on a face or an edge
        middle = (na == 1 ? a[0] : b[0]);
        return true;
    }
    if (na == 2 && nb == 2)
    {
        return segmentMiddle(a[0], a[1], b[0], b[1], tol, middle, region);
    }
    if (na == 2)
    {
        return clipSegment(a[0], a[1], b, tol, middle, region);
    }
    if (nb == 2)
    {
        return clipSegment(b[0], b[1], a, tol, middle, region);
    }

    // Two polygons: a clipped by each edge of b (Sutherland & Hodgman)
    DynamicList<vector2D> out(a);
    DynamicList<vector2D> in;
    forAll(b, i)
    {
        const vector2D& p = b[i];
        const vector2D e(b[b.fcIndex(i)] - p);
        in.transfer(out);
        out.clear();
        forAll(in, k)
        {
            const vector2D& S = in[in.rcIndex(k)];
            const vector2D& E = in[k];
            const scalar fS = cross2(e, S - p);
            const scalar fE = cross2(e, E - p);
            if (fE >= 0)
            {
                if (fS < 0)
                {
                    out.append(S + (fS/(fS - fE))*(E - S));
                }
                out.append(E);
            }
            else if (fS >= 0)
            {
                out.append(S + (fS/(fS - fE))*(E - S));
            }
        }
        if (out.empty())
        {
            return false;
        }
    }
    middle = polygonCentroid(out, tol*tol);
    if (region)
    {
        // The corners (clipping can repeat one or leave one on an edge:
        // the hull counts each corner once) moved together so that their
        // mean is the centroid
        const List<vector2D> corners(hull(out, tol));
        vector2D mean(Zero);
        for (const vector2D& p : corners)
        {
            mean += p;
        }
        mean /= corners.size();
        scalar extent = 0;
        for (const vector2D& p : corners)
        {
            extent = max(extent, mag(p - mean));
        }
        if (extent > tol)
        {
            for (const vector2D& p : corners)
            {
                region->append(p + middle - mean);
            }
        }
    }
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::contactPatch::contactPatch
(
    const vector& n,
    const vector& planeNormal
)
:
    n_(n),
    t1_(Zero),
    t2_(Zero),
    planar_(magSqr(planeNormal) > 0)
{
    if (planar_)
    {
        t2_ = planeNormal;
        t1_ = t2_ ^ n_;
    }
    else
    {
        // The coordinate axis least aligned with n
        const vector a(cmptMag(n_));
        vector e(Zero);
        e[(a.x() <= a.y() && a.x() <= a.z()) ? 0 : (a.y() <= a.z() ? 1 : 2)]
            = 1;
        t1_ = n_ ^ e;
        t1_ /= mag(t1_);
        t2_ = n_ ^ t1_;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::fbm::contactPatch::centre
(
    const point& c0,
    const UList<point>& ptsA,
    const UList<scalar>& wA,
    const UList<point>& ptsB,
    const UList<scalar>& wB,
    const scalar length,
    DynamicList<point>* region
) const
{
    if (region)
    {
        region->clear();
    }
    if (ptsA.size() <= 1 && ptsB.size() <= 1)
    {
        return c0;
    }
    const List<vector2D> a(project(c0, ptsA, wA));
    const List<vector2D> b(project(c0, ptsB, wB));
    const scalar tol = 1e-9*length;

    if (planar_)
    {
        scalar lo = 0, hi = 0;
        const scalar m = intervalMiddle(a, b, lo, hi);
        if (region && hi - lo > tol)
        {
            region->append(c0 + lo*t1_);
            region->append(c0 + hi*t1_);
        }
        return c0 + m*t1_;
    }

    vector2D m(Zero);
    DynamicList<vector2D> q;
    if (!hullMiddle(hull(a, tol), hull(b, tol), tol, m, region ? &q : nullptr))
    {
        return c0;
    }
    if (region)
    {
        for (const vector2D& p : q)
        {
            region->append(c0 + p.x()*t1_ + p.y()*t2_);
        }
    }
    return c0 + m.x()*t1_ + m.y()*t2_;
}


// ************************************************************************* //
