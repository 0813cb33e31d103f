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
    Test-collisionMap

Description
    Stability map of the contact model without fluid: the overlap
    stiffness eps'_P (fbm::contactModels::singhRepulsion, rangePlusLinear, eps'_W =
    eps'_P/2; the range branch fixed at the DKT tutorial's level-3 values,
    range 0.0625, eps_P 1e-5, eps_W 5e-6, cgs, 2D law per unit length)
    against the sub-steps per contact time nStepsPerContact of
    fbm::particleCollisions. Disks of radius 0.1 and density 1.01 (DKT).

    Two tests for each (eps'_P, n):
    - headOn: two disks approach each other at -u and +u from just outside
      the range, until they have separated again;
    - rest: one disk released from rest touching the bottom wall under
      load x g (the weight of a column of load disks), for a time T.

    Each test records the largest overlap / R (and the value from energy
    conservation of the law), the energy error, the momentum error
    (headOn), and whether it failed: NaN, crossing (the disks pass each
    other, or the disk crosses the wall), overlap > R, energy gain > 10 %
    (headOn: kinetic energy after / before > 1.1; rest: mean total energy
    of the last tenth of the run above that of the first tenth by more than
    10 % of the oscillation energy), or not separated (headOn).

    The sub-step is dt_s = t_c/n, t_c the contact time of
    fbm::particleCollisions (the stiffest branch, pair or wall). For n >= 3
    the run calls particleCollisions::move with dt = dt_s (one sub-step per
    call, sampled at every sub-step). n < 3 is below the lower limit of
    nStepsPerContact: these runs, and the fixed physical sub-step runs
    (the sub-step of the DKT law, eps'_P = 1e-4, n = 20, at every
    stiffness), make the same calls as move() (beginSubCycles, the contact
    forces, kick, drift, contact forces, kick, endSubCycles) at a sub-step
    the law's bound would not allow; the first check below shows that this
    copy is bit-identical to move().

    Writes one CSV row per run.

Usage
    Test-collisionMap -case case [-csv map.csv] [-u 10] [-load 10]
        [-T 0.1] [-eps '(1e-3 1e-4)'] [-n '(1 2 20)'] [-noFixed]
        [-tests '(headOn rest)']

    \table
        Option | Description                               | Default
        -csv   | output file                               | map.csv
        -u     | impact speed of each disk [cm/s]          | 10
        -load  | rest: weight carried, in disk weights     | 10
        -T     | rest: duration [s]                        | 0.1
        -eps   | eps'_P values [cm^3/dyn]                  | 1e-3 ... 1e-8
        -n     | nStepsPerContact values                   | 1 1.5 2 3 5 10 20 50
        -noFixed | no fixed physical sub-step runs         | (runs them)
        -tests | headOn, rest or both                      | (headOn rest)
    \endtable

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "particleCollisions.H"
#include "contactModel.H"
#include "bodyInput.H"
#include "rigidBodyMotion.H"
#include "OFstream.H"
#include "Tuple2.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// DKT tutorial, level 3 (cgs): disk radius and density, range branch
static const scalar R = 0.1;
static const scalar rhoS = 1.01;
static const scalar rangeRho = 1.5/24;
static const scalar epsP = 1e-5;
static const scalar epsW = 5e-6;
static const scalar gAcc = 980;

// No fluid: a vanishing fluid density (the body update divides by nothing)
static const scalar rhoF = 1e-12;


// Collisions dictionary for eps'_P (eps'_W = eps'_P/2)
dictionary collisionsDict(const scalar epsPO, const scalar nSteps)
{
    dictionary coeffs;
    coeffs.add("overlapForce", "rangePlusLinear");
    coeffs.add("range", rangeRho);
    coeffs.add("epsP", epsP);
    coeffs.add("epsPOverlap", epsPO);
    coeffs.add("epsW", epsW);
    coeffs.add("epsWOverlap", 0.5*epsPO);

    dictionary dict;
    dict.add("model", "singhRepulsion");
    dict.add("singhRepulsionCoeffs", coeffs);
    dict.add("nStepsPerContact", nSteps);
    dict.add("maxSubCycles", 1000);
    return dict;
}


// Body dictionary
fbm::body* newBody
(
    const word& name,
    const point& X,
    const vector& U,
    const fvMesh& mesh
)
{
    return fbm::bodyInput::newRoundBody
    (
        name, R, rhoS, fbm::bodyState(X, U, Zero), true, false, mesh
    ).ptr();
}


// Potential per unit length of the rangePlusLinear law between centres at
// distance D, contact size s: -dPhi/dD = D f(D), F = (Xi - Xj) f(D)
scalar potential
(
    const scalar D,
    const scalar s,
    const scalar eps,
    const scalar epsO
)
{
    if (D >= s + rangeRho) return 0;
    const scalar u = s + rangeRho - D;
    scalar phi = ((s + rangeRho)*pow3(u)/3 - pow4(u)/4)/eps;
    if (D < s)
    {
        const scalar v = s - D;
        phi += (s*sqr(v)/2 - pow3(v)/3)/epsO;
    }
    return phi;
}


// Root of a decreasing-then-any function by bisection on [a, b], f(a) > 0,
// f(b) < 0
template<class Func>
scalar bisect(Func f, scalar a, scalar b)
{
    for (label i = 0; i < 200; ++i)
    {
        const scalar c = 0.5*(a + b);
        if (f(c) > 0) a = c; else b = c;
    }
    return 0.5*(a + b);
}


// One velocity-Verlet sub-step of dtSub: particleCollisions::move when the
// law's bound allows it in one sub-step, else the same calls
void subStep
(
    const fvMesh& mesh,
    fbm::particleCollisions& coll,
    PtrList<fbm::body>& bodies,
    const vector& g,
    const scalar dtSub,
    const bool useMove
)
{
    const fbm::rigidBodyMotion motion(g, rhoF, 0, mesh);
    if (useMove)
    {
        coll.move(bodies, motion, dtSub);
        return;
    }

    for (fbm::body& b : bodies) b.beginSubCycles();
    List<vector> F;
    coll.contactForces(bodies, F);
    forAll(bodies, i)
    {
        motion.kick(bodies[i], 0.5*dtSub, F[i]);
        motion.drift(bodies[i], dtSub);
    }
    coll.contactForces(bodies, F);
    forAll(bodies, i)
    {
        motion.kick(bodies[i], 0.5*dtSub, F[i]);
    }
    for (fbm::body& b : bodies) motion.endSubCycles(b, dtSub);
}


// Result of one run
struct result
{
    word status = "ok";
    scalar tc = 0;
    scalar dtSub = 0;
    scalar nEff = 0;
    scalar nOwn = 0;                // sub-steps per t_c of the tested contact
    label steps = 0;
    label stepsOverlap = 0;
    scalar maxOverlap = 0;          // / R
    scalar overlapTheory = 0;       // / R
    scalar minGap = GREAT;          // / R
    scalar energyRatio = 1;         // headOn: KE after/before; rest: 1 + drift
    scalar energyErrMax = 0;        // max |E - E0| / energy scale
    scalar momentumErr = 0;         // / (M u); -1: not defined (rest)
};


// Sub-step for a run: fixedDt > 0 wins, else t_c/n
void setStep
(
    const fbm::particleCollisions& coll,
    const scalar nDict,
    const scalar n,
    const scalar fixedDt,
    result& r,
    bool& useMove
)
{
    r.tc = nDict*coll.dtSubMax();
    if (fixedDt > 0)
    {
        r.dtSub = fixedDt;
    }
    else if (n == nDict)
    {
        r.dtSub = coll.dtSubMax();
    }
    else
    {
        r.dtSub = r.tc/n;
    }
    r.nEff = r.tc/r.dtSub;
    useMove = (r.dtSub <= coll.dtSubMax());
}


// Two disks head on at -u and +u
result headOn
(
    const fvMesh& mesh,
    const scalar epsPO,
    const scalar n,
    const scalar fixedDt,
    const scalar u
)
{
    result r;

    const scalar z = mesh.bounds().centre().z();
    const scalar depth = mesh.bounds().span().z();
    const scalar s = 2*R;
    const scalar D0 = s + rangeRho*(1 + 1e-3);
    PtrList<fbm::body> bodies(2);
    bodies.set
    (
        0, newBody("b0", point(1 - D0/2, 1, z), vector(u, 0, 0), mesh)
    );
    bodies.set
    (
        1, newBody("b1", point(1 + D0/2, 1, z), vector(-u, 0, 0), mesh)
    );
    const scalar nDict = max(n, scalar(3));
    fbm::particleCollisions coll(collisionsDict(epsPO, nDict), mesh, bodies);
    bool useMove = true;
    setStep(coll, nDict, n, fixedDt, r, useMove);

    const scalar M = bodies[0].mass();
    const scalar KE0 = M*sqr(u);            // both disks
    r.nOwn =
        constant::mathematical::pi
       *Foam::sqrt(0.5*M/(depth*coll.model().pairStiffness(R, R)))/r.dtSub;
    const vector P0(M*bodies[0].U() + M*bodies[1].U());

    // Largest overlap from energy conservation: depth Phi(D) = KE0
    {
        const scalar Dmin = bisect
        (
            [&](scalar D){ return depth*potential(D, s, epsP, epsPO) - KE0; },
            1e-12*s, s + rangeRho
        );
        r.overlapTheory = (s - Dmin)/R;
    }

    auto energy = [&]()
    {
        const scalar D = mag(bodies[0].centre() - bodies[1].centre());
        return 0.5*M*(magSqr(bodies[0].U()) + magSqr(bodies[1].U()))
            + depth*potential(D, s, epsP, epsPO);
    };
    const scalar E0 = energy();

    // Time limit: ten times the free approach and rebound through the
    // range, and 200 contact times
    const scalar tMax = 10*2*(rangeRho + s)/(2*u) + 200*r.tc;
    const label maxSteps = 10000000;

    try
    {
        scalar t = 0;
        while (true)
        {
            subStep(mesh, coll, bodies, Zero, r.dtSub, useMove);
            t += r.dtSub;
            ++r.steps;

            const vector d(bodies[1].centre() - bodies[0].centre());
            const scalar D = mag(d);
            const scalar E = energy();
            if (!std::isfinite(D) || !std::isfinite(E))
            {
                r.status = "NaN";
                break;
            }
            if (d.x() <= 0)
            {
                r.status = "crossed";
                break;
            }
            r.maxOverlap = max(r.maxOverlap, (s - D)/R);
            r.minGap = min(r.minGap, (D - s)/R);
            if (D < s) ++r.stepsOverlap;
            r.energyErrMax = max(r.energyErrMax, mag(E - E0)/E0);
            r.momentumErr = max
            (
                r.momentumErr,
                mag(M*bodies[0].U() + M*bodies[1].U() - P0)/(M*u)
            );

            const vector dU(bodies[1].U() - bodies[0].U());
            if (D > s + rangeRho && (dU & d) > 0)
            {
                break;
            }
            if (t > tMax || r.steps >= maxSteps)
            {
                r.status = "notSeparated";
                break;
            }
        }
    }
    catch (const Foam::error& err)
    {
        r.status = "crossed";
    }

    if (r.status == "ok" || r.status == "notSeparated")
    {
        const scalar KE =
            0.5*M*(magSqr(bodies[0].U()) + magSqr(bodies[1].U()));
        r.energyRatio = KE/KE0;
    }
    else
    {
        r.energyRatio = GREAT;
    }

    if (r.status == "ok")
    {
        if (r.maxOverlap > 1) r.status = "overlap>R";
        else if (r.energyRatio > 1.1) r.status = "energyGain";
    }
    return r;
}


// One disk released from rest touching the bottom wall under load x g
result rest
(
    const fvMesh& mesh,
    const scalar epsPO,
    const scalar n,
    const scalar fixedDt,
    const scalar load,
    const scalar T
)
{
    result r;

    const scalar z = mesh.bounds().centre().z();
    const scalar depth = mesh.bounds().span().z();
    const scalar epsWO = 0.5*epsPO;
    const vector g(0, -load*gAcc, 0);
    PtrList<fbm::body> bodies(1);
    bodies.set
    (
        0, newBody("b0", point(1, R, z), Zero, mesh)
    );
    const scalar nDict = max(n, scalar(3));
    fbm::particleCollisions coll(collisionsDict(epsPO, nDict), mesh, bodies);
    bool useMove = true;
    setStep(coll, nDict, n, fixedDt, r, useMove);

    const scalar M = bodies[0].mass();
    r.nOwn =
        constant::mathematical::pi
       *Foam::sqrt(M/(depth*coll.model().wallStiffness(R)))/r.dtSub;
    const scalar W = (M - rhoF*bodies[0].shape().volume())*load*gAcc;

    // Potential energy at height y (the bottom wall at y = 0): the wall
    // image at distance D' = 2y, U = Phi(2y)/2
    auto Epot = [&](scalar y)
    {
        return W*y + depth*0.5*potential(2*y, 2*R, epsW, epsWO);
    };
    auto energy = [&]()
    {
        return 0.5*M*magSqr(bodies[0].U()) + Epot(bodies[0].centre().y());
    };
    const scalar E0 = energy();

    // Equilibrium (force balance) and the lowest point from energy
    // conservation
    const scalar yEq = bisect
    (
        [&](scalar y)
        {
            const point X(1, y, z);
            const point Xw(1, -y, z);
            return depth*coll.model().wallForce(X, R, Xw).y() - W;
        },
        1e-12*R, R + 0.5*rangeRho
    );
    const scalar Eosc = E0 - Epot(yEq);
    const scalar yMin = bisect
    (
        [&](scalar y){ return Epot(y) - E0; }, 1e-12*R, yEq
    );
    r.overlapTheory = (R - yMin)/R;

    const label nSteps = label(std::ceil(T/r.dtSub));
    const label nTenth = max(label(1), nSteps/10);
    scalar Efirst = 0, Elast = 0;
    try
    {
        for (label step = 0; step < nSteps; ++step)
        {
            subStep(mesh, coll, bodies, g, r.dtSub, useMove);
            ++r.steps;
            const scalar y = bodies[0].centre().y();
            const scalar E = energy();
            if (!std::isfinite(y) || !std::isfinite(E))
            {
                r.status = "NaN";
                break;
            }
            if (y <= 0)
            {
                r.status = "crossed";
                break;
            }
            r.maxOverlap = max(r.maxOverlap, (R - y)/R);
            r.minGap = min(r.minGap, (y - R)/R);
            if (y < R) ++r.stepsOverlap;
            r.energyErrMax = max(r.energyErrMax, mag(E - E0)/Eosc);
            if (step < nTenth) Efirst += E/nTenth;
            if (step >= nSteps - nTenth) Elast += E/nTenth;
        }
    }
    catch (const Foam::error& err)
    {
        r.status = "crossed";
    }

    r.momentumErr = -1;
    r.energyRatio = (r.status == "ok") ? 1 + (Elast - Efirst)/Eosc : GREAT;
    if (r.status == "ok")
    {
        if (r.maxOverlap > 1) r.status = "overlap>R";
        else if (r.energyRatio > 1.1) r.status = "energyGain";
    }
    return r;
}


int main(int argc, char *argv[])
{
    argList::addOption("csv", "file", "output CSV (map.csv)");
    argList::addOption("u", "speed", "impact speed of each disk (10)");
    argList::addOption("load", "factor", "rest: load in disk weights (10)");
    argList::addOption("T", "time", "rest: duration (0.1)");
    argList::addOption("eps", "list", "eps'_P values");
    argList::addOption("n", "list", "nStepsPerContact values");
    argList::addBoolOption("noFixed", "no fixed physical sub-step runs");
    argList::addOption("tests", "list", "(headOn rest)");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const fileName csvName(args.getOrDefault<fileName>("csv", "map.csv"));
    const scalar u = args.getOrDefault<scalar>("u", 10);
    const scalar load = args.getOrDefault<scalar>("load", 10);
    const scalar T = args.getOrDefault<scalar>("T", 0.1);
    const scalarList epss
    (
        args.getOrDefault<scalarList>
        (
            "eps", scalarList({1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8})
        )
    );
    const scalarList ns
    (
        args.getOrDefault<scalarList>
        (
            "n", scalarList({1, 1.5, 2, 3, 5, 10, 20, 50})
        )
    );
    const bool fixed = !args.found("noFixed");
    const wordList tests
    (
        args.getOrDefault<wordList>("tests", wordList({"headOn", "rest"}))
    );

    FatalError.throwExceptions();
    const int infoLevel = messageStream::level;

    // -- The copy of move() is bit-identical to move() -----------------------
    label nFailed = 0;
    {
        const scalar z = mesh.bounds().centre().z();
        const scalar D0 = 2*R + rangeRho;
        PtrList<fbm::body> a(2), b(2);
        for (PtrList<fbm::body>* bs : {&a, &b})
        {
            bs->set(0, newBody("b0", point(1 - D0/2, 1, z), vector(10, 0, 0), mesh));
            bs->set(1, newBody("b1", point(1 + D0/2, 1, z), vector(-10, 0, 0), mesh));
        }
        messageStream::level = 0;
        fbm::particleCollisions ca(collisionsDict(1e-5, 3), mesh, a);
        fbm::particleCollisions cb(collisionsDict(1e-5, 3), mesh, b);
        scalar maxDiff = 0;
        for (label i = 0; i < 3000; ++i)
        {
            subStep(mesh, ca, a, vector(0, -gAcc, 0), ca.dtSubMax(), true);
            subStep(mesh, cb, b, vector(0, -gAcc, 0), cb.dtSubMax(), false);
            for (label j = 0; j < 2; ++j)
            {
                maxDiff = max(maxDiff, mag(a[j].centre() - b[j].centre()));
                maxDiff = max(maxDiff, mag(a[j].U() - b[j].U()));
            }
        }
        messageStream::level = infoLevel;
        const bool ok = (maxDiff == 0);
        Info<< (ok ? "PASS" : "FAIL")
            << " copy of particleCollisions::move bit-identical over 3000"
            << " sub-steps (largest difference " << maxDiff << ")" << nl;
        if (!ok) ++nFailed;
    }

    // Fixed physical sub-step: that of the DKT law (eps'_P = 1e-4, n = 20)
    scalar fixedDt = 0;
    {
        PtrList<fbm::body> bodies(1);
        bodies.set(0, newBody("b0", point(1, 1, mesh.bounds().centre().z()), Zero, mesh));
        messageStream::level = 0;
        fbm::particleCollisions coll(collisionsDict(1e-4, 20), mesh, bodies);
        messageStream::level = infoLevel;
        fixedDt = coll.dtSubMax();
        Info<< "Fixed physical sub-step (eps'_P 1e-4, n 20): " << fixedDt
            << nl;
    }

    OFstream csv(csvName);
    csv << "test,epsPOverlap,nStepsPerContact,mode,u,load,t_c,dtSub,nEff,"
        << "nOwn,steps,stepsOverlap,maxOverlapR,overlapTheoryR,minGapR,"
        << "energyRatio,energyErrMax,momentumErr,status" << nl;

    Info<< nl << "test    eps'_P   n     nEff    overlap/R (theory)  "
        << "E ratio    |dE|max    status" << nl;

    for (const word& test : tests)
    {
        for (const scalar eps : epss)
        {
            List<Tuple2<scalar, word>> runs;
            for (const scalar n : ns) runs.append({n, "scaled"});
            if (fixed) runs.append({0, "fixed"});

            for (const auto& run : runs)
            {
                const scalar n = run.first();
                const bool isFixed = (run.second() == "fixed");
                const scalar nUse = isFixed ? 20 : n;
                const scalar fdt = isFixed ? fixedDt : 0;

                messageStream::level = 0;
                result r;
                if (test == "headOn")
                {
                    r = headOn(mesh, eps, nUse, fdt, u);
                }
                else if (test == "rest")
                {
                    r = rest(mesh, eps, nUse, fdt, load, T);
                }
                else
                {
                    messageStream::level = infoLevel;
                    FatalErrorInFunction
                        << "Unknown test " << test << ": headOn or rest"
                        << nl;
                    FatalError.throwExceptions(false);
                    FatalError.exit();
                }
                messageStream::level = infoLevel;

                csv << test << ',' << eps << ',' << (isFixed ? r.nEff : n)
                    << ',' << run.second() << ',' << u << ',' << load << ','
                    << r.tc << ',' << r.dtSub << ',' << r.nEff << ','
                    << r.nOwn << ',' << r.steps << ',' << r.stepsOverlap << ','
                    << r.maxOverlap << ',' << r.overlapTheory << ','
                    << r.minGap << ',';
                if (r.energyRatio < GREAT) csv << r.energyRatio;
                else csv << "nan";
                csv << ','
                    << r.energyErrMax << ',';
                if (r.momentumErr >= 0) csv << r.momentumErr;
                else csv << "nan";
                csv << ',' << r.status << nl;

                Info<< test << "  " << eps << "  "
                    << (isFixed ? word("fixed") : Foam::name(n)) << "  "
                    << r.nEff << "  " << r.maxOverlap << " ("
                    << r.overlapTheory << ")  " << r.energyRatio << "  "
                    << r.energyErrMax << "  " << r.status << nl;
            }
        }
    }

    Info<< nl << "Wrote " << csvName << nl;
    return nFailed;
}


// ************************************************************************* //
