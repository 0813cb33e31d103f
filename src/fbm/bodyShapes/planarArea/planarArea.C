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

#include "planarArea.H"
#include "mathematicalConstants.H"
#include "FixedList.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fbm::planarArea::clip
(
    const UList<vector2D>& in,
    const direction dir,
    const scalar value,
    const bool above,
    DynamicList<vector2D>& out
)
{
    out.clear();
    const label n = in.size();
    for (label k = 0; k < n; ++k)
    {
        const vector2D& a = in[k];
        const vector2D& b = in[(k + 1) % n];
        const scalar da = above ? a[dir] - value : value - a[dir];
        const scalar db = above ? b[dir] - value : value - b[dir];
        if (da >= 0)
        {
            out.append(a);
        }
        if ((da > 0 && db < 0) || (da < 0 && db > 0))
        {
            vector2D x(a + (da/(da - db))*(b - a));
            x[dir] = value;
            out.append(x);
        }
    }
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::fbm::planarArea::area(const UList<vector2D>& p)
{
    scalar s = 0;
    const label n = p.size();
    for (label k = 0; k < n; ++k)
    {
        const vector2D& a = p[k];
        const vector2D& b = p[(k + 1) % n];
        s += a.x()*b.y() - a.y()*b.x();
    }
    return 0.5*s;
}


Foam::scalar Foam::fbm::planarArea::diskTriangle
(
    const vector2D& a,
    const vector2D& b,
    const scalar R
)
{
    const scalar R2 = sqr(R);

    // Points where the edge a + t (b - a), 0 < t < 1, crosses the circle
    const vector2D d(b - a);
    const scalar A = d & d;
    if (A < VSMALL*R2)
    {
        return 0;
    }
    const scalar B = a & d;
    const scalar C = (a & a) - R2;
    const scalar disc = sqr(B) - A*C;

    FixedList<vector2D, 4> p;
    label n = 0;
    p[n++] = a;
    if (disc > 0)
    {
        const scalar root = std::sqrt(disc);
        const scalar t1 = (-B - root)/A;
        const scalar t2 = (-B + root)/A;
        if (t1 > 0 && t1 < 1) p[n++] = a + t1*d;
        if (t2 > 0 && t2 < 1) p[n++] = a + t2*d;
    }
    p[n++] = b;

    // Inside the disk a triangle, outside a sector
    scalar s = 0;
    for (label i = 0; i < n - 1; ++i)
    {
        const vector2D& q = p[i];
        const vector2D& r = p[i + 1];
        const scalar cross = q.x()*r.y() - q.y()*r.x();
        if (magSqr(0.5*(q + r)) < R2)
        {
            s += 0.5*cross;
        }
        else
        {
            s += 0.5*R2*std::atan2(cross, q & r);
        }
    }
    return s;
}


Foam::scalar Foam::fbm::planarArea::diskPolygon
(
    const UList<vector2D>& p,
    const scalar R
)
{
    const scalar R2 = sqr(R);
    const label n = p.size();

    bool allIn = true, anyIn = false;
    for (const vector2D& v : p)
    {
        if (magSqr(v) < R2) anyIn = true; else allIn = false;
    }
    if (allIn)
    {
        // A disk is convex: the polygon lies in it
        return area(p);
    }
    if (!anyIn)
    {
        // Every vertex outside: the circle meets the boundary only if an
        // edge comes closer than R to the origin; if none does, the disk
        // is inside the polygon (the origin left of every edge) or apart
        bool meets = false, originIn = true;
        for (label k = 0; k < n && !meets; ++k)
        {
            const vector2D& a = p[k];
            const vector2D& b = p[(k + 1) % n];
            const vector2D d(b - a);
            const scalar dd = d & d;
            const scalar t =
                dd > 0 ? max(scalar(0), min(scalar(1), -(a & d)/dd)) : 0;
            meets = magSqr(a + t*d) < R2;
            originIn = originIn && (a.x()*b.y() - a.y()*b.x() >= 0);
        }
        if (!meets)
        {
            return originIn ? constant::mathematical::pi*R2 : 0;
        }
    }

    scalar s = 0;
    for (label k = 0; k < n; ++k)
    {
        s += diskTriangle(p[k], p[(k + 1) % n], R);
    }
    return s;
}


Foam::scalar Foam::fbm::planarArea::boxPolygon
(
    const UList<vector2D>& p,
    const vector2D& lo,
    const vector2D& hi
)
{
    DynamicList<vector2D> a(p.size() + 4), b(p.size() + 4);
    clip(p, 0, lo.x(), true, a);
    clip(a, 0, hi.x(), false, b);
    clip(b, 1, lo.y(), true, a);
    clip(a, 1, hi.y(), false, b);
    return b.size() < 3 ? 0 : mag(area(b));
}


// ************************************************************************* //
