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

#include "iterated.H"
#include "fvMatrices.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace pressureSteps
{
    defineTypeNameAndDebug(iterated, 0);
    addToRunTimeSelectionTable(pressureStep, iterated, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::pressureSteps::iterated::iterated
(
    const dictionary& coeffs,
    const couplingModels::semiImplicit& coupling,
    const bodySystem& system
)
:
    pressureStep(coupling, system)
{
    if (coeffs.found("addedMassInterval", keyType::LITERAL))
    {
        FatalIOErrorInFunction(coeffs)
            << "addedMassInterval in " << coeffs.name() << " is"
            << " pressureSolve newton's; pressureSolve is " << typeName
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fbm::pressureSteps::iterated::velocity
(
    const label i
) const
{
    FatalErrorInFunction
        << "pressureSolve " << typeName << " has no rigid body"
        << abort(FatalError);
    return Zero;
}


void Foam::fbm::pressureSteps::iterated::solve
(
    fvScalarMatrix& pEqn,
    volScalarField& p,
    const volScalarField& rAtU,
    const dictionary& solverDict,
    const label refCell,
    List<vector>& P,
    List<vector>& Q
)
{
    pEqn.solve(solverDict);
}


// ************************************************************************* //
