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
    - cells inside (alpha = 1): u = U + w x (x - X) to 1/penaltyMax;
    - cut cells: u = alpha u_s + (1 - alpha) u_f, u_f = H/A of the matrix
      without the forcing evaluated at the solution (the row-wise blend the
      forcing is built to give), to solver round-off;
    - cells outside: the matrix is unchanged there.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "fictitiousBoundary.H"
#include "fbmTest.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    fbm::fictitiousBoundary fb(mesh);
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

    const scalarField& alpha = fb.alpha();
    const vectorField& Us = fb.Us();
    const vectorField uf(UEqn0.H()().primitiveField()/UEqn0.A()().primitiveField());

    scalar maxUs = 0;
    scalar errInside = 0;
    scalar errCut = 0;
    scalar errRigid = 0;
    label nInside = 0, nCut = 0;
    forAll(b.cells(), i)
    {
        const label celli = b.cells()[i];
        const vector us(b.velocityAt(mesh.C()[celli]));
        maxUs = max(maxUs, mag(us));
        errRigid = max(errRigid, mag(us - Us[celli]));
        if (alpha[celli] >= 1)
        {
            errInside = max(errInside, mag(U[celli] - us));
            ++nInside;
        }
        else
        {
            const vector blend(alpha[celli]*us + (1 - alpha[celli])*uf[celli]);
            errCut = max(errCut, mag(U[celli] - blend));
            ++nCut;
        }
    }

    Info<< "body " << b.name() << ": U " << b.U() << " omega " << b.omega()
        << ", " << nInside << " inside cells, " << nCut << " cut cells" << nl;

    fbmTest::check("U.solid = U + w x r", errRigid, 0, 1e-12*maxUs);
    fbmTest::check
    (
        "inside: |u - (U + w x r)| <= 2 max|u_s|/penaltyMax",
        errInside, 0, 2*maxUs/1e6
    );
    fbmTest::check
    (
        "cut cells: |u - (alpha u_s + (1-alpha) u_f)|", errCut, 0, 1e-10*maxUs
    );
    fbmTest::check("some inside cells", scalar(nInside > 0), 1, 0);
    fbmTest::check("some cut cells", scalar(nCut > 0), 1, 0);

    return fbmTest::result();
}


// ************************************************************************* //
