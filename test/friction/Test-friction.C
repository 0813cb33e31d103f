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
    Test-friction

Description
    The Coulomb friction of fbm::particleCollisions (frictionCoeff) without
    fluid, on a 2D mesh with walls (the floor y = ymin), against exact
    solutions of rigid-body mechanics on an incline (gravity g = 10 turned
    by theta = 20 degrees; tan(theta) = 0.364):
    - a block (polygon 0.2 x 0.1) resting on the floor: with mu = 0.5 it
      holds (it creeps: the friction has no tangential spring; its path
      against the frictionless one, and without turning its creep speed
      against g sin(theta) 2 dt_s); with mu = 0.2 it slides with a = g
      (sin(theta) - mu cos(theta)), without friction with a = g
      sin(theta), and it does not tip over;
    - a disk (circle R 0.1, rotating) on the floor: with mu = 0.5 (above
      tan(theta)/3) it rolls without slipping, a = 2/3 g sin(theta),
      omega = -U/R; with mu = 0.05 (below) it slips, a = g (sin(theta) -
      mu cos(theta)), d(omega)/dt = -2 mu g cos(theta)/R;
    - two spinning disks and two turned rectangles colliding obliquely
      without gravity, mu = 0.3: linear and angular momentum (about the
      origin, with the spins) kept to round-off, kinetic energy not above
      the start, the spins changed by the friction (they are not without
      it);
    - frictionCoeff 0 leaves a round pair's motion as it was (no torque,
      no spin change);
    - on a 3D mesh instead: a sphere rolling (a = 5/7 g sin(theta)) and
      slipping (d(omega)/dt = -5/2 mu g cos(theta)/R), an ellipsoid lying
      on the incline (rotation off) sliding and held, two spinning spheres
      colliding obliquely.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bodyShape.H"
#include "body.H"
#include "particleCollisions.H"
#include "rigidBodyMotion.H"
#include "fbmTest.H"
#include "OFstream.H"
#include "Tuple2.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

const scalar gMag = 10;
const scalar theta = 20*constant::mathematical::pi/180;


// The friction model (frictionModel) of every run of this test: the
// default (velocityRegularised) or that of -model
word frictionModelType;


dictionary collisionsDict
(
    const scalar mu,
    const scalar damping,
    const scalar muStatic = 0
)
{
    dictionary coeffs;
    coeffs.add("overlapForce", "rangePlusLinear");
    coeffs.add("range", 0.02);
    coeffs.add("epsP", 1e-4);
    coeffs.add("epsPOverlap", 1e-4);
    coeffs.add("epsW", 5e-5);
    coeffs.add("epsWOverlap", 5e-5);

    dictionary dict;
    dict.add("model", "singhRepulsion");
    dict.add("singhRepulsionCoeffs", coeffs);
    dict.add("dampingRatio", damping);
    dict.add("frictionCoeff", mu);
    if (mu > 0 && !frictionModelType.empty())
    {
        dict.add("frictionModel", frictionModelType);
        dictionary spring;
        spring.add("stiffnessRatio", 2.0/7);
        spring.add("dampingRatio", 0.5);
        if (muStatic > 0)
        {
            spring.add("staticFrictionCoeff", muStatic);
        }
        dict.add("tangentialSpringCoeffs", spring);
    }
    return dict;
}


dictionary boxDict(const scalar a, const scalar b)
{
    dictionary d;
    d.add("type", "polygon");
    d.add
    (
        "vertices",
        List<vector2D>
        ({
            vector2D(-a/2, -b/2), vector2D(a/2, -b/2),
            vector2D(a/2, b/2), vector2D(-a/2, b/2)
        })
    );
    return d;
}


dictionary circleDict(const scalar R)
{
    dictionary d;
    d.add("type", "circle");
    d.add("radius", R);
    return d;
}


dictionary sphereDict(const scalar R)
{
    dictionary d;
    d.add("type", "sphere");
    d.add("radius", R);
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


// A box of edges L as a triSurface body: its OBJ file written to
// constant/triSurface/<name>.obj
dictionary boxSurfaceDict
(
    const Time& runTime,
    const word& name,
    const vector& L
)
{
    const fileName dir(runTime.path()/runTime.constant()/"triSurface");
    mkDir(dir);
    OFstream os(dir/(name + ".obj"));
    for (label k = 0; k < 8; ++k)
    {
        os  << "v " << ((k & 1) ? L.x() : 0) << ' '
            << ((k & 2) ? L.y() : 0) << ' ' << ((k & 4) ? L.z() : 0) << nl;
    }
    // Outward normals: vertex k = x bit 1, y bit 2, z bit 4 (1-based)
    os  << "f 1 3 4\nf 1 4 2\n"      // z = 0
        << "f 5 6 8\nf 5 8 7\n"      // z = L
        << "f 1 2 6\nf 1 6 5\n"      // y = 0
        << "f 3 7 8\nf 3 8 4\n"      // y = L
        << "f 1 5 7\nf 1 7 3\n"      // x = 0
        << "f 2 4 8\nf 2 8 6\n";     // x = L
    dictionary d;
    d.add("type", "triSurface");
    d.add("file", fileName(name + ".obj"));
    return d;
}


autoPtr<fbm::body> newBody
(
    const word& name,
    const dictionary& shapeDict,
    const point& X,
    const vector& U,
    const vector& omega,
    const scalar angle,
    const fvMesh& mesh,
    const bool rotates = true,
    const bool translates = true
)
{
    fbm::bodyState s(X, U, omega);
    const scalar c = Foam::cos(angle), sn = Foam::sin(angle);
    s.setOrientation(tensor(c, -sn, 0, sn, c, 0, 0, 0, 1), Zero);
    return autoPtr<fbm::body>
    (
        new fbm::body
        (
            name, fbm::bodyShape::New(shapeDict, mesh), 1.0, s, translates,
            rotates
        )
    );
}


// A body settled on the floor with vertical gravity, then on the incline
// (gravity turned by theta) for 0.5 s: the velocity along the incline and
// the angular velocity at t = 0.1 and 0.5 after the turn, the distance
// travelled. With slabDict it rests instead on a fixed body of that shape,
// a slab 0.1 thick lying on the floor: the same incline through a pair
// contact
struct inclineResult
{
    scalar a;
    scalar alpha;
    scalar distance;
    scalar Uend;
    scalar omegaEnd;
    scalar omegaMagEnd;
    scalar R;
    scalar maxTilt;
    scalar dtSub;
    scalar slip;
};


inclineResult incline
(
    const dictionary& shapeDict,
    const scalar halfHeight,
    const scalar mu,
    const fvMesh& mesh,
    const bool rotates = true,
    const label nSteps = 250,
    const scalar muStatic = 0,
    const scalar U0 = 0,
    const dictionary* slabDict = nullptr
)
{
    const bool onSlab = slabDict;
    const boundBox& bb = mesh.bounds();
    const scalar base = onSlab ? 0.1 : 0;
    const point X0
    (
        0.3, bb.min().y() + base + halfHeight + 0.012, bb.centre().z()
    );
    PtrList<fbm::body> bodies(onSlab ? 2 : 1);
    bodies.set(0, newBody("b0", shapeDict, X0, Zero, Zero, 0, mesh, rotates));
    if (onSlab)
    {
        const point Xs(0.5, bb.min().y() + 0.05, bb.centre().z());
        bodies.set
        (
            1,
            newBody
            (
                "slab", *slabDict, Xs, Zero, Zero, 0, mesh, false, false
            )
        );
    }
    fbm::particleCollisions coll
    (
        collisionsDict(mu, 0.5, muStatic), mesh, bodies
    );
    const fbm::rigidBodyMotion settle(vector(0, -gMag, 0), 1e-12, 0, mesh);
    const fbm::rigidBodyMotion slope
    (
        gMag*vector(Foam::sin(theta), -Foam::cos(theta), 0), 1e-12, 0, mesh
    );
    const scalar dt = 0.002;
    for (label step = 0; step < 500; ++step)
    {
        coll.move(bodies, settle, dt);
    }
    const fbm::body& b = bodies[0];
    const scalar x0 = b.centre().x();
    // The body's front lower point (of a box: its front lower corner while
    // it tilts by less than atan(0.2)), whose motion along the incline is
    // the sliding at the contact, its pitching taken out
    const vector front(0.2, -1, 0);
    auto frontX = [&]()
    {
        return b.centre().x() + b.shape().support(b.state().Q(), front).x();
    };
    const scalar f0 = frontX();
    // Set sliding down the incline at the turn (U0 > 0)
    bodies[0].state().U() = vector(U0, 0, 0);
    scalar U1 = 0, w1 = 0, maxTilt = 0;
    for (label step = 1; step <= nSteps; ++step)
    {
        coll.move(bodies, slope, dt);
        maxTilt = max(maxTilt, mag(b.state().Q().yx()));
        if (step == 50)
        {
            U1 = b.U().x();
            w1 = b.omega().z();
        }
    }
    inclineResult r;
    r.a = (b.U().x() - U1)/(dt*(nSteps - 50));
    r.alpha = (b.omega().z() - w1)/(dt*(nSteps - 50));
    r.slip = frontX() - f0;
    r.distance = b.centre().x() - x0;
    r.Uend = b.U().x();
    r.omegaEnd = b.omega().z();
    r.omegaMagEnd = mag(b.omega());
    r.R = b.shape().radius();
    r.maxTilt = maxTilt;
    r.dtSub = dt/coll.nSubCycles(dt);
    Info<< "    mu " << mu << ": a " << r.a << ", d(omega)/dt " << r.alpha
        << ", distance in 0.5 s " << r.distance << ", U " << r.Uend
        << ", omega " << r.omegaEnd << ", largest tilt " << maxTilt
        << ", " << (onSlab ? "pair gap " : "wall gap ")
        << (onSlab ? coll.minPairGap() : coll.minWallGap())
        << ", slip " << r.slip
        << nl;
    return r;
}


// A body the friction holds on the incline: at rest (|U| below 1e-6 of
// g sin(theta) 1 s), its contact point slid by the spring's stretch only
// (below 1e-4)
void checkHeld(const string& what, const inclineResult& r)
{
    fbmTest::check
    (
        what + ": at rest (|U| / g sin(theta) 1 s)",
        mag(r.Uend)/(gMag*Foam::sin(theta)), 0, 1e-6
    );
    fbmTest::check(what + ": slid below 1e-4", mag(r.slip), 0, 1e-4);
}


// Two bodies colliding obliquely without gravity: momentum, angular
// momentum, energy, and the change of the spins
void oblique
(
    const word& name,
    const dictionary& shapeDict,
    const scalar mu,
    const bool expectSpinChange,
    const fvMesh& mesh
)
{
    const point C(mesh.bounds().centre());
    PtrList<fbm::body> bodies(2);
    bodies.set
    (
        0,
        newBody("b0", shapeDict, C + vector(-0.2, 0.03, 0), vector(1, 0, 0), vector(0, 0, 5), 0.3, mesh)
    );
    bodies.set
    (
        1,
        newBody("b1", shapeDict, C + vector(0.2, -0.03, 0), vector(-1, 0, 0), vector(0, 0, -2), -0.2, mesh)
    );
    fbm::particleCollisions coll(collisionsDict(mu, 0), mesh, bodies);
    const fbm::rigidBodyMotion motion(Zero, 1e-12, 0, mesh);

    auto momentum = [&]()
    {
        vector P(Zero);
        for (const fbm::body& b : bodies) P += b.mass()*b.U();
        return P;
    };
    auto angularMomentum = [&]()
    {
        vector L(Zero);
        for (const fbm::body& b : bodies)
        {
            L += b.mass()*(b.centre() ^ b.U()) + (b.inertia() & b.omega());
        }
        return L;
    };
    auto energy = [&]()
    {
        scalar E = 0;
        for (const fbm::body& b : bodies)
        {
            E += 0.5*b.mass()*magSqr(b.U())
               + 0.5*(b.omega() & (b.inertia() & b.omega()));
        }
        return E;
    };
    const vector P0(momentum()), L0(angularMomentum());
    const scalar E0 = energy();
    const scalar w00 = bodies[0].omega().z(), w10 = bodies[1].omega().z();
    scalar minGap = GREAT;
    for (label step = 0; step < 80; ++step)
    {
        coll.move(bodies, motion, 0.005);
        minGap = min(minGap, coll.minPairGap());
    }
    const scalar Pscale = bodies[0].mass()*1.0;
    // Round-off of some thousand sub-steps on L ~ m u |X| about the origin
    const scalar Lscale =
        Pscale*(mag(bodies[0].centre()) + bodies[0].shape().radius());
    const scalar dw =
        mag(bodies[0].omega().z() - w00) + mag(bodies[1].omega().z() - w10);
    Info<< "    " << name << ", mu " << mu << ": smallest gap " << minGap
        << ", spins " << w00 << " " << w10 << " -> "
        << bodies[0].omega().z() << " " << bodies[1].omega().z()
        << ", energy / start " << energy()/E0 << nl;
    fbmTest::check(name + ": they met (smallest gap < 0.02)", scalar(minGap < 0.02), 1, 0);
    fbmTest::check(name + ": momentum kept", mag(momentum() - P0)/Pscale, 0, 1e-12);
    fbmTest::check
    (
        name + ": angular momentum kept",
        mag(angularMomentum() - L0)/Lscale, 0, 1e-12
    );
    fbmTest::check(name + ": energy not above the start", scalar(energy() <= E0*(1 + 1e-3)), 1, 0);
    fbmTest::check
    (
        name + (expectSpinChange ? ": spins changed" : ": spins unchanged"),
        scalar(dw > 1e-3), expectSpinChange ? 1 : 0, 0
    );
}


// A round body (I = k m R^2) of radius 0.1 on the incline: with mu 0.5 it
// rolls without slipping, a = g sin(theta)/(1 + k); with mu 0.05 it slips,
// a = g (sin - mu cos) and d(omega)/dt = -mu g cos(theta)/(k R)
void rollAndSlip
(
    const dictionary& shapeDict,
    const scalar k,
    const fvMesh& mesh
)
{
    const scalar s = Foam::sin(theta), c = Foam::cos(theta);
    const inclineResult roll(incline(shapeDict, 0.1, 0.5, mesh));
    const inclineResult slip(incline(shapeDict, 0.1, 0.05, mesh));
    const word kName(Foam::name(k));
    fbmTest::check
    (
        "mu 0.5: rolls, a = g sin(theta)/(1 + k), k " + kName,
        roll.a/(gMag*s/(1 + k)), 1, 1e-2
    );
    fbmTest::check
    (
        "mu 0.5: without slipping, |U + omega R| / U",
        mag(roll.Uend + roll.omegaEnd*roll.R)/roll.Uend, 0, 1e-2
    );
    fbmTest::check
    (
        "mu 0.05: slips, a = g (sin - mu cos)",
        slip.a/(gMag*(s - 0.05*c)), 1, 1e-3
    );
    fbmTest::check
    (
        "mu 0.05: d(omega)/dt = -mu g cos/(k R), k " + kName,
        slip.alpha/(-0.05*gMag*c/(k*0.1)), 1, 1e-3
    );
}


int main(int argc, char *argv[])
{
    argList::addOption
    (
        "csv", "file",
        "instead of the checks, the incline for a range of mu (block, block"
        " not turning, disk, block on a fixed slab) into a CSV file"
        " (validation/friction; with -model, that model's)"
    );
    argList::addOption
    (
        "model", "name",
        "the friction model (frictionModel; default velocityRegularised):"
        " tangentialSpring checks that a held body holds"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar s = Foam::sin(theta), c = Foam::cos(theta);
    frictionModelType = args.getOrDefault<word>("model", word::null);
    const bool spring = (frictionModelType == "tangentialSpring");
    if (!frictionModelType.empty() && !spring)
    {
        FatalErrorInFunction
            << "-model " << frictionModelType << ": this test knows"
            << " tangentialSpring (and the default without -model)"
            << exit(FatalError);
    }

    // The fixed slab of the pair-contact incline: a rectangle 0.96 x 0.1
    // in 2D, a triSurface box 0.96 x 0.1 x 0.96 in 3D
    const dictionary slabDict
    (
        mesh.nSolutionD() == 3
      ? boxSurfaceDict(runTime, "slab", vector(0.96, 0.1, 0.96))
      : boxDict(0.96, 0.1)
    );

    fileName csvFile;
    if (args.readIfPresent("csv", csvFile))
    {
        OFstream os(csvFile);
        os.precision(8);
        os  << "body,mu,a,a_exact,distance,U_end,omega_end,slip,"
            << "largest_tilt,dt_sub,corner_slip" << nl;
        const List<scalar> mus
        ({
            0, 0.05, 0.1, 0.1213, 0.15, 0.2, 0.25, 0.3, 0.35, 0.364, 0.4,
            0.5, 0.6
        });
        for (const scalar mu : mus)
        {
            const scalar aSlide = gMag*max(s - mu*c, scalar(0));
            const inclineResult block(incline(boxDict(0.2, 0.1), 0.05, mu, mesh));
            const inclineResult held(incline(boxDict(0.2, 0.1), 0.05, mu, mesh, false));
            const inclineResult disk(incline(circleDict(0.1), 0.1, mu, mesh));
            const inclineResult slab
            (
                incline
                (
                    boxDict(0.2, 0.1), 0.05, mu, mesh, true, 250, 0, 0,
                    &slabDict
                )
            );
            const scalar aDisk =
                (mu >= s/(3*c)) ? 2.0/3*gMag*s : gMag*(s - mu*c);
            for
            (
                const Tuple2<word, const inclineResult*>& r
              : List<Tuple2<word, const inclineResult*>>
                ({
                    {"block", &block}, {"blockNotTurning", &held},
                    {"disk", &disk}, {"blockOnSlab", &slab}
                })
            )
            {
                const inclineResult& q = *r.second();
                const bool isDisk = (r.first() == "disk");
                os  << r.first() << ',' << mu << ',' << q.a << ','
                    << (isDisk ? aDisk : aSlide) << ',' << q.distance << ','
                    << q.Uend << ',' << q.omegaEnd << ','
                    << (isDisk ? (q.Uend + q.omegaEnd*q.R)/q.Uend : 0) << ','
                    << q.maxTilt << ',' << q.dtSub << ',' << q.slip << nl;
            }
        }
        Info<< "Written " << csvFile << nl;
        return 0;
    }

    if (mesh.nSolutionD() == 3)
    {
        // ---- 3D: a sphere and an ellipsoid on the incline ----
        Info<< nl << "Sphere R 0.1 on the incline, theta 20 degrees" << nl;
        rollAndSlip(sphereDict(0.1), 0.4, mesh);

        Info<< nl << "Ellipsoid (0.15 0.06 0.1) lying on the incline" << nl;
        const dictionary ell(ellipsoidDict(vector(0.15, 0.06, 0.1)));
        const inclineResult slide(incline(ell, 0.06, 0.2, mesh, false));
        const inclineResult held(incline(ell, 0.06, 0.5, mesh, false));
        fbmTest::check
        (
            "ellipsoid, mu 0.2: a = g (sin - mu cos)",
            slide.a/(gMag*(s - 0.2*c)), 1, 1e-3
        );
        if (spring)
        {
            // The spring holds it: at rest, displaced by the spring's
            // stretch only (m g sin(theta)/k_t, below 1e-4 here)
            checkHeld("ellipsoid, mu 0.5, spring", held);
        }
        else
        {
            fbmTest::check
            (
                "ellipsoid, mu 0.5: creep speed / (g sin(theta) 2 dt_s)",
                held.Uend/(gMag*s*2*held.dtSub), 1, 0.05
            );
        }

        // A box on a fixed slab, face on face (triSurface boxes): the
        // pair-contact incline of 2D below in 3D, its dashpot shared among
        // the corners of the faces' overlap
        Info<< nl << "Box 0.2 x 0.1 x 0.2 on a fixed slab 0.96 x 0.1 x 0.96"
            << ", theta 20 degrees" << nl;
        const dictionary box3(boxSurfaceDict(runTime, "box", vector(0.2, 0.1, 0.2)));
        const inclineResult boxSlide
        (
            incline(box3, 0.05, 0.2, mesh, true, 250, 0, 0, &slabDict)
        );
        const inclineResult boxHold
        (
            incline(box3, 0.05, 0.5, mesh, true, 250, 0, 0, &slabDict)
        );
        fbmTest::check
        (
            "box on a slab, mu 0.2: a = g (sin - mu cos)",
            boxSlide.a/(gMag*(s - 0.2*c)), 1, 1e-3
        );
        fbmTest::check
        (
            "box on a slab, mu 0.2: no rocking (|omega| R / U at the end)",
            boxSlide.omegaMagEnd*boxSlide.R/boxSlide.Uend, 0, 1e-2
        );
        fbmTest::check
        (
            "box on a slab, mu 0.2: does not tip (largest tilt < 0.05)",
            boxSlide.maxTilt, 0, 0.05
        );
        fbmTest::check
        (
            "box on a slab, mu 0.5: holds (distance / frictionless"
            " 1/2 g sin(theta) (0.5 s)^2)",
            boxHold.distance/(0.5*gMag*s*0.25), 0, 1e-2
        );

        Info<< nl << "Oblique collision, no gravity" << nl;
        oblique("spheres", sphereDict(0.1), 0.3, true, mesh);
        return fbmTest::result();
    }

    // ---- A block on the incline ----
    {
        Info<< nl << "Block 0.2 x 0.1 on the incline, theta 20 degrees" << nl;
        const dictionary box(boxDict(0.2, 0.1));
        const inclineResult free(incline(box, 0.05, 0, mesh));
        const inclineResult slide(incline(box, 0.05, 0.2, mesh));
        const inclineResult hold(incline(box, 0.05, 0.5, mesh));
        fbmTest::check("no friction: a = g sin(theta)", free.a/(gMag*s), 1, 1e-3);
        fbmTest::check
        (
            "mu 0.2: a = g (sin - mu cos)", slide.a/(gMag*(s - 0.2*c)), 1, 1e-3
        );
        // The friction at the face pitches the block forward until the
        // face's contact point (the weighted middle of its vertices near
        // the wall, bodyShape::planeContact) has moved forward enough to
        // balance its torque: it tilts by 0.0049 and does not tip over
        // (the dashpot shared among the face's points damps the rocking;
        // with the dashpot at the middle alone it rocked up to 0.018 and
        // crept 9 times faster when held)
        fbmTest::check("mu 0.2: does not tip (largest tilt < 0.05)", slide.maxTilt, 0, 0.05);
        // Held: the creep speed about g sin(theta) 2 dt_s, far below the
        // frictionless path 1/2 g sin(theta) t^2
        fbmTest::check
        (
            "mu 0.5: holds (path / frictionless path)",
            hold.distance/free.distance, 0, 1e-2
        );
        const inclineResult held(incline(box, 0.05, 0.5, mesh, false));
        if (spring)
        {
            // Static friction (staticFrictionCoeff 0.5, frictionCoeff 0.2,
            // tan(theta) 0.364 between them; not turning): from rest the
            // block holds as with mu 0.5; set sliding at 0.5 m/s it slides
            // on with the kinetic a = g (sin - 0.2 cos); with frictionCoeff
            // 0.4 (above tan(theta)), set sliding at 0.2 m/s, it slows down
            // at g (0.4 cos - sin), stops (after 0.59 s) and holds
            const inclineResult sHeld
            (
                incline(box, 0.05, 0.2, mesh, false, 250, 0.5)
            );
            const inclineResult sSlide
            (
                incline(box, 0.05, 0.2, mesh, false, 250, 0.5, 0.5)
            );
            const inclineResult sStop
            (
                incline(box, 0.05, 0.4, mesh, false, 500, 0.5, 0.2)
            );
            checkHeld("static 0.5, kinetic 0.2, from rest", sHeld);
            fbmTest::check
            (
                "static 0.5, kinetic 0.2, sliding: a = g (sin - 0.2 cos)",
                sSlide.a/(gMag*(s - 0.2*c)), 1, 1e-3
            );
            // Slows down to rest at t = U0/(g (0.4 cos - sin)), 0.59 s,
            // having slid U0^2/(2 g (0.4 cos - sin)), 0.059
            const scalar decel = gMag*(0.4*c - s);
            fbmTest::check
            (
                "static 0.5, kinetic 0.4, sliding: stops (|U| / g sin(theta) 1 s)",
                mag(sStop.Uend)/(gMag*s), 0, 1e-6
            );
            fbmTest::check
            (
                "static 0.5, kinetic 0.4, sliding: path / U0^2/(2 g (0.4 cos - sin))",
                sStop.distance/(0.04/(2*decel)), 1, 1e-2
            );

            // The spring holds it: at rest, its front corner slid by the
            // spring's stretch only (m g sin(theta)/k_t, 2.5e-5 here).
            // Turning, it first pitches forward onto that corner (tilt
            // 0.016, the centre moving 8e-4 along the incline with it),
            // slowly: at rest from about t = 4 (|U| 2.8e-7 at t = 5)
            const inclineResult turning(incline(box, 0.05, 0.5, mesh, true, 2500));
            checkHeld("mu 0.5, spring, turning, 5 s, corner", turning);
            checkHeld("mu 0.5, spring, not turning, corner", held);
        }
        else
        {
            // Held without turning: the creep speed of the sticking
            // branch, g sin(theta) tau with tau = 2 dt_s (the turning block
            // above, with its smaller sub-step, 1.8e-3 against 1.5e-3)
            fbmTest::check
            (
                "mu 0.5, not turning: creep speed / (g sin(theta) 2 dt_s)",
                held.Uend/(gMag*s*2*held.dtSub), 1, 0.05
            );
        }
    }

    // ---- The block on a fixed slab: the incline through a pair contact ----
    {
        Info<< nl << "Block 0.2 x 0.1 on a fixed slab 0.96 x 0.1, theta 20"
            << " degrees" << nl;
        const dictionary box(boxDict(0.2, 0.1));
        auto onSlab = [&](const scalar mu, const bool rotates)
        {
            return incline(box, 0.05, mu, mesh, rotates, 250, 0, 0, &slabDict);
        };
        const inclineResult free(onSlab(0, true));
        const inclineResult slide(onSlab(0.2, true));
        const inclineResult hold(onSlab(0.5, true));
        // The same on the floor (a wall contact), for comparison
        const inclineResult floorSlide(incline(box, 0.05, 0.2, mesh));
        const inclineResult floorHold(incline(box, 0.05, 0.5, mesh));
        fbmTest::check
        (
            "slab, no friction: a = g sin(theta)", free.a/(gMag*s), 1, 1e-3
        );
        fbmTest::check
        (
            "slab, mu 0.2: a = g (sin - mu cos)",
            slide.a/(gMag*(s - 0.2*c)), 1, 1e-3
        );
        // The face on the slab's face pitches forward as on the floor and
        // rests at that tilt: the rocking speed |omega| R at the end
        // against the sliding speed (with the dashpot at the middle of the
        // faces' overlap alone, 5.3e-2; measured 5.8e-4 with it shared
        // among the overlap's ends, 1.0e-3 on the floor) and the largest
        // tilt against the floor's (0.0119 against 0.0049 without the
        // shared dashpot; 0.0049 with it)
        fbmTest::check
        (
            "slab, mu 0.2: no rocking (|omega| R / U at the end)",
            mag(slide.omegaEnd)*slide.R/slide.Uend, 0, 1e-2
        );
        fbmTest::check
        (
            "slab, mu 0.2: largest tilt / the floor's",
            slide.maxTilt/floorSlide.maxTilt, 1, 0.1
        );
        fbmTest::check
        (
            "slab, mu 0.5: holds (path / frictionless path)",
            hold.distance/free.distance, 0, 1e-2
        );
        // Held, it rocks no more than on the floor (|omega| R at the end:
        // 3.0e-2 without the shared dashpot, 8.0e-4 with it, 1.4e-3 on
        // the floor)
        fbmTest::check
        (
            "slab, mu 0.5: |omega| R at the end / the floor's",
            mag(hold.omegaEnd)/max(mag(floorHold.omegaEnd), VSMALL), 0, 1
        );
    }

    // ---- A disk on the incline ----
    {
        Info<< nl << "Disk R 0.1 on the incline, theta 20 degrees" << nl;
        rollAndSlip(circleDict(0.1), 0.5, mesh);
    }

    // ---- Oblique collisions without gravity ----
    {
        Info<< nl << "Oblique collisions, no gravity" << nl;
        oblique("disks", circleDict(0.1), 0.3, true, mesh);
        oblique("disks without friction", circleDict(0.1), 0, false, mesh);
        oblique("rectangles", boxDict(0.2, 0.1), 0.3, true, mesh);
    }

    return fbmTest::result();
}


// ************************************************************************* //
