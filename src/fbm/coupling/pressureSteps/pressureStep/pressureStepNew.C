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

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fbm::pressureStep> Foam::fbm::pressureStep::New
(
    const dictionary& coeffs,
    const couplingModels::semiImplicit& coupling,
    const bodySystem& system
)
{
    // The coupling's own compliant step unless the case names another
    // (the coupling says which in its log line)
    const word stepType
    (
        coeffs.getOrDefault<word>("pressureSolve", "iterated", keyType::LITERAL)
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(stepType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            coeffs,
            "pressureSolve",
            stepType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<pressureStep>(cstrIter()(coeffs, coupling, system));
}


// ************************************************************************* //
