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
    The Newton-Euler integration of fbm::rigidBodyMotion against exact
    solutions, on a body built without a dictionary or a fictitiousBoundary
    (a circle on a 2D mesh, a sphere in 3D, of radius 0.2 and density 2 at
    the middle of the case's mesh; no fluid solve):
    - free fall in vacuum (rhoFluid 1e-12 times the body density, no
      hydrodynamic force): U = g t and X = X0 + g t^2/2, exact for the
      Euler/trapezoidal scheme with constant acceleration;
    - buoyancy: a = (1 - rho_f/rho_s) g;
    - a constant torque T about the axis (z in 2D, any axis for a sphere):
      omega = T t / I, theta = T t^2 / (2 I), and the orientation tensor
      is the rotation by theta;
    - the virtual-mass stabilisation (addedMassCoeff C_a) keeps the
      constant-force limit a = F_net/M: the acceleration after n steps
      is a_exact (1 - r^n), r = C_a M_f/(M + C_a M_f);
    - the sub-steps of the contact model (kick, drift, kick: velocity
      Verlet) with a constant force: U = g t and X = X0 + g t^2/2, exact
      as well, and the same as the plain steps;
    - the fluid's rate (fbm::fluidRate) of a body's velocity history
      against OpenFOAM's own backward ddt of a uniform field with that
      history, over steps of varying size;
    - the virtual mass with the backward time scheme: a model fluid whose
      force is the added mass -C_a M_f D (D the fluid's rate) makes the
      explicit steps repeat the implicit (monolithic) recurrence
      (M + (1 + w) C_a M_f) a^{n+1} = (M - M_f) g + w C_a M_f a^n step by
      step (steps of constant size), with no mode alternating from step
      to step, and tend to (M - M_f) g/(M + C_a M_f).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bodyInput.H"
#include "rigidBodyMotion.H"
#include "fluidRate.H"
#include "backwardDdtScheme.H"
#include "fbmTest.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    autoPtr<fbm::body> bodyPtr
    (
        fbm::bodyInput::newRoundBody
        (
            "body0", 0.2, 2,
            fbm::bodyState(mesh.bounds().centre(), Zero, Zero),
            true, true, mesh
        )
    );
    fbm::body& b = bodyPtr();
    fbm::bodyState& s = b.state();

    const bool twoD = (mesh.nSolutionD() == 2);
    const vector g(0, -9.81, twoD ? 0 : 1.5);
    const scalar dt = 1e-3;
    const label nSteps = 200;
    const scalar t = nSteps*dt;
    const point X0(b.centre());
    const scalar scale = mag(g)*t*t;

    // Free fall in vacuum
    {
        const fbm::rigidBodyMotion vacuum(g, 1e-12*b.rho(), 0, mesh);
        for (label i = 0; i < nSteps; ++i)
        {
            vacuum.move(b, dt);
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
        s.centre() = X0;
        s.U() = Zero;

        const fbm::rigidBodyMotion motion(g, 0.4*b.rho(), 0, mesh);
        for (label i = 0; i < nSteps; ++i)
        {
            motion.move(b, dt);
        }
        fbmTest::check
        (
            "buoyant fall: a = (1 - rho_f/rho_s) g", s.acceleration(),
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
        const fbm::rigidBodyMotion vacuum(g, 1e-12*b.rho(), 0, mesh);
        for (label i = 0; i < nSteps; ++i)
        {
            vacuum.move(b, dt);
        }
        fbmTest::check
        (
            "constant torque: omega = T t / I", b.omega(), T*t/Iaxis*axis,
            1e-12*T*t/Iaxis
        );
        const scalar theta = 0.5*T*t*t/Iaxis;
        fbmTest::check
        (
            "constant torque: theta = T t^2 / (2 I)", s.theta(), theta*axis,
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
            "constant torque: Q rotates by theta", s.Q() & e, expected, 1e-12
        );
    }

    // Virtual-mass stabilisation with a constant net force
    {
        s.U() = Zero;
        s.omega() = Zero;
        s.acceleration() = Zero;
        b.setForce(vector::zero, vector::zero);

        const scalar rhoF = 0.9*b.rho();
        const scalar Ca = 1;
        const scalar V = b.shape().volume();
        const scalar M = b.rho()*V, Mf = rhoF*V;
        const scalar r = Ca*Mf/(M + Ca*Mf);
        const label n = 3;
        const fbm::rigidBodyMotion motion(g, rhoF, Ca, mesh);
        for (label i = 0; i < n; ++i)
        {
            motion.move(b, dt);
        }
        const vector aExact((M - Mf)/M*g);
        fbmTest::check
        (
            "added mass: a_n = a (1 - r^n)", s.acceleration(),
            aExact*(1 - Foam::pow(r, n)), 1e-12*mag(aExact)
        );
    }

    // Sub-steps (kick, drift, kick) in vacuum from rest at X0: exact for a
    // constant force, and the held acceleration is the mean over the step
    {
        s.centre() = X0;
        s.U() = Zero;
        s.omega() = Zero;
        s.acceleration() = Zero;
        s.angularAcceleration() = Zero;
        b.setForce(vector::zero, vector::zero);

        const fbm::rigidBodyMotion vacuum(g, 1e-12*b.rho(), 0, mesh);
        const label nSub = 7;
        const scalar dtSub = dt/nSub;
        for (label i = 0; i < nSteps; ++i)
        {
            b.beginSubCycles();
            for (label k = 0; k < nSub; ++k)
            {
                vacuum.kick(b, 0.5*dtSub, Zero);
                vacuum.drift(b, dtSub);
                vacuum.kick(b, 0.5*dtSub, Zero);
            }
            vacuum.endSubCycles(b, dt);
        }
        fbmTest::check
        (
            "sub-steps: U = g t", b.U(), g*t*(1 - 1e-12), 1e-11*mag(g)*t
        );
        fbmTest::check
        (
            "sub-steps: X = X0 + g t^2/2", b.centre(),
            X0 + 0.5*g*t*t*(1 - 1e-12), 1e-11*scale
        );
        fbmTest::check
        (
            "sub-steps: mean acceleration g", s.acceleration(),
            g*(1 - 1e-12), 1e-9*mag(g)
        );
    }

    // The fluid's rate against backwardDdtScheme: a uniform field with the
    // body's velocity history, steps of varying size (the first one Euler,
    // as backwardDdtScheme steps while the time index is below 2)
    fbm::fluidRate bdf2(runTime, fbm::fluidRate::scheme::backward);
    {
        fv::backwardDdtScheme<vector> ddtScheme(mesh);
        volVectorField Uf
        (
            IOobject("Ufluid", runTime.timeName(), mesh),
            mesh,
            dimensionedVector(dimVelocity, Zero)
        );
        Uf.oldTime().oldTime();
        vector Uold(Zero), aOld(Zero);
        const scalar steps[] = {1e-3, 1e-3, 1.3e-3, 0.7e-3, 0.9e-3, 1.6e-3};
        for (const scalar dtk : steps)
        {
            runTime.setDeltaT(dtk);
            ++runTime;
            const scalar tk = runTime.value();
            const vector Uk
            (
                Foam::sin(40*tk), Foam::cos(25*tk) - 1, twoD ? 0 : tk*tk
            );
            Uf == dimensionedVector("U", dimVelocity, Uk);
            const vector a((Uk - Uold)/dtk);
            const vector ddt(ddtScheme.fvcDdt(Uf)().primitiveField()[0]);
            fbmTest::check
            (
                "fluid rate = backward ddt(U) at t = " + Foam::name(tk)
              + " (w " + Foam::name(bdf2.weight()) + ")",
                bdf2.rate(a, aOld), ddt, 1e-9*mag(ddt)
            );
            aOld = a;
            Uold = Uk;
        }
    }

    // Virtual mass with the backward scheme and a model fluid of added
    // mass C_a M_f, from rest: first with steps of constant size (no
    // alternating mode from the first step on), then with steps of
    // varying size (as adjustTimeStep makes them), where this step's
    // weight w and the last step's w^n differ
    for (const bool varying : {false, true})
    {
        const word kind(varying ? "varying steps" : "constant steps");
        s.U() = Zero;
        s.omega() = Zero;
        s.acceleration() = Zero;
        s.angularAcceleration() = Zero;
        s.beginStep();
        s.beginStep();
        b.setForce(vector::zero, vector::zero);

        const scalar rhoF = 0.8*b.rho();
        const scalar Ca = 1;
        const scalar V = b.shape().volume();
        const scalar M = b.rho()*V, Mf = rhoF*V;
        const fbm::rigidBodyMotion motion(g, rhoF, Ca, mesh, &bdf2);
        const vector aLimit((M - Mf)/(M + Ca*Mf)*g);

        // A step of the size of the first below before the start from rest
        runTime.setDeltaT(dt);
        ++runTime;
        bdf2.beginStep();
        vector aMono(Zero);
        scalar worst = 0, w = 0, wPrev = bdf2.weight(), worstW0 = 0;
        scalar wMin = 1, wMax = 0;
        bool alternates = false;
        vector aPrev(Zero), daPrev(Zero);
        // Varying: the step grows and shrinks by up to 30 %, constant from
        // i = 30 on for the limit below (alternation is checked there)
        const label firstChecked = varying ? 32 : 1;
        for (label i = 0; i < 40; ++i)
        {
            runTime.setDeltaT
            (
                (varying && i < 30) ? dt*(1 + 0.3*Foam::sin(1.7*i)) : dt
            );
            ++runTime;
            bdf2.beginStep();
            w = bdf2.weight();
            worstW0 = max(worstW0, mag(bdf2.weight0() - wPrev));
            wPrev = w;
            wMin = min(wMin, w);
            wMax = max(wMax, w);
            s.beginStep();
            motion.move(b, runTime.deltaTValue());
            // The model fluid's force held over the next step
            b.setForce
            (
                -Ca*Mf*bdf2.rate(s.acceleration(), s.acceleration0()),
                vector::zero
            );

            aMono = ((M - Mf)*g + w*Ca*Mf*aMono)/(M + (1 + w)*Ca*Mf);
            worst = max(worst, mag(s.acceleration() - aMono)/mag(g));
            const vector da(s.acceleration() - aPrev);
            if (i >= firstChecked && (da & daPrev) < 0) alternates = true;
            daPrev = da;
            aPrev = s.acceleration();
        }
        fbmTest::check
        (
            "fluid rate, " + kind + ": weight0() = the last step's weight (w "
          + Foam::name(wMin) + " to " + Foam::name(wMax) + ")",
            worstW0, 0, 1e-15
        );
        fbmTest::check
        (
            "backward virtual mass, " + kind + ": explicit = monolithic",
            worst, 0, 1e-12
        );
        fbmTest::check
        (
            "backward virtual mass, " + kind + ": no alternating mode",
            scalar(alternates), 0, 0
        );
        fbmTest::check
        (
            "backward virtual mass, " + kind
          + ": a -> (M - M_f) g/(M + C_a M_f)",
            s.acceleration(), aLimit, 1e-10*mag(g)
        );
    }

    return fbmTest::result();
}


// ************************************************************************* //
