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
    fbmSetParticles

Group
    grpPreProcessingUtilities

Description
    Writes a particle list for the particleLists of constant/fbmProperties
    (see fbm::bodyInput): particles from lattices and random
    packings, optionally settled under gravity by the contact model alone
    (no fluid) to make a bed.

    Generators (in order; each avoids the particles already placed only if
    it is random):
    - lattice: n = (nx ny nz) particles at origin + i a + j b + k c with
      spacing (a, b, c along x, y, z); shiftOddColumns is added to the
      particles of odd i, shiftOddRows to those of odd j (staggered and
      hexagonal lattices); number (optional) keeps the first particles
      (i fastest, then j, then k).
    - random: number particles with their centres uniformly in box, the
      surfaces at least minGap apart and from the earlier particles
      (random sequential addition with a cell list, seeded: the same seed
      gives the same list). Fails after maxTries attempts.

    Settling (optional settle dictionary): the particles become translating
    bodies of density rho (circles on a 2D mesh, spheres in 3D) that move
    under gravity (constant/g), buoyancy (rhoFluid of
    constant/fbmProperties) and the contact forces of the collisions
    dictionary of constant/fbmProperties with the sub-cycling of
    fbm::particleCollisions, plus a linear damping force -c M U in place of
    the fluid: no drag law, only a way to dissipate the energy. It stops at
    endTime or when the largest speed falls below stopSpeed, and the list
    written holds the settled centres.

Usage
    fbmSetParticles [-case DIR] [-dict FILE]

    system/setParticlesDict:
    \verbatim
    output      "constant/smallParticles";
    generators
    {
        rows
        {
            type            lattice;
            radius          0.025;
            origin          (0.035 1.2 0);
            n               (100 100 1);
            spacing         (0.0498 0.068 0);
            shiftOddColumns (0 0.034 0);    // optional, default 0
            shiftOddRows    (0 0 0);        // optional, default 0
            number          10000;          // optional, default all
        }
        bed
        {
            type            random;
            radius          0.025;
            number          2000;
            box             ((0.035 0.035 0) (1.965 3.9 0));
            minGap          0.01;
            seed            1;
            maxTries        10000000;
        }
    }
    settle                  // optional
    {
        rho         1.5;    // particle density
        deltaT      1e-3;   // time step (sub-cycled for the contact)
        endTime     5;
        damping     10;     // c [1/s]
        stopSpeed   0.01;   // stop when every particle is slower
    }
    \endverbatim

    \table
        Property   | Description                               | Required
        output     | particle list file, relative to the case  | yes
        generators | dictionary of lattice and random generators | yes
        settle     | settle under gravity with the contact model | no
    \endtable

    The file holds particles ( (x y z) radius ... ); for #include in a
    particleLists entry.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include <cmath>
#include "Random.H"
#include "Enum.H"
#include "HashTable.H"
#include "uniformDimensionedFields.H"
#include "bodyInput.H"
#include "rigidBodyMotion.H"
#include "particleCollisions.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

enum class generatorType { lattice, random };

static const Enum<generatorType> generatorTypeNames
({
    { generatorType::lattice, "lattice" },
    { generatorType::random, "random" },
});


//- Lattice of particles
void addLattice
(
    const dictionary& dict,
    DynamicList<point>& X,
    DynamicList<scalar>& R
)
{
    const scalar r = dict.getCheck<scalar>("radius", scalarMinMax(0, GREAT));
    const point origin(dict.get<point>("origin"));
    const Vector<label> n(dict.get<Vector<label>>("n"));
    const vector a(dict.get<vector>("spacing"));
    const vector shiftCol(dict.getOrDefault<vector>("shiftOddColumns", Zero));
    const vector shiftRow(dict.getOrDefault<vector>("shiftOddRows", Zero));
    const label nAll = n.x()*n.y()*n.z();
    const label number =
        dict.getCheckOrDefault<label>("number", nAll, labelMinMax(0, nAll));

    label count = 0;
    for (label k = 0; k < n.z(); ++k)
    {
        for (label j = 0; j < n.y(); ++j)
        {
            for (label i = 0; i < n.x() && count < number; ++i, ++count)
            {
                point p
                (
                    origin + vector(i*a.x(), j*a.y(), k*a.z())
                );
                if (i % 2) p += shiftCol;
                if (j % 2) p += shiftRow;
                X.append(p);
                R.append(r);
            }
        }
    }
    Info<< "    lattice " << dict.dictName() << ": " << count << " particles"
        << nl;
}


//- Random sequential addition with a cell list
void addRandom
(
    const dictionary& dict,
    DynamicList<point>& X,
    DynamicList<scalar>& R
)
{
    const scalar r = dict.getCheck<scalar>("radius", scalarMinMax(0, GREAT));
    const label number =
        dict.getCheck<label>("number", labelMinMax(0, labelMax));
    const FixedList<point, 2> box(dict.get<FixedList<point, 2>>("box"));
    const scalar gap = dict.getCheck<scalar>("minGap", scalarMinMax(0, GREAT));
    const label seed = dict.get<label>("seed");
    const label maxTries =
        dict.getCheck<label>("maxTries", labelMinMax(1, labelMax));

    scalar rMax = r;
    for (const scalar Ri : R) rMax = max(rMax, Ri);
    const scalar w = 2*rMax + gap;

    // Cell list over the box grown by w (earlier particles outside it
    // cannot be within reach)
    const point lo(box[0] - vector::uniform(w));
    const point hi(box[1] + vector::uniform(w));
    auto cellOf = [&](const point& p, label& ix, label& iy, label& iz)
    {
        ix = label(std::floor((p.x() - lo.x())/w));
        iy = label(std::floor((p.y() - lo.y())/w));
        iz = label(std::floor((p.z() - lo.z())/w));
    };
    auto key = [](label ix, label iy, label iz)
    {
        return word
        (
            Foam::name(ix) + '_' + Foam::name(iy) + '_' + Foam::name(iz)
        );
    };
    HashTable<DynamicList<label>> cells;
    auto insert = [&](const label pi)
    {
        label ix, iy, iz;
        cellOf(X[pi], ix, iy, iz);
        cells(key(ix, iy, iz)).append(pi);
    };
    forAll(X, pi)
    {
        const point& p = X[pi];
        if
        (
            p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y()
         && p.y() <= hi.y() && p.z() >= lo.z() && p.z() <= hi.z()
        )
        {
            insert(pi);
        }
    }

    Random rnd(seed);
    label placed = 0;
    label tries = 0;
    while (placed < number)
    {
        if (++tries > maxTries)
        {
            FatalIOErrorInFunction(dict)
                << "Generator " << dict.dictName() << ": placed only "
                << placed << " of " << number << " particles in " << maxTries
                << " tries (maxTries); the box is too full for random"
                << " addition (use a lattice and settle)"
                << exit(FatalIOError);
        }
        const point p
        (
            rnd.position<scalar>(box[0].x(), box[1].x()),
            rnd.position<scalar>(box[0].y(), box[1].y()),
            rnd.position<scalar>(box[0].z(), box[1].z())
        );
        label ix, iy, iz;
        cellOf(p, ix, iy, iz);
        bool free = true;
        for (label dx = -1; dx <= 1 && free; ++dx)
        {
            for (label dy = -1; dy <= 1 && free; ++dy)
            {
                for (label dz = -1; dz <= 1 && free; ++dz)
                {
                    const auto iter =
                        cells.cfind(key(ix + dx, iy + dy, iz + dz));
                    if (!iter.found()) continue;
                    for (const label pj : *iter)
                    {
                        if (mag(X[pj] - p) < r + R[pj] + gap)
                        {
                            free = false;
                            break;
                        }
                    }
                }
            }
        }
        if (free)
        {
            X.append(p);
            R.append(r);
            insert(X.size() - 1);
            ++placed;
        }
    }
    Info<< "    random " << dict.dictName() << ": " << placed
        << " particles in " << tries << " tries" << nl;
}


//- Settle the particles under gravity with the contact model, no fluid
void settle
(
    const dictionary& dict,
    const fvMesh& mesh,
    List<point>& X,
    const List<scalar>& R
)
{
    const scalar rho = dict.getCheck<scalar>("rho", scalarMinMax(0, GREAT));
    const scalar dt = dict.getCheck<scalar>("deltaT", scalarMinMax(0, GREAT));
    const scalar endTime =
        dict.getCheck<scalar>("endTime", scalarMinMax(0, GREAT));
    const scalar c = dict.getCheck<scalar>("damping", scalarMinMax(0, GREAT));
    const scalar stopSpeed =
        dict.getCheck<scalar>("stopSpeed", scalarMinMax(0, GREAT));
    if (c*dt >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "damping times deltaT is " << c*dt << ": it must be below 1"
            << " for the explicit damping" << exit(FatalIOError);
    }

    const IOdictionary fbmDict
    (
        IOobject
        (
            "fbmProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const scalar rhoFluid =
        fbmDict.getCheck<scalar>("rhoFluid", scalarMinMax(0, GREAT));
    const vector g
    (
        uniformDimensionedVectorField
        (
            IOobject
            (
                "g",
                mesh.time().constant(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        ).value()
    );

    // The particles as translating bodies
    PtrList<fbm::body> bodies(X.size());
    forAll(X, i)
    {
        bodies.set
        (
            i,
            fbm::bodyInput::newRoundBody
            (
                "p" + Foam::name(i), R[i], rho,
                fbm::bodyState(X[i], Zero, Zero), true, false, mesh
            )
        );
    }

    fbm::particleCollisions collisions
    (
        fbmDict.subDict("collisions"), mesh, bodies
    );
    const fbm::rigidBodyMotion motion(g, rhoFluid, 0, mesh);

    scalar t = 0;
    label step = 0;
    scalar maxU = GREAT;
    while (t < endTime - 0.5*dt)
    {
        // The damping force, held over the step like a hydrodynamic force
        for (fbm::body& b : bodies)
        {
            b.setForce(-c*b.mass()*b.U(), Zero);
        }
        collisions.move(bodies, motion, dt);
        t += dt;
        ++step;

        maxU = 0;
        for (const fbm::body& b : bodies)
        {
            maxU = max(maxU, mag(b.U()));
        }
        if (step % 100 == 0)
        {
            Info<< "settle: t = " << t << " largest speed " << maxU
                << ", smallest pair gap " << collisions.minPairGap()
                << ", wall gap " << collisions.minWallGap() << nl;
        }
        if (maxU < stopSpeed && t > 10*dt)
        {
            break;
        }
    }

    scalar top = -GREAT;
    forAll(X, i)
    {
        X[i] = bodies[i].centre();
        top = max(top, (X[i] & (-g/mag(g))) + R[i]);
    }
    Info<< "settle: stopped at t = " << t << " (" << step << " steps),"
        << " largest speed " << maxU << ", smallest pair gap "
        << collisions.minPairGap() << ", wall gap "
        << collisions.minWallGap() << ", top of the bed (against g) "
        << top << nl;
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write a particle list (lattices, random packings, optionally"
        " settled under gravity by the contact model) for the particleLists"
        " of constant/fbmProperties"
    );
    argList::noParallel();
    argList::addOption
    (
        "dict",
        "file",
        "Use the given dictionary (relative to the case) in place of"
        " system/setParticlesDict"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    // system/setParticlesDict, or the file of -dict (relative to the case)
    IOobject dictIO
    (
        "setParticlesDict",
        runTime.system(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (args.found("dict"))
    {
        fileName dictFile(args.get<fileName>("dict"));
        if (!dictFile.isAbsolute())
        {
            dictFile = runTime.path()/dictFile;
        }
        dictIO = IOobject
        (
            dictFile, mesh, IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
    }
    if (!dictIO.typeHeaderOk<IOdictionary>(false))
    {
        FatalErrorInFunction
            << "Cannot read " << dictIO.objectPath() << exit(FatalError);
    }
    const IOdictionary dict(dictIO);

    DynamicList<point> Xd;
    DynamicList<scalar> Rd;
    const dictionary& gens = dict.subDict("generators");
    for (const entry& e : gens)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(gens)
                << "Entry '" << e.keyword() << "' of generators is not a"
                << " dictionary" << exit(FatalIOError);
        }
        switch (generatorTypeNames.get("type", e.dict()))
        {
            case generatorType::lattice: addLattice(e.dict(), Xd, Rd); break;
            case generatorType::random: addRandom(e.dict(), Xd, Rd); break;
        }
    }

    List<point> X(std::move(Xd));
    const List<scalar> R(std::move(Rd));

    if (dict.found("settle"))
    {
        settle(dict.subDict("settle"), mesh, X, R);
    }

    const fileName out(runTime.path()/dict.get<fileName>("output"));
    OFstream os(out);
    os.precision(10);
    os  << "// fbmSetParticles: " << X.size() << " particles, (x y z) radius"
        << nl << "particles" << nl << X.size() << nl << token::BEGIN_LIST
        << nl;
    forAll(X, i)
    {
        os  << "    " << X[i] << ' ' << R[i] << nl;
    }
    os  << token::END_LIST << token::END_STATEMENT << nl;

    Info<< "Wrote " << X.size() << " particles to " << out << nl
        << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
