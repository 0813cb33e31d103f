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

#include "semiImplicit.H"
#include "bodySystem.H"
#include "fluidRate.H"

// The restart state of coupling semiImplicit

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::couplingModels::semiImplicit::readState
(
    const dictionary& state
)
{
    // The viscous limit of the step after the restart time
    if (stateHasEntry(state, "viscousDeltaT"))
    {
        limit_.read(state.subDict(system_.bodies()[0].name()));
    }

    // The pressure force and the shell of the step that led to the
    // restart time
    const PtrList<body>& bodies = system_.bodies();
    if (stateHasEntry(state, "pressureForce"))
    {
        forAll(bodies, bi)
        {
            const dictionary& d = state.subDict(bodies[bi].name());
            pressureForce_[bi] = d.get<vector>("pressureForce");
            pressureTorque_[bi] = d.get<vector>("pressureTorque");
            inertia_.read(bi, d);
        }
        lastStepKnown_ = true;
    }
    else
    {
        Info<< "fbm: coupling " << type() << ": no pressureForce in "
            << state.name() << "; the first step takes that of the"
            << " restart pressure on the moved bodies" << nl;
    }

    // The pressure step's state (pressureSolve newton: the added mass of
    // the pressure operator and the step it was solved in)
    pressureStep_->readState(state);

    // With backward: the push of the bodies' cells in the step that led
    // to the restart time, which the enclosed fluid's rate of the next
    // step holds too (written with backward only)
    if (stateHasEntry(state, "directForceEuler"))
    {
        forAll(bodies, bi)
        {
            const dictionary& d = state.subDict(bodies[bi].name());
            directForceEuler_[bi] = d.get<vector>("directForceEuler");
            directTorqueEuler_[bi] = d.get<vector>("directTorqueEuler");
        }
    }
    else if
    (
        lastStepKnown_
     && system_.mesh().ddtScheme("ddt(U)")[0].wordToken() == "backward"
    )
    {
        Info<< "fbm: coupling " << type() << ": no directForceEuler in "
            << state.name() << " (a state written with Euler); with"
            << " backward the first step takes the last step's push of the"
            << " bodies' cells as zero" << nl;
    }
}


void Foam::fbm::couplingModels::semiImplicit::writeState
(
    const label bi,
    Ostream& os
) const
{
    if (lastStepKnown_)
    {
        os.writeEntry("pressureForce", pressureForce_[bi]);
        os.writeEntry("pressureTorque", pressureTorque_[bi]);
        inertia_.write(bi, os);
    }
    const fluidRate* rate = system_.rate();
    if (rate && rate->timeScheme() == fluidRate::scheme::backward)
    {
        os.writeEntry("directForceEuler", directForceEuler_[bi]);
        os.writeEntry("directTorqueEuler", directTorqueEuler_[bi]);
    }
    // The viscous limit of the next step (the same for every body)
    limit_.write(os);
    // The pressure step's state (pressureSolve newton: the added mass of
    // the pressure operator, the same for every body)
    pressureStep_->writeState(os);
}

// ************************************************************************* //
