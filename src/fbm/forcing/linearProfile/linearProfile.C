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

#include "linearProfile.H"
#include "body.H"
#include "fvMatrices.H"
#include "syncTools.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace velocityForcings
{
    defineTypeNameAndDebug(linearProfile, 0);
    addToRunTimeSelectionTable(velocityForcing, linearProfile, dictionary);
}
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fbm::velocityForcings::linearProfile::insideWeight
(
    const fvMatrix<vector>& UEqn,
    const label celli
) const
{
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const scalarField& upper = UEqn.upper();
    const scalarField& lower = UEqn.lower();

    scalar S = 0;
    for (const label facei : mesh_.cells()[celli])
    {
        if (facei < nInternal)
        {
            const bool isOwner = (own[facei] == celli);
            const label nbr = isOwner ? nei[facei] : own[facei];
            if (distance_[nbr] <= 0)
            {
                const scalar aN = -(isOwner ? upper[facei] : lower[facei]);
                S += max(aN, scalar(0))*(-distance_[nbr]);
            }
        }
        else if (coupled_)
        {
            // The neighbour on the other side of a coupled face: its
            // coefficient is in boundaryCoeffs
            const label patchi = patches.whichPatch(facei);
            const scalar dN = nbrDistance_[facei - nInternal];
            if (patches[patchi].coupled() && dN <= 0)
            {
                const scalar aN = UEqn.boundaryCoeffs()[patchi]
                    [facei - patches[patchi].start()].component(0);
                S += max(aN, scalar(0))*(-dN);
            }
        }
    }
    return S;
}


void Foam::fbm::velocityForcings::linearProfile::markNearer
(
    const body& b,
    const label bi,
    const label celli,
    const scalar d,
    vectorField& Us,
    scalarField& id,
    labelHashSet& active
)
{
    if (d < distance_[celli])
    {
        distance_[celli] = d;
        Us[celli] = b.velocityAt(mesh_.C()[celli]);
        id[celli] = bi;
    }
    active.insert(celli);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::velocityForcings::linearProfile::linearProfile
(
    const fvMesh& mesh,
    const dictionary& dict,
    const bool coupled
)
:
    velocityForcing(mesh, dict, coupled),
    distance_(mesh.nCells(), GREAT),
    nbrDistance_(mesh.nFaces() - mesh.nInternalFaces(), GREAT)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::velocityForcings::linearProfile::clear
(
    const labelUList& activeCells
)
{
    for (const label celli : activeCells)
    {
        distance_[celli] = GREAT;
    }
}


void Foam::fbm::velocityForcings::linearProfile::mark
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
    const labelListList& cellCells = mesh_.cellCells();
    const bodyShape& shape = b.shape();

    // Cells with the centre inside and their face neighbours; the nearest
    // surface gives u_s
    for (const label celli : b.cells())
    {
        const scalar d = shape.signedDistance(C[celli] - b.centre());
        if (d <= 0)
        {
            markNearer(b, bi, celli, d, Us, id, active);
            for (const label nbr : cellCells[celli])
            {
                markNearer
                (
                    b, bi, nbr, shape.signedDistance(C[nbr] - b.centre()),
                    Us, id, active
                );
            }
        }
    }
}


void Foam::fbm::velocityForcings::linearProfile::markCoupled
(
    const PtrList<body>& bodies,
    vectorField& Us,
    scalarField& id,
    labelHashSet& active
)
{
    if (!coupled_)
    {
        return;
    }

    // Face neighbours across coupled (processor, cyclic) patches of inside
    // cells: this side knows them from the other side's distance and body
    // index
    const vectorField& C = mesh_.C();
    scalarField nbrId;
    syncTools::swapBoundaryCellList(mesh_, distance_, nbrDistance_);
    syncTools::swapBoundaryCellList(mesh_, id, nbrId);

    const label nInternal = mesh_.nInternalFaces();
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled()) continue;

        const labelUList& faceCells = pp.faceCells();
        forAll(faceCells, i)
        {
            const label bFacei = pp.start() + i - nInternal;
            if (nbrDistance_[bFacei] > 0) continue;

            const label celli = faceCells[i];
            const label bj = label(nbrId[bFacei]);
            const body& b = bodies[bj];
            markNearer
            (
                b, bj, celli, b.shape().signedDistance(C[celli] - b.centre()),
                Us, id, active
            );
        }
    }
}


Foam::scalar Foam::fbm::velocityForcings::linearProfile::penaltyFactor
(
    const fvMatrix<vector>& UEqn,
    const scalarField& aP,
    const label celli,
    const scalar alpha
) const
{
    if (distance_[celli] > 0)
    {
        // S/d for a fluid cell beside inside cells
        const scalar S = insideWeight(UEqn, celli)/aP[celli];
        return (S > 0) ? min(S/distance_[celli], penaltyMax_) : 0;
    }
    return penaltyMax_;
}


// ************************************************************************* //
