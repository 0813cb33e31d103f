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

#include "bodyInertia.H"
#include "bodySystem.H"
#include "sumOverProcessors.H"
#include "fvMatrices.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The inertia tensor about the centre of a mass dm at r from it
inline Foam::symmTensor pointInertia
(
    const Foam::scalar dm,
    const Foam::vector& r
)
{
    return dm*(Foam::magSqr(r)*Foam::symmTensor::I - Foam::sqr(r));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyInertia::bodyInertia(const bodySystem& system)
:
    system_(system),
    shellMass_(system.bodies().size(), Zero),
    shellInertia_(system.bodies().size(), Zero),
    dampingMass_(system.bodies().size(), Zero),
    dampingInertia_(system.bodies().size(), Zero),
    nextDampingMass_(system.bodies().size(), Zero),
    nextDampingInertia_(system.bodies().size(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::bodyInertia::clear()
{
    shellMass_ = Zero;
    shellInertia_ = Zero;
    dampingMass_ = Zero;
    dampingInertia_ = Zero;
}


void Foam::fbm::bodyInertia::measureDamping
(
    const fvMatrix<vector>& UEqn,
    const boolList& selected
)
{
    // Within a step the penalty changes the body's velocity by dU and the
    // viscous stress of the faces from a cell of rigid share w_c to a
    // neighbour of smaller share w_n drags the fluid with it: the body's
    // force changes by -D dU, D = rho_f sum a_cn (w_c - w_n), a lagged
    // stiffness whose step dt D is advanced with the body from the next
    // step on
    const fictitiousBoundary& fb = system_.fb();
    const fvMesh& mesh = system_.mesh();
    const scalarField& lambda = fb.lambda();
    const scalarField& id = fb.bodyID();
    const scalarField& diag = UEqn.diag();
    const labelList& active = fb.activeCells();

    if (weightField_.size() != mesh.nCells())
    {
        weightField_.setSize(mesh.nCells());
        weightField_ = 0;
    }
    for (const label celli : active)
    {
        const label bi = label(id[celli]);
        if (bi >= 0 && selected[bi] && diag[celli] > 0)
        {
            weightField_[celli] = lambda[celli]/diag[celli];
        }
    }

    const PtrList<body>& bodies = system_.bodies();
    const vectorField& C = mesh.C().primitiveField();
    const labelUList& own = UEqn.lduAddr().lowerAddr();
    const labelUList& nei = UEqn.lduAddr().upperAddr();
    const scalarField& upper = UEqn.upper();
    const scalarField& lower = UEqn.lower();
    const cellList& cells = mesh.cells();
    const label nInternalFaces = mesh.nInternalFaces();
    const scalar rhoFluid = system_.rhoFluid();
    const scalar dt = mesh.time().deltaTValue();

    nextDampingMass_ = Zero;
    nextDampingInertia_ = Zero;
    for (const label celli : active)
    {
        const scalar wc = weightField_[celli];
        if (wc <= 0) continue;

        const label bi = label(id[celli]);
        scalar g = 0;
        for (const label facei : cells[celli])
        {
            if (facei >= nInternalFaces) continue;
            const bool isOwner = (own[facei] == celli);
            const label other = isOwner ? nei[facei] : own[facei];
            const scalar a = -(isOwner ? upper[facei] : lower[facei]);
            const scalar dw = wc - weightField_[other];
            if (a > 0 && dw > 0)
            {
                g += a*dw;
            }
        }
        const scalar dm = dt*rhoFluid*g;
        nextDampingMass_[bi] += dm;
        nextDampingInertia_[bi] +=
            pointInertia(dm, C[celli] - bodies[bi].centre());
    }
    for (const label celli : active)
    {
        weightField_[celli] = 0;
    }

    sumOverProcessors(nextDampingMass_);
    sumOverProcessors(nextDampingInertia_);
}


void Foam::fbm::bodyInertia::update
(
    const labelUList& cells,
    const UList<scalar>& weight
)
{
    const PtrList<body>& bodies = system_.bodies();
    const vectorField& C = system_.mesh().C().primitiveField();
    const scalarField& V = system_.mesh().V();
    const scalarField& id = system_.fb().bodyID();
    const scalarField& alpha = system_.fb().alpha();
    const scalar rhoFluid = system_.rhoFluid();

    shellMass_ = Zero;
    shellInertia_ = Zero;
    forAll(cells, i)
    {
        const label celli = cells[i];
        const label bi = label(id[celli]);
        const scalar dm =
            rhoFluid*max(weight[i] - alpha[celli], scalar(0))*V[celli];
        shellMass_[bi] += dm;
        shellInertia_[bi] += pointInertia(dm, C[celli] - bodies[bi].centre());
    }
    sumOverProcessors(shellMass_);
    sumOverProcessors(shellInertia_);

    dampingMass_ = nextDampingMass_;
    dampingInertia_ = nextDampingInertia_;
}


void Foam::fbm::bodyInertia::read
(
    const label bi,
    const dictionary& bodyState
)
{
    shellMass_[bi] = bodyState.getCheck<scalar>
    (
        "shellMass", [](scalar m){ return m >= 0; }
    );
    shellInertia_[bi] = bodyState.get<symmTensor>("shellInertia");
    dampingMass_[bi] = bodyState.getCheck<scalar>
    (
        "dampingMass", [](scalar m){ return m >= 0; }
    );
    dampingInertia_[bi] = bodyState.get<symmTensor>("dampingInertia");
}


void Foam::fbm::bodyInertia::write(const label bi, Ostream& os) const
{
    os.writeEntry("shellMass", shellMass_[bi]);
    os.writeEntry("shellInertia", shellInertia_[bi]);
    os.writeEntry("dampingMass", dampingMass_[bi]);
    os.writeEntry("dampingInertia", dampingInertia_[bi]);
}


// ************************************************************************* //
