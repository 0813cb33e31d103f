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

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fbm::velocityForcing> Foam::fbm::velocityForcing::New
(
    const fvMesh& mesh,
    const dictionary& dict,
    const bool coupled
)
{
    // Required: the two forcings differ in accuracy, no silent default
    const word forcingType(dict.get<word>("forcing", keyType::LITERAL));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(forcingType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "forcing",
            forcingType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<velocityForcing>(cstrIter()(mesh, dict, coupled));
}


// ************************************************************************* //
