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
#include "correctCoupled.H"
#include "scratchField.H"
#include "fvMatrices.H"
#include "fvcGrad.H"
#include "fvcFlux.H"
#include "fvcSnGrad.H"
#include "surfaceInterpolate.H"

// The pressure step of coupling semiImplicit: the heavy bodies' cells
// respond to the pressure in each corrector (constrainPressureStep) and
// the bodies take the pressure impulse of the step (beforeForces)


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
    corrector_ = 0;
}


void Foam::fbm::couplingModels::semiImplicit::reportForceChange
(
    const label n,
    const List<vector>& before,
    const List<vector>& after
) const
{
    scalar change = 0;
    scalar size = 0;
    forAll(after, bi)
    {
        if (!heavy_[bi]) continue;
        change += magSqr(after[bi] - before[bi]);
        size += magSqr(after[bi]);
    }
    Info<< "fbm: semiImplicit: pressure corrector " << n
        << " changed the bodies' pressure force by "
        << (size > 0 ? Foam::sqrt(change/size) : scalar(0))
        << " (relative)" << endl;
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
    List<vector> before;
    if (debug && !newStep)
    {
        before = lastForce_;
    }
    pressureForces(gradP, lastForce_, lastTorque_);
    ++corrector_;
    if (debug && !newStep)
    {
        reportForceChange(corrector_ - 1, before, lastForce_);
    }

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
    // The pressure step may make a body's cells rigid in the pressure
    // equation (no compliance; pressureSolve newton): they take its
    // estimate of the rigid velocity of the step's pressure force in place
    // of that of the last step (solvePressure() improves the estimate
    // after each corrector; the first is the last step's force)
    pressureStep_->correct
    (
        newStep, cells_, weight_, pressureForce_, pressureTorque_
    );
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const label bi = label(id[celli]);
        const scalar w = weight_[i];
        lastGradP_[i] = gradP[celli];
        if (pressureStep_->rigid(bi))
        {
            dRigidi[celli] = w*
            (
                pressureStep_->velocity(i)
              - rigidImpulse
                (
                    bi, pressureForce_[bi], pressureTorque_[bi], C[celli]
                )
            );
            HbyAi[celli] += dRigidi[celli];
            continue;
        }
        const scalar tau = responseTime(bi);
        rAtUi[celli] += w*tau;
        wTaui[celli] = w*tau;
        dRigidi[celli] = w*
        (
            rigidImpulse(bi, lastForce_[bi], lastTorque_[bi], C[celli])
          - rigidImpulse(bi, pressureForce_[bi], pressureTorque_[bi], C[celli])
        );
        HbyAi[celli] += wTaui[celli]*gradP[celli] + dRigidi[celli];
    }
    fluxForce_ = lastForce_;
    fluxTorque_ = lastTorque_;
    cellForce_ = lastForce_;
    cellTorque_ = lastTorque_;

    // Processor and cyclic neighbours take the new values
    correctCoupled(rAtU);
    correctCoupled(wTau);
    correctCoupled(dRigid);
    correctCoupled(HbyA);
    phiHbyA +=
        fvc::flux(dRigid)
      + fvc::interpolate(wTau)*fvc::snGrad(p)*mesh.magSf();
}


void Foam::fbm::couplingModels::semiImplicit::solvePressure
(
    fvScalarMatrix& pEqn,
    volScalarField& p,
    const volScalarField& rAtU,
    const dictionary& solverDict,
    const label refCell
)
{
    // The pressure step solves it (fluxForce_, the force whose rigid
    // velocity the flux took, changes in its rigid bodies' motion)
    pressureStep_->solve
    (
        pEqn, p, rAtU, solverDict, refCell, fluxForce_, fluxTorque_
    );
}


void Foam::fbm::couplingModels::semiImplicit::correctVelocity
(
    volVectorField& U
)
{
    // The cells hold the rigid velocity the corrector's flux was solved
    // with; a rigid body of the pressure step (pressureSolve newton) has a
    // new estimate after the corrector's Newton step. Its cells take it
    // now, so that the next corrector's H (the fluid's momentum coupling
    // to the body's cells, viscous and convective) sees the estimate that
    // corrector's pressure is solved with. Without this the fluid beside a
    // light body lagged a corrector behind it: a disk of rho_s/rho_f 0.55
    // at viscous ratios of 1 and above diverged with two PISO correctors,
    // and so did Xia et al.'s ellipse (validation/semiImplicitHistory.md)
    cellForce_ = fluxForce_;
    cellTorque_ = fluxTorque_;
    pressureStep_->stepForces(cellForce_, cellTorque_);

    const scalarField& id = system_.fb().bodyID();
    const vectorField& C = system_.mesh().C().primitiveField();
    vectorField& u = U.primitiveFieldRef();
    bool changed = false;
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const label bi = label(id[celli]);
        if (!pressureStep_->rigid(bi)) continue;

        u[celli] += weight_[i]*
        (
            rigidImpulse(bi, cellForce_[bi], cellTorque_[bi], C[celli])
          - rigidImpulse(bi, fluxForce_[bi], fluxTorque_[bi], C[celli])
        );
        changed = true;
    }
    if (returnReduce(changed, orOp<bool>()))
    {
        U.correctBoundaryConditions();
    }
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
    if (impulse_ == impulseForm::final || debug)
    {
        pressureForces(gradP, P, Q);
        if (debug)
        {
            reportForceChange(corrector_, lastForce_, P);
        }
    }
    if (impulse_ == impulseForm::solved)
    {
        P = fluxForce_;
        Q = fluxTorque_;
    }
    else
    {
        // The pressure step's estimate of the step's pressure force (its
        // rigid bodies; pressureSolve newton)
        pressureStep_->stepForces(P, Q);
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
        const scalar tau =
            pressureStep_->rigid(bi) ? scalar(0) : responseTime(bi);
        u[celli] += weight_[i]*
        (
            tau*(gradP[celli] - lastGradP_[i])
          + Rnew
          - rigidImpulse(bi, cellForce_[bi], cellTorque_[bi], C[celli])
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
        const scalar M =
            inertia_.totalMass(bi, bodyRate()*b.rho()*b.shape().volume(), c);
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


// ************************************************************************* //
