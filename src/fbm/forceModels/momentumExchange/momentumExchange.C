/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "momentumExchange.H"
#include "footprint.H"
#include "body.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace forceModels
{
    defineTypeNameAndDebug(momentumExchange, 0);
    addToRunTimeSelectionTable(forceModel, momentumExchange, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::forceModels::momentumExchange::momentumExchange
(
    const dictionary& dict
)
:
    forceModel(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::forceModels::momentumExchange::calcForces
(
    const footprint& fp,
    const volVectorField& U,
    const volScalarField& p,
    const volScalarField& nuEff,
    List<vector>& force,
    List<vector>& torque
) const
{
    const PtrList<body>& bodies = fp.bodies();
    const scalar rhoFluid = fp.rhoFluid();
    const vectorField& C = fp.mesh().C().primitiveField();
    const scalarField& lambda = fp.lambda();
    const scalarField& bodyID = fp.bodyID().primitiveField();
    const vectorField& Us = fp.Us().primitiveField();

    force = Zero;
    torque = Zero;

    for (const label celli : fp.activeCells())
    {
        const label bi = label(bodyID[celli]);
        if (bi < 0) continue;

        const vector f(rhoFluid*lambda[celli]*(U[celli] - Us[celli]));
        force[bi] += f;
        torque[bi] += (C[celli] - bodies[bi].centre()) ^ f;
    }

    // Rate of change of the momentum of the fluid the rigid body encloses
    forAll(bodies, bi)
    {
        const body& b = bodies[bi];
        if (b.moves() && Pstream::master())
        {
            const bodyState& s = b.state();
            const scalar Vf = b.shape().volume();
            force[bi] += rhoFluid*Vf*fp.fluidAcceleration(s);
            torque[bi] +=
                (rhoFluid/b.rho())
               *(b.inertia() & fp.fluidAngularAcceleration(s));
        }
    }

    // A coupling that set the velocity of the bodies' cells besides the
    // penalty (semiImplicit, after the pressure step) pushed the enclosed
    // fluid with a force of its own: the body's acceleration above holds
    // it, the forcing's reaction does not (the penalty's target moved with
    // the cells), so it is not the fluid's force on the body
    const List<vector>& Fd = fp.directForce();
    const List<vector>& Td = fp.directTorque();
    if (Fd.size() && Pstream::master())
    {
        forAll(bodies, bi)
        {
            force[bi] -= Fd[bi];
            torque[bi] -= Td[bi];
        }
    }
}


// ************************************************************************* //
