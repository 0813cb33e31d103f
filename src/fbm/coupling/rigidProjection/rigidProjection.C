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

#include "rigidProjection.H"
#include "sumOverProcessors.H"
#include "bodySystem.H"
#include "fvMatrices.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace couplingModels
{
    defineTypeNameAndDebug(rigidProjection, 0);
    addToRunTimeSelectionTable(couplingModel, rigidProjection, dictionary);
}
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

const Foam::List<Foam::vector>*
Foam::fbm::couplingModels::rigidProjection::projectedContactForces() const
{
    if
    (
        projectContacts_ && system_.hasCollisions()
     && projectedForce_.size() == system_.bodies().size()
    )
    {
        return &projectedForce_;
    }
    return nullptr;
}


const Foam::List<Foam::vector>*
Foam::fbm::couplingModels::rigidProjection::projectedContactTorques() const
{
    if
    (
        projectedContactForces()
     && projectedTorque_.size() == system_.bodies().size()
    )
    {
        return &projectedTorque_;
    }
    return nullptr;
}


Foam::vector
Foam::fbm::couplingModels::rigidProjection::contactAngularAcceleration
(
    const body& b,
    const vector& Tc
) const
{
    // dw = I^-1 Tc with the body's inertia in the world frame; in 2D the
    // rotation about the empty direction only (as
    // fbm::rigidBodyMotion::angularAcceleration)
    return system_.motion().planeRotation(inv(b.inertia()) & Tc);
}


void Foam::fbm::couplingModels::rigidProjection::relaxProjectedForce()
{
    if (!projectedContactForces())
    {
        return;
    }
    const particleCollisions& collisions = system_.collisions();
    const List<vector>& Fc = collisions.meanForce();
    const List<vector>& Tc = collisions.meanTorque();
    if (contactRelaxation_ == 1)
    {
        projectedForce_ = Fc;
        projectedTorque_ = Tc;
    }
    else
    {
        forAll(projectedForce_, bi)
        {
            projectedForce_[bi] +=
                contactRelaxation_*(Fc[bi] - projectedForce_[bi]);
        }
        // Round bodies: Tc and p_T zero, left alone (no round-off)
        forAll(projectedTorque_, bi)
        {
            if (Tc[bi] != vector::zero || projectedTorque_[bi] != vector::zero)
            {
                projectedTorque_[bi] +=
                    contactRelaxation_*(Tc[bi] - projectedTorque_[bi]);
            }
        }
    }
}


void Foam::fbm::couplingModels::rigidProjection::projectionForces
(
    const volVectorField& U,
    List<vector>& force,
    List<vector>& torque
) const
{
    // Over the cells of each projected body (fractions a):
    // - the momentum the body's share gained over the step,
    //   dP = sum a V (u - u^0), and its moment dL;
    // - for the rigid blend at the end of the step, which also moves the
    //   fluid share (1 - a) of partly covered cells towards the body's
    //   motion (an impulse the body gives): with w = (1 - a) a V,
    //   K = sum w, Ku = sum w u, and for the rotation KJ = sum w (|r|^2 I
    //   - r r), Lu = sum w r x u
    const fvMesh& mesh = system_.mesh();
    const PtrList<body>& bodies = system_.bodies();
    const vectorField& u = U.primitiveField();
    const vectorField& u0 = U.oldTime().primitiveField();
    const vectorField& C = mesh.C().primitiveField();
    const scalarField& V = mesh.V();

    const label nb = bodies.size();
    List<vector> dP(nb, Zero), dL(nb, Zero), Ku(nb, Zero), Lu(nb, Zero);
    scalarList K(nb, Zero);
    List<symmTensor> KJ(nb, Zero);
    forAll(bodies, bi)
    {
        if (!projected(bi)) continue;

        const body& b = bodies[bi];
        const labelList& cells = b.cells();
        const scalarList& a = b.alpha();
        forAll(cells, i)
        {
            const label celli = cells[i];
            const vector r(C[celli] - b.centre());
            const vector du(a[i]*V[celli]*(u[celli] - u0[celli]));
            dP[bi] += du;
            dL[bi] += r ^ du;

            const scalar w = (1 - a[i])*a[i]*V[celli];
            K[bi] += w;
            Ku[bi] += w*u[celli];
            KJ[bi] += w*(magSqr(r)*symmTensor::I - sqr(r));
            Lu[bi] += w*(r ^ u[celli]);
        }
    }
    for (List<vector>* l : {&dP, &dL, &Ku, &Lu})
    {
        sumOverProcessors(*l);
    }
    sumOverProcessors(K);
    sumOverProcessors(KJ);

    // The body's new velocity conserves the momentum of the body and of
    // the fluid share the blend moves:
    //     M U + rho_f (K U - Ku) = M U^0 + rho_s dP,
    // and likewise, per principal axis, its angular velocity. The force
    // is the body's rate of change of momentum less its submerged weight,
    // which the equations of motion add back.
    const List<vector>* Fc = projectedContactForces();
    const List<vector>* Tc = projectedContactTorques();
    const scalar rhoFluid = system_.rhoFluid();
    const vector& g = system_.motion().g();

    const scalar dt = mesh.time().deltaTValue();
    forAll(bodies, bi)
    {
        if (!projected(bi)) continue;

        const body& b = bodies[bi];
        const scalar Vb = b.shape().volume();
        const scalar M = b.rho()*Vb;

        const vector Unew
        (
            (M*b.U() + b.rho()*dP[bi] + rhoFluid*Ku[bi])
           /(M + rhoFluid*K[bi])
        );
        force[bi] = M*(Unew - b.U())/dt - (M - rhoFluid*Vb)*g;
        if (Fc)
        {
            // The contacts act again in the sub-steps that follow
            force[bi] -= (*Fc)[bi];
        }

        const symmTensor I(b.inertia());
        const vector Lnew(b.rho()*dL[bi] + rhoFluid*Lu[bi]);
        vector wNew(b.omega());
        const direction diagCmpt[3] =
            { symmTensor::XX, symmTensor::YY, symmTensor::ZZ };
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            const scalar Idd = I.component(diagCmpt[d]);
            if (Idd <= 0) continue;
            const scalar Kdd = rhoFluid*KJ[bi].component(diagCmpt[d]);
            wNew[d] = (Idd*b.omega()[d] + Lnew[d])/(Idd + Kdd);
        }
        torque[bi] = (I & (wNew - b.omega()))/dt;
        if (Tc && (*Tc)[bi] != vector::zero)
        {
            // The contact torque acts again in the sub-steps (zero, and
            // left alone, for round bodies). The flow solve gave the body
            // the angular momentum I dw dt = Tc dt (dw = I^-1 Tc), which
            // the balance above turned into a torque per axis: that is
            // what is taken out (Tc itself in 2D, where the empty axis is
            // decoupled; in 3D the same per-axis balance as the
            // hydrodynamic torque's, so the contact torque cancels)
            const vector Lc(I & contactAngularAcceleration(b, (*Tc)[bi]));
            vector dwc(Zero);
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                const scalar Idd = I.component(diagCmpt[d]);
                if (Idd > 0) dwc[d] = Lc[d]/Idd;
            }
            torque[bi] -= I & dwc;
        }
    }
}


void Foam::fbm::couplingModels::rigidProjection::rigidify
(
    volVectorField& U,
    const labelList& cells,
    const scalarList& alpha,
    const labelList& id,
    const List<point>& centres
) const
{
    const PtrList<body>& bodies = system_.bodies();
    vectorField& u = U.primitiveFieldRef();
    const vectorField& C = system_.mesh().C().primitiveField();

    forAll(cells, i)
    {
        const label bi = id[i];
        if (bi < 0 || !projected(bi)) continue;

        const body& b = bodies[bi];
        const label celli = cells[i];
        const vector Ub(b.U() + (b.omega() ^ (C[celli] - centres[bi])));
        u[celli] = (1 - alpha[i])*u[celli] + alpha[i]*Ub;
    }
    U.correctBoundaryConditions();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::couplingModels::rigidProjection::rigidProjection
(
    const dictionary& dict,
    bodySystem& system
)
:
    couplingModel(dict, system),
    projectContacts_
    (
        dict.getOrDefault<bool>("projectContacts", dict.isDict("collisions"))
    ),
    contactRelaxation_
    (
        dict.getCheckOrDefault<scalar>
        (
            "contactRelaxation", 1, [](scalar b){ return b > 0 && b <= 1; }
        )
    )
{
    if (!projectContacts_ && dict.found("contactRelaxation"))
    {
        FatalIOErrorInFunction(dict)
            << "contactRelaxation without projectContacts in "
            << dict.name() << nl
            << "    It relaxes the contact forces that projectContacts puts"
            << " into the flow solve: remove it or set projectContacts yes"
            << exit(FatalIOError);
    }

    // The added mass is in the fluid solve: no virtual-mass term
    rejectAddedMassCoeff();

    requireEuler
    (
        "The extra inertia of the bodies is an implicit Euler term of the"
        " momentum matrix."
    );

    const PtrList<body>& bodies = system.bodies();
    forAll(bodies, bi)
    {
        penalised_[bi] = !(bodies[bi].translates() || bodies[bi].rotates());
    }

    if (projectContacts_)
    {
        Info<< "fbm: projectContacts: contactRelaxation "
            << contactRelaxation_ << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::fbm::couplingModels::rigidProjection::description() const
{
    return type() + (projectContacts_ ? " (projectContacts)" : "");
}


void Foam::fbm::couplingModels::rigidProjection::start()
{
    if (!projectContacts_ || !system_.hasCollisions())
    {
        return;
    }

    particleCollisions& collisions = system_.collisions();
    if (restartForce_.size())
    {
        collisions.setMeanForce(restartForce_);
        projectedForce_ = restartForce_;
        Info<< "fbm: projectContacts: contact forces of the last step"
            << " read with the body state" << nl;
        if (restartTorque_.size())
        {
            collisions.setMeanTorque(restartTorque_);
            Info<< "fbm: projectContacts: contact torques of the last step"
                << " read with the body state" << nl;
        }
        else
        {
            // An earlier state without contactTorque: the torques at the
            // restart positions (zero for round bodies)
            collisions.initMeanTorque(system_.bodies());
        }
        projectedTorque_ = collisions.meanTorque();
    }
    else
    {
        collisions.initMeanForce(system_.bodies());
        projectedForce_ = collisions.meanForce();
        projectedTorque_ = collisions.meanTorque();
    }
}


void Foam::fbm::couplingModels::rigidProjection::constrain
(
    fvMatrix<vector>& UEqn
) const
{
    // The cells of the projected bodies: no penalty, but the body's extra
    // inertia (rho_s/rho_f - 1) alpha (du/dt - g) with implicit Euler, so
    // the fluid solve treats them as a heavier fluid
    const fictitiousBoundary& fb = system_.fb();
    const PtrList<body>& bodies = system_.bodies();
    const scalar rhoFluid = system_.rhoFluid();
    const vector& g = system_.motion().g();

    scalarField& diag = UEqn.diag();
    vectorField& source = UEqn.source();
    const scalarField& alpha = fb.alpha();
    const scalarField& id = fb.bodyID();
    const scalarField& V = fb.mesh().V();
    const vectorField& U0 = UEqn.psi().oldTime().primitiveField();
    const scalar dt = fb.mesh().time().deltaTValue();

    // projectContacts: the contact force of the last step on the body,
    // spread over its cells as alpha V Fc/(rho_f V_b)
    const List<vector>* Fc = projectedContactForces();
    scalarList rhoVb;
    if (Fc)
    {
        rhoVb.setSize(bodies.size());
        forAll(rhoVb, bi)
        {
            rhoVb[bi] = rhoFluid*bodies[bi].shape().volume();
        }
    }

    // projectContacts, non-round bodies: the contact torque of the last
    // step as the force density of the rigid rotation it gives,
    // alpha V (rho_s/rho_f) (dw x r), dw = I^-1 Tc (the header's
    // derivation). Bodies without a contact torque (round ones) take no
    // term at all, so that their solve is unchanged to the bit
    const List<vector>* Tc = projectedContactTorques();
    List<vector> dw;
    boolList hasTorque;
    if (Tc)
    {
        dw.setSize(bodies.size(), Zero);
        hasTorque.setSize(bodies.size(), false);
        forAll(bodies, bi)
        {
            if (!projected(bi) || (*Tc)[bi] == vector::zero) continue;
            const body& b = bodies[bi];
            dw[bi] =
                (b.rho()/rhoFluid)*contactAngularAcceleration(b, (*Tc)[bi]);
            hasTorque[bi] = true;
        }
        if (!hasTorque.found(true))
        {
            Tc = nullptr;
        }
    }
    const vectorField& C = fb.mesh().C().primitiveField();

    for (const label celli : fb.activeCells())
    {
        const label bi = label(id[celli]);
        if (bi < 0 || !projected(bi)) continue;

        const scalar c =
            (bodies[bi].rho()/rhoFluid - 1)*alpha[celli]*V[celli]/dt;
        diag[celli] += c;
        source[celli] += c*(U0[celli] + dt*g);
        if (Fc)
        {
            source[celli] += alpha[celli]*V[celli]*(*Fc)[bi]/rhoVb[bi];
        }
        if (Tc && hasTorque[bi])
        {
            source[celli] +=
                alpha[celli]*V[celli]
               *(dw[bi] ^ (C[celli] - bodies[bi].centre()));
        }
    }
}


bool Foam::fbm::couplingModels::rigidProjection::afterFlow
(
    volVectorField& U,
    List<vector>& force,
    List<vector>& torque
)
{
    phaseTimes& times = system_.times();
    {
        phaseTimes::scope forcesTime(times, phaseTimes::forces);
        projectionForces(U, force, torque);
    }

    holdForces(force, torque);
    PtrList<body>& bodies = system_.bodies();

    // The footprint the flow was solved with: the flow there takes the
    // bodies' new velocities (the cells a body moves into keep their
    // fluid velocity; the next step accelerates them and charges the
    // body)
    const fictitiousBoundary& fb = system_.fb();
    const labelList cells(fb.activeCells());
    scalarList alpha(cells.size());
    labelList id(cells.size());
    forAll(cells, i)
    {
        alpha[i] = fb.alpha()[cells[i]];
        id[i] = label(fb.bodyID()[cells[i]]);
    }
    List<point> centres(bodies.size());
    forAll(bodies, bi)
    {
        centres[bi] = bodies[bi].centre();
    }

    // The bodies move over the step with these forces (and the contacts)
    const bool inside = system_.advance();
    relaxProjectedForce();

    phaseTimes::scope forcingTime(times, phaseTimes::forcing);
    rigidify(U, cells, alpha, id, centres);

    return inside;
}


void Foam::fbm::couplingModels::rigidProjection::readState
(
    const dictionary& state
)
{
    // projectContacts: the contact force of the step that led to the
    // restart time, when the earlier run wrote it (contactForce)
    const PtrList<body>& bodies = system_.bodies();
    const bool hasContact = stateHasEntry(state, "contactForce");
    if (projectContacts_ && hasContact)
    {
        restartForce_.setSize(bodies.size());
        forAll(bodies, bi)
        {
            restartForce_[bi] =
                state.subDict(bodies[bi].name()).get<vector>("contactForce");
        }

        // The contact torque beside it (a state written before it was
        // projected has none: start() takes the torques at the restart
        // positions)
        if (stateHasEntry(state, "contactTorque"))
        {
            restartTorque_.setSize(bodies.size());
            forAll(bodies, bi)
            {
                restartTorque_[bi] =
                    state.subDict(bodies[bi].name())
                   .get<vector>("contactTorque");
            }
        }
    }
}


void Foam::fbm::couplingModels::rigidProjection::writeState
(
    const label bi,
    Ostream& os
) const
{
    // The contact force the next flow solve takes, so that a restart
    // repeats an uninterrupted run
    const List<vector>* Fc = projectedContactForces();
    if (Fc)
    {
        os.writeEntry("contactForce", (*Fc)[bi]);
    }
    const List<vector>* Tc = projectedContactTorques();
    if (Tc)
    {
        os.writeEntry("contactTorque", (*Tc)[bi]);
    }
}


// ************************************************************************* //
