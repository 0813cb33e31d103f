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
    Test-bodyShapes

Description
    The non-spherical shapes against exact values, on a 2D mesh (ellipse,
    polygon) or a 3D mesh (ellipsoid):
    - volume, centroid and inertia tensor against the closed forms (an
      ellipse, a rectangle and a right triangle with a product of inertia,
      an ellipsoid);
    - the signed distance at points where it is known by hand (also the
      inside points of an ellipse's major axis, whose nearest point is off
      the axis), and, at random points in a rotated orientation, the
      closest point x = r - d n on the surface, r - x along the normal, and
      |d| no larger than the distance to any of a dense set of surface
      points (so the closest point is the global one);
    - the bounding box of the rotated shape;
    - fbm::planarArea's exact areas (disk in a polygon, polygon in a box)
      against closed forms;
    - the solid fraction: sum of boxFraction h^2 (h^3) over a grid of boxes
      of size h covering the rotated shape (grid offset from the centre)
      against the exact area (volume), at four sizes h; the error is
      printed for each and checked: round-off for the ellipse and polygon
      (exact fractions), the bound stated in the test for the sampled 3D
      shapes; the ellipse's and polygon's cut cells one by one against the
      sampling at depth 10;
    - bad polygons (non-convex, clockwise, self-intersecting, too few
      vertices): a FatalIOError naming the keyword and the body.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "ellipse.H"
#include "ellipsoid.H"
#include "polygon.H"
#include "planarArea.H"
#include "Random.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "fbmTest.H"

using namespace Foam;

// Rotation by the angle phi about the unit axis k
tensor rotation(const vector& k, const scalar phi)
{
    const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
    return tensor::I + Foam::sin(phi)*K + (1 - Foam::cos(phi))*(K & K);
}


// Relative error of sum(boxFraction) over a grid of boxes of size h
// covering the shape's bounding box, against its exact area (volume);
// with 'base' the base class's sampling of the lab-frame distance instead
// of the shape's own boxFraction
scalar fractionError
(
    const fbm::bodyShape& s,
    const scalar h,
    const label nSub,
    const bool twoD,
    const scalar exact,
    const bool base = false
)
{
    const vector ext(s.halfExtent());
    const vector offset(0.31*h, 0.17*h, 0.23*h);
    label n[3];
    for (direction d = 0; d < 3; ++d)
    {
        n[d] = (twoD && d == 2) ? 1 : label(std::ceil(ext[d]/h)) + 2;
    }
    scalar sum = 0;
    for (label i = -n[0]; i < n[0]; ++i)
    {
        for (label j = -n[1]; j < n[1]; ++j)
        {
            for (label k = (twoD ? 0 : -n[2]); k < n[2]; ++k)
            {
                const point lo
                (
                    i*h + offset.x(), j*h + offset.y(),
                    twoD ? -0.5 : k*h + offset.z()
                );
                const point hi(lo + vector(h, h, twoD ? 1 : h));
                const boundBox bb(lo, hi);
                sum +=
                    (base ? s.sampleFraction(bb, nSub) : s.boxFraction(bb, nSub))
                   *(twoD ? h*h : h*h*h);
            }
        }
    }
    return (sum - exact)/exact;
}


// An exact fraction against the adaptive sampling of the base class at
// depth 10 (leaves delta = h/1024), cell by cell over the cut boxes of a
// grid of size h: planar leaves on a curve of curvature kappa lose at most
// about delta^2 (delta kappa) each along the 4 h/delta cut leaves, a corner
// at most delta^2: |difference| <= 4 kappa h (delta/h)^2 + 3 (delta/h)^2
void cellsAgainstSampling
(
    const word& name,
    const fbm::bodyShape& s,
    const scalar h,
    const scalar kappa
)
{
    const vector ext(s.halfExtent());
    const vector offset(0.31*h, 0.17*h, 0);
    const label nx = label(std::ceil(ext.x()/h)) + 2;
    const label ny = label(std::ceil(ext.y()/h)) + 2;
    scalar worst = 0;
    label nCut = 0;
    for (label i = -nx; i < nx; ++i)
    {
        for (label j = -ny; j < ny; ++j)
        {
            const point lo(i*h + offset.x(), j*h + offset.y(), -0.5);
            const boundBox bb(lo, lo + vector(h, h, 1));
            const scalar exact = s.boxFraction(bb, 0);
            const scalar sampled = s.sampleFraction(bb, 10);
            if ((exact > 0 && exact < 1) || (sampled > 0 && sampled < 1))
            {
                ++nCut;
                worst = max(worst, mag(exact - sampled));
            }
        }
    }
    const scalar tol = (4*kappa*h + 3)/sqr(1024.0);
    Info<< "    " << name << ": " << nCut << " cut cells at h = " << h
        << ", largest difference to the sampling at depth 10 " << worst
        << " (bound " << tol << ")" << nl;
    fbmTest::check(name + ": cut cells found", scalar(nCut > 10), 1, 0);
    fbmTest::check(name + ": cells against sampling", worst, 0, tol);
}


// Second order in h: the error falls by more than 2.5 when h halves
void convergence(const word& name, const scalar err, scalar& errPrev)
{
    if (errPrev != 0)
    {
        fbmTest::check
        (
            name + ": error ratio when h halves > 2.5",
            scalar(mag(errPrev) > 2.5*mag(err)), 1, 0
        );
        Info<< "    ratio " << errPrev/err << nl;
    }
    errPrev = err;
}


// At random points: the closest point x = r - d n is on the surface, no
// farther than any of the surface points pts, and (smooth shapes) the
// normal there is n
void checkDistances
(
    const word& name,
    const fbm::bodyShape& s,
    const List<vector>& pts,
    const scalar R,
    const bool twoD,
    const label nPoints,
    const bool smooth = true
)
{
    Random rnd(1234);
    scalar worstOn = 0, worstAlong = 0, worstMin = 0;
    for (label i = 0; i < nPoints; ++i)
    {
        vector r(rnd.sample01<vector>() - 0.5*vector::one);
        r *= 3*R;
        if (twoD) r.z() = 0;
        const scalar d = s.signedDistance(r);
        const vector n(s.normal(r));
        const point x(r - d*n);
        worstOn = max(worstOn, mag(s.signedDistance(x)));
        scalar dMin = GREAT;
        for (const vector& p : pts)
        {
            dMin = min(dMin, mag(r - p));
        }
        worstMin = max(worstMin, mag(d) - dMin);
        const vector nx(s.normal(x));
        worstAlong = max(worstAlong, mag(nx - n));
    }
    fbmTest::check
    (
        name + ": closest point on the surface |d(r - d n)|/R",
        worstOn/R, 0, 1e-10
    );
    if (smooth)
    {
        fbmTest::check
        (
            name + ": normal at the closest point is the normal"
            " |n(x) - n(r)|", worstAlong, 0, 1e-8
        );
    }
    fbmTest::check
    (
        name + ": |d| <= distance to every surface sample (max excess/R)",
        max(worstMin/R, scalar(0)), 0, 1e-12
    );
}


// Write a cube of side 1 as OBJ (corners offset + (0|1)^3), outward (or
// inward) triangles, without the last nDrop triangles
void writeCube
(
    const fileName& path,
    const vector& offset,
    const bool inward,
    const label nDrop = 0
)
{
    mkDir(path.path());
    OFstream os(path);
    for (label k = 0; k < 2; ++k)
    {
        os  << "v " << offset.x() << ' ' << offset.y() << ' '
            << offset.z() + k << nl
            << "v " << offset.x() + 1 << ' ' << offset.y() << ' '
            << offset.z() + k << nl
            << "v " << offset.x() + 1 << ' ' << offset.y() + 1 << ' '
            << offset.z() + k << nl
            << "v " << offset.x() << ' ' << offset.y() + 1 << ' '
            << offset.z() + k << nl;
    }
    const label tri[12][3] =
    {
        {0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
        {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}
    };
    for (label i = 0; i < 12 - nDrop; ++i)
    {
        os  << "f " << tri[i][0] + 1 << ' '
            << (inward ? tri[i][2] : tri[i][1]) + 1 << ' '
            << (inward ? tri[i][1] : tri[i][2]) + 1 << nl;
    }
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar pi = constant::mathematical::pi;
    const bool twoD = (mesh.nSolutionD() == 2);
    const scalar L = twoD ? mesh.bounds().span().z() : 1;

    if (twoD)
    {
        // ---- fbm::planarArea by hand ----
        {
            typedef fbm::planarArea pa;
            auto square = [](const scalar x0, const scalar y0, const scalar s)
            {
                return List<vector2D>
                ({
                    vector2D(x0, y0), vector2D(x0 + s, y0),
                    vector2D(x0 + s, y0 + s), vector2D(x0, y0 + s)
                });
            };
            const scalar R = 0.7;
            fbmTest::check
            (
                "planarArea: disk inside a square", 
                pa::diskPolygon(square(-1, -1, 2), R), pi*R*R, 1e-15
            );
            fbmTest::check
            (
                "planarArea: square inside the disk",
                pa::diskPolygon(square(-0.4, -0.4, 0.8), R), 0.64, 1e-15
            );
            fbmTest::check
            (
                "planarArea: square apart (touching at (R, 0))",
                pa::diskPolygon(square(R, -0.5, 1), R), 0, 0
            );
            fbmTest::check
            (
                "planarArea: a quadrant",
                pa::diskPolygon(square(0, 0, 1), R), pi*R*R/4, 1e-15
            );
            // The segment beyond x = d: R^2 acos(d/R) - d sqrt(R^2 - d^2)
            const scalar d = 0.3;
            fbmTest::check
            (
                "planarArea: a circular segment",
                pa::diskPolygon(square(d, -1, 2), R),
                R*R*Foam::acos(d/R) - d*Foam::sqrt(R*R - d*d), 1e-15
            );
            // The same across the corners of a bigger square: the disk
            // minus the segment beyond x = -d, and clockwise a negative
            const List<vector2D> sq(square(-d, -1, 2));
            fbmTest::check
            (
                "planarArea: disk less a segment",
                pa::diskPolygon(sq, R),
                pi*R*R - (R*R*Foam::acos(d/R) - d*Foam::sqrt(R*R - d*d)),
                1e-15
            );
            const List<vector2D> tri
            ({vector2D(-1, -1), vector2D(3, -1), vector2D(-1, 3)});
            fbmTest::check
            (
                "planarArea: triangle clipped to the unit square",
                pa::boxPolygon(tri, vector2D(0, 0), vector2D(1, 1)), 1, 1e-15
            );
            fbmTest::check
            (
                "planarArea: triangle clipped to a box across its edge",
                pa::boxPolygon(tri, vector2D(0, 0), vector2D(2, 2)), 2,
                1e-15
            );
            fbmTest::check
            (
                "planarArea: clockwise triangle clipped",
                pa::boxPolygon
                (
                    List<vector2D>({tri[0], tri[2], tri[1]}),
                    vector2D(0, 0), vector2D(2, 2)
                ),
                2, 1e-15
            );
            // Across the bottom edge and the hypotenuse: [0.5, 2.5] x
            // [-2, 0] keeps the trapezoid under x + y = 2 above y = -1,
            // (2.5 - 0.5) x 1 less the corner triangle beyond x + y = 2
            // (x from 2 to 2.5 at y = 0, 1/8)
            fbmTest::check
            (
                "planarArea: triangle clipped across two edges",
                pa::boxPolygon(tri, vector2D(0.5, -2), vector2D(2.5, 0)),
                2 - 0.125, 1e-15
            );
            fbmTest::check
            (
                "planarArea: box apart from the triangle",
                pa::boxPolygon(tri, vector2D(2, 2), vector2D(3, 3)), 0, 0
            );
        }

        // ---- Ellipse a = 0.2, b = 0.1 ----
        dictionary dict;
        dict.add("type", "ellipse");
        dict.add("a", 0.2);
        dict.add("b", 0.1);
        autoPtr<fbm::bodyShape> ePtr(fbm::bodyShape::New(dict, mesh));
        fbm::bodyShape& e = ePtr();
        const scalar a = 0.2, b = 0.1;
        const scalar V = pi*a*b*L;

        fbmTest::check("ellipse: volume", e.volume(), V, 1e-15);
        const symmTensor I(e.inertiaPerDensity());
        fbmTest::check("ellipse: Izz", I.zz(), V*(a*a + b*b)/4, 1e-18);
        fbmTest::check("ellipse: Ixx", I.xx(), V*(b*b/4 + L*L/12), 1e-18);
        fbmTest::check("ellipse: Iyy", I.yy(), V*(a*a/4 + L*L/12), 1e-18);
        fbmTest::check("ellipse: Ixy", I.xy(), 0, 0);
        fbmTest::check("ellipse: centroid", e.centroid(), Zero, 0);
        fbmTest::check("ellipse: radius", e.radius(), a, 0);

        fbmTest::check
        (
            "ellipse: d on the major axis outside",
            e.signedDistance(vector(-0.25, 0, 0.03)), 0.05, 1e-14
        );
        fbmTest::check
        (
            "ellipse: d on the minor axis outside",
            e.signedDistance(vector(0, 0.13, 0)), 0.03, 1e-14
        );
        fbmTest::check
        (
            "ellipse: d at the centre", e.signedDistance(Zero), -b, 1e-14
        );
        // Inside on the major axis, |x0| < (a^2 - b^2)/a: the nearest
        // points are off the axis, d = -b sqrt(1 - x0^2/(a^2 - b^2))
        for (const scalar x0 : {0.05, 0.1, 0.149})
        {
            fbmTest::check
            (
                "ellipse: d inside on the major axis at x = "
              + std::to_string(x0),
                e.signedDistance(vector(x0, 0, 0)),
                -b*Foam::sqrt(1 - sqr(x0)/(a*a - b*b)), 1e-13
            );
        }

        // Rotated by 30 degrees
        const scalar phi = pi/6;
        const tensor Q(rotation(vector(0, 0, 1), phi));
        e.setOrientation(Q);
        const vector ua(Q & vector(1, 0, 0)), vb(Q & vector(0, 1, 0));
        fbmTest::check
        (
            "ellipse rotated: d along the turned major axis",
            e.signedDistance(0.27*ua), 0.07, 1e-14
        );
        fbmTest::check
        (
            "ellipse rotated: normal along the turned minor axis",
            e.normal(-0.12*vb), -vb, 1e-14
        );
        fbmTest::check
        (
            "ellipse rotated: half extent",
            vector(e.halfExtent().x(), e.halfExtent().y(), 0),
            vector
            (
                Foam::sqrt(sqr(a*Foam::cos(phi)) + sqr(b*Foam::sin(phi))),
                Foam::sqrt(sqr(a*Foam::sin(phi)) + sqr(b*Foam::cos(phi))),
                0
            ),
            1e-15
        );
        {
            List<vector> pts(20000);
            forAll(pts, i)
            {
                const scalar s = 2*pi*i/pts.size();
                pts[i] = Q & vector(a*Foam::cos(s), b*Foam::sin(s), 0);
            }
            checkDistances("ellipse", e, pts, a, true, 400);
        }

        // Solid fraction against the grid size: exact (the unit disk's
        // share of the cell mapped to the disk's frame), to round-off at
        // every h
        Info<< nl << "ellipse (a/b = 2, 30 degrees): solid fraction" << nl;
        for (const scalar h : {0.1, 0.05, 0.025, 0.0125})
        {
            const scalar err = fractionError(e, h, 4, true, pi*a*b);
            Info<< "    b/h = " << b/h << "  relative area error " << err
                << nl;
            fbmTest::check
            (
                "ellipse: area exact at b/h = " + std::to_string(b/h),
                err, 0, 1e-13
            );
        }
        cellsAgainstSampling("ellipse", e, 0.025, a/(b*b));

        // ---- Polygons ----
        {
            // Right triangle (0 0) (0.3 0) (0 0.2): centroid (0.1 0.2/3),
            // about the centroid int u^2 = p^3 q/36, int v^2 = p q^3/36,
            // int u v = -p^2 q^2/72
            const scalar p = 0.3, q = 0.2;
            dictionary d;
            d.add("type", "polygon");
            d.add
            (
                "vertices",
                List<vector2D>({vector2D(0, 0), vector2D(p, 0), vector2D(0, q)})
            );
            autoPtr<fbm::bodyShape> tPtr(fbm::bodyShape::New(d, mesh));
            fbm::bodyShape& t = tPtr();
            const scalar A = p*q/2, Vt = A*L;
            fbmTest::check("triangle: volume", t.volume(), Vt, 1e-16);
            fbmTest::check
            (
                "triangle: centroid", t.centroid(), vector(p/3, q/3, 0), 1e-16
            );
            const symmTensor It(t.inertiaPerDensity());
            const scalar Suu = pow3(p)*q/36, Svv = p*pow3(q)/36;
            const scalar Suv = -sqr(p*q)/72;
            fbmTest::check("triangle: Ixx", It.xx(), L*Svv + Vt*L*L/12, 1e-18);
            fbmTest::check("triangle: Iyy", It.yy(), L*Suu + Vt*L*L/12, 1e-18);
            fbmTest::check("triangle: Izz", It.zz(), L*(Suu + Svv), 1e-18);
            fbmTest::check("triangle: Ixy", It.xy(), -L*Suv, 1e-18);
            fbmTest::check("triangle: Ixz, Iyz", It.xz() + It.yz(), 0, 0);
            // Relative to the centroid (p/3, q/3): the hypotenuse's
            // midpoint and beyond it, a vertex, inside
            const vector c(p/3, q/3, 0);
            const vector nh(vector(q, p, 0)/Foam::sqrt(p*p + q*q));
            fbmTest::check
            (
                "triangle: d beyond the hypotenuse",
                t.signedDistance(vector(p/2, q/2, 0) + 0.01*nh - c), 0.01,
                1e-15
            );
            fbmTest::check
            (
                "triangle: normal beyond the hypotenuse",
                t.normal(vector(p/2, q/2, 0) + 0.01*nh - c), nh, 1e-14
            );
            fbmTest::check
            (
                "triangle: d beyond the corner (0 0)",
                t.signedDistance(vector(-0.03, -0.04, 0) - c), 0.05, 1e-15
            );
            fbmTest::check
            (
                "triangle: d inside near the bottom edge",
                t.signedDistance(vector(0.05, 0.01, 0) - c), -0.01, 1e-15
            );

            t.setOrientation(rotation(vector(0, 0, 1), 1.0));
            List<vector> pts(30000);
            const List<vector2D> P
            ({vector2D(0, 0), vector2D(p, 0), vector2D(0, q)});
            forAll(pts, i)
            {
                const label edge = 3*i/pts.size();
                const scalar s = 3.0*i/pts.size() - edge;
                const vector2D x
                (
                    (1 - s)*P[edge] + s*P[(edge + 1) % 3]
                  - vector2D(p/3, q/3)
                );
                pts[i] = t.orientation() & vector(x.x(), x.y(), 0);
            }
            checkDistances("triangle", t, pts, 0.2, true, 400, false);

            Info<< nl << "triangle (turned by 1 rad): solid fraction" << nl;
            for (const scalar h : {0.1, 0.05, 0.025, 0.0125})
            {
                const scalar err = fractionError(t, h, 4, true, A);
                Info<< "    q/h = " << q/h << "  relative area error " << err
                    << nl;
                fbmTest::check
                (
                    "triangle: area exact at q/h = " + std::to_string(q/h),
                    err, 0, 1e-13
                );
            }
            cellsAgainstSampling("triangle", t, 0.025, 0);
        }
        {
            // Rectangle 0.3 x 0.1, not at the origin: Izz = V (w^2 + h^2)/12
            dictionary d;
            d.add("type", "polygon");
            d.add
            (
                "vertices",
                List<vector2D>
                ({
                    vector2D(1, 2), vector2D(1.3, 2), vector2D(1.3, 2.1),
                    vector2D(1, 2.1)
                })
            );
            autoPtr<fbm::bodyShape> rPtr(fbm::bodyShape::New(d, mesh));
            const scalar Vr = 0.03*L;
            fbmTest::check("rectangle: volume", rPtr->volume(), Vr, 1e-15);
            fbmTest::check
            (
                "rectangle: centroid", rPtr->centroid(),
                vector(1.15, 2.05, 0), 1e-14
            );
            fbmTest::check
            (
                "rectangle: Izz", rPtr->inertiaPerDensity().zz(),
                Vr*(0.09 + 0.01)/12, 1e-15
            );
            fbmTest::check
            (
                "rectangle: Ixy", rPtr->inertiaPerDensity().xy(), 0, 1e-17
            );
        }

        // Bad polygons: a FatalIOError naming 'vertices' and the body
        FatalIOError.throwExceptions();
        const List<List<vector2D>> bad
        ({
            // Clockwise square
            {vector2D(0, 0), vector2D(0, 1), vector2D(1, 1), vector2D(1, 0)},
            // Non-convex (an arrow head)
            {
                vector2D(0, 0), vector2D(1, 0.5), vector2D(0, 1),
                vector2D(0.3, 0.5)
            },
            // Self-intersecting star, every turn to the left
            {
                vector2D(0, 1), vector2D(-0.588, -0.809),
                vector2D(0.951, 0.309), vector2D(-0.951, 0.309),
                vector2D(0.588, -0.809)
            },
            // Too few
            {vector2D(0, 0), vector2D(1, 0)},
            // Collinear vertices
            {vector2D(0, 0), vector2D(1, 0), vector2D(2, 0), vector2D(1, 1)}
        });
        forAll(bad, i)
        {
            dictionary body;
            body.name() = "fbmProperties.bodies.badPolygon";
            body.add("type", "polygon");
            body.add("vertices", bad[i]);
            bool thrown = false, named = false;
            try
            {
                fbm::bodyShape::New(body, mesh);
            }
            catch (const Foam::IOerror& err)
            {
                thrown = true;
                const std::string msg(err.message());
                named =
                    msg.find("vertices") != std::string::npos
                 && msg.find("badPolygon") != std::string::npos;
                Info<< "    bad polygon " << i << ": " << msg.c_str() << nl;
            }
            fbmTest::check
            (
                "bad polygon " + std::to_string(i) + " refused, naming the"
                " keyword and the body", scalar(thrown && named), 1, 0
            );
        }
        FatalIOError.dontThrowExceptions();
    }
    else
    {
        // ---- Ellipsoid 0.2, 0.15, 0.1 ----
        const vector e0(0.2, 0.15, 0.1);
        dictionary dict;
        dict.add("type", "ellipsoid");
        dict.add("a", e0.x());
        dict.add("b", e0.y());
        dict.add("c", e0.z());
        autoPtr<fbm::bodyShape> ePtr(fbm::bodyShape::New(dict, mesh));
        fbm::bodyShape& e = ePtr();
        const scalar V = 4.0/3.0*pi*e0.x()*e0.y()*e0.z();
        fbmTest::check("ellipsoid: volume", e.volume(), V, 1e-16);
        const symmTensor I(e.inertiaPerDensity());
        fbmTest::check
        (
            "ellipsoid: Ixx", I.xx(), V*(sqr(e0.y()) + sqr(e0.z()))/5, 1e-18
        );
        fbmTest::check
        (
            "ellipsoid: Iyy", I.yy(), V*(sqr(e0.x()) + sqr(e0.z()))/5, 1e-18
        );
        fbmTest::check
        (
            "ellipsoid: Izz", I.zz(), V*(sqr(e0.x()) + sqr(e0.y()))/5, 1e-18
        );
        fbmTest::check
        (
            "ellipsoid: products of inertia", I.xy() + I.xz() + I.yz(), 0, 0
        );
        fbmTest::check("ellipsoid: radius", e.radius(), 0.2, 0);
        fbmTest::check
        (
            "ellipsoid: d on the x axis", e.signedDistance(vector(0.3, 0, 0)),
            0.1, 1e-14
        );
        fbmTest::check
        (
            "ellipsoid: d on the z axis", e.signedDistance(vector(0, 0, -0.12)),
            0.02, 1e-14
        );
        fbmTest::check
        (
            "ellipsoid: d at the centre", e.signedDistance(Zero), -0.1, 1e-14
        );
        // Inside on the x axis: nearest point in the x-z plane (smallest
        // axis c), d = -c sqrt(1 - x0^2/(a^2 - c^2))
        fbmTest::check
        (
            "ellipsoid: d inside on the x axis",
            e.signedDistance(vector(0.1, 0, 0)),
            -e0.z()*Foam::sqrt(1 - 0.01/(0.04 - 0.01)), 1e-13
        );

        const tensor Q
        (
            rotation(vector(1, 2, 3)/Foam::sqrt(14.0), 0.7)
        );
        e.setOrientation(Q);
        fbmTest::check
        (
            "ellipsoid rotated: d along the turned y axis",
            e.signedDistance(Q & vector(0, 0.2, 0)), 0.05, 1e-14
        );
        {
            vector h(Zero);
            for (direction d = 0; d < 3; ++d)
            {
                h[d] = Foam::sqrt
                (
                    sqr(Q(d, 0)*e0.x()) + sqr(Q(d, 1)*e0.y())
                  + sqr(Q(d, 2)*e0.z())
                );
            }
            fbmTest::check("ellipsoid rotated: half extent", e.halfExtent(), h, 1e-15);
        }
        {
            const label nTheta = 300, nPhi = 600;
            List<vector> pts(nTheta*nPhi);
            for (label i = 0; i < nTheta; ++i)
            {
                const scalar th = pi*(i + 0.5)/nTheta;
                for (label j = 0; j < nPhi; ++j)
                {
                    const scalar ph = 2*pi*j/nPhi;
                    pts[i*nPhi + j] = Q & vector
                    (
                        e0.x()*Foam::sin(th)*Foam::cos(ph),
                        e0.y()*Foam::sin(th)*Foam::sin(ph),
                        e0.z()*Foam::cos(th)
                    );
                }
            }
            checkDistances("ellipsoid", e, pts, 0.2, false, 100);
        }

        Info<< nl << "ellipsoid (0.2 0.15 0.1, turned): solid fraction" << nl;
        scalar errPrev = 0;
        for (const scalar h : {0.1, 0.05, 0.025})
        {
            const scalar err = fractionError(e, h, 4, false, V);
            convergence("ellipsoid", err, errPrev);
            const scalar errLab = fractionError(e, h, 4, false, V, true);
            Info<< "    c/h = " << e0.z()/h << "  relative volume error "
                << err << " (sampling the lab-frame distance: " << errLab
                << ")" << nl;
            // Bound: planar leaves of mapped size up to h/16/c on the
            // unit sphere (the lab-frame sampling printed beside it has
            // leaves h/16 on a smallest radius of curvature c^2/a)
            fbmTest::check
            (
                "ellipsoid: volume error at c/h = " + std::to_string(e0.z()/h),
                err, 0, sqr(h/16/e0.z())
            );
        }

        // ---- triSurface: a cube of side 0.2 from an OBJ file ----
        const fileName dir
        (
            runTime.globalPath()/runTime.constant()/"triSurface"
        );
        const scalar side = 0.2;
        const vector corner(1, 2, 3);
        writeCube(dir/"cube.obj", corner, false);
        writeCube(dir/"cubeInward.obj", corner, true);
        writeCube(dir/"cubeOpen.obj", corner, false, 1);
        for (const word file : {"cube.obj", "cubeInward.obj"})
        {
            dictionary d;
            d.add("type", "triSurface");
            d.add("file", fileName(file));
            d.add("scale", side);
            autoPtr<fbm::bodyShape> cPtr(fbm::bodyShape::New(d, mesh));
            fbm::bodyShape& cube = cPtr();
            const scalar Vc = pow3(side);
            const word n("triSurface " + file + ": ");
            fbmTest::check(n + "volume", cube.volume(), Vc, 1e-15);
            fbmTest::check
            (
                n + "centroid", cube.centroid(), side*(corner + 0.5*vector::one),
                1e-14
            );
            const symmTensor Ic(cube.inertiaPerDensity());
            fbmTest::check
            (
                n + "inertia diagonal",
                vector(Ic.xx(), Ic.yy(), Ic.zz()),
                Vc*sqr(side)/6*vector::one, 1e-17
            );
            fbmTest::check
            (
                n + "products of inertia", mag(Ic.xy()) + mag(Ic.xz())
              + mag(Ic.yz()), 0, 1e-18
            );
            fbmTest::check
            (
                n + "radius", cube.radius(), side*Foam::sqrt(3.0)/2, 1e-15
            );
            fbmTest::check
            (
                n + "d beyond a face", cube.signedDistance(vector(0.15, 0, 0)),
                0.05, 1e-14
            );
            fbmTest::check
            (
                n + "normal beyond a face", cube.normal(vector(0, -0.15, 0.01)),
                vector(0, -1, 0), 1e-14
            );
            fbmTest::check
            (
                n + "d beyond a corner",
                cube.signedDistance(vector(0.13, 0.14, 0.1)),
                Foam::sqrt(sqr(0.03) + sqr(0.04)), 1e-14
            );
            fbmTest::check
            (
                n + "d inside near a face",
                cube.signedDistance(vector(0, 0, -0.07)), -0.03, 1e-14
            );
            fbmTest::check
            (
                n + "d at the centre", cube.signedDistance(Zero), -0.1, 1e-14
            );

            cube.setOrientation(Q);
            fbmTest::check
            (
                n + "turned: d beyond the turned x face",
                cube.signedDistance(Q & vector(0.16, 0.02, -0.03)), 0.06, 1e-14
            );
            {
                vector h(Zero);
                for (direction dd = 0; dd < 3; ++dd)
                {
                    h[dd] = 0.5*side
                       *(mag(Q(dd, 0)) + mag(Q(dd, 1)) + mag(Q(dd, 2)));
                }
                fbmTest::check
                (
                    n + "turned: half extent", cube.halfExtent(), h, 1e-15
                );
            }
            if (file == "cube.obj")
            {
                Info<< nl << "cube (side 0.2, turned): solid fraction" << nl;
                scalar errPrev = 0;
                for (const scalar h : {0.1, 0.05, 0.025})
                {
                    const scalar err = fractionError(cube, h, 4, false, Vc);
                    convergence("cube", err, errPrev);
                    Info<< "    side/h = " << side/h
                        << "  relative volume error " << err << nl;
                    // Bound: flat faces are exact; the leaves (size
                    // delta = h/16) along the 12 edges lose at most
                    // delta^2 per length
                    fbmTest::check
                    (
                        "cube: volume error at side/h = "
                      + std::to_string(side/h),
                        err, 0, 12*side*sqr(h/16)/Vc
                    );
                }
            }
        }
        {
            FatalIOError.throwExceptions();
            dictionary d;
            d.name() = "fbmProperties.bodies.openCube";
            d.add("type", "triSurface");
            d.add("file", fileName("cubeOpen.obj"));
            bool thrown = false, named = false;
            try
            {
                fbm::bodyShape::New(d, mesh);
            }
            catch (const Foam::IOerror& err)
            {
                thrown = true;
                const std::string msg(err.message());
                named = msg.find("not closed") != std::string::npos
                     && msg.find("openCube") != std::string::npos;
                Info<< "    open surface: " << msg.c_str() << nl;
            }
            fbmTest::check
            (
                "open surface refused, naming the body", scalar(thrown && named),
                1, 0
            );
            FatalIOError.dontThrowExceptions();
        }
    }

    return fbmTest::result();
}


// ************************************************************************* //
