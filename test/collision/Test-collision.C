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
    Test-collision

Description
    The contact model (paper Eq. 9-10, fbm::contactModels::singhRepulsion), the walls,
    the grid search and the sub-cycled body update, on a mesh with one
    planar wall patch per side (test/cases/box2D):
    - each branch of the pair law against the hand formula, both overlap
      forms, at and between the branch limits; F_ij = -F_ji exactly;
    - coefficients in units of h;
    - the reported stiffness bounds |dF/dD| sampled by finite differences;
    - walls: the planar walls found (empty patches are not walls), the
      image point, the wall force of each branch through
      particleCollisions (times the mesh depth in 2D);
    - grid search against all pairs: 500 random particles in 3D, in a
      plane, and a sparse set; polydisperse sets with large particles; a
      large particle beside centres that spread by round-off in one
      direction; one particle: no pairs;
    - a sub-cycled head-on collision of two disks without fluid:
      momentum conserved, the largest overlap below 5 % of R1 + R2
      (energy estimate 2.5 %), rebound speed within 1 % of the impact
      speed (an elastic law).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "contactModel.H"
#include "singhRepulsion.H"
#include "contactSearch.H"
#include "wallPlanes.H"
#include "particleCollisions.H"
#include "bodyInput.H"
#include "rigidBodyMotion.H"
#include "Random.H"
#include "fbmTest.H"

using namespace Foam;

// Collisions dictionary with the given law coefficients
dictionary collisionsDict
(
    const word& overlap,
    const scalar range,
    const scalar epsP,
    const scalar epsPO,
    const scalar epsW,
    const scalar epsWO
)
{
    dictionary coeffs;
    coeffs.add("overlapForce", overlap);
    coeffs.add("range", range);
    coeffs.add("epsP", epsP);
    coeffs.add("epsPOverlap", epsPO);
    coeffs.add("epsW", epsW);
    coeffs.add("epsWOverlap", epsWO);

    dictionary dict;
    dict.add("model", "singhRepulsion");
    dict.add("singhRepulsionCoeffs", coeffs);
    return dict;
}


// A round body, built without a dictionary
Foam::autoPtr<fbm::body> newBody
(
    const word& name,
    const scalar R,
    const point& X,
    const vector& U,
    const fvMesh& mesh
)
{
    return fbm::bodyInput::newRoundBody
    (
        name, R, 1.0, fbm::bodyState(X, U, Zero), true, false, mesh
    );
}


// Sorted copy of a pair list
List<labelPair> sorted(const UList<labelPair>& pairs)
{
    List<labelPair> s(pairs);
    Foam::sort
    (
        s,
        [](const labelPair& a, const labelPair& b)
        {
            return a.first() < b.first()
                || (a.first() == b.first() && a.second() < b.second());
        }
    );
    return s;
}


// Grid search against all pairs
void checkSearch(const word& what, const pointField& X, const scalarField& R,
    const scalar range)
{
    fbm::contactSearch search;
    search.search(X, R, range);
    const List<labelPair> grid(sorted(search.pairs()));
    const List<labelPair> all(sorted(fbm::contactSearch::allPairs(X, R, range)));
    bool same = (grid.size() == all.size());
    for (label i = 0; same && i < grid.size(); ++i)
    {
        same = (grid[i] == all[i]);
    }
    Info<< "    " << what << ": grid " << search.nCells() << ", "
        << grid.size() << " pairs, all-pairs " << all.size() << nl;
    fbmTest::check(what + ": grid pairs = all pairs", scalar(same), 1, 0);
    fbmTest::check(what + ": some pairs found", scalar(all.size() > 10), 1, 0);
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar rho = 0.1;     // range
    const scalar epsP = 1e-3, epsPO = 1e-2, epsW = 5e-4, epsWO = 5e-3;

    // -- Pair law, each branch, both overlap forms -------------------------
    for (const word overlap : {"linear", "rangePlusLinear"})
    {
        const dictionary dict
        (
            collisionsDict(overlap, rho, epsP, epsPO, epsW, epsWO)
        );
        autoPtr<fbm::contactModel> law(fbm::contactModel::New(dict, 0.05));
        const bool additive = (overlap == "rangePlusLinear");

        const scalar Ri = 0.2, Rj = 0.3, s = Ri + Rj;
        const point Xi(0.1, -0.2, 0.3);
        const vector e(vector(1, 2, -2)/3);

        const scalar Ds[] = {0.75, s + rho, 0.55, s, 0.45, 0.2};
        for (const scalar D : Ds)
        {
            const point Xj(Xi - D*e);   // Xi - Xj = D e
            scalar f = 0;
            if (D <= s + rho && D >= s)
            {
                f = sqr(s + rho - D)/epsP;
            }
            else if (D < s)
            {
                f = (s - D)/epsPO + (additive ? sqr(s + rho - D)/epsP : 0);
            }
            const vector Fij(law->pairForce(Xi, Ri, Xj, Rj));
            const vector Fji(law->pairForce(Xj, Rj, Xi, Ri));
            fbmTest::check
            (
                overlap + ": F_ij at D = " + std::to_string(D),
                Fij, f*(Xi - Xj), 1e-12*(1 + mag(f*D))
            );
            fbmTest::check
            (
                overlap + ": F_ij + F_ji = 0 (exact) at D = "
              + std::to_string(D),
                Fij + Fji, vector::zero, 0
            );
        }

        // Stiffness bound against finite differences of |F|(D) and the
        // transverse stiffness |F|/D, D in [s/2, s + rho]
        const scalar k = law->pairStiffness(Ri, Rj);
        scalar kFD = 0;
        const label nD = 2000;
        for (label i = 1; i < nD; ++i)
        {
            const scalar D = 0.5*s + (s + rho + 0.01 - 0.5*s)*i/nD;
            const scalar dD = 1e-7;
            const scalar F1 = mag(law->pairForce(Xi, Ri, Xi - (D - dD)*e, Rj));
            const scalar F2 = mag(law->pairForce(Xi, Ri, Xi - (D + dD)*e, Rj));
            // skip the jump of the linear form at contact
            if ((D - dD < s) != (D + dD < s)) continue;
            kFD = max(kFD, mag(F2 - F1)/(2*dD));
            kFD = max(kFD, mag(law->pairForce(Xi, Ri, Xi - D*e, Rj))/D);
        }
        Info<< "    " << overlap << ": stiffness bound " << k
            << ", sampled largest " << kFD << nl;
        fbmTest::check
        (
            overlap + ": pair stiffness bound >= sampled, and within 2x",
            scalar(k >= kFD*(1 - 1e-6) && k <= 2*kFD), 1, 0
        );
    }

    // -- Coefficients in units of h ----------------------------------------
    {
        dictionary dict(collisionsDict("linear", 1.5, 2, 3, 1, 1.5));
        dict.subDict("singhRepulsionCoeffs").add
        (
            "unitsOfH", wordList({"range", "epsP", "epsPOverlap", "epsW"})
        );
        const scalar h = 0.02;
        autoPtr<fbm::contactModel> law(fbm::contactModel::New(dict, h));
        const fbm::contactModels::singhRepulsion& sr =
            refCast<const fbm::contactModels::singhRepulsion>(law());
        fbmTest::check("unitsOfH: range = 1.5 h", sr.range(), 1.5*h, 1e-15);
        fbmTest::check("unitsOfH: epsP = 2 h^2", sr.epsP(), 2*h*h, 1e-15);
        fbmTest::check("unitsOfH: epsPOverlap = 3 h", sr.epsPOverlap(), 3*h, 1e-15);
        fbmTest::check("unitsOfH: epsW = 1 h^2", sr.epsW(), h*h, 1e-15);
        fbmTest::check("unitsOfH: epsWOverlap absolute", sr.epsWOverlap(), 1.5, 0);
    }

    // -- Walls ---------------------------------------------------------------
    const scalar depth = mesh.bounds().span().z();
    {
        const fbm::wallPlanes walls(mesh);
        fbmTest::check("walls: 4 planar walls (empty skipped)",
            walls.size(), 4, 0);
        const label bottom = walls.names().find("bottom");
        const label left = walls.names().find("left");
        const point X(0.3, 0.2, 0.05);
        fbmTest::check("walls: image across bottom", walls.image(bottom, X),
            point(0.3, -0.2, 0.05), 1e-14);
        fbmTest::check("walls: image across left", walls.image(left, X),
            point(-0.3, 0.2, 0.05), 1e-14);
        fbmTest::check("walls: distance to bottom", walls.distance(bottom, X),
            0.2, 1e-14);
    }

    // Wall force of each branch through particleCollisions (one body, so
    // no pair search), both overlap forms
    for (const word overlap : {"linear", "rangePlusLinear"})
    {
        const bool additive = (overlap == "rangePlusLinear");
        const scalar R = 0.1, range = 0.05;
        const dictionary dict
        (
            collisionsDict(overlap, range, epsP, epsPO, epsW, epsWO)
        );
        for (const scalar d : {0.2, 0.125, 0.11, 0.1, 0.09})
        {
            PtrList<fbm::body> bodies(1);
            bodies.set(0, newBody("b", R, point(0.5, d, 0.05), Zero, mesh));
            fbm::particleCollisions coll(dict, mesh, bodies);
            List<vector> F;
            coll.contactForces(bodies, F);

            const scalar D = 2*d, s = 2*R;
            scalar f = 0;
            if (D <= s + range && D >= s)
            {
                f = sqr(s + range - D)/epsW;
            }
            else if (D < s)
            {
                f = (s - D)/epsWO + (additive ? sqr(s + range - D)/epsW : 0);
            }
            fbmTest::check
            (
                overlap + ": wall force at distance " + std::to_string(d),
                F[0], depth*f*vector(0, D, 0), 1e-12*(1 + depth*f*D)
            );
        }
    }

    // -- Grid search against all pairs --------------------------------------
    {
        Random rnd(1234);
        const label n = 500;
        pointField X(n);
        scalarField R(n);
        forAll(X, i)
        {
            X[i] = point(rnd.sample01<scalar>(), rnd.sample01<scalar>(),
                rnd.sample01<scalar>());
            R[i] = 0.01 + 0.03*rnd.sample01<scalar>();
        }
        checkSearch("search 3D, 500", X, R, 0.01);

        forAll(X, i)
        {
            X[i].z() = 0.05;
        }
        checkSearch("search 2D, 500", X, R, 0.005);

        // Sparse: two clusters far apart (the grid width grows)
        forAll(X, i)
        {
            if (i % 2) X[i] += vector(1e4, -3e3, 0);
        }
        checkSearch("search sparse, 500", X, R, 0.005);

        // Polydisperse: 500 small and 6 large (> 4 Rmin: box queries),
        // two of them overlapping each other, in 3D and in a plane
        pointField Xp(n + 6);
        scalarField Rp(n + 6);
        forAll(Xp, i)
        {
            Xp[i] = point(rnd.sample01<scalar>(), rnd.sample01<scalar>(),
                rnd.sample01<scalar>());
            Rp[i] = 0.01 + 0.01*rnd.sample01<scalar>();
        }
        for (label i = n; i < n + 6; ++i)
        {
            Rp[i] = 0.1 + 0.1*rnd.sample01<scalar>();
        }
        Xp[n + 1] = Xp[n] + vector(0.15, 0, 0);
        checkSearch("search polydisperse 3D, 506", Xp, Rp, 0.01);
        forAll(Xp, i)
        {
            Xp[i].z() = 0.05;
        }
        checkSearch("search polydisperse 2D, 506", Xp, Rp, 0.01);

        // A large particle beside a small one whose centres differ by
        // round-off in one direction (a cell width of 1e-11 there): the
        // large one's reach of many cell widths (before 2026-12-05 it
        // overflowed a label: a floating-point exception, or the pair
        // missed where exceptions are off)
        {
            fbm::contactSearch search;
            const pointField Xl
            ({
                point(0.3, 0.17, 0.5 + 1e-11), point(0.5, 0.05, 0.5),
                point(0.9, 0.5, 0.5)
            });
            const scalarField Rl({0.15, 0.68, 0.1});
            search.search(Xl, Rl, 0.02);
            const List<labelPair> all
            (
                sorted(fbm::contactSearch::allPairs(Xl, Rl, 0.02))
            );
            const List<labelPair> grid(sorted(search.pairs()));
            fbmTest::check
            (
                "search: large particle, centres spread by 1e-11 in z:"
                " grid pairs = all pairs",
                scalar(grid == all && all.size() == 2), 1, 0
            );
        }

        fbm::contactSearch search;
        search.search(pointField(1, Zero), scalarField(1, 1.0), 1.0);
        fbmTest::check("search: one particle, no pairs",
            search.pairs().size(), 0, 0);
    }

    // -- Sub-cycled head-on collision without fluid -------------------------
    {
        const scalar R = 0.1, u = 1;
        const dictionary dict
        (
            collisionsDict("rangePlusLinear", 0.02, 1e-4, 1e-4, 5e-5, 5e-5)
        );
        const point X0(0.35, 0.5, 0.05), X1(0.65, 0.5, 0.05);
        PtrList<fbm::body> bodies(2);
        bodies.set(0, newBody("b0", R, X0, vector(u, 0, 0), mesh));
        bodies.set(1, newBody("b1", R, X1, vector(-u, 0, 0), mesh));
        const fbm::rigidBodyMotion motion(Zero, 1e-12, 0, mesh);
        fbm::particleCollisions coll(dict, mesh, bodies);

        const scalar dt = 0.01;
        const label n = coll.nSubCycles(dt);
        Info<< "    head-on: " << n << " sub-steps per step of " << dt << nl;
        fbmTest::check("head-on: sub-cycled (n > 1)", scalar(n > 1), 1, 0);

        const vector P0(bodies[0].mass()*bodies[0].U()
            + bodies[1].mass()*bodies[1].U());
        const scalar m = bodies[0].mass();
        scalar minD = GREAT;
        vector maxDP(Zero);
        for (label step = 0; step < 10; ++step)
        {
            // minimum distance sampled at every sub-step: one sub-step at a
            // time with the driver's n (same as move())
            coll.move(bodies, motion, dt);
            minD = min(minD, mag(bodies[0].centre() - bodies[1].centre()));
            const vector P(bodies[0].mass()*bodies[0].U()
                + bodies[1].mass()*bodies[1].U());
            if (mag(P - P0) > mag(maxDP)) maxDP = P - P0;
        }
        // finer sampling of the overlap: repeat with one sub-step per call
        {
            PtrList<fbm::body> b2(2);
            b2.set(0, newBody("b0", R, X0, vector(u, 0, 0), mesh));
            b2.set(1, newBody("b1", R, X1, vector(-u, 0, 0), mesh));
            const scalar dts = dt/n;
            for (label k = 0; k < 10*n; ++k)
            {
                coll.move(b2, motion, dts);
                minD = min(minD, mag(b2[0].centre() - b2[1].centre()));
            }
        }
        const scalar overlap = max(0, 2*R - minD)/(2*R);
        Info<< "    head-on: smallest distance " << minD
            << ", overlap " << 100*overlap << " % of R1 + R2" << nl;
        fbmTest::check("head-on: momentum conserved", maxDP, vector::zero,
            1e-12*m*u);
        fbmTest::check("head-on: overlap < 5 % of R1 + R2", scalar(overlap < 0.05), 1, 0);
        fbmTest::check("head-on: overlap reached (> 0.5 %)", scalar(overlap > 0.005), 1, 0);
        fbmTest::check("head-on: body 0 rebounds at -u (1 %)",
            bodies[0].U().x(), -u, 0.01*u);
        fbmTest::check("head-on: body 1 rebounds at +u (1 %)",
            bodies[1].U().x(), u, 0.01*u);
        fbmTest::check("head-on: no transverse motion",
            mag(bodies[0].U().y()) + mag(bodies[1].U().y()), 0, 1e-14);
    }

    return fbmTest::result();
}


// ************************************************************************* //
