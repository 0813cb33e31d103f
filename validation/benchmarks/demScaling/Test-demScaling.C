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
    Test-demScaling

Description
    Time of one DEM sub-step against the number of particles N: disks of
    radius 0.025 on a square lattice (surface gap 0.005, inside the range
    0.01 of the Singh repulsion, so every particle has 4 to 8 interacting
    neighbours) with a random jitter, in a box that grows with N. A
    sub-step is what fbm::particleCollisions does per sub-cycle: the cell
    list search (fbm::contactSearch), the pair forces (fbm::contactModels::singhRepulsion,
    paper Eq. 9) and the velocity-Verlet kick and drift. Prints the time
    per sub-step and per particle for each N, and the ratio to the
    smallest N: linear growth gives a constant time per particle.

Usage
    Test-demScaling [-N '(1000 10000 100000)'] [-steps 20]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "mathematicalConstants.H"
#include <chrono>
#include "cpuTime.H"
#include "contactSearch.H"
#include "contactModel.H"
#include "demLattice.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    argList::noCheckProcessorDirectories();
    argList::addOption("N", "list", "particle numbers");
    argList::addOption("steps", "n", "sub-steps timed per N");
    argList args(argc, argv, false, false, false);

    const labelList Ns
    (
        args.getOrDefault<labelList>("N", labelList({1000, 10000, 100000}))
    );
    const label nSteps = args.getOrDefault<label>("steps", 20);

    const dictionary dict(demLattice::collisionsDict());
    const scalar h = 0.0125;
    autoPtr<fbm::contactModel> law(fbm::contactModel::New(dict, h));

    const scalar r = demLattice::radius;
    const scalar m = 1.5*constant::mathematical::pi*r*r;
    const scalar dt = 1e-5;

    Info<< "N  time/sub-step [s]  time/(sub-step N) [s]  ratio to N = "
        << Ns[0] << " (per particle)  pairs" << nl;

    scalar perParticle0 = -1;
    for (const label N : Ns)
    {
        pointField X(demLattice::centres(N, point::zero));
        vectorField V(N, Zero);
        scalarField R(N, r);
        fbm::contactSearch search;
        vectorField F(N, Zero);
        const scalar range = law->range();

        auto forces = [&]()
        {
            search.search(X, R, range);
            F = Zero;
            for (const labelPair& ij : search.pairs())
            {
                const label i = ij.first();
                const label j = ij.second();
                const vector Fij(law->pairForce(X[i], R[i], X[j], R[j]));
                F[i] += Fij;
                F[j] -= Fij;
            }
        };

        forces();
        const auto start = std::chrono::steady_clock::now();
        for (label step = 0; step < nSteps; ++step)
        {
            forAll(X, i)
            {
                V[i] += (0.5*dt/m)*F[i];
                X[i] += dt*V[i];
            }
            forces();
            forAll(X, i)
            {
                V[i] += (0.5*dt/m)*F[i];
            }
        }
        const scalar t =
            std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - start
            ).count()/nSteps;
        const scalar perParticle = t/N;
        if (perParticle0 < 0) perParticle0 = perParticle;

        Info<< N << "  " << t << "  " << perParticle << "  "
            << perParticle/perParticle0 << "  " << search.pairs().size()
            << nl;
    }

    Info<< "End" << nl;
    return 0;
}


// ************************************************************************* //
