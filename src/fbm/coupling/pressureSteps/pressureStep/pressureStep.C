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

#include "pressureStep.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(pressureStep, 0);
    defineRunTimeSelectionTable(pressureStep, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::pressureStep::pressureStep
(
    const couplingModels::semiImplicit& coupling,
    const bodySystem& system
)
:
    coupling_(coupling),
    system_(system)
{}


// ************************************************************************* //
