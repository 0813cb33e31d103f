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
    Test-intruderDEM

Description
    The big disk of the bigParticleDiving tutorial dropped into its settled
    bed with the contact model alone: no fluid, gravity with the buoyancy
    of a fluid at rest (rhoFluid of constant/fbmProperties) and a linear
    damping force -c M U on every body in place of the drag, as in the
    settling of fbmSetParticles. The contact forces are those of the
    collisions dictionary of constant/fbmProperties (fbm::particleCollisions,
    sub-cycled).

    The damping only takes the kinetic energy away: where the big disk
    comes to rest is where the contact network of the bed carries its
    submerged weight. Comparing that depth with the coupled fbmFoam runs
    tells whether the fluid or the bed decides the regime.

    Reads the bodies/big entry (radius, centre; rho from -rho) and the
    particle list of particleLists/small (the file written by
    fbmSetParticles, "(x y z) radius" per particle) of
    constant/fbmProperties. Writes t, the big disk's centre height and
    vertical velocity, the largest speed of any body and the smallest pair
    and wall gaps (from the sub-steps) every -writeInterval to -csv.

Usage
    Test-intruderDEM -case CASE -rho 1.5 [-endTime 5] [-deltaT 5e-5]
        [-damping 50] [-writeInterval 0.01] [-csv intruder.csv]

    \table
        Option   | Description                                  | Default
        -rho     | density of the big disk                      | required
        -endTime | end time [s]                                 | 5
        -deltaT  | step of the damping force (contacts sub-cycled) | 5e-5
        -damping | c of the damping force -c M U [1/s]          | 50
        -writeInterval | output interval [s]                    | 0.01
        -csv     | output file                                  | intruder.csv
    \endtable

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "uniformDimensionedFields.H"
#include "bodyInput.H"
#include "rigidBodyMotion.H"
#include "particleCollisions.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- A circle translating only and starting from rest (the contact forces
//  are central: no torques)
fbm::body* translatingBody
(
    const word& name,
    const scalar radius,
    const scalar rho,
    const point& centre,
    const fvMesh& mesh
)
{
    return fbm::bodyInput::newRoundBody
    (
        name, radius, rho, fbm::bodyState(centre, Zero, Zero), true, false,
        mesh
    ).ptr();
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Drop the big disk of bigParticleDiving into its bed with the"
        " contact model alone (no fluid, a damping force in its place)"
    );
    argList::noParallel();
    argList::addOption("rho", "scalar", "density of the big disk");
    argList::addOption("endTime", "scalar", "end time (default 5)");
    argList::addOption("deltaT", "scalar", "step (default 5e-5)");
    argList::addOption("damping", "scalar", "c [1/s] (default 50)");
    argList::addOption("writeInterval", "scalar", "default 0.01");
    argList::addOption("csv", "file", "output (default intruder.csv)");

    #include "setRootCase.H"
    #include "createTime.H"

    const scalar rhoBig = args.get<scalar>("rho");
    const scalar endTime = args.getOrDefault<scalar>("endTime", 5);
    const scalar dt = args.getOrDefault<scalar>("deltaT", 5e-5);
    const scalar c = args.getOrDefault<scalar>("damping", 50);
    const scalar dtWrite = args.getOrDefault<scalar>("writeInterval", 0.01);
    const fileName csvName(args.getOrDefault<fileName>("csv", "intruder.csv"));
    if (!(rhoBig > 0) || !(dt > 0) || !(c >= 0) || c*dt >= 1)
    {
        FatalErrorInFunction
            << "-rho and -deltaT must be positive, -damping not negative"
            << " and damping*deltaT below 1" << exit(FatalError);
    }

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

    const IOdictionary fbmDict
    (
        IOobject
        (
            "fbmProperties",
            runTime.constant(),
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
                runTime.constant(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        ).value()
    );
    PtrList<fbm::body> bodies;

    // The big disk first, with the density of -rho
    const dictionary& bigDict = fbmDict.subDict("bodies").subDict("big");
    bodies.append
    (
        translatingBody
        (
            "big", bigDict.get<scalar>("radius"), rhoBig,
            bigDict.get<point>("centre"), mesh
        )
    );

    // The bed: the particle list of particleLists/small, read as fbmFoam
    // reads it
    const dictionary& smallDict =
        fbmDict.subDict("particleLists").subDict("small");
    pointField smallX;
    scalarField smallR, smallRho;
    fbm::bodyInput::readParticleList(smallDict, smallX, smallR, smallRho);
    forAll(smallX, i)
    {
        bodies.append
        (
            translatingBody
            (
                "small" + Foam::name(i), smallR[i], smallRho[i], smallX[i],
                mesh
            )
        );
    }
    const scalar rhoSmall = smallDict.get<scalar>("rho");
    Info<< "intruder: big disk rho " << rhoBig << " and " << bodies.size() - 1
        << " bed disks of rho " << rhoSmall << ", rhoFluid " << rhoFluid
        << ", damping " << c << " 1/s" << nl;

    fbm::particleCollisions collisions
    (
        fbmDict.subDict("collisions"), mesh, bodies
    );
    const fbm::rigidBodyMotion motion(g, rhoFluid, 0, mesh);

    OFstream csv(csvName);
    csv.precision(10);
    csv << "t,y,Uy,maxU,minPairGap,minWallGap" << nl;
    const vector up(-g/mag(g));

    scalar t = 0;
    scalar tNext = 0;
    scalar minPair = GREAT;
    scalar minWall = GREAT;
    while (t < endTime - 0.5*dt)
    {
        for (fbm::body& b : bodies)
        {
            b.setForce(-c*b.mass()*b.U(), Zero);
        }
        collisions.move(bodies, motion, dt);
        t += dt;
        minPair = min(minPair, collisions.minPairGap());
        minWall = min(minWall, collisions.minWallGap());

        if (t >= tNext - 0.5*dt)
        {
            scalar maxU = 0;
            for (const fbm::body& b : bodies) maxU = max(maxU, mag(b.U()));
            const fbm::body& big = bodies[0];
            if (!std::isfinite(maxU))
            {
                FatalErrorInFunction
                    << "not finite at t = " << t << exit(FatalError);
            }
            csv << t << ',' << (big.centre() & up) << ',' << (big.U() & up)
                << ',' << maxU << ',' << minPair << ',' << minWall
                << endl;    // kept when a later step stops the run
            minPair = GREAT;
            minWall = GREAT;
            tNext += dtWrite;
        }
    }
    Info<< "intruder: t = " << t << ", big disk at "
        << (bodies[0].centre() & up) << nl << "End" << nl;

    return 0;
}


// ************************************************************************* //
