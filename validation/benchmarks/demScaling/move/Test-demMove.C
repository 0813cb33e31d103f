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
    Test-demMove

Description
    Time of one DEM sub-step of the library, fbm::particleCollisions::move
    on fbm::body objects (what fbmFoam runs), against the number of
    particles N: the lattice of Test-demScaling (disks of radius 0.025,
    surface gap 0.005, inside the range 0.01, a jitter of 0.001) in the
    case's box, at rest under gravity, with the walls of the mesh, the
    dashpot of the tutorials (dampingRatio 0.5) and no hydrodynamic force.
    Each N: one move() of -steps sub-steps to warm up, then one timed.
    Prints the time per sub-step and per particle, and the ratio to the
    smallest N.

Usage
    Test-demMove -case CASE [-N '(1000 10000 100000)'] [-steps 20]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include <chrono>
#include "demLattice.H"
#include "bodyInput.H"
#include "rigidBodyMotion.H"
#include "particleCollisions.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("N", "list", "particle numbers");
    argList::addOption("steps", "n", "sub-steps timed per N");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const labelList Ns
    (
        args.getOrDefault<labelList>("N", labelList({1000, 10000, 100000}))
    );
    const label nSteps = args.getOrDefault<label>("steps", 20);

    const dictionary dict
    (
        demLattice::collisionsDict
        (
            "nStepsPerContact 20; dampingRatio 0.5; maxSubCycles 100000;"
        )
    );

    const scalar r = demLattice::radius;
    const vector g(0, -980, 0);
    const scalar zMid = 0.5*(mesh.bounds().min().z() + mesh.bounds().max().z());
    const point origin
    (
        mesh.bounds().min().x() + 0.05, mesh.bounds().min().y() + 0.05, zMid
    );

    Info<< "N  time/sub-step [s]  time/(sub-step N) [s]  ratio to N = "
        << Ns[0] << " (per particle)" << nl;

    scalar perParticle0 = -1;
    for (const label N : Ns)
    {
        const pointField X(demLattice::centres(N, origin));
        const vector margin(0.04, 0.04, 0);     // r + range < 0.04
        if
        (
           !boundBox
            (
                mesh.bounds().min() + margin, mesh.bounds().max() - margin
            ).contains(X)
        )
        {
            FatalErrorInFunction
                << N << " disks do not fit into the mesh " << mesh.bounds()
                << exit(FatalError);
        }

        PtrList<fbm::body> bodies(N);
        forAll(bodies, i)
        {
            bodies.set
            (
                i,
                fbm::bodyInput::newRoundBody
                (
                    "p" + Foam::name(i), r, 1.5,
                    fbm::bodyState(X[i], Zero, Zero), true, false, mesh
                )
            );
        }

        fbm::particleCollisions collisions(dict, mesh, bodies);
        const fbm::rigidBodyMotion motion(g, 1, 0, mesh);
        const scalar dt = nSteps*collisions.dtSubMax();

        collisions.move(bodies, motion, dt);
        const auto start = std::chrono::steady_clock::now();
        collisions.move(bodies, motion, dt);
        const scalar t =
            std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - start
            ).count()/nSteps;
        const scalar perParticle = t/N;
        if (perParticle0 < 0) perParticle0 = perParticle;

        Info<< N << "  " << t << "  " << perParticle << "  "
            << perParticle/perParticle0 << nl;
    }

    Info<< "End" << nl;
    return 0;
}


// ************************************************************************* //
