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

#include "coulombFriction.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::coulombFriction::coulombFriction
(
    const dictionary& dict,
    const vector& planeMask,
    const scalar depth
)
:
    mu_
    (
        dict.getCheckOrDefault<scalar>
        (
            "frictionCoeff", 0, [](scalar mu){ return mu >= 0; }
        )
    ),
    planeMask_(planeMask),
    depth_(depth),
    tau_(GREAT)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::coulombFriction::writeInfo() const
{
    if (active())
    {
        Info<< "fbm: collisions: Coulomb friction, frictionCoeff " << mu_
            << " (history-free: sticking creeps at about the held"
            << " acceleration times 2 dt_s)" << nl;
    }
}


// ************************************************************************* //
