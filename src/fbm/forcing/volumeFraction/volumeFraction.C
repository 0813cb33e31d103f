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

#include "volumeFraction.H"
#include "body.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace velocityForcings
{
    defineTypeNameAndDebug(volumeFraction, 0);
    addToRunTimeSelectionTable(velocityForcing, volumeFraction, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::velocityForcings::volumeFraction::volumeFraction
(
    const fvMesh& mesh,
    const dictionary& dict,
    const bool coupled
)
:
    velocityForcing(mesh, dict, coupled)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::velocityForcings::volumeFraction::mark
(
    const body& b,
    const label bi,
    const scalarField& alpha,
    vectorField& Us,
    scalarField& id,
    labelHashSet& active
)
{
    const vectorField& C = mesh_.C();
    const labelList& cells = b.cells();
    const scalarList& a = b.alpha();
    forAll(cells, i)
    {
        const label celli = cells[i];
        if (a[i] > alpha[celli])
        {
            Us[celli] = b.velocityAt(C[celli]);
            id[celli] = bi;
        }
        active.insert(celli);
    }
}


Foam::scalar Foam::fbm::velocityForcings::volumeFraction::penaltyFactor
(
    const fvMatrix<vector>& UEqn,
    const scalarField& aP,
    const label celli,
    const scalar alpha
) const
{
    return (alpha < 1) ? min(alpha/(1 - alpha), penaltyMax_) : penaltyMax_;
}


// ************************************************************************* //
