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
#include "body.H"
#include "polyMesh.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::rigidBodyMotion::rigidBodyMotion
(
    const vector& g,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const polyMesh& mesh
)
:
    g_(g),
    rhoFluid_(rhoFluid),
    addedMassCoeff_(addedMassCoeff),
    planeMask_(1, 1, 1)
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

    Fheld = (M - Mf)*g_ + b.force();
    Flag = addedMassCoeff_*Mf*aLag;
    Meff = M + addedMassCoeff_*Mf;
}


Foam::vector Foam::fbm::rigidBodyMotion::angularAcceleration
(
    const body& b,
    const vector& omegaDotLag
) const
{
    // Same virtual-mass stabilisation as the translation, with the
    // inertia of the enclosed fluid I_f = (rho_f/rho_s) I
    const symmTensor I(b.inertia());
    const symmTensor If((rhoFluid_/b.rho())*I);
    const vector& omega = b.omega();
    vector wDot
    (
        inv(I + addedMassCoeff_*If)
      & (
            b.torque() - (omega ^ (I & omega))
          + addedMassCoeff_*(If & omegaDotLag)
        )
    );
    if (cmptMin(planeMask_) == 0)
    {
        // 2D: rotation about the empty direction only
        wDot = wDot - cmptMultiply(planeMask_, wDot);
    }
    return wDot;
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

    if (b.rotates())
    {
        const vector wDot(angularAcceleration(b, s.angularAcceleration()));
        const vector w0(s.omega());
        s.omega() += dt*wDot;
        s.angularAcceleration() = wDot;

        // Rotate the orientation by the mean angular velocity of the step
        s.rotate(0.5*dt*(w0 + s.omega()));
    }
    else
    {
        s.rotate(dt*s.omega());
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
    if (b.rotates())
    {
        s.omega() += dt*angularAcceleration(b, b.omegaDotHeld());
    }
}


void Foam::fbm::rigidBodyMotion::drift(body& b, const scalar dt) const
{
    // Integrated or prescribed (held) velocities alike
    bodyState& s = b.state();
    s.centre() += dt*s.U();
    s.rotate(dt*s.omega());
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
    for (label step = 0; step < n; ++step)
    {
        if (b.rotates())
        {
            s.omega() += h*angularAcceleration(b, b.omegaDotHeld());
        }
        s.rotate(dtSub*s.omega());
        if (b.rotates())
        {
            s.omega() += h*angularAcceleration(b, b.omegaDotHeld());
        }
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
