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

#include "couplingModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fbm::couplingModel> Foam::fbm::couplingModel::New
(
    const dictionary& dict,
    bodySystem& system
)
{
    // The paper's explicit coupling unless the case names one; said in the
    // log either way, so that a case without the entry shows what it ran
    const bool given = dict.found("coupling");
    const word modelType(dict.getOrDefault<word>("coupling", "explicit"));
    Info<< "fbm: coupling " << modelType;
    if (!given)
    {
        Info<< " (the default: no coupling entry in " << dict.name() << ")";
    }
    Info<< nl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "coupling",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<couplingModel>(cstrIter()(dict, system));
}


// ************************************************************************* //
