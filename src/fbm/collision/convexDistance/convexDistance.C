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

#include "convexDistance.H"
#include "bodyShape.H"
#include "DynamicList.H"
#include "labelPair.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Closest point of the segment (P[0], P[1]) to the origin: the vertices
// kept (idx) and their weights; returns their number
label closestSegment(const point P[], label idx[], scalar w[])
{
    const vector t(P[1] - P[0]);
    const scalar tt = magSqr(t);
    const scalar s = (tt > 0) ? -(P[0] & t)/tt : 0;
    if (s <= 0)
    {
        idx[0] = 0; w[0] = 1;
        return 1;
    }
    if (s >= 1)
    {
        idx[0] = 1; w[0] = 1;
        return 1;
    }
    idx[0] = 0; w[0] = 1 - s;
    idx[1] = 1; w[1] = s;
    return 2;
}


// Closest point of the triangle P[0..2] to the origin by its Voronoi
// regions (Ericson 2005, 5.1.5); interior: the point is inside the
// triangle (not on an edge or vertex)
label closestTriangle
(
    const point P[],
    label idx[],
    scalar w[],
    bool& interior
)
{
    interior = false;
    const point& a = P[0];
    const point& b = P[1];
    const point& c = P[2];
    const vector ab(b - a), ac(c - a);

    const scalar d1 = -(ab & a), d2 = -(ac & a);
    if (d1 <= 0 && d2 <= 0)
    {
        idx[0] = 0; w[0] = 1;
        return 1;
    }
    const scalar d3 = -(ab & b), d4 = -(ac & b);
    if (d3 >= 0 && d4 <= d3)
    {
        idx[0] = 1; w[0] = 1;
        return 1;
    }
    const scalar vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        const scalar s = d1/(d1 - d3);
        idx[0] = 0; w[0] = 1 - s;
        idx[1] = 1; w[1] = s;
        return 2;
    }
    const scalar d5 = -(ab & c), d6 = -(ac & c);
    if (d6 >= 0 && d5 <= d6)
    {
        idx[0] = 2; w[0] = 1;
        return 1;
    }
    const scalar vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        const scalar s = d2/(d2 - d6);
        idx[0] = 0; w[0] = 1 - s;
        idx[1] = 2; w[1] = s;
        return 2;
    }
    const scalar va = d3*d6 - d5*d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        const scalar s = (d4 - d3)/((d4 - d3) + (d5 - d6));
        idx[0] = 1; w[0] = 1 - s;
        idx[1] = 2; w[1] = s;
        return 2;
    }

    const scalar sum = va + vb + vc;
    if (!(sum > 0))
    {
        // Degenerate (collinear) triangle: the best of its edges
        scalar best = GREAT;
        label m = 0;
        for (label e = 0; e < 3; ++e)
        {
            const point Pe[2] = {P[e], P[(e + 1) % 3]};
            label ie[2];
            scalar we[2];
            const label me = closestSegment(Pe, ie, we);
            vector v(Zero);
            for (label k = 0; k < me; ++k) v += we[k]*Pe[ie[k]];
            if (magSqr(v) < best)
            {
                best = magSqr(v);
                m = me;
                for (label k = 0; k < me; ++k)
                {
                    idx[k] = (e + ie[k]) % 3;
                    w[k] = we[k];
                }
            }
        }
        return m;
    }

    interior = true;
    const scalar v = vb/sum, s = vc/sum;
    idx[0] = 0; w[0] = 1 - v - s;
    idx[1] = 1; w[1] = v;
    idx[2] = 2; w[2] = s;
    return 3;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

bool Foam::fbm::convexDistance::closest
(
    label& n,
    point W[4],
    point A[4],
    point B[4],
    scalar lambda[4]
) const
{
    label idx[4] = {0, 0, 0, 0};
    scalar w[4] = {0, 0, 0, 0};
    label m = 0;
    bool inside = false;

    if (n == 1)
    {
        lambda[0] = 1;
        return false;
    }
    else if (n == 2)
    {
        m = closestSegment(W, idx, w);
    }
    else if (n == 3)
    {
        bool interior;
        m = closestTriangle(W, idx, w, interior);
        // In the plane the triangle holds the origin
        inside = interior && magSqr(planeNormal_) > 0;
    }
    else
    {
        // Tetrahedron: the closest of the faces the origin lies outside of
        static const label face[4][4] =
            {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
        scalar best = GREAT;
        bool anyOutside = false;
        for (label f = 0; f < 4; ++f)
        {
            const point& p0 = W[face[f][0]];
            const vector nrm((W[face[f][1]] - p0) ^ (W[face[f][2]] - p0));
            const vector toL(W[face[f][3]] - p0);
            const scalar sO = -(p0 & nrm);
            const scalar sL = toL & nrm;
            // Flat tetrahedron: every face is a candidate
            const bool flat =
                mag(sL) <= 1e-12*mag(nrm)*mag(toL) || mag(nrm) == 0;
            if (!flat && sO*sL >= 0)
            {
                continue;
            }
            anyOutside = true;
            const point P[3] = {p0, W[face[f][1]], W[face[f][2]]};
            label it[3];
            scalar wt[3];
            bool interior;
            const label mt = closestTriangle(P, it, wt, interior);
            vector v(Zero);
            for (label k = 0; k < mt; ++k) v += wt[k]*P[it[k]];
            if (magSqr(v) < best)
            {
                best = magSqr(v);
                m = mt;
                for (label k = 0; k < mt; ++k)
                {
                    idx[k] = face[f][it[k]];
                    w[k] = wt[k];
                }
            }
        }
        if (!anyOutside)
        {
            for (label k = 0; k < 4; ++k)
            {
                lambda[k] = 0.25;
            }
            return true;
        }
    }

    if (inside)
    {
        for (label k = 0; k < n; ++k)
        {
            lambda[k] = w[k];
        }
        return true;
    }

    // Keep the vertices used, in order
    point Wn[4], An[4], Bn[4];
    for (label k = 0; k < m; ++k)
    {
        Wn[k] = W[idx[k]];
        An[k] = A[idx[k]];
        Bn[k] = B[idx[k]];
    }
    for (label k = 0; k < m; ++k)
    {
        W[k] = Wn[k];
        A[k] = An[k];
        B[k] = Bn[k];
        lambda[k] = w[k];
    }
    n = m;
    return false;
}


void Foam::fbm::convexDistance::epa2D
(
    const bodyShape& sA, const tensor& QA, const point& XA,
    const bodyShape& sB, const tensor& QB, const point& XB,
    const point W[4], const point A[4], const point B[4],
    const scalar delta,
    result& res
) const
{
    const vector& e = planeNormal_;

    // The polygon, counter-clockwise about e
    DynamicList<point> PW(16), PA(16), PB(16);
    const bool ccw = ((((W[1] - W[0]) ^ (W[2] - W[0])) & e) >= 0);
    const label order[3] = {0, ccw ? 1 : 2, ccw ? 2 : 1};
    for (const label k : order)
    {
        PW.append(W[k]);
        PA.append(A[k]);
        PB.append(B[k]);
    }

    label iBest = 0;
    vector nBest(Zero);
    scalar dBest = 0;
    for (label it = 0; it < maxIter_; ++it)
    {
        ++res.iterations;

        // Edge nearest the origin (outward normal t x e)
        dBest = GREAT;
        forAll(PW, i)
        {
            const label j = PW.fcIndex(i);
            vector nrm((PW[j] - PW[i]) ^ e);
            const scalar l = mag(nrm);
            if (l <= VSMALL) continue;
            nrm /= l;
            const scalar d = nrm & PW[i];
            if (d < dBest)
            {
                dBest = d;
                iBest = i;
                nBest = nrm;
            }
        }

        const point a(XA + sA.support(QA, nBest));
        const point b(XB + sB.support(QB, -nBest));
        vector w(a - b);
        w -= (w & e)*e;

        bool dup = false;
        forAll(PW, k)
        {
            if (PW[k] == w) dup = true;
        }
        if (((w & nBest) - dBest <= delta) || dup)
        {
            res.converged = true;
            break;
        }

        // Insert w after iBest
        PW.append(w);
        PA.append(a);
        PB.append(b);
        for (label k = PW.size() - 1; k > iBest + 1; --k)
        {
            std::swap(PW[k], PW[k - 1]);
            std::swap(PA[k], PA[k - 1]);
            std::swap(PB[k], PB[k - 1]);
        }
    }

    // The origin's projection on the nearest edge
    const label i = iBest;
    const label j = PW.fcIndex(i);
    const vector t(PW[j] - PW[i]);
    const scalar s =
        min(max(-(PW[i] & t)/max(magSqr(t), VSMALL), scalar(0)), scalar(1));
    res.pA = PA[i] + s*(PA[j] - PA[i]);
    res.pB = PB[i] + s*(PB[j] - PB[i]);
    res.gap = -dBest;
    res.normal = nBest;
}


void Foam::fbm::convexDistance::epa3D
(
    const bodyShape& sA, const tensor& QA, const point& XA,
    const bodyShape& sB, const tensor& QB, const point& XB,
    const point W[4], const point A[4], const point B[4],
    const scalar delta,
    result& res
) const
{
    struct face
    {
        label v[3];
        vector n;
        scalar d;
        bool valid;
    };

    DynamicList<point> PW(64), PA(64), PB(64);
    for (label k = 0; k < 4; ++k)
    {
        PW.append(W[k]);
        PA.append(A[k]);
        PB.append(B[k]);
    }

    // A face (i, j, k) with its unit normal pointing away from the point
    // 'inner' (a point of the polytope off its plane)
    auto makeFace = [&](label i, label j, label k, const point& inner)
    {
        face f;
        f.v[0] = i; f.v[1] = j; f.v[2] = k;
        vector nrm((PW[j] - PW[i]) ^ (PW[k] - PW[i]));
        if ((nrm & (inner - PW[i])) > 0)
        {
            std::swap(f.v[1], f.v[2]);
            nrm = -nrm;
        }
        const scalar l = mag(nrm);
        f.valid = (l > VSMALL);
        f.n = f.valid ? nrm/l : vector::zero;
        f.d = f.valid ? (f.n & PW[i]) : GREAT;
        return f;
    };

    DynamicList<face> faces(128);
    faces.append(makeFace(0, 1, 2, PW[3]));
    faces.append(makeFace(0, 3, 1, PW[2]));
    faces.append(makeFace(0, 2, 3, PW[1]));
    faces.append(makeFace(1, 3, 2, PW[0]));

    // A point inside the polytope (the centroid of the first tetrahedron)
    const point inner(0.25*(PW[0] + PW[1] + PW[2] + PW[3]));

    label fBest = 0;
    for (label it = 0; it < maxIter_; ++it)
    {
        ++res.iterations;

        scalar dBest = GREAT;
        fBest = -1;
        forAll(faces, f)
        {
            if (faces[f].valid && faces[f].d < dBest)
            {
                dBest = faces[f].d;
                fBest = f;
            }
        }
        if (fBest < 0)
        {
            break;
        }
        const vector nBest(faces[fBest].n);

        const point a(XA + sA.support(QA, nBest));
        const point b(XB + sB.support(QB, -nBest));
        const point w(a - b);

        bool dup = false;
        forAll(PW, k)
        {
            if (PW[k] == w) dup = true;
        }
        if (((w & nBest) - dBest <= delta) || dup)
        {
            res.converged = true;
            break;
        }

        // Remove the faces w sees; the horizon: their edges not shared by
        // two removed faces
        const label iw = PW.size();
        PW.append(w);
        PA.append(a);
        PB.append(b);
        DynamicList<labelPair> horizon(32);
        forAll(faces, f)
        {
            face& fc = faces[f];
            if (!fc.valid || ((fc.n & (w - PW[fc.v[0]])) <= 0)) continue;
            fc.valid = false;
            for (label k = 0; k < 3; ++k)
            {
                const labelPair edge(fc.v[k], fc.v[(k + 1) % 3]);
                bool shared = false;
                forAll(horizon, h)
                {
                    if
                    (
                        horizon[h].first() == edge.second()
                     && horizon[h].second() == edge.first()
                    )
                    {
                        horizon[h] = horizon.last();
                        horizon.remove();
                        shared = true;
                        break;
                    }
                }
                if (!shared) horizon.append(edge);
            }
        }
        for (const labelPair& edge : horizon)
        {
            faces.append(makeFace(edge.first(), edge.second(), iw, inner));
        }
    }

    if (fBest < 0)
    {
        // Degenerate polytope: touching
        res.gap = 0;
        res.normal = vector::zero;
        res.pA = PA[0];
        res.pB = PB[0];
        return;
    }

    // Barycentric coordinates of the origin's projection on the face
    const face& f = faces[fBest];
    const point p(f.d*f.n);
    const vector v0(PW[f.v[1]] - PW[f.v[0]]);
    const vector v1(PW[f.v[2]] - PW[f.v[0]]);
    const vector v2(p - PW[f.v[0]]);
    const scalar d00 = v0 & v0, d01 = v0 & v1, d11 = v1 & v1;
    const scalar d20 = v2 & v0, d21 = v2 & v1;
    const scalar den = d00*d11 - d01*d01;
    scalar l1 = 0, l2 = 0;
    if (mag(den) > VSMALL)
    {
        l1 = (d11*d20 - d01*d21)/den;
        l2 = (d00*d21 - d01*d20)/den;
    }
    const scalar l0 = 1 - l1 - l2;
    res.pA = l0*PA[f.v[0]] + l1*PA[f.v[1]] + l2*PA[f.v[2]];
    res.pB = l0*PB[f.v[0]] + l1*PB[f.v[1]] + l2*PB[f.v[2]];
    res.gap = -f.d;
    res.normal = f.n;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::convexDistance::convexDistance
(
    const vector& planeNormal,
    const scalar tol,
    const scalar epaTol3D,
    const label maxIter
)
:
    planeNormal_(planeNormal),
    tol_(tol),
    epaTol3D_(epaTol3D),
    maxIter_(maxIter)
{
    const scalar m = mag(planeNormal_);
    if (m > 0)
    {
        planeNormal_ /= m;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fbm::convexDistance::result Foam::fbm::convexDistance::distance
(
    const bodyShape& sA, const tensor& QA, const point& XA,
    const bodyShape& sB, const tensor& QB, const point& XB,
    const vector& v0
) const
{
    const vector& e = planeNormal_;
    const bool twoD = magSqr(e) > 0;
    auto inPlane = [&](const vector& x)
    {
        return twoD ? vector(x - (x & e)*e) : x;
    };

    result res;
    res.gap = 0;
    res.normal = vector::zero;
    res.pA = XA;
    res.pB = XB;
    res.iterations = 0;
    res.converged = false;
    res.overlap = false;

    const scalar delta = tol_*(sA.radius() + sB.radius());

    // Simplex of support points of C = A - B (W) and of A and B
    point W[4], A[4], B[4];
    scalar lambda[4];
    label n = 0;

    // Start from the given direction or the centres' difference, a point
    // of C (only the first support query uses v before the simplex has a
    // point, so its length does not matter)
    vector v(inPlane(v0));
    if (magSqr(v) <= VSMALL*VSMALL)
    {
        v = inPlane(XA - XB);
    }
    else
    {
        v *= mag(XA - XB)/mag(v);
    }
    if (magSqr(v) <= sqr(delta))
    {
        v = inPlane(vector(1, 0, 0));
        if (magSqr(v) < 0.5) v = inPlane(vector(0, 1, 0));
        v *= delta;
    }
    vector vPrev(v);

    for (label it = 0; it < maxIter_; ++it)
    {
        ++res.iterations;

        const point a(XA + sA.support(QA, -v));
        const point b(XB + sB.support(QB, v));
        const point w(inPlane(a - b));

        const scalar vv = magSqr(v);
        bool dup = false;
        for (label k = 0; k < n; ++k)
        {
            if (W[k] == w) dup = true;
        }
        if (n > 0 && (dup || vv - (v & w) <= delta*Foam::sqrt(vv)))
        {
            res.converged = true;
            break;
        }

        W[n] = w;
        A[n] = a;
        B[n] = b;
        ++n;

        if (closest(n, W, A, B, lambda))
        {
            // The origin inside: overlap, the depth by EPA
            res.overlap = true;
            if (twoD)
            {
                epa2D(sA, QA, XA, sB, QB, XB, W, A, B, delta, res);
            }
            else
            {
                epa3D
                (
                    sA, QA, XA, sB, QB, XB, W, A, B,
                    epaTol3D_*(sA.radius() + sB.radius()), res
                );
            }
            return res;
        }

        vPrev = v;
        v = Zero;
        for (label k = 0; k < n; ++k)
        {
            v += lambda[k]*W[k];
        }

        if (magSqr(v) <= sqr(delta))
        {
            // The origin on the simplex (within the tolerance): touching,
            // or overlapping with a simplex not yet full (a symmetric
            // pair). Add support points normal to the simplex while C
            // extends beyond the tolerance there; a full simplex holds
            // the origin: EPA. Otherwise the origin is on C's boundary
            // with the outward normal m: touching.
            vector m(Zero);
            const label n0 = n;
            while (n >= 2 && n < (twoD ? 3 : 4))
            {
                if (n == 2)
                {
                    const vector t(W[1] - W[0]);
                    if (twoD)
                    {
                        m = t ^ e;
                    }
                    else
                    {
                        // Any direction normal to t
                        const vector ax
                        (
                            mag(t.x()) <= mag(t.y()) && mag(t.x()) <= mag(t.z())
                          ? vector(1, 0, 0)
                          : mag(t.y()) <= mag(t.z())
                          ? vector(0, 1, 0) : vector(0, 0, 1)
                        );
                        m = t ^ ax;
                    }
                }
                else
                {
                    m = (W[1] - W[0]) ^ (W[2] - W[0]);
                }
                const scalar mm = mag(m);
                if (mm <= VSMALL)
                {
                    break;
                }
                m /= mm;
                const point a(XA + sA.support(QA, m));
                const point b(XB + sB.support(QB, -m));
                const point w(inPlane(a - b));
                if ((w & m) <= delta)
                {
                    break;
                }
                W[n] = w;
                A[n] = a;
                B[n] = b;
                ++n;
            }
            if (n == (twoD ? 3 : 4))
            {
                res.overlap = true;
                if (twoD)
                {
                    epa2D(sA, QA, XA, sB, QB, XB, W, A, B, delta, res);
                }
                else
                {
                    epa3D
                    (
                        sA, QA, XA, sB, QB, XB, W, A, B,
                        epaTol3D_*(sA.radius() + sB.radius()), res
                    );
                }
                return res;
            }
            res.converged = true;
            if (magSqr(m) > 0)
            {
                res.pA = Zero;
                res.pB = Zero;
                for (label k = 0; k < n0; ++k)
                {
                    res.pA += lambda[k]*A[k];
                    res.pB += lambda[k]*B[k];
                }
                res.gap = mag(v);
                res.normal = m;
                return res;
            }
            break;
        }
    }

    // Witness points from the simplex weights
    if (n > 0)
    {
        res.pA = Zero;
        res.pB = Zero;
        for (label k = 0; k < n; ++k)
        {
            res.pA += lambda[k]*A[k];
            res.pB += lambda[k]*B[k];
        }
    }
    const scalar mv = mag(v);
    res.gap = mv;
    res.normal = (mv > VSMALL) ? vector(-v/mv) : vector(-vPrev/mag(vPrev));

    return res;
}


// ************************************************************************* //
