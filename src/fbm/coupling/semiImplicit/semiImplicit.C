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

#include "semiImplicit.H"
#include "bodySystem.H"
#include "sumOverProcessors.H"
#include "fvMatrices.H"
#include "addToRunTimeSelectionTable.H"


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace couplingModels
{
    defineTypeNameAndDebug(semiImplicit, 0);
    addToRunTimeSelectionTable(couplingModel, semiImplicit, dictionary);
}
}
}

const Foam::Enum
<
    Foam::fbm::couplingModels::semiImplicit::impulseForm
>
Foam::fbm::couplingModels::semiImplicit::impulseFormNames
({
    { impulseForm::final, "final" },
    { impulseForm::solved, "solved" },
});

const Foam::Enum
<
    Foam::fbm::couplingModels::semiImplicit::bodyScheme
>
Foam::fbm::couplingModels::semiImplicit::bodySchemeNames
({
    { bodyScheme::fluid, "fluid" },
    { bodyScheme::Euler, "Euler" },
});


// Largest share of the body's inertia that the lagged direct force may
// take (below 1: the stability bound of a lagged mass; 0.9 leaves the
// bodies down to rho_s/rho_f of about 1.1 untouched)
const Foam::scalar
Foam::fbm::couplingModels::semiImplicit::maxDirectMass_ = 0.9;

// The default of maxViscousRatio (semiImplicitCoeffs)
const Foam::scalar
Foam::fbm::couplingModels::semiImplicit::defaultMaxViscousRatio_ = 1.6;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// An optional word of the coefficients that must be one of names: the
// default when absent, a FatalIOError naming the keyword, the file and the
// allowed words (with what they mean) when it is not one of them
template<class Form>
Form readForm
(
    const Foam::dictionary& coeffs,
    const Foam::word& key,
    const Foam::Enum<Form>& names,
    const Form deflt,
    const char* meaning,
    bool& given
)
{
    using namespace Foam;
    given = coeffs.found(key, keyType::LITERAL);
    if (!given)
    {
        return deflt;
    }
    const word form(coeffs.get<word>(key, keyType::LITERAL));
    if (!names.found(form))
    {
        FatalIOErrorInFunction(coeffs)
            << key << " " << form << " in " << coeffs.name()
            << " is not one of " << flatOutput(names.toc()) << nl
            << "    " << meaning
            << exit(FatalIOError);
    }
    return names[form];
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fbm::couplingModels::semiImplicit::shellRate() const
{
    const fluidRate* rate = system_.rate();
    return rate ? 1 + rate->weight() : 1;
}


Foam::scalar Foam::fbm::couplingModels::semiImplicit::bodyRate() const
{
    return bodyScheme_ == bodyScheme::fluid ? shellRate() : 1;
}


Foam::scalar Foam::fbm::couplingModels::semiImplicit::responseTime
(
    const label bi
) const
{
    // dt rho_f/rho of body and shell together: mass M + m in the volume
    // V_b + m/rho_f (the shell's inertia at the fluid's rate, the body's
    // at its own, bodyRate())
    const body& b = system_.bodies()[bi];
    const scalar Vb = b.shape().volume();
    return
        system_.mesh().time().deltaTValue()
       *(system_.rhoFluid()*Vb + inertia_.shellMass(bi))
       /inertia_.totalMass(bi, bodyRate()*b.rho()*Vb, shellRate());
}


Foam::vector Foam::fbm::couplingModels::semiImplicit::rigidImpulse
(
    const label bi,
    const vector& P,
    const vector& Q,
    const point& x
) const
{
    const body& b = system_.bodies()[bi];
    const scalar dt = system_.mesh().time().deltaTValue();
    const scalar M =
        inertia_.totalMass
        (
            bi, bodyRate()*b.rho()*b.shape().volume(), shellRate()
        );
    return
        cmptMultiply(planeMask_, dt*P/M)
      + (angularImpulse(bi, dt*Q) ^ (x - b.centre()));
}


Foam::vector Foam::fbm::couplingModels::semiImplicit::angularImpulse
(
    const label bi,
    const vector& L
) const
{
    const body& b = system_.bodies()[bi];
    if (!b.rotates())
    {
        return Zero;
    }
    const symmTensor I
    (
        inertia_.totalInertia(bi, bodyRate()*b.inertia(), shellRate())
    );
    if (cmptSum(axisMask_) == 1)
    {
        // 2D: about the empty direction, a principal direction of I
        return cmptMultiply(axisMask_, L)/(axisMask_ & (I & axisMask_));
    }
    return inv(I) & L;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::couplingModels::semiImplicit::semiImplicit
(
    const dictionary& dict,
    bodySystem& system
)
:
    couplingModel(dict, system),
    impulse_(impulseForm::final),
    bodyScheme_(bodyScheme::fluid),
    heavy_(system.bodies().size(), false),
    timeIndex_(-1),
    corrector_(0),
    fluxForce_(system.bodies().size(), Zero),
    fluxTorque_(system.bodies().size(), Zero),
    cellForce_(system.bodies().size(), Zero),
    cellTorque_(system.bodies().size(), Zero),
    pressureForce_(system.bodies().size(), Zero),
    pressureTorque_(system.bodies().size(), Zero),
    directForce_(system.bodies().size(), Zero),
    directTorque_(system.bodies().size(), Zero),
    directForceEuler_(system.bodies().size(), Zero),
    directTorqueEuler_(system.bodies().size(), Zero),
    lastDirectForceEuler_(system.bodies().size(), Zero),
    lastDirectTorqueEuler_(system.bodies().size(), Zero),
    inertia_(system),
    limit_
    (
        dict.optionalSubDict(typeName + "Coeffs"),
        typeName,
        defaultMaxViscousRatio_
    ),
    lastStepKnown_(false),
    planeMask_(vector::one),
    axisMask_(vector::one)
{
    rejectContactProjection();
    rejectAddedMassCoeff();

    // The pressure force the bodies take at the end of a step, and the
    // time scheme of their velocity
    const dictionary& coeffs = dict.optionalSubDict(typeName + "Coeffs");
    bool impulseGiven = false, schemeGiven = false;
    impulse_ = readForm
    (
        coeffs, "impulse", impulseFormNames, impulseForm::final,
        "final: the pressure force of the final pressure; solved: the one"
        " the last pressure corrector was solved with",
        impulseGiven
    );
    bodyScheme_ = readForm
    (
        coeffs, "bodyScheme", bodySchemeNames, bodyScheme::fluid,
        "fluid: the bodies' velocity at the rate of the fluid's ddt(U)"
        " (BDF2 with backward); Euler: Euler's whatever the fluid's",
        schemeGiven
    );
    Info<< "fbm: coupling " << type() << ": impulse "
        << impulseFormNames[impulse_] << (impulseGiven ? "" : " (default)")
        << ", bodyScheme " << bodySchemeNames[bodyScheme_]
        << (schemeGiven ? "" : " (default)") << nl;

    // The pressure equation needs PIMPLE's consistent (SIMPLEC) 1/A: with
    // PISO's a_P the fluid beside a body responds to the pressure as if it
    // were 1 + 2 nD nu dt/h^2 times heavier than it is (its neighbours
    // held), the body's pressure impulse overshoots in each corrector and
    // the force oscillates from step to step (measured: the settling disk
    // at R/h 3 and nu dt/h^2 0.69 swings by +-50 % after 50 steps, by
    // +-0.5 % with consistent yes)
    const fvMesh& mesh = system.mesh();
    const dictionary& pimpleDict = mesh.solutionDict().subDict("PIMPLE");
    if (!pimpleDict.getOrDefault<bool>("consistent", false))
    {
        FatalIOErrorInFunction(pimpleDict)
            << "coupling " << type() << " (" << dict.name() << ") needs"
            << " consistent yes in " << pimpleDict.name() << nl
            << "    Its pressure step takes the fluid's response to the"
            << " pressure from PIMPLE's consistent (SIMPLEC) 1/A; with"
            << " PISO's the body's force oscillates from step to step at"
            << " viscous numbers nu dt/h^2 near 1"
            << exit(FatalIOError);
    }

    // How the pressure step finds the bodies' response (run-time
    // selected; its constructor checks its own entries)
    pressureStep_ = pressureStep::New(coeffs, *this, system);
    Info<< "fbm: coupling " << type() << ": pressureSolve "
        << pressureStep_->type()
        << (coeffs.found("pressureSolve", keyType::LITERAL)
            ? "" : " (default)") << nl;

    if (mesh.nSolutionD() == 2)
    {
        const Vector<label>& sd = mesh.solutionD();
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            planeMask_[d] = (sd[d] < 0) ? 0 : 1;
            axisMask_[d] = 1 - planeMask_[d];
        }
    }

    const PtrList<body>& bodies = system.bodies();
    forAll(bodies, bi)
    {
        heavy_[bi] = bodies[bi].translates();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fbm::couplingModels::semiImplicit::beforeFlow()
{
    // The state of the last step, before the bodies are advanced
    PtrList<body>& bodies = system_.bodies();
    const label nb = bodies.size();
    List<vector> U0(nb), a0(nb), omega0(nb), omegaDot0(nb);
    List<vector> a00(nb), omegaDot00(nb);
    forAll(bodies, bi)
    {
        const bodyState& s = bodies[bi].state();
        U0[bi] = s.U();
        a0[bi] = s.acceleration();
        omega0[bi] = s.omega();
        omegaDot0[bi] = s.angularAcceleration();
        a00[bi] = s.acceleration00();
        omegaDot00[bi] = s.angularAcceleration00();
    }

    const bool inside = system_.advance();

    // The shell of fluid the penalty moves with a body, and the fluid the
    // viscous stress drags with it within a step, are part of the force
    // model's force as their inertia -m a of the last step: advance them
    // with the body, (M + m)(U - U^n) = M (U* - U^n) + dt m a^n (and
    // likewise the rotation), so that this inertia is not lagged
    //
    // With backward the force held the shell's inertia at the fluid's
    // rate of the last step, -m_s D^n, D^n = (1 + w^n) a^n - w^n a^{n-1},
    // and the shell's rate in this step is D = (1 + w) a - w a^n
    // (fbm::fluidRate): (M + (1 + w) m_s + m_d)(U - U^n) = M (U* - U^n) +
    // dt (m_s (D^n + w a^n) + m_d a^n), m_d the damping mass, whose lagged
    // force is a velocity's response, not a rate; Euler (w = w^n = 0) is
    // the line above, bit for bit
    //
    // With bodyScheme fluid the body's own velocity takes the fluid's rate
    // too, M D = F (BDF2 with backward): its mass counts 1 + w and its
    // last acceleration w M a^n joins the right-hand side (system_.advance()
    // stepped U* with Euler's M (U* - U^n) = dt F)
    const fluidRate* rate = system_.rate();
    const scalar w = rate ? rate->weight() : 0;
    const scalar w0 = rate ? rate->weight0() : 0;
    if (lastStepKnown_)
    {
        const scalar dt = system_.mesh().time().deltaTValue();
        bool changed = false;
        forAll(bodies, bi)
        {
            const scalar m = inertia_.mass(bi);
            if (!heavy_[bi] || (m <= 0 && bodyRate() == 1)) continue;

            body& b = bodies[bi];
            bodyState& s = b.state();
            const scalar M = b.rho()*b.shape().volume();
            const scalar ms = inertia_.shellMass(bi);
            const vector dU
            (
                (w == 0 && w0 == 0)
              ? (M*(s.U() - U0[bi]) + dt*m*a0[bi])/(M + m)
              : (
                    M*(s.U() - U0[bi])
                  + dt*(bodyRate() - 1)*M*a0[bi]
                  + dt*
                    (
                        ms*((1 + w0)*a0[bi] - w0*a00[bi] + w*a0[bi])
                      + (m - ms)*a0[bi]
                    )
                )/inertia_.totalMass(bi, bodyRate()*M, 1 + w)
            );
            s.U() = U0[bi] + cmptMultiply(planeMask_, dU);
            s.acceleration() = (s.U() - U0[bi])/dt;
            if (b.rotates())
            {
                const symmTensor& Js = inertia_.shellInertia(bi);
                const vector L
                (
                    (w == 0 && w0 == 0)
                  ? (b.inertia() & (s.omega() - omega0[bi]))
                  + dt*(inertia_.inertia(bi) & omegaDot0[bi])
                  : (b.inertia() & (s.omega() - omega0[bi]))
                  + dt*(bodyRate() - 1)*(b.inertia() & omegaDot0[bi])
                  + dt*
                    (
                        (
                            Js
                          & (
                                (1 + w0)*omegaDot0[bi] - w0*omegaDot00[bi]
                              + w*omegaDot0[bi]
                            )
                        )
                      + ((inertia_.inertia(bi) - Js) & omegaDot0[bi])
                    )
                );
                s.omega() = omega0[bi] + angularImpulse(bi, L);
                s.angularAcceleration() = (s.omega() - omega0[bi])/dt;
            }
            changed = true;
        }
        if (changed)
        {
            system_.fb().updateVelocity();
        }
    }

    return inside;
}


void Foam::fbm::couplingModels::semiImplicit::estimateMaxDeltaT
(
    const volScalarField& nuEff
)
{
    limit_.estimate(nuEff, system_.fb(), heavy_);
}


void Foam::fbm::couplingModels::semiImplicit::constrain
(
    fvMatrix<vector>& UEqn
) const
{
    // The damping mass of this step and the viscous limit of the next,
    // both read off the momentum matrix
    inertia_.measureDamping(UEqn, heavy_);
    limit_.update(UEqn, system_.fb(), heavy_, system_.rate());
}


bool Foam::fbm::couplingModels::semiImplicit::afterFlow
(
    volVectorField& U,
    List<vector>& force,
    List<vector>& torque
)
{
    holdForces(force, torque);
    return true;
}


// ************************************************************************* //
