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

#include "bodyShape.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fbm::bodyShape> Foam::fbm::bodyShape::New
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    const word shapeType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(shapeType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "body shape",
            shapeType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<bodyShape>(cstrIter()(dict, mesh));
}


// ************************************************************************* //
