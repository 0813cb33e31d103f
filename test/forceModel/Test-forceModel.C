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
    Test-forceModel

Description
    The force models on their own, without a fictitiousBoundary: a body
    (a circle on a 2D mesh, a sphere in 3D, radius 0.2 at the middle of
    the case's mesh) is given its covered cells by hand (body::updateCells
    with a cell octree built here), and the footprint the models read
    (fbm::footprint) is made of fields set here:
    - volumeIntegral, hydrostatic p = g.(x - X), u = 0: F = -rho g V and
      T = -rho M1 x g (V and M1 the covered volume and its first moment
      about the centre), to round-off;
    - momentumExchange, with penalty coefficients lambda, rigid velocity
      U.solid and velocity u set to arbitrary values in arbitrary cells:
      F = rho sum lambda (u - u_s) + rho V a and
      T = rho sum (x - X) x lambda (u - u_s) + (rho/rho_s) I omegaDot,
      with the body moving (translate, rotate on) and holding an
      acceleration a and angular acceleration omegaDot.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bodyInput.H"
#include "footprint.H"
#include "forceModel.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "Random.H"
#include "fbmTest.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar rho = 1.3;
    const point X(mesh.bounds().centre());
    PtrList<fbm::body> bodies(1);
    bodies.set
    (
        0,
        fbm::bodyInput::newRoundBody
        (
            "body0", 0.2, 2, fbm::bodyState(X, Zero, Zero), true, true, mesh
        )
    );
    fbm::body& b = bodies[0];

    // Covered cells through a cell octree of our own
    List<boundBox> cellBb(mesh.nCells());
    forAll(cellBb, celli)
    {
        cellBb[celli] = boundBox(mesh.points(), mesh.cellPoints()[celli], false);
    }
    treeBoundBox overallBb(mesh.points());
    overallBb.min() -= point::uniform(1e-6);
    overallBb.max() += point::uniform(1e-6);
    const indexedOctree<treeDataCell> tree
    (
        treeDataCell(true, mesh, polyMesh::CELL_TETS), overallBb, 8, 10, 100
    );
    b.updateCells(mesh, tree, cellBb, 4);

    volScalarField alpha
    (
        IOobject("alpha.solid", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    volVectorField Us
    (
        IOobject("U.solid", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );
    volScalarField bodyID
    (
        IOobject("bodyID", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("bodyID", dimless, -1)
    );
    scalar Vcov = 0;
    vector M1(Zero);
    forAll(b.cells(), i)
    {
        const label celli = b.cells()[i];
        alpha[celli] = b.alpha()[i];
        bodyID[celli] = 0;
        Vcov += b.alpha()[i]*mesh.V()[celli];
        M1 += b.alpha()[i]*mesh.V()[celli]*(mesh.C()[celli] - X);
    }
    alpha.correctBoundaryConditions();
    bodyID.correctBoundaryConditions();

    Info<< "body0: " << b.cells().size() << " covered cells, covered volume "
        << Vcov << " (shape " << b.shape().volume() << ")" << nl;
    fbmTest::check("covered cells found", scalar(b.cells().size() > 0), 1, 0);

    volScalarField p
    (
        IOobject("p", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar(sqr(dimVelocity), Zero),
        calculatedFvPatchScalarField::typeName
    );
    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        calculatedFvPatchVectorField::typeName
    );
    const volScalarField nuEff
    (
        IOobject("nuEff", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("nu", sqr(dimLength)/dimTime, 0.01)
    );

    List<vector> F(1, Zero), T(1, Zero);

    // volumeIntegral on a hydrostatic pressure
    {
        const vector g(0, -9.81, 0);
        forAll(p, celli)
        {
            p[celli] = (g & (mesh.C()[celli] - X));
        }
        forAll(p.boundaryField(), patchi)
        {
            const vectorField& Cf = mesh.C().boundaryField()[patchi];
            forAll(Cf, i)
            {
                p.boundaryFieldRef()[patchi][i] = (g & (Cf[i] - X));
            }
        }

        const labelList none;
        const scalarField noLambda(mesh.nCells(), Zero);
        const fbm::footprint fp
        (
            mesh, bodies, rho, alpha, Us, bodyID, none, noLambda
        );
        dictionary d;
        d.add("forceModel", "volumeIntegral");
        fbm::forceModel::New(d)->calcForces(fp, U, p, nuEff, F, T);

        fbmTest::check
        (
            "volumeIntegral, hydrostatic: F = -rho g V", F[0], -rho*g*Vcov,
            1e-10*mag(g)*Vcov
        );
        fbmTest::check
        (
            "volumeIntegral, hydrostatic: T = -rho M1 x g", T[0],
            -rho*(M1 ^ g), 1e-10*rho*mag(g)*Vcov*mesh.bounds().mag()
        );
    }

    // momentumExchange on arbitrary values
    {
        const vector a(0.3, -2, 0);
        const vector omegaDot(0, 0, 5);
        b.state().acceleration() = a;
        b.state().angularAcceleration() = omegaDot;

        Random rnd(4321);
        auto sample = [&]()
        {
            return vector
            (
                rnd.sample01<scalar>() - 0.5,
                rnd.sample01<scalar>() - 0.5,
                mesh.nSolutionD() == 3 ? rnd.sample01<scalar>() - 0.5 : 0
            );
        };
        scalarField lambda(mesh.nCells(), Zero);
        DynamicList<label> active;
        vector Fexact(Zero), Texact(Zero);
        for (label celli = 0; celli < mesh.nCells(); celli += 3)
        {
            active.append(celli);
            lambda[celli] = rnd.sample01<scalar>();
            Us[celli] = sample();
            U[celli] = sample();
            bodyID[celli] = 0;
            const vector f(rho*lambda[celli]*(U[celli] - Us[celli]));
            Fexact += f;
            Texact += (mesh.C()[celli] - X) ^ f;
        }
        Fexact += rho*b.shape().volume()*a;
        Texact += (rho/b.rho())*(b.inertia() & omegaDot);

        const fbm::footprint fp
        (
            mesh, bodies, rho, alpha, Us, bodyID, active, lambda
        );
        dictionary d;
        d.add("forceModel", "momentumExchange");
        fbm::forceModel::New(d)->calcForces(fp, U, p, nuEff, F, T);

        const scalar scale = mag(Fexact) + rho*mesh.nCells();
        fbmTest::check
        (
            "momentumExchange: F = rho sum lambda (u - u_s) + rho V a", F[0],
            Fexact, 1e-12*scale
        );
        fbmTest::check
        (
            "momentumExchange: T = rho sum r x lambda (u - u_s)"
            " + (rho/rho_s) I omegaDot", T[0], Texact,
            1e-12*scale*mesh.bounds().mag()
        );
    }

    return fbmTest::result();
}


// ************************************************************************* //
