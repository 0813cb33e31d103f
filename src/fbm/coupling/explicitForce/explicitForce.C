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

#include "explicitForce.H"
#include "bodySystem.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace couplingModels
{
    defineTypeNameAndDebug(explicitForce, 0);
    addToRunTimeSelectionTable(couplingModel, explicitForce, dictionary);
}
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::couplingModels::explicitForce::checkDensityRatios() const
{
    // One warning for the first such body, with the count
    const scalar rhoFluid = system_.rhoFluid();
    label nLight = 0;
    const body* first = nullptr;
    for (const body& b : system_.bodies())
    {
        if (b.translates() && addedMassCoeff_ == 0 && b.rho() < 1.2*rhoFluid)
        {
            if (!nLight) first = &b;
            ++nLight;
        }
    }
    if (nLight)
    {
        WarningInFunction
            << "Body " << first->name() << ": density ratio "
            << first->rho()/rhoFluid << " with the explicit coupling"
            << " and addedMassCoeff 0 in " << dict_.name() << nl
            << "    is likely to oscillate or diverge (lagged added"
            << " mass); set addedMassCoeff 0.5 to 1 or coupling"
            << " semiImplicit";
        if (nLight > 1)
        {
            Info<< " (" << nLight << " such bodies)";
        }
        Info<< endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::couplingModels::explicitForce::explicitForce
(
    const dictionary& dict,
    bodySystem& system
)
:
    couplingModel(dict, system),
    addedMassCoeff_
    (
        dict.getCheckOrDefault<scalar>
        (
            "addedMassCoeff", 0, [](scalar c){ return c >= 0; }
        )
    ),
    free_(system.bodies().size(), false),
    limit_(dict.optionalSubDict(typeName + "Coeffs"), typeName, 0)
{
    const PtrList<body>& bodies = system.bodies();
    forAll(bodies, bi)
    {
        free_[bi] = bodies[bi].translates() || bodies[bi].rotates();
    }

    rejectContactProjection();

    checkDensityRatios();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fbm::couplingModels::explicitForce::beforeFlow()
{
    return system_.advance();
}


void Foam::fbm::couplingModels::explicitForce::estimateMaxDeltaT
(
    const volScalarField& nuEff
)
{
    limit_.estimate(nuEff, system_.fb(), free_);
}


void Foam::fbm::couplingModels::explicitForce::constrain
(
    fvMatrix<vector>& UEqn
) const
{
    limit_.update(UEqn, system_.fb(), free_, system_.rate());
}


bool Foam::fbm::couplingModels::explicitForce::afterFlow
(
    volVectorField& U,
    List<vector>& force,
    List<vector>& torque
)
{
    holdForces(force, torque);
    return true;
}


void Foam::fbm::couplingModels::explicitForce::readState
(
    const dictionary& state
)
{
    if (limit_.active() && stateHasEntry(state, "viscousDeltaT"))
    {
        limit_.read(state.subDict(system_.bodies()[0].name()));
    }
}


void Foam::fbm::couplingModels::explicitForce::writeState
(
    const label bi,
    Ostream& os
) const
{
    limit_.write(os);
}


// ************************************************************************* //
