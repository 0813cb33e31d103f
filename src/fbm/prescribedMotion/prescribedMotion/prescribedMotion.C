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

#include "prescribedMotion.H"
#include "bodyState.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(prescribedMotion, 0);
    defineRunTimeSelectionTable(prescribedMotion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::prescribedMotion::prescribedMotion(const point& centre0)
:
    centre0_(centre0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::prescribedMotion::set(const scalar t, bodyState& s) const
{
    s.centre() = centre0_ + displacement(t);
    s.U() = velocity(t);
}


// ************************************************************************* //
