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

#include "fictitiousBoundary.H"
#include "body.H"
#include "sumOverProcessors.H"
#include "fvMatrices.H"
#include "HashSet.H"
#include "Random.H"
#include "unitConversion.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::fictitiousBoundary::buildCellTree()
{
    // Cell bounding boxes, once
    const pointField& pts = mesh_.points();
    const labelListList& cellPts = mesh_.cellPoints();
    forAll(cellBb_, celli)
    {
        cellBb_[celli] = boundBox(pts, cellPts[celli], false);
    }

    // Cell octree as polyMesh::cellTree(), but caching the cell boxes. On
    // a one-cell-thick 2D mesh every octant split in the empty direction
    // would cut every cell, the duplicity limit would stop the refinement
    // early and leave leaves of thousands of cells: the tree's box is
    // stretched in that direction (2^maxLevel times the mesh depth, the
    // mesh at its low end) so that the mesh stays in one octant at every
    // level.
    const label maxLevel = 10;
    treeBoundBox overallBb(pts);
    Random rndGen(261782);
    overallBb = overallBb.extend(rndGen, 1e-4);
    overallBb.min() -= point::uniform(ROOTVSMALL);
    overallBb.max() += point::uniform(ROOTVSMALL);

    const Vector<label>& sd = mesh_.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0)
        {
            overallBb.max()[d] = overallBb.min()[d]
              + pow(2.0, scalar(maxLevel + 1))*overallBb.span()[d];
        }
    }

    cellTree_.reset
    (
        new indexedOctree<treeDataCell>
        (
            treeDataCell(true, mesh_, polyMesh::CELL_TETS),
            overallBb,
            maxLevel,
            10,             // leafsize
            5.0             // duplicity
        )
    );
}


Foam::tmp<Foam::scalarField> Foam::fbm::fictitiousBoundary::serialDiagonal
(
    const fvMatrix<vector>& UEqn
) const
{
    // Faces on coupled patches (processor, cyclic) keep their
    // coefficients in internalCoeffs, not in diag: added once per call,
    // patch by patch
    tmp<scalarField> tdiag(new scalarField(UEqn.diag()));
    scalarField& diag = tdiag.ref();

    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    forAll(patches, patchi)
    {
        if (!patches[patchi].coupled()) continue;

        const labelUList& faceCells = patches[patchi].faceCells();
        const Field<vector>& ic = UEqn.internalCoeffs()[patchi];
        forAll(faceCells, i)
        {
            diag[faceCells[i]] += ic[i].component(0);
        }
    }
    return tdiag;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::fictitiousBoundary::fictitiousBoundary
(
    const fvMesh& mesh,
    const dictionary& dict,
    PtrList<body>& bodies
)
:
    mesh_(mesh),
    bodies_(bodies),
    nSubdivision_
    (
        dict.getCheckOrDefault<label>
        (
            "nSubdivision", 4, [](label n){ return n >= 0 && n <= 10; }
        )
    ),
    coupled_
    (
        returnReduce
        (
            [&mesh]()
            {
                for (const polyPatch& pp : mesh.boundaryMesh())
                {
                    if (pp.coupled()) return true;
                }
                return false;
            }(),
            orOp<bool>()
        )
    ),
    forcing_(velocityForcing::New(mesh, dict, coupled_)),
    cellBb_(mesh.nCells()),
    cellTree_(),
    alpha_
    (
        IOobject
        (
            "alpha.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    Us_
    (
        IOobject
        (
            "U.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    bodyID_
    (
        IOobject
        (
            "bodyID",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("bodyID", dimless, -1)
    ),
    activeCells_(),
    lambda_(mesh.nCells(), Zero)
{
    buildCellTree();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarList Foam::fbm::fictitiousBoundary::coveredVolumes() const
{
    scalarList vol(bodies_.size());
    forAll(bodies_, bi)
    {
        vol[bi] = bodies_[bi].localCoveredVolume(mesh_);
    }
    sumOverProcessors(vol);
    return vol;
}


Foam::scalarList Foam::fbm::fictitiousBoundary::smallestCellSizes() const
{
    const Vector<label>& solD = mesh_.solutionD();

    scalarList h(bodies_.size(), VGREAT);
    forAll(bodies_, bi)
    {
        for (const label celli : bodies_[bi].cells())
        {
            const vector span(cellBb_[celli].span());
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (solD[d] > 0)
                {
                    h[bi] = min(h[bi], span[d]);
                }
            }
        }
    }
    Pstream::listCombineGather(h, minEqOp<scalar>());
    Pstream::listCombineScatter(h);
    return h;
}


Foam::scalar Foam::fbm::fictitiousBoundary::largestCellSize() const
{
    const Vector<label>& sd = mesh_.solutionD();
    scalar h = 0;
    for (const boundBox& bb : cellBb_)
    {
        const vector span(bb.span());
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (sd[d] > 0) h = max(h, span[d]);
        }
    }
    reduce(h, maxOp<scalar>());
    return h;
}


Foam::scalar Foam::fbm::fictitiousBoundary::volumeTolerance
(
    const body& b,
    const scalar hMax
) const
{
    const scalar delta = hMax/pow(2.0, scalar(nSubdivision_));
    return max(1e-3, sqr(delta/b.shape().radius()));
}


bool Foam::fbm::fictitiousBoundary::surfaceInside
(
    const body& b,
    point& outside
) const
{
    const bodyShape& shape = b.shape();
    if (!shape.hasSupport())
    {
        return true;
    }

    // The directions: in 2D every degree in the solution plane (e1, e2);
    // in 3D the six axes and a Fibonacci spiral of 400 over the sphere
    const Vector<label>& sd = mesh_.solutionD();
    DynamicList<vector> dirs;
    if (mesh_.nSolutionD() == 2)
    {
        vector e[2] = {Zero, Zero};
        label k = 0;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (sd[d] > 0) e[k++][d] = 1;
        }
        for (label i = 0; i < 360; ++i)
        {
            const scalar phi = degToRad(scalar(i));
            dirs.append(cos(phi)*e[0] + sin(phi)*e[1]);
        }
    }
    else
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            vector e(Zero);
            e[d] = 1;
            dirs.append(e);
            dirs.append(-e);
        }
        const label n = 400;
        const scalar golden = constant::mathematical::pi*(3 - sqrt(5.0));
        for (label i = 0; i < n; ++i)
        {
            const scalar z = 1 - (2*i + 1)/scalar(n);
            const scalar rho = sqrt(max(scalar(0), 1 - z*z));
            dirs.append(vector(rho*cos(golden*i), rho*sin(golden*i), z));
        }
    }

    // The cell search (body::findCell) uses the tet decomposition, built
    // collectively: every processor comes here for the same bodies
    (void)mesh_.tetBasePtIs();
    const point& X = b.centre();
    pointField pts(dirs.size());
    boolList found(dirs.size(), false);
    forAll(dirs, i)
    {
        pts[i] = X + (1 - 1e-6)*shape.support(shape.orientation(), dirs[i]);
        found[i] = body::findCell(mesh_, *cellTree_, pts[i]) >= 0;
    }
    Pstream::listCombineGather(found, orEqOp<bool>());
    Pstream::listCombineScatter(found);

    forAll(found, i)
    {
        if (!found[i])
        {
            outside = pts[i];
            return false;
        }
    }
    return true;
}


void Foam::fbm::fictitiousBoundary::update()
{
    // Clear the previous footprint
    scalarField& alpha = alpha_.primitiveFieldRef();
    vectorField& Us = Us_.primitiveFieldRef();
    scalarField& id = bodyID_.primitiveFieldRef();
    forcing_->clear(activeCells_);
    for (const label celli : activeCells_)
    {
        alpha[celli] = 0;
        Us[celli] = Zero;
        id[celli] = -1;
        lambda_[celli] = 0;
    }

    labelHashSet active;

    forAll(bodies_, bi)
    {
        body& b = bodies_[bi];
        b.updateCells(mesh_, *cellTree_, cellBb_, nSubdivision_);

        // The forcing marks the body's cells against the fractions of the
        // bodies before it
        forcing_->mark(b, bi, alpha, Us, id, active);

        const labelList& cells = b.cells();
        const scalarList& a = b.alpha();
        forAll(cells, i)
        {
            alpha[cells[i]] = min(alpha[cells[i]] + a[i], scalar(1));
        }
    }

    forcing_->markCoupled(bodies_, Us, id, active);

    activeCells_ = active.sortedToc();

    alpha_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();
    bodyID_.correctBoundaryConditions();
}


void Foam::fbm::fictitiousBoundary::updateVelocity()
{
    vectorField& Us = Us_.primitiveFieldRef();
    const scalarField& id = bodyID_;
    const vectorField& C = mesh_.C();
    for (const label celli : activeCells_)
    {
        const label bi = label(id[celli]);
        if (bi >= 0)
        {
            Us[celli] = bodies_[bi].velocityAt(C[celli]);
        }
    }
    Us_.correctBoundaryConditions();
}


void Foam::fbm::fictitiousBoundary::constrain
(
    fvMatrix<vector>& UEqn,
    const boolList& penalised
) const
{
    scalarField& diag = UEqn.diag();
    vectorField& source = UEqn.source();
    const scalarField& alpha = alpha_;
    const vectorField& Us = Us_;
    const scalarField& id = bodyID_;

    // The diagonal a_P of a cell as in a serial run
    tmp<scalarField> tdiagCoupled;
    if (coupled_)
    {
        tdiagCoupled = serialDiagonal(UEqn);
    }
    const scalarField& aPs = coupled_ ? tdiagCoupled() : diag;

    for (const label celli : activeCells_)
    {
        const label bi = label(id[celli]);
        if (bi >= 0 && !penalised[bi])
        {
            // Left to the coupling model
            lambda_[celli] = 0;
            continue;
        }

        const scalar k =
            forcing_->penaltyFactor(UEqn, aPs, celli, alpha[celli]);
        lambda_[celli] = k*aPs[celli];

        diag[celli] += lambda_[celli];
        source[celli] += lambda_[celli]*Us[celli];
    }
}


// ************************************************************************* //
