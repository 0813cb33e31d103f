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

#include "pressureAddedMass.H"
#include "fvMatrices.H"
#include "fvmLaplacian.H"
#include "fvcDiv.H"
#include "fvcFlux.H"
#include "fvcGrad.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "sumOverProcessors.H"
#include "correctCoupled.H"
#include "scratchField.H"


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::fbm::pressureAddedMass::modeVelocity
(
    const label j,
    const point& x
) const
{
    if (modeRotation_[j])
    {
        return modeDir_[j] ^ (x - centres_[modeBody_[j]]);
    }
    return modeDir_[j];
}


void Foam::fbm::pressureAddedMass::solveModes
(
    const volScalarField& p,
    const volScalarField& rAtU,
    const dictionary& solverDict,
    const label refCell,
    const scalar rhoFluid
)
{
    const label n = size();
    const vectorField& C = mesh_.C().primitiveField();

    // The mode pressures take the pressure's boundary conditions made
    // homogeneous: zero where it is fixed, zero gradient elsewhere (the
    // modes' flux through the boundary is zero), the constraint patches
    // (processor, cyclic, empty) as they are
    wordList types(p.boundaryField().size());
    forAll(types, patchi)
    {
        const fvPatchScalarField& pp = p.boundaryField()[patchi];
        if (polyPatch::constraintType(pp.patch().type()))
        {
            types[patchi] = pp.patch().type();
        }
        else if (pp.fixesValue())
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
        else
        {
            types[patchi] = zeroGradientFvPatchScalarField::typeName;
        }
    }

    B_.setSize(n);
    B_ = Zero;

    const word lapName("laplacian(" + rAtU.name() + ',' + p.name() + ')');
    for (label j = 0; j < n; ++j)
    {
        if (!modeSolved_[j])
        {
            continue;
        }
        volScalarField y
        (
            scratchField<scalar>
            (
                "fbmModePressure" + Foam::name(j), mesh_, p.dimensions(), types
            )
        );

        // The divergence of the mode's rigid velocity on its body's cells
        volVectorField wPhi
        (
            scratchField<vector>("fbmModeVelocity", mesh_, dimVelocity)
        );
        vectorField& wPhii = wPhi.primitiveFieldRef();
        forAll(cells_, i)
        {
            if (cellBody_[i] == modeBody_[j])
            {
                wPhii[cells_[i]] = weight_[i]*modeVelocity(j, C[cells_[i]]);
            }
        }
        correctCoupled(wPhi);

        fvScalarMatrix yEqn
        (
            fvm::laplacian(rAtU, y, lapName) == fvc::div(fvc::flux(wPhi))
        );
        if (p.needReference())
        {
            yEqn.setReference(refCell, 0);
        }
        yEqn.solve(solverDict);

        const scalarList gy(modeForces(y, rhoFluid));
        for (label i = 0; i < n; ++i)
        {
            if (modeSolved_[i])
            {
                B_(i, j) = gy[i];
            }
        }
    }

    solveIndex_ = mesh_.time().timeIndex();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::pressureAddedMass::pressureAddedMass(const fvMesh& mesh)
:
    mesh_(mesh),
    solveIndex_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::pressureAddedMass::setModes
(
    const boolList& free,
    const boolList& rotates,
    const boolList& isotropic,
    const List<point>& centres,
    const vector& planeMask,
    const vector& axisMask,
    const labelUList& cells,
    const labelUList& cellBody,
    const scalarUList& weight
)
{
    DynamicList<label> body;
    DynamicList<vector> dir;
    DynamicList<bool> rotation;
    DynamicList<bool> solved;

    // The modes of body bi along the directions of mask
    auto addModes = [&]
    (
        const label bi,
        const vector& mask,
        const bool rotate,
        const bool ownPressure
    )
    {
        for (Foam::direction d = 0; d < vector::nComponents; ++d)
        {
            if (mask[d] > 0)
            {
                vector e(Zero);
                e[d] = 1;
                body.append(bi);
                dir.append(e);
                rotation.append(rotate);
                solved.append(ownPressure);
            }
        }
    };
    forAll(free, bi)
    {
        if (!free[bi]) continue;
        addModes(bi, planeMask, false, true);
        if (rotates[bi])
        {
            addModes(bi, axisMask, true, !isotropic[bi]);
        }
    }

    modeBody_.transfer(body);
    modeDir_.transfer(dir);
    modeRotation_.transfer(rotation);
    modeSolved_.transfer(solved);
    centres_ = centres;
    cells_ = cells;
    cellBody_ = cellBody;
    weight_ = weight;
}


Foam::scalarList Foam::fbm::pressureAddedMass::modeForces
(
    const volScalarField& q,
    const scalar rhoFluid
) const
{
    const volVectorField gradQ(fvc::grad(q, "grad(p)"));
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V();

    scalarList g(size(), Zero);
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const vector f(-rhoFluid*weight_[i]*V[celli]*gradQ[celli]);
        forAll(modeBody_, j)
        {
            if (modeBody_[j] == cellBody_[i])
            {
                g[j] += modeVelocity(j, C[celli]) & f;
            }
        }
    }
    sumOverProcessors(g);
    return g;
}


Foam::vector Foam::fbm::pressureAddedMass::velocity
(
    const scalarList& a,
    const label i
) const
{
    const point& x = mesh_.C()[cells_[i]];
    vector u(Zero);
    forAll(modeBody_, j)
    {
        if (modeBody_[j] == cellBody_[i])
        {
            u += a[j]*modeVelocity(j, x);
        }
    }
    return u;
}


void Foam::fbm::pressureAddedMass::update
(
    const volScalarField& p,
    const volScalarField& rAtU,
    const dictionary& solverDict,
    const label refCell,
    const scalar rhoFluid,
    const label interval
)
{
    if
    (
        size()
     && (
            solveIndex_ < 0
         || B_.m() != size()
         || mesh_.time().timeIndex() - solveIndex_ >= interval
        )
    )
    {
        solveModes(p, rAtU, solverDict, refCell, rhoFluid);
    }
}


void Foam::fbm::pressureAddedMass::newtonStep
(
    const scalarList& g,
    const scalarSquareMatrix& G,
    scalarList& a
) const
{
    const label n = size();
    scalarSquareMatrix J(n, Zero);
    scalarList da(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        da[i] = -a[i];
        for (label k = 0; k < n; ++k)
        {
            da[i] += G(i, k)*g[k];
            scalar GB = 0;
            for (label l = 0; l < n; ++l)
            {
                GB += G(i, l)*B_(l, k);
            }
            J(i, k) = (i == k ? 1 : 0) - GB;
        }
    }
    Foam::solve(J, da);
    forAll(a, i)
    {
        a[i] += da[i];
    }
}


void Foam::fbm::pressureAddedMass::write(Ostream& os) const
{
    if (solveIndex_ < 0)
    {
        return;
    }
    os.writeEntry("addedMassIndex", solveIndex_);
    scalarList flat(B_.m()*B_.n());
    label k = 0;
    for (label i = 0; i < B_.m(); ++i)
    {
        for (label j = 0; j < B_.n(); ++j)
        {
            flat[k++] = B_(i, j);
        }
    }
    os.writeEntry("addedMassMatrix", flat);
}


void Foam::fbm::pressureAddedMass::read(const dictionary& bodyState)
{
    const label index = bodyState.get<label>("addedMassIndex");
    const scalarList flat(bodyState.get<scalarList>("addedMassMatrix"));
    const label n = label(Foam::sqrt(scalar(flat.size())) + 0.5);
    bool finite = true;
    for (const scalar b : flat)
    {
        finite = finite && std::isfinite(b);
    }
    if (index < 0 || n*n != flat.size() || !finite)
    {
        FatalIOErrorInFunction(bodyState)
            << "addedMassIndex " << index << " and addedMassMatrix (size "
            << flat.size() << ") in " << bodyState.name() << " are not a"
            << " time index and a finite square matrix"
            << exit(FatalIOError);
    }
    solveIndex_ = index;
    B_.setSize(n);
    label k = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            B_(i, j) = flat[k++];
        }
    }
}


// ************************************************************************* //
