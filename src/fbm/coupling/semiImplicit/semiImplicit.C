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
#include "fvcGrad.H"
#include "fvcFlux.H"
#include "fvcSnGrad.H"
#include "surfaceInterpolate.H"
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


// Largest share of the body's inertia that the lagged direct force may
// take (below 1: the stability bound of a lagged mass; 0.9 leaves the
// bodies down to rho_s/rho_f of about 1.1 untouched)
const Foam::scalar
Foam::fbm::couplingModels::semiImplicit::maxDirectMass_ = 0.9;

// The default of maxViscousRatio (semiImplicitCoeffs)
const Foam::scalar
Foam::fbm::couplingModels::semiImplicit::defaultMaxViscousRatio_ = 1.6;


// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The coupled patches (processor, cyclic) of a field take the new cell
// values; the other patches keep theirs (HbyA's wall values are the
// constrained ones of constrainHbyA)
template<class Type>
void correctCoupled
(
    Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& fld
)
{
    using namespace Foam;
    typename GeometricField<Type, fvPatchField, volMesh>::Boundary& bf =
        fld.boundaryFieldRef();

    const Pstream::commsTypes commsType =
        (Pstream::defaultCommsType == Pstream::commsTypes::nonBlocking)
      ? Pstream::commsTypes::nonBlocking
      : Pstream::commsTypes::blocking;

    const label nReq = Pstream::nRequests();
    forAll(bf, patchi)
    {
        if (bf[patchi].coupled())
        {
            bf[patchi].initEvaluate(commsType);
        }
    }
    if (commsType == Pstream::commsTypes::nonBlocking && Pstream::parRun())
    {
        Pstream::waitRequests(nReq);
    }
    forAll(bf, patchi)
    {
        if (bf[patchi].coupled())
        {
            bf[patchi].evaluate(commsType);
        }
    }
}

// A zero field of the mesh, not registered and not written: the scratch
// fields of the pressure step
template<class Type>
Foam::tmp<Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>>
scratchField
(
    const Foam::word& name,
    const Foam::fvMesh& mesh,
    const Foam::dimensionSet& dims
)
{
    using namespace Foam;
    return tmp<GeometricField<Type, fvPatchField, volMesh>>::New
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensioned<Type>(dims, Zero)
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::couplingModels::semiImplicit::startStep
(
    const volScalarField& p
)
{
    const fictitiousBoundary& fb = system_.fb();
    const scalarField& id = fb.bodyID();

    DynamicList<label> cells(fb.activeCells().size());
    for (const label celli : fb.activeCells())
    {
        const label bi = label(id[celli]);
        if (bi >= 0 && heavy_[bi])
        {
            cells.append(celli);
        }
    }
    cells_.transfer(cells);
    weight_.setSize(cells_.size());
    weight_ = 0;
    lastGradP_.setSize(cells_.size());
    lastGradP_ = Zero;

    timeIndex_ = system_.mesh().time().timeIndex();
}


void Foam::fbm::couplingModels::semiImplicit::pressureForces
(
    const volVectorField& gradP,
    List<vector>& P,
    List<vector>& Q
) const
{
    const PtrList<body>& bodies = system_.bodies();
    const vectorField& C = system_.mesh().C().primitiveField();
    const scalarField& V = system_.mesh().V();
    const scalarField& id = system_.fb().bodyID();
    const scalar rhoFluid = system_.rhoFluid();

    P.setSize(bodies.size());
    Q.setSize(bodies.size());
    P = Zero;
    Q = Zero;
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const label bi = label(id[celli]);
        const vector f(-rhoFluid*weight_[i]*V[celli]*gradP[celli]);
        P[bi] += f;
        Q[bi] += (C[celli] - bodies[bi].centre()) ^ f;
    }
    sumOverProcessors(P);
    sumOverProcessors(Q);

    forAll(bodies, bi)
    {
        P[bi] = cmptMultiply(planeMask_, P[bi]);
        Q[bi] = cmptMultiply(axisMask_, Q[bi]);
    }
}


Foam::scalar Foam::fbm::couplingModels::semiImplicit::shellRate() const
{
    const fluidRate* rate = system_.rate();
    return rate ? 1 + rate->weight() : 1;
}


Foam::scalar Foam::fbm::couplingModels::semiImplicit::responseTime
(
    const label bi
) const
{
    // dt rho_f/rho of body and shell together: mass M + m in the volume
    // V_b + m/rho_f (the shell's inertia at the fluid's rate)
    const body& b = system_.bodies()[bi];
    const scalar Vb = b.shape().volume();
    return
        system_.mesh().time().deltaTValue()
       *(system_.rhoFluid()*Vb + inertia_.shellMass(bi))
       /inertia_.totalMass(bi, b.rho()*Vb, shellRate());
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
        inertia_.totalMass(bi, b.rho()*b.shape().volume(), shellRate());
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
    const symmTensor I(inertia_.totalInertia(bi, b.inertia(), shellRate()));
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
    heavy_(system.bodies().size(), false),
    timeIndex_(-1),
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

    // The pressure force the bodies take at the end of a step
    const dictionary& coeffs = dict.optionalSubDict(typeName + "Coeffs");
    const bool impulseGiven = coeffs.found("impulse", keyType::LITERAL);
    if (impulseGiven)
    {
        const word form(coeffs.get<word>("impulse", keyType::LITERAL));
        if (!impulseFormNames.found(form))
        {
            FatalIOErrorInFunction(coeffs)
                << "impulse " << form << " in " << coeffs.name()
                << " is not one of "
                << flatOutput(impulseFormNames.toc()) << nl
                << "    final: the pressure force of the final pressure;"
                << " solved: the one the last pressure corrector was"
                << " solved with"
                << exit(FatalIOError);
        }
        impulse_ = impulseFormNames[form];
    }
    Info<< "fbm: coupling " << type() << ": impulse "
        << impulseFormNames[impulse_] << (impulseGiven ? "" : " (default)")
        << nl;

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
            if (!heavy_[bi] || m <= 0) continue;

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
                  + dt*
                    (
                        ms*((1 + w0)*a0[bi] - w0*a00[bi] + w*a0[bi])
                      + (m - ms)*a0[bi]
                    )
                )/inertia_.totalMass(bi, M, 1 + w)
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


void Foam::fbm::couplingModels::semiImplicit::constrainPressureStep
(
    const volScalarField& rAU,
    volScalarField& rAtU,
    volVectorField& HbyA,
    surfaceScalarField& phiHbyA,
    const volScalarField& p
)
{
    const fvMesh& mesh = system_.mesh();
    const bool newStep = (timeIndex_ != mesh.time().timeIndex());
    if (newStep)
    {
        startStep(p);
    }

    // The rigid share w of a penalised cell: with the penalty lambda on
    // the diagonal a_P + lambda, rAU = V/(a_P + lambda), w = lambda rAU/V
    const fictitiousBoundary& fb = system_.fb();
    const scalarField& lambda = fb.lambda();
    const scalarField& id = fb.bodyID();
    const scalarField& V = mesh.V();
    const vectorField& C = mesh.C().primitiveField();
    const scalarField& rAUi = rAU.primitiveField();
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        weight_[i] = lambda[celli]*rAUi[celli]/V[celli];
    }

    // The pressure force before this corrector
    const volVectorField gradP(fvc::grad(p));
    pressureForces(gradP, lastForce_, lastTorque_);

    if (newStep && !lastStepKnown_)
    {
        // The first step of a run without the last step's state: the
        // pressure force of the present pressure on the new footprint,
        // and no shell (the bodies were advanced without it; the shell of
        // this step is taken from the next step on)
        pressureForce_ = lastForce_;
        pressureTorque_ = lastTorque_;
        inertia_.clear();
        lastStepKnown_ = true;
    }

    // The rigid share responds to the pressure as body and shell do, as
    // matter of their mean density (1/A += w tau in the pressure
    // equation). HbyA takes the pressure impulse of the last step out of
    // the body's velocity (the step's own pressure puts the new one back),
    // and adds the response to the pressure p before this corrector less
    // its rigid part, so that the body's cells deform only by the change
    // of the pressure over the corrector, not by the whole non-uniform
    // pressure gradient (which would drive a spurious flux through the
    // body every step). The flux takes the same change, its response part
    // in the face form of the pressure equation's own term, w tau snGrad p
    // (as PIMPLE consistent adds its (rAtU - rAU) snGrad p): the two
    // cancel when the pressure stops changing. The flux of the cells'
    // w tau grad p instead (until 2026-12-05) left their difference, a
    // flux through the body's interface proportional to the step that
    // stayed in a steady state: the settling disk at R/h 6 (level 4,
    // backward) settled 0.27 % slower at its step than at half of it
    volScalarField wTau(scratchField<scalar>("wTau", mesh, rAtU.dimensions()));
    volVectorField dRigid
    (
        scratchField<vector>("dRigid", mesh, HbyA.dimensions())
    );
    scalarField& rAtUi = rAtU.primitiveFieldRef();
    scalarField& wTaui = wTau.primitiveFieldRef();
    vectorField& dRigidi = dRigid.primitiveFieldRef();
    vectorField& HbyAi = HbyA.primitiveFieldRef();
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const label bi = label(id[celli]);
        const scalar w = weight_[i];
        const scalar tau = responseTime(bi);
        lastGradP_[i] = gradP[celli];
        rAtUi[celli] += w*tau;
        wTaui[celli] = w*tau;
        dRigidi[celli] = w*
        (
            rigidImpulse(bi, lastForce_[bi], lastTorque_[bi], C[celli])
          - rigidImpulse(bi, pressureForce_[bi], pressureTorque_[bi], C[celli])
        );
        HbyAi[celli] += wTaui[celli]*gradP[celli] + dRigidi[celli];
    }

    // Processor and cyclic neighbours take the new values
    correctCoupled(rAtU);
    correctCoupled(wTau);
    correctCoupled(dRigid);
    correctCoupled(HbyA);
    phiHbyA +=
        fvc::flux(dRigid)
      + fvc::interpolate(wTau)*fvc::snGrad(p)*mesh.magSf();
}


void Foam::fbm::couplingModels::semiImplicit::beforeForces
(
    volVectorField& U,
    const volScalarField& p
)
{
    const fvMesh& mesh = system_.mesh();
    directForce_ = Zero;
    directTorque_ = Zero;
    if (timeIndex_ != mesh.time().timeIndex())
    {
        // No pressure corrector in this step
        return;
    }

    PtrList<body>& bodies = system_.bodies();
    const volVectorField gradP(fvc::grad(p));

    // The pressure force of the step: that of the final pressure, or the
    // one the last corrector's pressure equation was solved with, so that
    // the bodies move as the fluid's flux around them says (impulse
    // solved: the rest of the final pressure's force reaches them a step
    // later through the force model's force, and the impulses telescope
    // over the steps as before)
    List<vector> P, Q;
    if (impulse_ == impulseForm::solved)
    {
        P = lastForce_;
        Q = lastTorque_;
    }
    else
    {
        pressureForces(gradP, P, Q);
    }

    // The bodies' new velocities: the pressure force of the last step
    // replaced by that of this one (and the accelerations of the step)
    const scalar dt = mesh.time().deltaTValue();
    forAll(bodies, bi)
    {
        if (!heavy_[bi]) continue;

        body& b = bodies[bi];
        bodyState& s = b.state();
        const vector dU
        (
            rigidImpulse(bi, P[bi] - pressureForce_[bi], Zero, b.centre())
        );
        const vector dOmega
        (
            angularImpulse(bi, dt*(Q[bi] - pressureTorque_[bi]))
        );
        s.U() += dU;
        s.acceleration() += dU/dt;
        s.omega() += dOmega;
        s.angularAcceleration() += dOmega/dt;
    }

    // The rigid share of the bodies' cells moves with the new velocity
    // instead of its response to the pressure in the last corrector, and
    // U.solid is that velocity: the force model sees the flow as the
    // penalty at the new velocity would have left it (the momentum
    // exchange lambda (u - u_s) then holds the body's rate of change of
    // velocity and the new pressure)
    // The cells' velocity is then the plain pressure step's plus w times
    // the rigid velocity of the pressure impulse R(P) - R(P^n): a force
    // on the enclosed fluid besides the penalty (directForce())
    const vectorField& C = mesh.C().primitiveField();
    const scalarField& V = mesh.V();
    const scalarField& id = system_.fb().bodyID();
    const scalar rhoFluid = system_.rhoFluid();
    vectorField& u = U.primitiveFieldRef();
    scalarList pushedMass(bodies.size(), Zero);
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const label bi = label(id[celli]);
        pushedMass[bi] += rhoFluid*weight_[i]*V[celli];
        const vector Rnew(rigidImpulse(bi, P[bi], Q[bi], C[celli]));
        u[celli] += weight_[i]*
        (
            responseTime(bi)*(gradP[celli] - lastGradP_[i])
          + Rnew
          - rigidImpulse(bi, lastForce_[bi], lastTorque_[bi], C[celli])
        );
        const vector f
        (
            rhoFluid*weight_[i]*V[celli]/dt
           *(
                Rnew
              - rigidImpulse
                (
                    bi, pressureForce_[bi], pressureTorque_[bi], C[celli]
                )
            )
        );
        directForce_[bi] += f;
        directTorque_[bi] += (C[celli] - bodies[bi].centre()) ^ f;
    }
    sumOverProcessors(directForce_);
    sumOverProcessors(directTorque_);
    sumOverProcessors(pushedMass);

    // The enclosed fluid's rate holds the cells' push at the fluid's rate:
    // with backward (1 + w) times this step's and -w times the last step's
    // (Euler: this step's, bit for bit)
    lastDirectForceEuler_ = directForceEuler_;
    lastDirectTorqueEuler_ = directTorqueEuler_;
    directForceEuler_ = directForce_;
    directTorqueEuler_ = directTorque_;
    if (const fluidRate* rate = system_.rate())
    {
        forAll(bodies, bi)
        {
            directForce_[bi] =
                rate->rate(directForceEuler_[bi], lastDirectForceEuler_[bi]);
            directTorque_[bi] =
                rate->rate
                (
                    directTorqueEuler_[bi], lastDirectTorqueEuler_[bi]
                );
        }
    }

    // The direct force reaches the body one step later, as a lagged mass
    // m_d = rho_f sum w V on the pressure part of its acceleration; a
    // lagged mass above the body's inertia makes the update unstable (a
    // light disk, rho_s/rho_f 0.5, swung by a factor of 4 at dt 2.5e-4,
    // where the damping mass is small), so it is kept at most
    // maxDirectMass_ times the inertia M + m of the step. With backward
    // the lagged mass is the fluid's rate coefficient 1 + w times m_d
    // (the light disk at dt 1e-3 drifted off its rising speed, 8.30
    // against 8.60-8.68 at the other steps, with m_d alone)
    const scalar c = shellRate();
    forAll(bodies, bi)
    {
        if (!heavy_[bi] || pushedMass[bi] <= 0) continue;
        const body& b = bodies[bi];
        const scalar M = inertia_.totalMass(bi, b.rho()*b.shape().volume(), c);
        const scalar f = min(scalar(1), maxDirectMass_*M/(c*pushedMass[bi]));
        directForce_[bi] *= f;
        directTorque_[bi] *= f;
    }
    U.correctBoundaryConditions();
    system_.fb().updateVelocity();

    // For the next step: this step's pressure force and shell
    pressureForce_ = P;
    pressureTorque_ = Q;
    inertia_.update(cells_, weight_);
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


void Foam::fbm::couplingModels::semiImplicit::readState
(
    const dictionary& state
)
{
    // The viscous limit of the step after the restart time
    if (stateHasEntry(state, "viscousDeltaT"))
    {
        limit_.read(state.subDict(system_.bodies()[0].name()));
    }

    // The pressure force and the shell of the step that led to the
    // restart time
    const PtrList<body>& bodies = system_.bodies();
    if (stateHasEntry(state, "pressureForce"))
    {
        forAll(bodies, bi)
        {
            const dictionary& d = state.subDict(bodies[bi].name());
            pressureForce_[bi] = d.get<vector>("pressureForce");
            pressureTorque_[bi] = d.get<vector>("pressureTorque");
            inertia_.read(bi, d);
        }
        lastStepKnown_ = true;
    }
    else
    {
        Info<< "fbm: coupling " << type() << ": no pressureForce in "
            << state.name() << "; the first step takes that of the"
            << " restart pressure on the moved bodies" << nl;
    }

    // With backward: the push of the bodies' cells in the step that led
    // to the restart time, which the enclosed fluid's rate of the next
    // step holds too (written with backward only)
    if (stateHasEntry(state, "directForceEuler"))
    {
        forAll(bodies, bi)
        {
            const dictionary& d = state.subDict(bodies[bi].name());
            directForceEuler_[bi] = d.get<vector>("directForceEuler");
            directTorqueEuler_[bi] = d.get<vector>("directTorqueEuler");
        }
    }
    else if
    (
        lastStepKnown_
     && system_.mesh().ddtScheme("ddt(U)")[0].wordToken() == "backward"
    )
    {
        Info<< "fbm: coupling " << type() << ": no directForceEuler in "
            << state.name() << " (a state written with Euler); with"
            << " backward the first step takes the last step's push of the"
            << " bodies' cells as zero" << nl;
    }
}


void Foam::fbm::couplingModels::semiImplicit::writeState
(
    const label bi,
    Ostream& os
) const
{
    if (lastStepKnown_)
    {
        os.writeEntry("pressureForce", pressureForce_[bi]);
        os.writeEntry("pressureTorque", pressureTorque_[bi]);
        inertia_.write(bi, os);
    }
    const fluidRate* rate = system_.rate();
    if (rate && rate->timeScheme() == fluidRate::scheme::backward)
    {
        os.writeEntry("directForceEuler", directForceEuler_[bi]);
        os.writeEntry("directTorqueEuler", directTorqueEuler_[bi]);
    }
    // The viscous limit of the next step (the same for every body)
    limit_.write(os);
}


// ************************************************************************* //
