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

#include "velocityForcing.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(velocityForcing, 0);
    defineRunTimeSelectionTable(velocityForcing, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::velocityForcing::velocityForcing
(
    const fvMesh& mesh,
    const dictionary& dict,
    const bool coupled
)
:
    mesh_(mesh),
    penaltyMax_
    (
        dict.getCheckOrDefault<scalar>
        (
            "penaltyMax", 1e6, [](scalar k){ return k >= 10; }
        )
    ),
    coupled_(coupled)
{}


// ************************************************************************* //
