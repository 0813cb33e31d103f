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
    Test-forceIntegral

Description
    The volume-integral force and torque (paper Eq. 14) on analytic fields,
    for the body of the case (forceModel volumeIntegral), against the values
    that follow from F = int alpha div(sigma) dV and
    T = int alpha r x div(sigma) dV for sigma symmetric:
    - hydrostatic p = -g.x, u = 0: the buoyancy F = -rho g V;
    - uniform p and u: F = 0, T = 0;
    - linear shear u = (gamma y, 0, 0): F = 0, T = 0 (no net stress);
    - rigid rotation u = w x r: no viscous stress, F = 0, T = 0;
    - quadratic u = (c y^2, 0, 0): div(sigma) = 2 rho nu c e_x, so
      F = 2 rho nu c V e_x.
    V is the covered volume sum(alpha V) (itself within the volume-fraction
    test's tolerance of the exact volume); the discrete identities hold to
    round-off on a uniform Cartesian mesh, so the tolerances are round-off
    multiples of the force scale.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bodySystem.H"
#include "fbmTest.H"

using namespace Foam;

// Set a field and its boundary values from a function of position
template<class Type, class Func>
void setField
(
    GeometricField<Type, fvPatchField, volMesh>& fld,
    const Func& f
)
{
    const fvMesh& mesh = fld.mesh();
    forAll(fld, celli)
    {
        fld[celli] = f(mesh.C()[celli]);
    }
    forAll(fld.boundaryField(), patchi)
    {
        fvPatchField<Type>& pf = fld.boundaryFieldRef()[patchi];
        const vectorField& Cf = mesh.C().boundaryField()[patchi];
        forAll(pf, i)
        {
            pf[i] = f(Cf[i]);
        }
    }
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    fbm::bodySystem fb(mesh);
    const fbm::body& b = fb.bodies()[0];
    const point X = b.centre();
    const scalar rho = fb.rhoFluid();
    const scalar nu = 0.01;

    // Covered volume and its first moment about the centre
    scalar Vcov = 0;
    vector M1(Zero);
    forAll(b.cells(), i)
    {
        const label celli = b.cells()[i];
        Vcov += b.alpha()[i]*mesh.V()[celli];
        M1 += b.alpha()[i]*mesh.V()[celli]*(mesh.C()[celli] - X);
    }

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
    volScalarField nuEff
    (
        IOobject("nuEff", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("nu", sqr(dimLength)/dimTime, nu)
    );

    // Scales for the round-off tolerances
    const scalar L = mesh.bounds().mag();
    const scalar tol = 1e-10;

    // Hydrostatic
    {
        const vector g(0, -9.81, 0);
        setField(p, [&](const point& x){ return (g & (x - X)); });
        setField(U, [](const point&){ return vector::zero; });
        fb.correctForces(U, p, nuEff);
        fbmTest::check
        (
            "hydrostatic: F = -rho g V", b.force(), -rho*g*Vcov,
            tol*mag(g)*Vcov
        );
        // T = -int alpha r x rho g (buoyancy at the centroid): zero for the
        // exact shape, here from the
        // first moment M1 of the discrete alpha
        fbmTest::check
        (
            "hydrostatic: T = -rho M1 x g", b.torque(), -rho*(M1 ^ g),
            tol*rho*mag(g)*Vcov*L
        );
    }

    // Uniform
    {
        setField(p, [](const point&){ return 3.0; });
        setField(U, [](const point&){ return vector(1, 0.5, 0.25); });
        fb.correctForces(U, p, nuEff);
        fbmTest::check("uniform: F = 0", b.force(), Zero, tol*3*Vcov/L);
        fbmTest::check("uniform: T = 0", b.torque(), Zero, tol*3*Vcov);
    }

    // Linear shear
    {
        const scalar gamma = 2;
        setField(p, [](const point&){ return 0.0; });
        setField(U, [&](const point& x){ return vector(gamma*x.y(), 0, 0); });
        fb.correctForces(U, p, nuEff);
        const scalar tau = rho*nu*gamma;
        fbmTest::check("linear shear: F = 0", b.force(), Zero, tol*tau*Vcov/L);
        fbmTest::check("linear shear: T = 0", b.torque(), Zero, tol*tau*Vcov);
    }

    // Rigid rotation
    {
        const vector w(0, 0, 3);
        setField(U, [&](const point& x){ return w ^ (x - X); });
        fb.correctForces(U, p, nuEff);
        fbmTest::check("rotation: F = 0", b.force(), Zero, tol*mag(w)*Vcov);
        fbmTest::check("rotation: T = 0", b.torque(), Zero, tol*mag(w)*Vcov*L);
    }

    // Quadratic velocity
    {
        const scalar c = 5;
        setField
        (
            U, [&](const point& x){ return vector(c*sqr(x.y() - X.y()), 0, 0); }
        );
        fb.correctForces(U, p, nuEff);
        const vector Fexact(2*rho*nu*c*Vcov, 0, 0);
        fbmTest::check
        (
            "quadratic: F = 2 rho nu c V e_x", b.force(), Fexact,
            1e-8*mag(Fexact)
        );
    }

    return fbmTest::result();
}


// ************************************************************************* //
