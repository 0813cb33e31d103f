/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

Application
    Test-velocityForcing

Description
    The rigid-body velocity imposition on a momentum matrix
    (fictitiousBoundary::constrain) for a moving, rotating body: one implicit
    step of ddt(U) - laplacian(nu, U) = 0 from rest, solved to round-off.
    - forcing volumeFraction: cells inside (alpha = 1) take
      u_s = U + w x (x - X) to 1/penaltyMax; cut cells the blend
      u = alpha u_s + (1 - alpha) u_f, u_f = H/A of the matrix without the
      forcing evaluated at the solution, to solver round-off;
    - forcing linearProfile: cells whose centre is inside take u_s; a fluid
      cell at distance d with inside face neighbours the blend with
      w = S/(d + S), S = sum a_N |d_N| / a_P, computed here from the
      geometry and the unforced matrix.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bodySystem.H"
#include "fbmTest.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    fbm::bodySystem fb(mesh);
    const fbm::body& b = fb.bodies()[0];

    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    );
    const dimensionedScalar nu("nu", sqr(dimLength)/dimTime, 0.05);

    runTime++;

    fvVectorMatrix UEqn0(fvm::ddt(U) - fvm::laplacian(nu, U));
    fvVectorMatrix UEqn(UEqn0);
    fb.constrain(UEqn);
    UEqn.solve();

    const scalarField& alpha = fb.fb().alpha();
    const vectorField& Us = fb.fb().Us();
    const vectorField uf
    (
        UEqn0.H()().primitiveField()/UEqn0.A()().primitiveField()
    );
    const bool linear =
        (fb.fb().forcing().type() == "linearProfile");

    // Expected weight of the blend in a cell
    const lduMatrix& m0 = UEqn0;
    auto dist = [&](const label celli)
    {
        return b.shape().signedDistance(mesh.C()[celli] - b.centre());
    };
    auto weight = [&](const label celli) -> scalar
    {
        if (!linear)
        {
            return alpha[celli];
        }
        const scalar d = dist(celli);
        if (d <= 0)
        {
            return 1;
        }
        scalar S = 0;
        for (const label facei : mesh.cells()[celli])
        {
            if (facei >= mesh.nInternalFaces()) continue;
            const bool isOwner = (mesh.faceOwner()[facei] == celli);
            const label nbr =
                isOwner
              ? mesh.faceNeighbour()[facei]
              : mesh.faceOwner()[facei];
            if (dist(nbr) <= 0)
            {
                const scalar aN =
                    -(isOwner ? m0.upper()[facei] : m0.lower()[facei]);
                S += aN*(-dist(nbr));
            }
        }
        S /= m0.diag()[celli];
        return S/(d + S);
    };

    scalar maxUs = 0;
    scalar errInside = 0;
    scalar errCut = 0;
    scalar errRigid = 0;
    label nInside = 0, nCut = 0;
    forAll(mesh.C(), celli)
    {
        const scalar w = weight(celli);
        if (w <= 0) continue;

        const vector us(b.velocityAt(mesh.C()[celli]));
        maxUs = max(maxUs, mag(us));
        errRigid = max(errRigid, mag(us - Us[celli]));
        if (w >= 1)
        {
            errInside = max(errInside, mag(U[celli] - us));
            ++nInside;
        }
        else
        {
            const vector blend(w*us + (1 - w)*uf[celli]);
            errCut = max(errCut, mag(U[celli] - blend));
            ++nCut;
        }
    }

    Info<< "body " << b.name() << ": U " << b.U() << " omega " << b.omega()
        << ", forcing " << fb.fb().forcing().type()
        << ": " << nInside << " fully forced cells, " << nCut
        << " blended cells" << nl;

    fbmTest::check("U.solid = U + w x r", errRigid, 0, 1e-12*maxUs);
    fbmTest::check
    (
        "fully forced: |u - (U + w x r)| <= 2 max|u_s|/penaltyMax",
        errInside, 0, 2*maxUs/1e6
    );
    // Round-off of the solve, amplified by the conditioning that the
    // penalty (k_max = 1e6) gives the matrix
    fbmTest::check
    (
        "blended cells: |u - (w u_s + (1-w) u_f)|", errCut, 0, 1e-8*maxUs
    );
    fbmTest::check("some fully forced cells", scalar(nInside > 0), 1, 0);
    fbmTest::check("some blended cells", scalar(nCut > 0), 1, 0);

    return fbmTest::result();
}


// ************************************************************************* //
