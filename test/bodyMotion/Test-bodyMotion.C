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
    Test-bodyMotion

Description
    The Newton-Euler integration of fbm::body against exact solutions
    (the case's body0, translate and rotate on, no fluid solve):
    - free fall in vacuum (rhoFluid 1e-12 times the body density, no
      hydrodynamic force): U = g t and X = X0 + g t^2/2, exact for the
      Euler/trapezoidal scheme with constant acceleration;
    - buoyancy: a = (1 - rho_f/rho_s) g;
    - a constant torque T about the axis (z in 2D, any axis for a sphere):
      omega = T t / I, theta = T t^2 / (2 I), and the orientation tensor
      is the rotation by theta;
    - the virtual-mass stabilisation (addedMassCoeff C_a) keeps the
      constant-force limit a = F_net/M: the acceleration after n steps
      is a_exact (1 - r^n), r = C_a M_f/(M + C_a M_f).

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
    fbm::body& b = const_cast<fbm::body&>(fb.bodies()[0]);

    const bool twoD = (mesh.nSolutionD() == 2);
    const vector g(0, -9.81, twoD ? 0 : 1.5);
    const scalar dt = 1e-3;
    const label nSteps = 200;
    const scalar t = nSteps*dt;
    const point X0(b.centre());
    const scalar scale = mag(g)*t*t;

    // Free fall in vacuum
    {
        const scalar rhoVac = 1e-12*b.rho();
        for (label i = 0; i < nSteps; ++i)
        {
            b.move(g, rhoVac, 0, dt);
        }
        fbmTest::check
        (
            "free fall: U = g t", b.U(), g*t*(1 - 1e-12), 1e-12*mag(g)*t
        );
        fbmTest::check
        (
            "free fall: X = X0 + g t^2/2", b.centre(),
            X0 + 0.5*g*t*t*(1 - 1e-12), 1e-12*scale
        );
    }

    // Buoyancy: start again from rest at X0
    {
        dictionary state;
        b.writeState(state);
        state.set("centre", X0);
        state.set("U", vector::zero);
        b.readState(state);

        const scalar rhoF = 0.4*b.rho();
        for (label i = 0; i < nSteps; ++i)
        {
            b.move(g, rhoF, 0, dt);
        }
        fbmTest::check
        (
            "buoyant fall: a = (1 - rho_f/rho_s) g", b.acceleration(),
            0.6*g, 1e-12*mag(g)
        );
    }

    // Constant torque from rest
    {
        const vector axis(twoD ? vector(0, 0, 1) : vector(1, 2, 2)/3.0);
        const symmTensor I(b.inertia());
        const scalar Iaxis = axis & I & axis;
        const scalar T = 0.01*Iaxis;
        b.setForce(vector::zero, T*axis);
        for (label i = 0; i < nSteps; ++i)
        {
            b.move(g, 1e-12*b.rho(), 0, dt);
        }
        fbmTest::check
        (
            "constant torque: omega = T t / I", b.omega(), T*t/Iaxis*axis,
            1e-12*T*t/Iaxis
        );
        const scalar theta = 0.5*T*t*t/Iaxis;
        fbmTest::check
        (
            "constant torque: theta = T t^2 / (2 I)", b.theta(), theta*axis,
            1e-12*theta
        );
        // Rotation by theta about the axis, applied to a vector normal to it
        const vector e(twoD ? vector(1, 0, 0) : vector(2, -2, 1)/3.0);
        const vector expected
        (
            Foam::cos(theta)*e + Foam::sin(theta)*(axis ^ e)
        );
        fbmTest::check
        (
            "constant torque: Q rotates by theta", b.Q() & e, expected, 1e-12
        );
    }

    // Virtual-mass stabilisation with a constant net force
    {
        dictionary state;
        b.writeState(state);
        state.set("U", vector::zero);
        state.set("omega", vector::zero);
        state.set("acceleration", vector::zero);
        b.readState(state);
        b.setForce(vector::zero, vector::zero);

        const scalar rhoF = 0.9*b.rho();
        const scalar Ca = 1;
        const scalar V = b.shape().volume();
        const scalar M = b.rho()*V, Mf = rhoF*V;
        const scalar r = Ca*Mf/(M + Ca*Mf);
        const label n = 3;
        for (label i = 0; i < n; ++i)
        {
            b.move(g, rhoF, Ca, dt);
        }
        const vector aExact((M - Mf)/M*g);
        fbmTest::check
        (
            "added mass: a_n = a (1 - r^n)", b.acceleration(),
            aExact*(1 - Foam::pow(r, n)), 1e-12*mag(aExact)
        );
    }

    return fbmTest::result();
}


// ************************************************************************* //
