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

#include "velocityRegularised.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace frictionModels
{
    defineTypeNameAndDebug(velocityRegularised, 0);
    addToRunTimeSelectionTable
    (
        frictionModel,
        velocityRegularised,
        dictionary
    );
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::frictionModels::velocityRegularised::velocityRegularised
(
    const dictionary& dict,
    const vector& planeMask,
    const scalar depth
)
:
    frictionModel(dict, planeMask, depth),
    tau_(GREAT)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fbm::frictionModels::velocityRegularised::force
(
    const labelPair& contact,
    const vector& v,
    const vector& n,
    const scalar Fn,
    const scalar kn,
    const scalar wt
)
{
    const vector vt(tangential(v, n));
    const scalar magVt = mag(vt);
    if (Fn <= 0 || magVt < VSMALL)
    {
        return Zero;
    }
    if (wt <= 0)
    {
        return Zero;
    }

    // Coulomb's bound, or the force that stops the sliding over tau
    return -min(mu_*Fn, magVt/(wt*tau_*depth_))*(vt/magVt);
}


void Foam::fbm::frictionModels::velocityRegularised::writeInfo() const
{
    Info<< "fbm: collisions: Coulomb friction, frictionCoeff " << mu_
        << " (velocityRegularised, history-free: sticking creeps at about"
        << " the held acceleration times 2 dt_s)" << nl;
}


// ************************************************************************* //
