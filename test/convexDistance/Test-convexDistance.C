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
    Test-convexDistance

Description
    The support functions of the shapes and fbm::convexDistance (GJK, EPA)
    on a 2D mesh (ellipse, polygon, circle) or a 3D mesh (ellipsoid,
    sphere, triSurface cube), and the contacts of non-round bodies in
    fbm::particleCollisions without fluid:
    - support values against the analytic support function: ellipse and
      ellipsoid sqrt(n.A n), A = Q diag(a^2, ...) Q^T; a turned square
      (the depth of its lowest corner below the centre, s (|cos| + |sin|));
      a turned triSurface cube (s/2 sum |n.Q e_k|);
    - the gap of aligned shapes by hand: ellipses and ellipsoids on an axis,
      d - a1 - a2, separated and overlapping, normal and witness points;
    - random pairs (turned, separated and overlapping) against an
      independent reference: for convex sets the signed distance is the
      largest separation over unit directions n,
      max_n [n.(XB - XA) - h_A(n) - h_B(-n)] (h the support function),
      found by sampling the circle (sphere) of directions and refining;
      the gap to the GJK/EPA tolerance, the normal, and p_B - p_A = gap n;
    - a head-on collision of two turned ellipses (ellipsoids in 3D):
      linear and angular momentum conserved to round-off, the bodies turn
      (the contact torque), kinetic energy kept by the elastic law;
    - a rectangle, an ellipse (2D), an ellipsoid or a triSurface box (3D)
      dropped onto the bottom wall with damping and without fluid: never
      through the wall, no energy gained; the rectangle at rest on its long
      side (the smooth bodies and the box keep rocking without fluid or
      friction);
    - 2D: a pile of 40 ellipses and rectangles at random orientations
      dropped into the box: finite, inside the walls, no pair overlapping
      by more than 10 % of the bounding radius, no energy gained, settled
      (kinetic energy below 1e-3 of the start energy).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "convexDistance.H"
#include "bodyShape.H"
#include "body.H"
#include "particleCollisions.H"
#include "rigidBodyMotion.H"
#include "Random.H"
#include "OFstream.H"
#include "fbmTest.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Rotation by phi about the unit axis k (Rodrigues)
tensor rotation(const vector& k, const scalar phi)
{
    const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
    return tensor::I + Foam::sin(phi)*K + (1 - Foam::cos(phi))*(K & K);
}


autoPtr<fbm::bodyShape> shape(const dictionary& dict, const fvMesh& mesh)
{
    return fbm::bodyShape::New(dict, mesh);
}


dictionary ellipseDict(const scalar a, const scalar b)
{
    dictionary d;
    d.add("type", "ellipse");
    d.add("a", a);
    d.add("b", b);
    return d;
}


dictionary ellipsoidDict(const vector& e)
{
    dictionary d;
    d.add("type", "ellipsoid");
    d.add("a", e.x());
    d.add("b", e.y());
    d.add("c", e.z());
    return d;
}


dictionary polygonDict(const List<vector2D>& v)
{
    dictionary d;
    d.add("type", "polygon");
    d.add("vertices", v);
    return d;
}


dictionary roundDict(const word& type, const scalar R)
{
    dictionary d;
    d.add("type", type);
    d.add("radius", R);
    return d;
}


// Separation of A and B along the unit direction n
scalar separation
(
    const fbm::bodyShape& A, const tensor& QA, const point& XA,
    const fbm::bodyShape& B, const tensor& QB, const point& XB,
    const vector& n
)
{
    return (n & (XB - XA)) - (n & A.support(QA, n)) + (n & B.support(QB, -n));
}


// Reference signed distance: the largest separation over the directions
// of the plane (2D, e the plane normal) or the sphere (3D), sampled and
// refined by a pattern search; nRef the maximising direction
scalar reference
(
    const fbm::bodyShape& A, const tensor& QA, const point& XA,
    const fbm::bodyShape& B, const tensor& QB, const point& XB,
    const bool twoD,
    vector& nRef
)
{
    const scalar pi = constant::mathematical::pi;
    auto dir2 = [](const scalar phi)
    {
        return vector(Foam::cos(phi), Foam::sin(phi), 0);
    };
    auto dir3 = [](const scalar th, const scalar ph)
    {
        return vector
        (
            Foam::sin(th)*Foam::cos(ph), Foam::sin(th)*Foam::sin(ph),
            Foam::cos(th)
        );
    };
    auto sep = [&](const vector& n)
    {
        return separation(A, QA, XA, B, QB, XB, n);
    };

    if (twoD)
    {
        scalar best = -GREAT, phiBest = 0;
        const label N = 7200;
        for (label k = 0; k < N; ++k)
        {
            const scalar phi = 2*pi*k/N;
            const scalar s = sep(dir2(phi));
            if (s > best)
            {
                best = s;
                phiBest = phi;
            }
        }
        // Golden section on the bracket around the best sample
        const scalar g = 0.5*(Foam::sqrt(5.0) - 1);
        scalar lo = phiBest - 2*pi/N, hi = phiBest + 2*pi/N;
        for (label it = 0; it < 200 && hi - lo > 1e-15; ++it)
        {
            const scalar x1 = hi - g*(hi - lo), x2 = lo + g*(hi - lo);
            if (sep(dir2(x1)) > sep(dir2(x2))) hi = x2; else lo = x1;
        }
        nRef = dir2(0.5*(lo + hi));
        return sep(nRef);
    }

    // Sphere: a Fibonacci set of directions, then a pattern search in
    // (theta, phi) about the best
    scalar best = -GREAT, thBest = 0, phBest = 0;
    const label N = 40000;
    for (label k = 0; k < N; ++k)
    {
        const scalar z = 1 - (2*k + 1.0)/N;
        const scalar th = Foam::acos(z);
        const scalar ph = pi*(3 - Foam::sqrt(5.0))*k;
        const scalar s = sep(dir3(th, ph));
        if (s > best)
        {
            best = s;
            thBest = th;
            phBest = ph;
        }
    }
    scalar step = 0.05;
    while (step > 1e-13)
    {
        bool moved = false;
        for (const vector2D& dp :
            {vector2D(1, 0), vector2D(-1, 0), vector2D(0, 1), vector2D(0, -1)})
        {
            const scalar th = thBest + step*dp.x();
            const scalar ph = phBest + step*dp.y()/max(Foam::sin(thBest), 0.1);
            const scalar s = sep(dir3(th, ph));
            if (s > best)
            {
                best = s;
                thBest = th;
                phBest = ph;
                moved = true;
            }
        }
        if (!moved) step *= 0.5;
    }
    nRef = dir3(thBest, phBest);
    return best;
}


// Random rotation: about the empty direction (2D), or about a random axis
tensor randomRotation(Random& rng, const bool twoD)
{
    const scalar pi = constant::mathematical::pi;
    if (twoD)
    {
        return rotation(vector(0, 0, 1), 2*pi*rng.sample01<scalar>());
    }
    vector axis(rng.sample01<vector>() - 0.5*vector::one);
    axis /= mag(axis);
    return rotation(axis, 2*pi*rng.sample01<scalar>());
}


// Random pairs of the shapes A and B against the reference
void checkRandom
(
    const word& name,
    const fbm::bodyShape& A,
    const fbm::bodyShape& B,
    const fbm::convexDistance& cd,
    const bool twoD,
    const label nPairs,
    const point& XA,
    Random& rng
)
{
    const scalar RA = A.radius(), RB = B.radius();
    // Tolerances of convexDistance (its defaults): GJK and the 2D EPA
    // 1e-10 (RA + RB), the 3D EPA 1e-8 (RA + RB)
    const scalar delta = 1e-10*(RA + RB);
    const scalar deltaEPA = (twoD ? 1e-10 : 1e-8)*(RA + RB);
    scalar maxGapErr = 0, maxNormalErr = 0, maxWitnessErr = 0;
    scalar maxGapErrO = 0, maxNormalErrO = 0;
    label maxIter = 0, nOverlap = 0, nConverged = 0;
    label iterCold = 0, iterWarm = 0, nConvergedWarm = 0, nApartWarm = 0;
    label iterColdO = 0, iterWarmO = 0;
    scalar maxWarmErr = 0;
    for (label k = 0; k < nPairs; ++k)
    {
        const tensor QA(randomRotation(rng, twoD));
        const tensor QB(randomRotation(rng, twoD));
        vector u(rng.sample01<vector>() - 0.5*vector::one);
        if (twoD) u.z() = 0;
        u /= mag(u);
        // Centre distances from deep overlap to clearly apart
        const scalar D = (0.3 + 0.9*rng.sample01<scalar>())*(RA + RB);
        const point XB(XA + D*u);

        const fbm::convexDistance::result r
        (
            cd.distance(A, QA, XA, B, QB, XB)
        );
        vector nRef;
        const scalar gRef = reference(A, QA, XA, B, QB, XB, twoD, nRef);

        // Warm starts: from the normal of a nearby configuration (B moved
        // by 1e-3 (RA + RB), as in the next collision sub-step) and from
        // the worst direction (the opposite of the answer): the same
        // answer within the tolerances
        vector du(rng.sample01<vector>() - 0.5*vector::one);
        if (twoD) du.z() = 0;
        const fbm::convexDistance::result rNear
        (
            cd.distance(A, QA, XA, B, QB, XB + 1e-3*(RA + RB)*du/mag(du))
        );
        const fbm::convexDistance::result rWarm
        (
            cd.distance(A, QA, XA, B, QB, XB, -rNear.normal)
        );
        const fbm::convexDistance::result rWrong
        (
            cd.distance(A, QA, XA, B, QB, XB, r.normal)
        );
        if (!r.overlap && !rNear.overlap)
        {
            iterCold += r.iterations;
            iterWarm += rWarm.iterations;
            ++nApartWarm;
        }
        else
        {
            iterColdO += r.iterations;
            iterWarmO += rWarm.iterations;
        }
        for (const auto* rh : {&rWarm, &rWrong})
        {
            const scalar tolGap = rh->overlap ? 2*deltaEPA : 2*delta;
            const scalar tolN =
                10*Foam::sqrt((rh->overlap ? deltaEPA : delta)/min(RA, RB));
            maxWarmErr = max
            (
                maxWarmErr,
                max
                (
                    mag(rh->gap - gRef)/(tolGap + 1e-14),
                    mag(rh->normal - nRef)/tolN
                )
            );
            if (rh->converged) ++nConvergedWarm;
        }

        if (r.overlap)
        {
            maxGapErrO = max(maxGapErrO, mag(r.gap - gRef));
            maxNormalErrO = max(maxNormalErrO, mag(r.normal - nRef));
        }
        else
        {
            maxGapErr = max(maxGapErr, mag(r.gap - gRef));
            maxNormalErr = max(maxNormalErr, mag(r.normal - nRef));
        }
        maxWitnessErr =
            max(maxWitnessErr, mag((r.pB - r.pA) - r.gap*r.normal));
        maxIter = max(maxIter, r.iterations);
        if (r.overlap) ++nOverlap;
        if (r.converged) ++nConverged;
    }
    Info<< "    " << name << ": " << nPairs << " pairs, " << nOverlap
        << " overlapping; largest gap error " << maxGapErr
        << " (overlapping: " << maxGapErrO << "), normal error "
        << maxNormalErr << " (" << maxNormalErrO << "), |pB - pA - gap n| "
        << maxWitnessErr << ", iterations at most " << maxIter << nl;
    // The gap to the tolerance of both bounds, plus the reference's own
    // round-off
    fbmTest::check(name + ": gap = reference (apart)", maxGapErr, 0, 2*delta + 1e-14);
    fbmTest::check(name + ": gap = reference (overlap)", maxGapErrO, 0, 2*deltaEPA + 1e-14);
    // The normal: the separation is flat to second order at its maximum,
    // so a gap tolerance delta leaves ~ sqrt(delta/R) in the direction
    fbmTest::check
    (
        name + ": normal = reference (apart)", maxNormalErr, 0,
        10*Foam::sqrt(delta/min(RA, RB))
    );
    fbmTest::check
    (
        name + ": normal = reference (overlap)", maxNormalErrO, 0,
        10*Foam::sqrt(deltaEPA/min(RA, RB))
    );
    fbmTest::check
    (
        name + ": pB - pA = gap n", maxWitnessErr, 0,
        10*Foam::sqrt(delta*min(RA, RB))
    );
    fbmTest::check(name + ": all converged", nConverged, nPairs, 0);
    Info<< "    " << name << ": warm start from a nearby normal, pairs"
        << " apart: " << scalar(iterWarm)/max(nApartWarm, 1)
        << " iterations per pair against "
        << scalar(iterCold)/max(nApartWarm, 1) << " from the centres;"
        << " overlapping: " << scalar(iterWarmO)/max(nPairs - nApartWarm, 1)
        << " against " << scalar(iterColdO)/max(nPairs - nApartWarm, 1)
        << "; error of the warm and the wrong-way starts in units of the"
        << " tolerances " << maxWarmErr << nl;
    fbmTest::check
    (
        name + ": warm and wrong-way starts = reference", maxWarmErr, 0, 1
    );
    fbmTest::check
    (
        name + ": warm and wrong-way starts converged", nConvergedWarm,
        2*nPairs, 0
    );
    fbmTest::check
    (
        name + ": warm start takes fewer iterations (pairs apart)",
        scalar(iterWarm < iterCold), 1, 0
    );
    fbmTest::check(name + ": some overlap", scalar(nOverlap > nPairs/10), 1, 0);
    fbmTest::check
    (
        name + ": some apart", scalar(nOverlap < nPairs - nPairs/10), 1, 0
    );
}


// Collisions dictionary (rangePlusLinear law)
dictionary collisionsDict
(
    const scalar range,
    const scalar epsP,
    const scalar epsW,
    const scalar damping
)
{
    dictionary coeffs;
    coeffs.add("overlapForce", "rangePlusLinear");
    coeffs.add("range", range);
    coeffs.add("epsP", epsP);
    coeffs.add("epsPOverlap", epsP);
    coeffs.add("epsW", epsW);
    coeffs.add("epsWOverlap", epsW);

    dictionary dict;
    dict.add("model", "singhRepulsion");
    dict.add("singhRepulsionCoeffs", coeffs);
    if (damping > 0)
    {
        dict.add("dampingRatio", damping);
    }
    return dict;
}


// A free body of the given shape
autoPtr<fbm::body> newBody
(
    const word& name,
    const dictionary& shapeDict,
    const point& X,
    const vector& U,
    const tensor& Q,
    const fvMesh& mesh
)
{
    fbm::bodyState s(X, U, Zero);
    s.setOrientation(Q, Zero);
    return autoPtr<fbm::body>
    (
        new fbm::body(name, shape(shapeDict, mesh), 1.0, s, true, true)
    );
}


// Angular momentum of the bodies about the origin (the component about the
// empty direction in 2D)
vector angularMomentum(const PtrList<fbm::body>& bodies)
{
    vector L(Zero);
    for (const fbm::body& b : bodies)
    {
        L += b.mass()*(b.centre() ^ b.U()) + (b.inertia() & b.omega());
    }
    return L;
}


scalar kineticEnergy(const PtrList<fbm::body>& bodies)
{
    scalar E = 0;
    for (const fbm::body& b : bodies)
    {
        E += 0.5*b.mass()*magSqr(b.U()) + 0.5*(b.omega() & (b.inertia() & b.omega()));
    }
    return E;
}


// Head-on collision of two turned bodies without fluid
void headOn
(
    const word& name,
    const dictionary& shapeDict,
    const tensor& Q0,
    const tensor& Q1,
    const fvMesh& mesh
)
{
    const point C(mesh.bounds().centre());
    const scalar u = 1;
    PtrList<fbm::body> bodies(2);
    bodies.set(0, newBody("b0", shapeDict, C - vector(0.25, 0, 0), vector(u, 0, 0), Q0, mesh));
    bodies.set(1, newBody("b1", shapeDict, C + vector(0.25, 0, 0), vector(-u, 0, 0), Q1, mesh));
    const fbm::rigidBodyMotion motion(Zero, 1e-12, 0, mesh);
    fbm::particleCollisions coll
    (
        collisionsDict(0.02, 1e-4, 5e-5, 0), mesh, bodies
    );

    const scalar m = bodies[0].mass();
    const vector P0(m*bodies[0].U() + m*bodies[1].U());
    const vector L0(angularMomentum(bodies));
    const scalar E0 = kineticEnergy(bodies);
    const scalar R = bodies[0].shape().radius();

    scalar maxDP = 0, maxDL = 0, minGap = GREAT;
    const scalar dt = 0.005;
    for (label step = 0; step < 80; ++step)
    {
        coll.move(bodies, motion, dt);
        minGap = min(minGap, coll.minPairGap());
        const vector P(m*bodies[0].U() + m*bodies[1].U());
        maxDP = max(maxDP, mag(P - P0));
        maxDL = max(maxDL, mag(angularMomentum(bodies) - L0));
    }
    const scalar E = kineticEnergy(bodies);
    Info<< "    " << name << ": " << coll.nSubCycles(dt) << " sub-steps per"
        << " step; smallest gap " << minGap << ", |dP| " << maxDP
        << ", |dL| " << maxDL << ", energy after/before " << E/E0
        << ", omega " << bodies[0].omega() << ' ' << bodies[1].omega()
        << ", U " << bodies[0].U() << ' ' << bodies[1].U() << nl;

    fbmTest::check(name + ": momentum conserved", maxDP, 0, 1e-13*m*u);
    // Round-off of some 4000 sub-steps on L ~ m u |X| about the origin
    const scalar Lscale = m*u*(mag(bodies[0].centre()) + R);
    fbmTest::check(name + ": angular momentum conserved", maxDL, 0, 1e-12*Lscale);
    fbmTest::check(name + ": contact reached (gap < range)", scalar(minGap < 0.02), 1, 0);
    fbmTest::check(name + ": overlap below 5 % of R", scalar(minGap > -0.05*R), 1, 0);
    fbmTest::check(name + ": bodies apart again", scalar(bodies[0].U().x() < 0 && bodies[1].U().x() > 0), 1, 0);
    fbmTest::check
    (
        name + ": the contact turned the bodies",
        scalar(mag(bodies[0].omega()) > 0.1*u/R), 1, 0
    );
    // The elastic law with 20 sub-steps per contact time: energy error of
    // velocity Verlet O((omega dt)^2) ~ 1e-3 (as the round head-on test)
    fbmTest::check(name + ": kinetic energy kept (1 %)", E/E0, 1, 0.01);
}


// A body dropped onto the bottom wall (y = ymin) with damping and without
// fluid (rho_f tiny). Always: never through the wall, and the mechanical
// energy (kinetic plus m g y) not above its start. expectRest: a body with
// corners (their impacts dissipate) comes to rest, kinetic energy below
// 1e-4 of the drop energy, on its long side (tilt of the long axis < 0.01
// rad), the gap within the range. A smooth body rocking on a frictionless
// wall hardly changes its gap, so the normal damping hardly acts: its rest
// needs the fluid (the coupled run of test/Alltest)
void dropOnWall
(
    const word& name,
    const dictionary& shapeDict,
    const scalar angle0,
    const scalar halfHeight,
    const bool expectRest,
    const fvMesh& mesh
)
{
    const bool twoD = (mesh.nSolutionD() == 2);
    const boundBox& bb = mesh.bounds();
    const scalar range = 0.02;
    const point X0(bb.centre().x(), bb.min().y() + 0.3, bb.centre().z());
    const tensor Q0
    (
        twoD
      ? rotation(vector(0, 0, 1), angle0)
      : rotation(vector(1, 0, 1)/Foam::sqrt(2.0), angle0)
    );
    PtrList<fbm::body> bodies(1);
    bodies.set(0, newBody("b0", shapeDict, X0, Zero, Q0, mesh));
    const scalar g = 10;
    const fbm::rigidBodyMotion motion(vector(0, -g, 0), 1e-12, 0, mesh);
    fbm::particleCollisions coll
    (
        collisionsDict(range, 1e-4, 5e-5, 0.5), mesh, bodies
    );
    const fbm::body& b = bodies[0];
    const scalar m = b.mass();
    auto energy = [&]()
    {
        return kineticEnergy(bodies) + m*g*(b.centre().y() - bb.min().y());
    };
    const scalar E0 = energy();
    const scalar Edrop = E0 - m*g*halfHeight;

    const scalar dt = 0.002;
    scalar minGap = GREAT, Emax = E0;
    for (label step = 0; step < 2500; ++step)
    {
        coll.move(bodies, motion, dt);
        if (step > 0) minGap = min(minGap, coll.minWallGap());
        Emax = max(Emax, energy());
    }
    // Lowest point's gap at the end
    const vector s(b.shape().support(b.state().Q(), vector(0, -1, 0)));
    const scalar gap = b.centre().y() + s.y() - bb.min().y();
    // Long axis: the body's x axis; its tilt out of the wall plane
    const vector ax(b.state().Q() & vector(1, 0, 0));
    const scalar tilt = Foam::asin(min(mag(ax.y()), 1.0));
    const scalar KE = kineticEnergy(bodies);
    Info<< "    " << name << ": smallest wall gap " << minGap
        << ", final gap " << gap << ", speed " << mag(b.U())
        << ", |omega| " << mag(b.omega()) << ", kinetic energy / drop energy "
        << KE/Edrop << ", largest energy / start " << Emax/E0
        << ", tilt of the long axis " << tilt << " rad" << nl;
    fbmTest::check(name + ": never through the wall (gap > 0)", scalar(minGap > 0), 1, 0);
    fbmTest::check(name + ": energy never above the start", scalar(Emax <= E0), 1, 0);
    if (expectRest)
    {
        fbmTest::check(name + ": final gap within the range", scalar(gap > 0 && gap < 0.5*range), 1, 0);
        fbmTest::check(name + ": at rest (kinetic energy < 1e-4 drop energy)", KE/Edrop, 0, 1e-4);
        fbmTest::check(name + ": long axis along the wall (tilt < 0.01)", scalar(tilt < 0.01), 1, 0);
    }
}


// A pile: 40 ellipses and rectangles (bounding radii 0.05, 0.045) on a
// lattice at random orientations, dropped into the box with damping and
// without fluid: the contacts of many non-round bodies stay finite, the
// bodies stay inside the walls and apart (smallest pair gap above -10 % of
// the bounding radius), no energy is gained, and the pile settles
void pile(const fvMesh& mesh, Random& rng)
{
    const boundBox& bb = mesh.bounds();
    const scalar z = bb.centre().z();
    PtrList<fbm::body> bodies(40);
    label k = 0;
    for (label row = 0; row < 5; ++row)
    {
        for (label col = 0; col < 8; ++col)
        {
            const point X(0.115 + 0.11*col, 0.3 + 0.11*row, z);
            const tensor Q
            (
                rotation(vector(0, 0, 1), 6.28*rng.sample01<scalar>())
            );
            const word name("p" + Foam::name(k));
            if (k % 4 == 3)
            {
                bodies.set
                (
                    k,
                    newBody
                    (
                        name,
                        polygonDict
                        ({
                            vector2D(-0.04, -0.02), vector2D(0.04, -0.02),
                            vector2D(0.04, 0.02), vector2D(-0.04, 0.02)
                        }),
                        X, Zero, Q, mesh
                    )
                );
            }
            else
            {
                bodies.set
                (
                    k, newBody(name, ellipseDict(0.05, 0.025), X, Zero, Q, mesh)
                );
            }
            ++k;
        }
    }
    const scalar g = 10;
    const fbm::rigidBodyMotion motion(vector(0, -g, 0), 1e-12, 0, mesh);
    fbm::particleCollisions coll
    (
        collisionsDict(0.01, 1e-5, 5e-6, 0.5), mesh, bodies
    );
    auto energy = [&]()
    {
        scalar E = kineticEnergy(bodies);
        for (const fbm::body& b : bodies)
        {
            E += b.mass()*g*(b.centre().y() - bb.min().y());
        }
        return E;
    };
    const scalar E0 = energy();
    scalar Emax = E0, minPair = GREAT, minWall = GREAT;
    bool finite = true;
    const scalar dt = 0.002;
    for (label step = 0; step < 1000; ++step)
    {
        coll.move(bodies, motion, dt);
        minPair = min(minPair, coll.minPairGap());
        minWall = min(minWall, coll.minWallGap());
        const scalar E = energy();
        finite = finite && std::isfinite(E);
        Emax = max(Emax, E);
    }
    const scalar KE = kineticEnergy(bodies);
    Info<< "    pile of 40: " << coll.nSubCycles(dt) << " sub-steps per step;"
        << " smallest pair gap " << minPair << ", wall gap " << minWall
        << ", largest energy / start " << Emax/E0
        << ", kinetic / start energy at the end " << KE/E0 << nl;
    fbmTest::check("pile: finite", scalar(finite), 1, 0);
    fbmTest::check("pile: never through a wall", scalar(minWall > 0), 1, 0);
    fbmTest::check("pile: pair overlap below 10 % of R", scalar(minPair > -0.005), 1, 0);
    fbmTest::check("pile: energy never above the start", scalar(Emax <= E0), 1, 0);
    fbmTest::check("pile: settled (kinetic < 1e-3 start energy)", KE/E0, 0, 1e-3);
}


// Write a box of sides L as OBJ, corners at (0|Lx, 0|Ly, 0|Lz)
void writeCube(const fileName& path, const vector& L = vector::one)
{
    mkDir(path.path());
    OFstream os(path);
    for (label k = 0; k < 2; ++k)
    {
        const scalar z = k*L.z();
        os  << "v 0 0 " << z << nl << "v " << L.x() << " 0 " << z << nl
            << "v " << L.x() << ' ' << L.y() << ' ' << z << nl
            << "v 0 " << L.y() << ' ' << z << nl;
    }
    const label tri[12][3] =
    {
        {0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
        {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}
    };
    for (label i = 0; i < 12; ++i)
    {
        os  << "f " << tri[i][0] + 1 << ' ' << tri[i][1] + 1 << ' '
            << tri[i][2] + 1 << nl;
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const bool twoD = (mesh.nSolutionD() == 2);
    const point C(mesh.bounds().centre());
    const fbm::convexDistance cd(twoD ? vector(0, 0, 1) : vector::zero);
    Random rng(12345);

    if (twoD)
    {
        // ---- Support functions ----
        {
            const scalar a = 0.2, b = 0.1;
            autoPtr<fbm::bodyShape> e(shape(ellipseDict(a, b), mesh));
            scalar err = 0;
            for (label k = 0; k < 100; ++k)
            {
                const tensor Q(randomRotation(rng, true));
                const scalar phi = 6.3*rng.sample01<scalar>();
                const vector n(Foam::cos(phi), Foam::sin(phi), 0);
                const vector u(Q & vector(1, 0, 0)), v(Q & vector(0, 1, 0));
                const scalar h =
                    Foam::sqrt(sqr(a*(n & u)) + sqr(b*(n & v)));
                err = max(err, mag((n & e->support(Q, n)) - h));
                // The support point lies on the surface
                e->setOrientation(Q);
                err = max(err, mag(e->signedDistance(e->support(Q, n))));
            }
            fbmTest::check("ellipse: support = sqrt(n.A n), on the surface", err, 0, 1e-15);

            // A square of side 2s turned by theta: its lowest point lies
            // s (|cos| + |sin|) below the centre
            const scalar s = 0.1;
            autoPtr<fbm::bodyShape> sq
            (
                shape
                (
                    polygonDict
                    ({
                        vector2D(-s, -s), vector2D(s, -s), vector2D(s, s),
                        vector2D(-s, s)
                    }),
                    mesh
                )
            );
            err = 0;
            for (const scalar th : {0.0, 0.3, 0.7854, 1.2, 2.5, -0.4})
            {
                const tensor Q(rotation(vector(0, 0, 1), th));
                const vector p(sq->support(Q, vector(0, -1, 0)));
                err = max
                (
                    err,
                    mag(-p.y() - s*(mag(Foam::cos(th)) + mag(Foam::sin(th))))
                );
            }
            fbmTest::check("turned square: depth below the centre s(|cos| + |sin|)", err, 0, 1e-15);
        }

        // ---- Aligned ellipses by hand ----
        {
            const scalar a1 = 0.2, b1 = 0.1, a2 = 0.15, b2 = 0.05;
            autoPtr<fbm::bodyShape> A(shape(ellipseDict(a1, b1), mesh));
            autoPtr<fbm::bodyShape> B(shape(ellipseDict(a2, b2), mesh));
            const scalar delta = 1e-10*(a1 + a2);
            const tensor I(tensor::I);
            for (const scalar d : {0.4, 0.351, 0.35})
            {
                const point XB(C + vector(d, 0, 0));
                const fbm::convexDistance::result r
                (
                    cd.distance(A(), I, C, B(), I, XB)
                );
                const word n("ellipses on the x axis, d = " + std::to_string(d));
                fbmTest::check(n + ": gap d - a1 - a2", r.gap, d - a1 - a2, delta);
                fbmTest::check(n + ": normal", r.normal, vector(1, 0, 0), 1e-4);
                fbmTest::check(n + ": pA", r.pA, C + vector(a1, 0, 0), 1e-4*a1);
                fbmTest::check(n + ": pB", r.pB, XB - vector(a2, 0, 0), 1e-4*a1);
            }
            // Side by side on the y axis, separated and overlapping: the
            // depth along y (the flat sides)
            for (const scalar d : {0.16, 0.145, 0.13})
            {
                const point XB(C + vector(0, d, 0));
                const fbm::convexDistance::result r
                (
                    cd.distance(A(), I, C, B(), I, XB)
                );
                const word n("ellipses on the y axis, d = " + std::to_string(d));
                fbmTest::check(n + ": gap d - b1 - b2", r.gap, d - b1 - b2, delta);
                fbmTest::check(n + ": normal", r.normal, vector(0, 1, 0), 1e-4);
                fbmTest::check(n + ": overlap flag", scalar(r.overlap), scalar(d < b1 + b2), 0);
            }
        }

        // ---- Random pairs against the reference ----
        {
            autoPtr<fbm::bodyShape> e1(shape(ellipseDict(0.2, 0.1), mesh));
            autoPtr<fbm::bodyShape> e2(shape(ellipseDict(0.12, 0.03), mesh));
            autoPtr<fbm::bodyShape> sq
            (
                shape
                (
                    polygonDict
                    ({
                        vector2D(0, 0), vector2D(0.3, 0), vector2D(0.3, 0.1),
                        vector2D(0, 0.1)
                    }),
                    mesh
                )
            );
            autoPtr<fbm::bodyShape> tri
            (
                shape
                (
                    polygonDict
                    ({vector2D(0, 0), vector2D(0.2, 0), vector2D(0.05, 0.15)}),
                    mesh
                )
            );
            autoPtr<fbm::bodyShape> circ(shape(roundDict("circle", 0.1), mesh));
            checkRandom("ellipse-ellipse", e1(), e2(), cd, true, 300, C, rng);
            checkRandom("rectangle-triangle", sq(), tri(), cd, true, 300, C, rng);
            checkRandom("ellipse-rectangle", e1(), sq(), cd, true, 300, C, rng);
            checkRandom("circle-ellipse", circ(), e2(), cd, true, 300, C, rng);
        }

        // ---- Head-on collision of two turned ellipses ----
        headOn
        (
            "head-on ellipses", ellipseDict(0.1, 0.05),
            rotation(vector(0, 0, 1), 0.4), rotation(vector(0, 0, 1), -1.1),
            mesh
        );

        // ---- Drops onto the bottom wall ----
        dropOnWall
        (
            "rectangle on the wall",
            polygonDict
            ({
                vector2D(-0.1, -0.04), vector2D(0.1, -0.04),
                vector2D(0.1, 0.04), vector2D(-0.1, 0.04)
            }),
            0.5, 0.04, true, mesh
        );
        dropOnWall("ellipse on the wall", ellipseDict(0.1, 0.05), 0.5, 0.05, false, mesh);

        // ---- A pile of 40 ellipses and rectangles ----
        pile(mesh, rng);
    }
    else
    {
        // ---- Support functions ----
        const vector e(0.2, 0.15, 0.1);
        autoPtr<fbm::bodyShape> E(shape(ellipsoidDict(e), mesh));
        {
            scalar err = 0;
            for (label k = 0; k < 100; ++k)
            {
                const tensor Q(randomRotation(rng, false));
                vector n(rng.sample01<vector>() - 0.5*vector::one);
                n /= mag(n);
                const tensor A
                (
                    Q & tensor(sqr(e.x()), 0, 0, 0, sqr(e.y()), 0, 0, 0, sqr(e.z()))
                  & Q.T()
                );
                err = max(err, mag((n & E->support(Q, n)) - Foam::sqrt(n & (A & n))));
                E->setOrientation(Q);
                err = max(err, mag(E->signedDistance(E->support(Q, n))));
            }
            E->setOrientation(tensor::I);
            fbmTest::check("ellipsoid: support = sqrt(n.A n), on the surface", err, 0, 1e-15);

            // A cube of side s from OBJ turned by Q: its support along n
            // is s/2 sum_k |n.Q e_k|
            const scalar s = 0.2;
            writeCube(runTime.globalPath()/runTime.constant()/"triSurface"/"cube.obj");
            dictionary d;
            d.add("type", "triSurface");
            d.add("file", fileName("cube.obj"));
            d.add("scale", s);
            autoPtr<fbm::bodyShape> cube(shape(d, mesh));
            err = 0;
            for (label k = 0; k < 100; ++k)
            {
                const tensor Q(randomRotation(rng, false));
                vector n(rng.sample01<vector>() - 0.5*vector::one);
                n /= mag(n);
                scalar h = 0;
                for (direction c = 0; c < 3; ++c)
                {
                    h += 0.5*s*mag(n & (Q & vector(c == 0, c == 1, c == 2)));
                }
                err = max(err, mag((n & cube->support(Q, n)) - h));
            }
            fbmTest::check("triSurface cube: support s/2 sum |n.Q e_k|", err, 0, 1e-15);
        }

        // ---- Aligned ellipsoids by hand ----
        {
            const vector e2(0.1, 0.08, 0.05);
            autoPtr<fbm::bodyShape> B(shape(ellipsoidDict(e2), mesh));
            const scalar delta = 1e-10*(e.x() + e2.x());
            const tensor I(tensor::I);
            for (const scalar d : {0.35, 0.3})
            {
                const fbm::convexDistance::result r
                (
                    cd.distance(E(), I, C, B(), I, C + vector(d, 0, 0))
                );
                const word n("ellipsoids on x, d = " + std::to_string(d));
                fbmTest::check(n + ": gap d - a1 - a2", r.gap, d - e.x() - e2.x(), delta);
                fbmTest::check(n + ": normal", r.normal, vector(1, 0, 0), 1e-4);
            }
            for (const scalar d : {0.16, 0.145, 0.14})
            {
                const fbm::convexDistance::result r
                (
                    cd.distance(E(), I, C, B(), I, C + vector(0, 0, d))
                );
                const word n("ellipsoids on z, d = " + std::to_string(d));
                // Overlapping: the tolerance of the 3D EPA
                fbmTest::check
                (
                    n + ": gap d - c1 - c2", r.gap, d - e.z() - e2.z(),
                    r.overlap ? 1e-8*(e.x() + e2.x()) : delta
                );
                const scalar tolG =
                    r.overlap ? 1e-8*(e.x() + e2.x()) : delta;
                fbmTest::check
                (
                    n + ": normal", r.normal, vector(0, 0, 1),
                    10*Foam::sqrt(tolG/e2.x())
                );
                fbmTest::check(n + ": overlap flag", scalar(r.overlap), scalar(d < e.z() + e2.z()), 0);
            }
        }

        // ---- Random pairs against the reference ----
        {
            autoPtr<fbm::bodyShape> E2(shape(ellipsoidDict(vector(0.12, 0.05, 0.03)), mesh));
            autoPtr<fbm::bodyShape> S(shape(roundDict("sphere", 0.1), mesh));
            checkRandom("ellipsoid-ellipsoid", E(), E2(), cd, false, 60, C, rng);
            checkRandom("sphere-ellipsoid", S(), E2(), cd, false, 40, C, rng);
        }

        // ---- Head-on collision of two turned ellipsoids ----
        headOn
        (
            "head-on ellipsoids", ellipsoidDict(vector(0.1, 0.06, 0.04)),
            rotation(vector(0, 0, 1), 0.4),
            rotation(vector(1, 1, 0)/Foam::sqrt(2.0), -1.1),
            mesh
        );
        dropOnWall("ellipsoid on the wall", ellipsoidDict(vector(0.1, 0.06, 0.04)), 0.5, 0.04, false, mesh);

        // A box 0.3 x 0.2 x 0.1 from OBJ (triSurface) on the wall: never
        // through it, no energy gained. Not at rest after 5 s: without
        // fluid or friction it keeps wobbling on its face (kinetic energy
        // 1.5 % of the drop energy at the end; the face touches at its
        // middle, where the normal damping hardly sees a rocking)
        writeCube
        (
            runTime.globalPath()/runTime.constant()/"triSurface"/"box.obj",
            vector(0.3, 0.2, 0.1)
        );
        dictionary boxDict;
        boxDict.add("type", "triSurface");
        boxDict.add("file", fileName("box.obj"));
        dropOnWall("triSurface box on the wall", boxDict, 0.5, 0.05, false, mesh);
    }

    return fbmTest::result();
}


// ************************************************************************* //
