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
#include "fictitiousBoundary.H"
#include "surfaceFields.H"
#include "fvcGrad.H"
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
    const fictitiousBoundary& fb,
    const volVectorField& U,
    const volScalarField& p,
    const volScalarField& nuEff,
    List<vector>& force,
    List<vector>& torque
) const
{
    const fvMesh& mesh = fb.mesh();
    const PtrList<body>& bodies = fb.bodies();
    const scalar rhoFluid = fb.rhoFluid();

    const tensorField gradU(fvc::grad(U)().primitiveField());

    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const scalarField& w = mesh.weights().primitiveField();
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& C = mesh.C().primitiveField();
    const cellList& cellFaces = mesh.cells();
    const label nInternal = mesh.nInternalFaces();

    // Zero field of mesh size, returned zero
    scalarField& alphaB = fb.scratch();

    forAll(bodies, bi)
    {
        const body& b = bodies[bi];
        const labelList& cells = b.cells();

        forAll(cells, i)
        {
            alphaB[cells[i]] = b.alpha()[i];
        }

        vector F(Zero);
        vector T(Zero);

        for (const label celli : b.bandCells(mesh))
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
