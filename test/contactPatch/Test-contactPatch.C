/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

Application
    Test-contactPatch

Description
    fbm::contactPatch, the contact point of two faces, against the overlap
    worked out by hand:
    - 2D (intervals along the tangent): two faces overlapping off-centre,
      a corner on a face, a face turning away (its far vertex weighted 1/2,
      and weighted 0: the corner, continuously), faces that miss each
      other, two single points (c0 unchanged);
    - 3D (convex hulls in the contact plane), in a frame turned and moved
      so that nothing lies along the coordinate axes: two squares
      overlapping in a rectangle (its centroid), a square turned by 45
      degrees inside another, a triangle clipped by a square, an edge
      across a face (the middle of the clipped edge), two crossing edges,
      two edges on one line (the middle of their overlap), a point on a
      face, faces that miss each other (c0), a face of weighted points
      (each moved towards the support point by its weight);
    every contact point on the contact plane through c0;
    - the region that spans each contact (the points among which
      fbm::particleCollisions shares a face-on-face dashpot): the ends of
      the overlap in 2D and of a clipped or overlapping edge in 3D, the
      corners of the overlap polygon (each once) in 3D, moved together so
      that their mean is the contact point; none where the contact is a
      point or the faces miss each other.

\*---------------------------------------------------------------------------*/

#include "contactPatch.H"
#include "tensor.H"
#include "fbmTest.H"

using namespace Foam;

// Rotation by phi about the unit axis k (Rodrigues)
tensor rotation(const vector& k, const scalar phi)
{
    const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
    return tensor::I + Foam::sin(phi)*K + (1 - Foam::cos(phi))*(K & K);
}


// The region of a contact: the expected points (in any order, each
// matched within tol) and its mean at the contact point
void checkRegion
(
    const string& what,
    const DynamicList<point>& region,
    const List<point>& expected,
    const point& centre,
    const scalar tol
)
{
    fbmTest::check
    (
        what + ": region size", scalar(region.size()),
        scalar(expected.size()), 0
    );
    if (region.size() != expected.size() || expected.empty())
    {
        return;
    }
    scalar worst = 0;
    for (const point& e : expected)
    {
        scalar nearest = GREAT;
        for (const point& p : region)
        {
            nearest = min(nearest, mag(p - e));
        }
        worst = max(worst, nearest);
    }
    fbmTest::check(what + ": region points", worst, 0, tol);
    point mean(Zero);
    for (const point& p : region)
    {
        mean += p;
    }
    mean /= region.size();
    fbmTest::check(what + ": region mean at the contact point", mean, centre, tol);
}


int main(int argc, char *argv[])
{
    // ---- 2D: the plane x-y, A below, B above, normal +y ----
    {
        const fbm::contactPatch patch(vector(0, 1, 0), vector(0, 0, 1));
        const point c0(0.18, 0.07, 0.05);
        const List<point> A({point(-0.25, 0.05, 0.05), point(0.25, 0.05, 0.05)});
        const List<scalar> wA({1.0, 1.0});
        Info<< "2D" << nl;
        auto centre = [&]
        (
            const List<point>& B,
            const List<scalar>& wB
        )
        {
            return patch.centre(c0, A, wA, B, wB, 0.5);
        };
        fbmTest::check
        (
            "face on face, off-centre: the middle of the overlap",
            centre({point(-0.02, 0.09, 0.05), point(0.18, 0.09, 0.05)}, {1.0, 1.0}),
            point(0.08, 0.07, 0.05), 1e-15
        );
        fbmTest::check
        (
            "a corner on a face: the corner",
            centre({point(0.1, 0.09, 0.05)}, {1.0}),
            point(0.1, 0.07, 0.05), 1e-15
        );
        fbmTest::check
        (
            "a face turning away, far vertex weighted 1/2",
            centre({point(-0.02, 0.09, 0.05), point(0.18, 0.1, 0.05)}, {1.0, 0.5}),
            point(0.03, 0.07, 0.05), 1e-15
        );
        fbmTest::check
        (
            "the far vertex weighted 1e-12: the corner, continuously",
            centre({point(-0.02, 0.09, 0.05), point(0.18, 0.1, 0.05)}, {1.0, 1e-12}),
            point(-0.02 + 1e-13, 0.07, 0.05), 1e-15
        );
        fbmTest::check
        (
            "faces that miss each other: the middle of the gap",
            centre({point(0.3, 0.09, 0.05), point(0.4, 0.09, 0.05)}, {1.0, 1.0}),
            point(0.275, 0.07, 0.05), 1e-15
        );
        fbmTest::check
        (
            "two single points: c0",
            patch.centre
            (
                c0, List<point>({A[0]}), List<scalar>({1.0}),
                List<point>({point(0.3, 0.09, 0.05)}), List<scalar>({1.0}), 0.5
            ),
            c0, 0
        );
    }

    // ---- 2D: the regions ----
    {
        const fbm::contactPatch patch(vector(0, 1, 0), vector(0, 0, 1));
        const point c0(0.18, 0.07, 0.05);
        const List<point> A({point(-0.25, 0.05, 0.05), point(0.25, 0.05, 0.05)});
        const List<scalar> w2({1.0, 1.0});
        DynamicList<point> region;
        Info<< nl << "2D regions" << nl;
        point c = patch.centre
        (
            c0, A, w2,
            List<point>({point(-0.02, 0.09, 0.05), point(0.18, 0.09, 0.05)}),
            w2, 0.5, &region
        );
        checkRegion
        (
            "face on face, off-centre: the overlap's ends", region,
            {point(-0.02, 0.07, 0.05), point(0.18, 0.07, 0.05)}, c, 1e-15
        );
        c = patch.centre
        (
            c0, A, w2, List<point>({point(0.1, 0.09, 0.05)}),
            List<scalar>({1.0}), 0.5, &region
        );
        checkRegion("a corner on a face: none", region, {}, c, 0);
        c = patch.centre
        (
            c0, A, w2,
            List<point>({point(0.3, 0.09, 0.05), point(0.4, 0.09, 0.05)}),
            w2, 0.5, &region
        );
        checkRegion("faces that miss each other: none", region, {}, c, 0);
    }

    // ---- 3D: local frame (s, t, n) turned by R and moved by X0 ----
    {
        const tensor R(rotation(vector(1, 2, -2)/3.0, 0.8));
        const point X0(0.3, -0.2, 0.7);
        const vector n(R & vector(0, 0, 1));
        const fbm::contactPatch patch(n, Zero);
        auto lab = [&](const scalar s, const scalar t, const scalar z)
        {
            return point(X0 + (R & vector(s, t, z)));
        };
        const point c0(lab(0.1, 0.2, 0.05));
        // A: a square face 2 x 2 below the plane, B's faces above it
        const List<point> A
        ({
            lab(-1, -1, -0.01), lab(1, -1, -0.01), lab(1, 1, -0.01),
            lab(-1, 1, -0.01)
        });
        const List<scalar> w4({1.0, 1.0, 1.0, 1.0});
        auto face = [&](const List<vector2D>& st)
        {
            List<point> B(st.size());
            forAll(st, k)
            {
                B[k] = lab(st[k].x(), st[k].y(), 0.02);
            }
            return B;
        };
        auto centre = [&](const List<vector2D>& st)
        {
            return patch.centre
            (
                c0, A, w4, face(st), List<scalar>(st.size(), scalar(1)), 3
            );
        };
        const scalar tol = 1e-14;
        Info<< nl << "3D" << nl;
        fbmTest::check
        (
            "two squares overlapping: the rectangle's centroid",
            centre({{0.5, 0.2}, {1.5, 0.2}, {1.5, 1.2}, {0.5, 1.2}}),
            lab(0.75, 0.6, 0.05), tol
        );
        const scalar r = 0.3/Foam::sqrt(2.0);
        fbmTest::check
        (
            "a turned square inside a square: its centre",
            centre({{0.2 - r, -0.4}, {0.2, -0.4 - r}, {0.2 + r, -0.4}, {0.2, -0.4 + r}}),
            lab(0.2, -0.4, 0.05), tol
        );
        fbmTest::check
        (
            "a triangle clipped by the square",
            centre({{0, 0}, {2, 0}, {0, 2}}),
            lab(0.5, 0.5, 0.05), tol
        );
        fbmTest::check
        (
            "an edge across the face: the middle of the clipped edge",
            centre({{-2, 0.3}, {0.5, 0.3}}),
            lab(-0.25, 0.3, 0.05), tol
        );
        fbmTest::check
        (
            "a point on the face: the point",
            centre({{0.2, 0.4}}),
            lab(0.2, 0.4, 0.05), tol
        );
        fbmTest::check
        (
            "faces that miss each other: c0",
            centre({{1.5, 1.5}, {2.5, 1.5}, {2.5, 2.5}, {1.5, 2.5}}),
            c0, tol
        );
        // Two edges: A an edge along s, B crossing it or on its line
        const List<point> edgeA({lab(-1, 0, -0.01), lab(1, 0, -0.01)});
        const List<scalar> w2({1.0, 1.0});
        fbmTest::check
        (
            "two crossing edges: the crossing",
            patch.centre(c0, edgeA, w2, face({{0.3, -1}, {0.3, 1}}), w2, 3),
            lab(0.3, 0, 0.05), tol
        );
        fbmTest::check
        (
            "two edges on one line: the middle of the overlap",
            patch.centre(c0, edgeA, w2, face({{0.5, 0}, {2, 0}}), w2, 3),
            lab(0.75, 0, 0.05), tol
        );
        // B the square of the first check with its vertices 2 and 3
        // weighted 1/2: each moves half way to the support vertex
        // (0.5, 0.2), giving the trapezoid (0.5, 0.2) (1, 0.2) (1, 0.7)
        // (0.5, 1.2); A cuts it at t = 1 to the pentagon (0.5, 0.2) (1, 0.2)
        // (1, 0.7) (0.7, 1) (0.5, 1), area 0.355, centroid
        // (519/710, 399/710)
        fbmTest::check
        (
            "a face of weighted points: shrunk towards the support",
            patch.centre
            (
                c0, A, w4,
                face({{0.5, 0.2}, {1.5, 0.2}, {1.5, 1.2}, {0.5, 1.2}}),
                List<scalar>({1.0, 0.5, 0.5, 1.0}), 3
            ),
            lab(519.0/710, 399.0/710, 0.05), tol
        );

        // The regions
        DynamicList<point> region;
        auto centreRegion = [&](const List<vector2D>& st)
        {
            return patch.centre
            (
                c0, A, w4, face(st), List<scalar>(st.size(), scalar(1)), 3,
                &region
            );
        };
        auto labs = [&](const List<vector2D>& st)
        {
            List<point> p(st.size());
            forAll(st, k)
            {
                p[k] = lab(st[k].x(), st[k].y(), 0.05);
            }
            return p;
        };
        point c(centreRegion({{0.5, 0.2}, {1.5, 0.2}, {1.5, 1.2}, {0.5, 1.2}}));
        checkRegion
        (
            "two squares overlapping: the rectangle's corners", region,
            labs({{0.5, 0.2}, {1, 0.2}, {1, 1}, {0.5, 1}}), c, tol
        );
        // The triangle's hypotenuse passes through the square's corner
        // (1, 1): the clipped polygon is the unit square, that corner once
        c = centreRegion({{0, 0}, {2, 0}, {0, 2}});
        checkRegion
        (
            "a triangle clipped by the square: the unit square's corners",
            region, labs({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), c, tol
        );
        // A right triangle inside the square: its corners moved together
        // so that their mean is its centroid (here the same)
        c = centreRegion({{-0.5, -0.5}, {0.4, -0.5}, {-0.5, 0.1}});
        checkRegion
        (
            "a triangle inside the square: its corners", region,
            labs({{-0.5, -0.5}, {0.4, -0.5}, {-0.5, 0.1}}), c, tol
        );
        // A quadrilateral whose corner mean is not its centroid: the
        // corners moved by the difference, (-0.05, 1/60) here
        // ((0, 0) (0.6, 0) (0.6, 0.2) (0, 0.6): area 0.24, centroid
        // (0.25, 13/60), corner mean (0.3, 0.2))
        c = centreRegion({{0, 0}, {0.6, 0}, {0.6, 0.2}, {0, 0.6}});
        fbmTest::check
        (
            "a quadrilateral: the contact point its centroid", c,
            lab(0.25, 13.0/60, 0.05), tol
        );
        checkRegion
        (
            "a quadrilateral: its corners moved to the centroid", region,
            labs
            ({
                {-0.05, 13.0/60 - 0.2}, {0.55, 13.0/60 - 0.2},
                {0.55, 13.0/60}, {-0.05, 0.6 + 13.0/60 - 0.2}
            }),
            c, tol
        );
        c = centreRegion({{-2, 0.3}, {0.5, 0.3}});
        checkRegion
        (
            "an edge across the face: the clipped edge's ends", region,
            labs({{-1, 0.3}, {0.5, 0.3}}), c, tol
        );
        c = centreRegion({{0.2, 0.4}});
        checkRegion("a point on the face: none", region, {}, c, 0);
        c = centreRegion({{1.5, 1.5}, {2.5, 1.5}, {2.5, 2.5}, {1.5, 2.5}});
        checkRegion("faces that miss each other: none", region, {}, c, 0);
        c = patch.centre
        (
            c0, edgeA, w2, face({{0.3, -1}, {0.3, 1}}), w2, 3, &region
        );
        checkRegion("two crossing edges: none", region, {}, c, 0);
        c = patch.centre
        (
            c0, edgeA, w2, face({{0.5, 0}, {2, 0}}), w2, 3, &region
        );
        checkRegion
        (
            "two edges on one line: the overlap's ends", region,
            labs({{0.5, 0}, {1, 0}}), c, tol
        );
    }

    return fbmTest::result();
}


// ************************************************************************* //
