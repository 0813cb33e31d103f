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

#include "newton.H"
#include "semiImplicit.H"
#include "bodySystem.H"
#include "sumOverProcessors.H"
#include "fvMatrices.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace pressureSteps
{
    defineTypeNameAndDebug(newton, 0);
    addToRunTimeSelectionTable(pressureStep, newton, dictionary);
}
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::pressureSteps::newton::selectRigid(const labelUList& cells)
{
    const fvMesh& mesh = system_.mesh();
    if (wallCell_.size() != mesh.nCells())
    {
        wallCell_.setSize(mesh.nCells());
        wallCell_ = false;
        for (const fvPatch& patch : mesh.boundary())
        {
            if (patch.type() == "wall")
            {
                for (const label celli : patch.faceCells())
                {
                    wallCell_[celli] = true;
                }
            }
        }
    }

    // A body whose footprint reaches a cell of a wall: with no fluid cell
    // left in the gap the rigid constraint and the lagged part of the
    // force disagree by the whole lubrication pressure (the settling disk
    // ran away at the wall, at a gap of 0.02-0.3 cells), so it takes the
    // iterated pressure step there
    const PtrList<body>& bodies = system_.bodies();
    const scalarField& id = system_.fb().bodyID();
    const boolList& heavy = coupling_.heavy();
    scalarList touching(bodies.size(), Zero);
    for (const label celli : cells)
    {
        if (wallCell_[celli])
        {
            touching[label(id[celli])] = 1;
        }
    }
    sumOverProcessors(touching);
    const boolList last(rigid_);
    rigid_.setSize(bodies.size());
    forAll(bodies, bi)
    {
        rigid_[bi] = heavy[bi] && touching[bi] == 0;
        if (heavy[bi] && last.size() == rigid_.size() && last[bi] != rigid_[bi])
        {
            Info<< "fbm: coupling " << coupling_.type() << ": body "
                << bodies[bi].name()
                << (rigid_[bi] ? " is clear of the walls again: newton"
                               : " reaches a cell of a wall: iterated")
                << " pressure step" << nl;
        }
    }
}


void Foam::fbm::pressureSteps::newton::setModes
(
    const labelUList& cells,
    const scalarUList& weight
)
{
    const PtrList<body>& bodies = system_.bodies();
    const scalarField& id = system_.fb().bodyID();
    boolList rotates(bodies.size()), isotropic(bodies.size());
    List<point> centres(bodies.size());
    forAll(bodies, bi)
    {
        rotates[bi] = bodies[bi].rotates();
        isotropic[bi] = bodies[bi].shape().isotropic();
        centres[bi] = bodies[bi].centre();
    }
    labelList cellBody(cells.size());
    forAll(cells, i)
    {
        cellBody[i] = label(id[cells[i]]);
    }
    addedMass_.setModes
    (
        rigid_, rotates, isotropic, centres,
        coupling_.planeMask(), coupling_.axisMask(),
        cells, cellBody, weight
    );
}


Foam::scalarSquareMatrix
Foam::fbm::pressureSteps::newton::mobility() const
{
    const label n = addedMass_.size();
    const PtrList<body>& bodies = system_.bodies();
    const scalar dt = system_.mesh().time().deltaTValue();
    scalarSquareMatrix G(n, Zero);
    for (label k = 0; k < n; ++k)
    {
        const label bi = addedMass_.body(k);
        const vector& ek = addedMass_.direction(k);
        const vector dU
        (
            addedMass_.rotation(k)
          ? coupling_.angularImpulse(bi, dt*ek)
          : coupling_.rigidImpulse(bi, ek, Zero, bodies[bi].centre())
        );
        for (label i = 0; i < n; ++i)
        {
            if
            (
                addedMass_.body(i) == bi
             && addedMass_.rotation(i) == addedMass_.rotation(k)
            )
            {
                G(i, k) = addedMass_.direction(i) & dU;
            }
        }
    }
    return G;
}


Foam::scalarList Foam::fbm::pressureSteps::newton::modeForces
(
    const List<vector>& P,
    const List<vector>& Q
) const
{
    scalarList g(addedMass_.size());
    forAll(g, j)
    {
        const label bi = addedMass_.body(j);
        g[j] =
            addedMass_.direction(j)
          & (addedMass_.rotation(j) ? Q[bi] : P[bi]);
    }
    return g;
}


void Foam::fbm::pressureSteps::newton::forcesOfVelocities
(
    const scalarSquareMatrix& mobility,
    const scalarList& a,
    List<vector>& P,
    List<vector>& Q
) const
{
    scalarSquareMatrix G(mobility);
    scalarList g(a);
    Foam::solve(G, g);
    forAll(g, j)
    {
        const label bi = addedMass_.body(j);
        const vector& e = addedMass_.direction(j);
        vector& f = addedMass_.rotation(j) ? Q[bi] : P[bi];
        f += (g[j] - (e & f))*e;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::pressureSteps::newton::newton
(
    const dictionary& coeffs,
    const couplingModels::semiImplicit& coupling,
    const bodySystem& system
)
:
    pressureStep(coupling, system),
    addedMass_(system.mesh()),
    addedMassInterval_
    (
        coeffs.getOrDefault<label>("addedMassInterval", 10, keyType::LITERAL)
    ),
    corrector_(0)
{
    // One Newton step per pressure solve
    const dictionary& pimpleDict =
        system.mesh().solutionDict().subDict("PIMPLE");
    if (pimpleDict.getOrDefault<label>("nNonOrthogonalCorrectors", 0))
    {
        FatalIOErrorInFunction(pimpleDict)
            << "pressureSolve " << typeName << " in " << coeffs.name()
            << " does not support nNonOrthogonalCorrectors > 0 in "
            << pimpleDict.name() << exit(FatalIOError);
    }
    if (addedMassInterval_ < 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "addedMassInterval " << addedMassInterval_ << " in "
            << coeffs.name() << " is below 1" << exit(FatalIOError);
    }
    Info<< "fbm: coupling " << coupling.type() << ": addedMassInterval "
        << addedMassInterval_
        << (coeffs.found("addedMassInterval", keyType::LITERAL)
            ? "" : " (default)") << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::pressureSteps::newton::correct
(
    const bool newStep,
    const labelUList& cells,
    const scalarUList& weight,
    const List<vector>& P,
    const List<vector>& Q
)
{
    if (newStep)
    {
        selectRigid(cells);
        corrector_ = 0;
    }
    ++corrector_;
    setModes(cells, weight);
    if (newStep)
    {
        // The first estimate: the rigid velocity of the last step's force
        modeVelocity_ =
            addedMass_.size() ? mobility()*modeForces(P, Q) : scalarList();
    }
}


void Foam::fbm::pressureSteps::newton::solve
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
    // The pressure with the bodies' cells at the present estimate
    pEqn.solve(solverDict);
    if (!addedMass_.size())
    {
        return;
    }

    // One Newton step of the estimate, with the added mass of the
    // pressure operator (solved again every addedMassInterval steps)
    addedMass_.update
    (
        p, rAtU, solverDict, refCell, system_.rhoFluid(),
        addedMassInterval_
    );
    fluxModeVelocity_ = modeVelocity_;
    const scalarSquareMatrix G(mobility());
    addedMass_.newtonStep
    (
        addedMass_.modeForces(p, system_.rhoFluid()), G, modeVelocity_
    );
    if (couplingModels::semiImplicit::debug)
    {
        // How far this corrector's Newton step moved the estimate: the
        // convergence of the fixed point over the correctors
        scalar change = 0, size = 0;
        forAll(modeVelocity_, j)
        {
            change += sqr(modeVelocity_[j] - fluxModeVelocity_[j]);
            size += sqr(modeVelocity_[j]);
        }
        Info<< "fbm: semiImplicit: newton step " << corrector_
            << " changed the bodies' rigid velocity estimate by "
            << (size > 0 ? Foam::sqrt(change/size) : scalar(0))
            << " (relative)" << endl;
    }

    // The force whose rigid velocity the flux took (the bodies of the
    // iterated step keep theirs)
    forcesOfVelocities(G, fluxModeVelocity_, P, Q);
}


void Foam::fbm::pressureSteps::newton::stepForces
(
    List<vector>& P,
    List<vector>& Q
) const
{
    if (addedMass_.size())
    {
        forcesOfVelocities(mobility(), modeVelocity_, P, Q);
    }
}


void Foam::fbm::pressureSteps::newton::readState(const dictionary& state)
{
    // The added mass and the step it was solved in (the same for every
    // body)
    if (coupling_.stateHasEntry(state, "addedMassMatrix"))
    {
        addedMass_.read(state.subDict(system_.bodies()[0].name()));
    }
}


// ************************************************************************* //
