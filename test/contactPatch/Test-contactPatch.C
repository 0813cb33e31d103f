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
    every contact point on the contact plane through c0.

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
    }

    return fbmTest::result();
}


// ************************************************************************* //
