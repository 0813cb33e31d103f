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

#include "rigidBodyMotion.H"
#include "principalAxes.H"
#include "body.H"
#include "polyMesh.H"
#include "fluidRate.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::rigidBodyMotion::rigidBodyMotion
(
    const vector& g,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const polyMesh& mesh,
    const fluidRate* rate
)
:
    g_(g),
    rhoFluid_(rhoFluid),
    addedMassCoeff_(addedMassCoeff),
    planeMask_(1, 1, 1),
    rate_(rate)
{
    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0)
        {
            planeMask_[d] = 0;
        }
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fbm::rigidBodyMotion::rateWeight() const
{
    return (rate_ && addedMassCoeff_ > 0) ? rate_->weight() : 0;
}


Foam::scalar Foam::fbm::rigidBodyMotion::rateWeight0() const
{
    return (rate_ && addedMassCoeff_ > 0) ? rate_->weight0() : 0;
}


Foam::vector Foam::fbm::rigidBodyMotion::laggedRate
(
    const vector& x,
    const vector& x00,
    const scalar w,
    const scalar w0
)
{
    if (w == 0 && w0 == 0)
    {
        return x;
    }
    // w x^n, the part of this step's rate on the right, and the last
    // step's rate (1 + w0) x^n - w0 x^{n-1}
    return (1 + w + w0)*x - w0*x00;
}


void Foam::fbm::rigidBodyMotion::translationTerms
(
    const body& b,
    const vector& aLag,
    vector& Fheld,
    vector& Flag,
    scalar& Meff
) const
{
    const scalar V = b.shape().volume();
    const scalar M = b.rho()*V;
    const scalar Mf = rhoFluid_*V;

    // aLag is the last step's acceleration; the one before it is the
    // state's acceleration00 (bodyState::beginStep() ran at this step's
    // start)
    const scalar w = rateWeight();
    Fheld = (M - Mf)*g_ + b.force();
    Flag = addedMassCoeff_*Mf
       *laggedRate(aLag, b.state().acceleration00(), w, rateWeight0());
    Meff = M + addedMassCoeff_*Mf*(1 + w);
}


Foam::vector Foam::fbm::rigidBodyMotion::angularAcceleration
(
    const body& b,
    const vector& omegaDotLag
) const
{
    return angularAcceleration(b, omegaDotLag, b.torque());
}


Foam::vector Foam::fbm::rigidBodyMotion::angularAcceleration
(
    const body& b,
    const vector& omegaDotLag,
    const vector& T
) const
{
    // Same virtual-mass stabilisation as the translation, with the
    // inertia of the enclosed fluid I_f = (rho_f/rho_s) I
    const symmTensor I(b.inertia());
    const symmTensor If((rhoFluid_/b.rho())*I);
    const vector& omega = b.omega();
    const scalar w = rateWeight();
    vector wDot
    (
        inv(I + addedMassCoeff_*(1 + w)*If)
      & (
            T - (omega ^ (I & omega))
          + addedMassCoeff_
           *(
                If
              & laggedRate
                (
                    omegaDotLag, b.state().angularAcceleration00(), w,
                    rateWeight0()
                )
            )
        )
    );
    // 2D: rotation about the empty direction only
    return planeRotation(wDot);
}


bool Foam::fbm::rigidBodyMotion::splitRotation(const body& b) const
{
    return b.rotates() && !b.shape().isotropic() && cmptMin(planeMask_) > 0;
}


Foam::vector Foam::fbm::rigidBodyMotion::splitTorque
(
    const body& b,
    const vector& omegaDotLag
) const
{
    return splitTorque(b, omegaDotLag, b.torque());
}


Foam::vector Foam::fbm::rigidBodyMotion::splitTorque
(
    const body& b,
    const vector& omegaDotLag,
    const vector& T
) const
{
    // (1 + c) dL/dt = T + c (I omegaDot^n + omega x I omega), c = C_a
    // rho_f/rho_s: the virtual-mass form of angularAcceleration() with
    // d(I omega)/dt = I omegaDot + omega x I omega
    const symmTensor I(b.inertia());
    const vector& omega = b.omega();
    const scalar c = addedMassCoeff_*rhoFluid_/b.rho();
    if (c == 0)
    {
        return T;
    }
    const scalar w = rateWeight();
    if (w == 0)
    {
        return
            (T + c*((I & omegaDotLag) + (omega ^ (I & omega))))
           /(1 + c);
    }
    const vector lag
    (
        laggedRate
        (
            omegaDotLag, b.state().angularAcceleration00(), w, rateWeight0()
        )
    );
    return
        (T + c*((I & lag) + (1 + w)*(omega ^ (I & omega))))
       /(1 + c*(1 + w));
}


void Foam::fbm::rigidBodyMotion::angularKick
(
    body& b,
    const scalar dt,
    const vector& T
) const
{
    // L = I omega += dt T at a fixed orientation
    bodyState& s = b.state();
    const symmTensor I(b.inertia());
    s.omega() = inv(I) & ((I & s.omega()) + dt*T);
}


void Foam::fbm::rigidBodyMotion::freeRotation(body& b, const scalar dt) const
{
    bodyState& s = b.state();

    // Principal axes of the body-frame inertia: I0 = E diag(lambda) E^T
    const symmTensor I0(b.rho()*b.shape().inertiaPerDensity());
    vector lambda(I0.xx(), I0.yy(), I0.zz());
    tensor E(tensor::I);
    if (I0.xy() != 0 || I0.xz() != 0 || I0.yz() != 0)
    {
        const principalAxes axes(I0);
        lambda = axes.values();
        E = axes.axes();
    }

    // Principal frame to lab, and the angular momentum in the principal
    // frame pi = P^T L = diag(lambda) P^T omega
    tensor P(s.Q() & E);
    vector pi(cmptMultiply(lambda, P.T() & s.omega()));
    const vector omega0(s.omega());

    // Exact flows of the three parts pi_k^2/(2 lambda_k) of the kinetic
    // energy: a rotation about principal axis k by theta = h pi_k/lambda_k,
    // body frame P <- P R_k(theta), pi <- R_k(theta)^T pi (L = P pi fixed).
    // Symmetric sequence 1 2 3 2 1 (Dullweber, Leimkuhler & McLachlan 1997)
    static const direction axis[5] = {0, 1, 2, 1, 0};
    static const scalar frac[5] = {0.5, 0.5, 1, 0.5, 0.5};
    for (label i = 0; i < 5; ++i)
    {
        const direction k = axis[i];
        const scalar theta = frac[i]*dt*pi[k]/lambda[k];
        const scalar c = Foam::cos(theta), sn = Foam::sin(theta);
        const direction p = (k + 1) % 3, q = (k + 2) % 3;
        tensor R(tensor::I);
        R(p, p) = c;
        R(p, q) = -sn;
        R(q, p) = sn;
        R(q, q) = c;
        P = P & R;
        pi = R.T() & pi;
    }

    s.omega() = P & vector(cmptDivide(pi, lambda));
    s.setOrientation(P & E.T(), 0.5*dt*(omega0 + s.omega()));
}


void Foam::fbm::rigidBodyMotion::rotate(body& b, const vector& phi) const
{
    bodyState& s = b.state();
    s.rotate(phi);
    if (!b.shape().isotropic())
    {
        s.setOrientation(s.Q(), Zero);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::rigidBodyMotion::move(body& b, const scalar dt) const
{
    bodyState& s = b.state();

    if (b.translates())
    {
        vector Fheld, Flag;
        scalar Meff;
        translationTerms(b, s.acceleration(), Fheld, Flag, Meff);
        // No contact force: adding a zero vector leaves the sum
        // bit-identical
        const vector aNew
        (
            acceleration(Fheld, Zero, Flag, Meff, planeMask_)
        );
        const vector U0(s.U());
        s.U() += dt*aNew;
        s.centre() += 0.5*dt*(U0 + s.U());
        s.acceleration() = aNew;
    }
    else
    {
        // Prescribed (held) velocity: the body moves with it
        s.centre() += dt*s.U();
    }

    if (splitRotation(b))
    {
        // Half kick, free rotation, half kick with the held torque
        const vector w0(s.omega());
        const vector T(splitTorque(b, s.angularAcceleration()));
        angularKick(b, 0.5*dt, T);
        freeRotation(b, dt);
        angularKick(b, 0.5*dt, T);
        s.angularAcceleration() = (s.omega() - w0)/dt;
    }
    else if (b.rotates())
    {
        const vector wDot(angularAcceleration(b, s.angularAcceleration()));
        const vector w0(s.omega());
        s.omega() += dt*wDot;
        s.angularAcceleration() = wDot;

        // Rotate the orientation by the mean angular velocity of the step
        rotate(b, 0.5*dt*(w0 + s.omega()));
    }
    else
    {
        rotate(b, dt*s.omega());
    }
}


void Foam::fbm::rigidBodyMotion::heldTranslation
(
    const body& b,
    vector& Fheld,
    vector& Flag,
    scalar& Meff
) const
{
    translationTerms(b, b.aHeld(), Fheld, Flag, Meff);
}


void Foam::fbm::rigidBodyMotion::kick
(
    body& b,
    const scalar dt,
    const vector& Fc
) const
{
    bodyState& s = b.state();
    if (b.translates())
    {
        vector Fheld, Flag;
        scalar Meff;
        heldTranslation(b, Fheld, Flag, Meff);
        s.U() += dt*acceleration(Fheld, Fc, Flag, Meff, planeMask_);
    }
    if (splitRotation(b))
    {
        angularKick(b, dt, splitTorque(b, b.omegaDotHeld()));
    }
    else if (b.rotates())
    {
        s.omega() += dt*angularAcceleration(b, b.omegaDotHeld());
    }
}


void Foam::fbm::rigidBodyMotion::drift(body& b, const scalar dt) const
{
    // Integrated or prescribed (held) velocities alike
    bodyState& s = b.state();
    s.centre() += dt*s.U();
    if (splitRotation(b))
    {
        freeRotation(b, dt);
    }
    else
    {
        rotate(b, dt*s.omega());
    }
}


void Foam::fbm::rigidBodyMotion::endTranslationSubCycles
(
    body& b,
    const point& centre,
    const vector& U,
    const label n,
    const scalar dtSub
) const
{
    bodyState& s = b.state();
    s.centre() = centre;
    s.U() = U;

    // The rotation part of kick() and drift(), sub-step by sub-step
    if (!b.rotates() && magSqr(s.omega()) == 0)
    {
        return;
    }
    const scalar h = 0.5*dtSub;
    if (splitRotation(b))
    {
        for (label step = 0; step < n; ++step)
        {
            angularKick(b, h, splitTorque(b, b.omegaDotHeld()));
            freeRotation(b, dtSub);
            angularKick(b, h, splitTorque(b, b.omegaDotHeld()));
        }
        return;
    }
    for (label step = 0; step < n; ++step)
    {
        if (b.rotates())
        {
            s.omega() += h*angularAcceleration(b, b.omegaDotHeld());
        }
        rotate(b, dtSub*s.omega());
        if (b.rotates())
        {
            s.omega() += h*angularAcceleration(b, b.omegaDotHeld());
        }
    }
}


void Foam::fbm::rigidBodyMotion::angularSubKick
(
    body& b,
    const scalar dt,
    const vector& Tc
) const
{
    if (splitRotation(b))
    {
        angularKick(b, dt, splitTorque(b, b.omegaDotHeld(), b.torque() + Tc));
    }
    else if (b.rotates())
    {
        b.state().omega() +=
            dt*angularAcceleration(b, b.omegaDotHeld(), b.torque() + Tc);
    }
}


void Foam::fbm::rigidBodyMotion::rotationDrift
(
    body& b,
    const scalar dt
) const
{
    if (!b.rotates() && magSqr(b.omega()) == 0)
    {
        return;
    }
    if (splitRotation(b))
    {
        freeRotation(b, dt);
    }
    else
    {
        rotate(b, dt*b.omega());
    }
}


void Foam::fbm::rigidBodyMotion::endSubCycles(body& b, const scalar dt) const
{
    bodyState& s = b.state();
    if (b.translates())
    {
        s.acceleration() = (s.U() - b.U0())/dt;
    }
    if (b.rotates())
    {
        s.angularAcceleration() = (s.omega() - b.omega0())/dt;
    }
}


// ************************************************************************* //
