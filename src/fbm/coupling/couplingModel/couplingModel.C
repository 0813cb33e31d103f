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
#include "bodySystem.H"
#include "fvMatrices.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(couplingModel, 0);
    defineRunTimeSelectionTable(couplingModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::couplingModel::couplingModel
(
    const dictionary& dict,
    bodySystem& system
)
:
    dict_(dict),
    system_(system),
    penalised_(system.bodies().size(), true)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::fbm::couplingModel::rejectContactProjection() const
{
    if (dict_.getOrDefault<bool>("projectContacts", false))
    {
        FatalIOErrorInFunction(dict_)
            << "projectContacts yes with coupling " << type() << " in "
            << dict_.name() << nl
            << "    The contact forces go into the flow solve of coupling"
            << " rigidProjection only: remove projectContacts or set it to"
            << " no" << exit(FatalIOError);
    }
    if (dict_.found("contactRelaxation"))
    {
        dict_.getCheck<scalar>
        (
            "contactRelaxation", [](scalar b){ return b > 0 && b <= 1; }
        );
        FatalIOErrorInFunction(dict_)
            << "contactRelaxation without projectContacts in "
            << dict_.name() << nl
            << "    It relaxes the contact forces that projectContacts puts"
            << " into the flow solve of coupling rigidProjection: remove it"
            << exit(FatalIOError);
    }
}


void Foam::fbm::couplingModel::requireEuler(const string& why) const
{
    const fvMesh& mesh = system_.mesh();
    const word ddtU(mesh.ddtScheme("ddt(U)")[0].wordToken());
    if (system_.anyMoves() && ddtU != "Euler")
    {
        FatalIOErrorInFunction(mesh.schemesDict().subDict("ddtSchemes"))
            << "coupling " << type() << " (" << dict_.name() << ")"
            << " needs ddtSchemes Euler for ddt(U), not " << ddtU << nl
            << "    " << why.c_str() << exit(FatalIOError);
    }
}


void Foam::fbm::couplingModel::rejectAddedMassCoeff() const
{
    const scalar Ca = dict_.getCheckOrDefault<scalar>
    (
        "addedMassCoeff", 0, [](scalar c){ return c >= 0; }
    );
    if (Ca != 0)
    {
        FatalIOErrorInFunction(dict_)
            << "addedMassCoeff " << Ca << " with coupling " << type()
            << " in " << dict_.name() << nl
            << "    This coupling carries the added mass in the flow solve;"
            << " addedMassCoeff is for the explicit coupling only: remove it"
            << " or set it to 0" << exit(FatalIOError);
    }
}


void Foam::fbm::couplingModel::holdForces
(
    const List<vector>& force,
    const List<vector>& torque
) const
{
    PtrList<body>& bodies = system_.bodies();
    forAll(bodies, bi)
    {
        bodies[bi].setForce(force[bi], torque[bi]);
    }
}


bool Foam::fbm::couplingModel::stateHasEntry
(
    const dictionary& state,
    const word& key
) const
{
    const PtrList<body>& bodies = system_.bodies();
    label nFound = 0;
    for (const body& b : bodies)
    {
        if (state.subDict(b.name()).found(key)) ++nFound;
    }
    if (nFound && nFound != bodies.size())
    {
        FatalIOErrorInFunction(state)
            << key << " given for " << nFound << " of the "
            << bodies.size() << " bodies in " << state.name()
            << nl << "    Give it for every body or for none"
            << exit(FatalIOError);
    }
    return nFound > 0;
}


void Foam::fbm::couplingModel::solvePressure
(
    fvScalarMatrix& pEqn,
    volScalarField& p,
    const volScalarField& rAtU,
    const dictionary& solverDict,
    const label refCell
)
{
    pEqn.solve(solverDict);
}


// ************************************************************************* //
