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

#include "frictionModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fbm::frictionModel> Foam::fbm::frictionModel::New
(
    const dictionary& dict,
    const vector& planeMask,
    const scalar depth
)
{
    const scalar mu
    (
        dict.getCheckOrDefault<scalar>
        (
            "frictionCoeff", 0, [](scalar mu){ return mu >= 0; }
        )
    );
    if (mu == 0)
    {
        if (dict.found("frictionModel"))
        {
            FatalIOErrorInFunction(dict)
                << "frictionModel " << dict.get<word>("frictionModel")
                << " without friction in " << dict.name() << nl
                << "    Set frictionCoeff > 0 or remove frictionModel"
                << exit(FatalIOError);
        }
        return nullptr;
    }

    const bool given = dict.found("frictionModel");
    const word modelType
    (
        given ? dict.get<word>("frictionModel") : word("velocityRegularised")
    );
    Info<< "fbm: collisions: friction model " << modelType
        << (given ? "" : " (default)") << nl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "frictionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<frictionModel>(cstrIter()(dict, planeMask, depth));
}


// ************************************************************************* //
