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

#include "volumeIntegral.H"
#include "footprint.H"
#include "body.H"
#include "surfaceFields.H"
#include "fvcGrad.H"
#include "bitSet.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace forceModels
{
    defineTypeNameAndDebug(volumeIntegral, 0);
    addToRunTimeSelectionTable(forceModel, volumeIntegral, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::forceModels::volumeIntegral::volumeIntegral(const dictionary& dict)
:
    forceModel(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::forceModels::volumeIntegral::calcForces
(
    const footprint& fp,
    const volVectorField& U,
    const volScalarField& p,
    const volScalarField& nuEff,
    List<vector>& force,
    List<vector>& torque
) const
{
    const fvMesh& mesh = fp.mesh();
    const PtrList<body>& bodies = fp.bodies();
    const scalar rhoFluid = fp.rhoFluid();

    const tensorField gradU(fvc::grad(U)().primitiveField());

    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const scalarField& w = mesh.weights().primitiveField();
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& C = mesh.C().primitiveField();
    const cellList& cellFaces = mesh.cells();
    const label nInternal = mesh.nInternalFaces();

    // Zero field of mesh size, returned zero
    // This body's fraction in every cell (zero outside its covered cells;
    // kept zero between calls)
    scalarField& alphaB = alphaB_;
    if (alphaB.size() != mesh.nCells())
    {
        alphaB.setSize(mesh.nCells(), Zero);
    }

    // Coupled (processor, cyclic) faces, only where the mesh has them: the
    // other side's solid fraction and body index from the evaluated patch
    // fields of alpha.solid and bodyID, the interpolation weight, and the
    // cells on this side next to each body's cells on the other side.
    // Elsewhere on the boundary alpha has zero gradient.
    bool coupled = false;
    for (const fvPatch& pp : mesh.boundary())
    {
        if (pp.coupled()) coupled = true;
    }

    const label nBFaces = coupled ? mesh.nFaces() - nInternal : 0;
    scalarField nbrAlpha(nBFaces, Zero);
    labelList nbrBody(nBFaces, -1);
    scalarField wB(nBFaces, scalar(1));
    bitSet onCoupled(coupled ? mesh.nCells() : 0);
    HashTable<DynamicList<label>, label, Hash<label>> nbrCells;
    if (coupled)
    {
        const volScalarField& alpha = fp.alpha();
        const volScalarField& id = fp.bodyID();
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& pp = mesh.boundary()[patchi];
            if (!pp.coupled()) continue;

            const scalarField a
            (
                alpha.boundaryField()[patchi].patchNeighbourField()
            );
            const scalarField n
            (
                id.boundaryField()[patchi].patchNeighbourField()
            );
            const scalarField& pw = mesh.weights().boundaryField()[patchi];
            const labelUList& faceCells = pp.faceCells();
            forAll(pp, i)
            {
                const label bFacei = pp.start() + i - nInternal;
                wB[bFacei] = pw[i];
                onCoupled.set(faceCells[i]);
                if (n[i] >= 0 && a[i] > 0)
                {
                    nbrAlpha[bFacei] = a[i];
                    nbrBody[bFacei] = label(n[i]);
                    nbrCells(nbrBody[bFacei]).append(faceCells[i]);
                }
            }
        }
    }

    forAll(bodies, bi)
    {
        const body& b = bodies[bi];
        const labelList& cells = b.cells();

        forAll(cells, i)
        {
            alphaB[cells[i]] = b.alpha()[i];
        }

        // The band, with the cells where grad(alpha) has a part from the
        // other side of a coupled face
        labelList extended;
        if (coupled)
        {
            labelHashSet all(b.bandCells(mesh));
            for (const label celli : cells)
            {
                if (onCoupled.test(celli)) all.insert(celli);
            }
            const auto iter = nbrCells.cfind(bi);
            if (iter.found())
            {
                all.insert(iter.val());
            }
            extended = all.sortedToc();
        }
        const labelList& band = coupled ? extended : b.bandCells(mesh);

        vector F(Zero);
        vector T(Zero);

        for (const label celli : band)
        {
            // Gauss gradient of this body's alpha times the cell volume
            vector gradAlphaV(Zero);
            for (const label facei : cellFaces[celli])
            {
                if (facei < nInternal)
                {
                    const scalar af =
                        w[facei]*alphaB[own[facei]]
                      + (1 - w[facei])*alphaB[nei[facei]];
                    gradAlphaV += (own[facei] == celli ? af : -af)*Sf[facei];
                }
                else if (coupled)
                {
                    // Coupled faces interpolate with the other side; the
                    // rest (weight 1, no neighbour) have zero gradient
                    const label bFacei = facei - nInternal;
                    const scalar af =
                        wB[bFacei]*alphaB[celli]
                      + (
                            nbrBody[bFacei] == bi
                          ? (1 - wB[bFacei])*nbrAlpha[bFacei]
                          : 0
                        );
                    gradAlphaV += af*Sf[facei];
                }
                else
                {
                    // Boundary faces: zero gradient
                    gradAlphaV += alphaB[celli]*Sf[facei];
                }
            }

            if (magSqr(gradAlphaV) == 0)
            {
                continue;
            }

            const tensor& gU = gradU[celli];
            const tensor sigma
            (
                rhoFluid
               *(-p[celli]*tensor::I + nuEff[celli]*(gU + gU.T()))
            );

            const vector f(-(sigma & gradAlphaV));
            F += f;
            T += (C[celli] - b.centre()) ^ f;
        }

        forAll(cells, i)
        {
            alphaB[cells[i]] = 0;
        }

        force[bi] = F;
        torque[bi] = T;
    }
}


// ************************************************************************* //
