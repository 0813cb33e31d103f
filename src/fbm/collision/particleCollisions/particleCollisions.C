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

#include "particleCollisions.H"
#include "principalAxes.H"
#include "body.H"
#include "rigidBodyMotion.H"
#include "fvMesh.H"
#include "volMesh.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fbm::particleCollisions::forceScale(const fvMesh& mesh)
{
    if (mesh.nSolutionD() == 3)
    {
        return 1;
    }

    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0)
        {
            return mesh.bounds().span()[d];
        }
    }
    return 1;
}


Foam::vector Foam::fbm::particleCollisions::planeMask(const fvMesh& mesh)
{
    vector mask(1, 1, 1);
    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0) mask[d] = 0;
    }
    return mask;
}


Foam::scalar Foam::fbm::particleCollisions::contactMass(const body& b) const
{
    const scalar m = b.translates() ? b.mass() : GREAT;
    if (b.shape().isotropic() || !b.rotates())
    {
        return m;
    }

    // Smallest moment of inertia about an axis the body turns about: the
    // empty direction's in 2D, the smallest principal one in 3D
    const symmTensor I0(b.rho()*b.shape().inertiaPerDensity());
    scalar Imin = 0;
    if (cmptMin(planeMask_) == 0)
    {
        const vector e(vector::one - planeMask_);
        Imin = e & (I0 & e);
    }
    else
    {
        Imin = principalAxes(I0).values().x();
    }
    const scalar R = b.shape().radius();
    return 1/((m < GREAT ? 1/m : 0) + sqr(R)/max(Imin, VSMALL));
}


Foam::scalar Foam::fbm::particleCollisions::meshSize(const fvMesh& mesh)
{
    const scalar Vmax = gMax(mesh.V().field());

    if (mesh.nSolutionD() == 3)
    {
        return Foam::cbrt(Vmax);
    }
    return Foam::sqrt(Vmax/forceScale(mesh));
}


const Foam::dictionary& Foam::fbm::particleCollisions::checkShapes
(
    const dictionary& dict,
    const PtrList<body>& bodies
)
{
    // The narrow phase of non-round bodies needs a support function
    for (const body& b : bodies)
    {
        if (!b.shape().isotropic() && !b.shape().hasSupport())
        {
            FatalIOErrorInFunction(dict)
                << "Body " << b.name() << ": the shape (type "
                << b.shape().type() << ") has no support function, so it"
                << " cannot take part in the contacts of the collisions"
                << " dictionary" << exit(FatalIOError);
        }
    }
    return dict;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::particleCollisions::particleCollisions
(
    const dictionary& dict,
    const fvMesh& mesh,
    const PtrList<body>& bodies
)
:
    dict_(checkShapes(dict, bodies)),
    h_(meshSize(mesh)),
    depth_(forceScale(mesh)),
    model_(contactModel::New(dict, h_)),
    nStepsPerContact_
    (
        dict.getCheckOrDefault<scalar>
        (
            "nStepsPerContact", 20, [](scalar n){ return n >= 3; }
        )
    ),
    maxSubCycles_
    (
        dict.getCheckOrDefault<label>
        (
            "maxSubCycles", 1000, [](label n){ return n >= 1; }
        )
    ),
    dampingRatio_
    (
        dict.getCheckOrDefault<scalar>
        (
            "dampingRatio", 0, [](scalar z){ return z >= 0 && z <= 1; }
        )
    ),
    friction_(frictionModel::New(dict, planeMask(mesh), depth_)),
    bodyNames_(bodies.size()),
    walls_(mesh),
    search_(),
    planeMask_(planeMask(mesh)),
    narrow_(vector::one - planeMask_),
    warmStart_(),
    useWarmStart_(dict.getOrDefault<bool>("narrowPhaseWarmStart", true)),
    inMove_(false),
    nNarrow_(0),
    nNarrowIter_(0),
    invInertia_(bodies.size(), Zero),
    invInertiaStamp_(bodies.size(), -1),
    nForceCalls_(0),
    round_(bodies.size(), true),
    allRound_(true),
    subRotates_(bodies.size(), false),
    anyTorque_(false),
    torque_(bodies.size(), Zero),
    mass_(bodies.size(), GREAT),
    dtSubMax_(GREAT),
    X_(bodies.size()),
    R_(bodies.size()),
    U_(bodies.size()),
    translates_(bodies.size()),
    Fheld_(bodies.size()),
    Flag_(bodies.size()),
    Meff_(bodies.size()),
    minPairGap_(GREAT),
    minWallGap_(GREAT)
{
    forAll(bodies, i)
    {
        round_[i] = bodies[i].shape().isotropic();
        allRound_ = allRound_ && round_[i];
        subRotates_[i] = !round_[i] || friction_.valid();
        bodyNames_[i] = bodies[i].name();
    }
    anyTorque_ = !allRound_ || friction_.valid();
    if (!allRound_)
    {
        Info<< "fbm: collisions: non-round bodies: closest points by"
            << " GJK/EPA on the support functions (convexDistance),"
            << " narrowPhaseWarmStart " << Switch(useWarmStart_) << nl;
    }

    // Stiffest contact: each pair of (radius, mass) classes with its
    // reduced mass, each class against a wall (fbm::contactTime)
    scalarList radii(bodies.size());
    scalarList masses(bodies.size());
    boolList moves(bodies.size());
    forAll(bodies, i)
    {
        radii[i] = bodies[i].shape().radius();
        masses[i] = contactMass(bodies[i]);
        moves[i] = bodies[i].translates();
    }
    const contactTime stiffest(*model_, depth_, radii, masses, moves);

    if (stiffest.anyMoving())
    {
        if (stiffest.valid())
        {
            dtSubMax_ = stiffest.tc()/nStepsPerContact_;
        }

        forAll(bodies, i)
        {
            if (bodies[i].translates()) mass_[i] = bodies[i].mass();
        }
        if (dampingRatio_ > 0)
        {
            Info<< "fbm: collisions: normal damping ratio " << dampingRatio_
                << nl;
        }
        if (friction_.valid())
        {
            friction_->writeInfo();
            friction_->setSubStep(dtSubMax_);
        }

        Info<< "fbm: collisions: h " << h_ << ", stiffness pair "
            << stiffest.kPmax() << " wall " << stiffest.kWmax()
            << ", smallest mass " << stiffest.mMin()
            << " (" << stiffest.nClasses() << " radius/mass classes)"
            << ": contact time " << nStepsPerContact_*dtSubMax_
            << ", largest sub-step " << dtSubMax_
            << " (nStepsPerContact " << nStepsPerContact_
            << ", maxSubCycles " << maxSubCycles_ << ")" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::fbm::particleCollisions::nSubCycles(const scalar dt) const
{
    const scalar n = std::ceil(dt/dtSubMax_ - 1e-12);
    return max(label(1), label(min(n, scalar(labelMax))));
}


void Foam::fbm::particleCollisions::contactForces
(
    const PtrList<body>& bodies,
    List<vector>& F
)
{
    forAll(bodies, i)
    {
        const body& b = bodies[i];
        X_[i] = b.centre();
        R_[i] = b.shape().radius();
        U_[i] = b.U();
        translates_[i] = b.translates();
    }
    arrayForces(bodies, F, torque_, 0);
}


void Foam::fbm::particleCollisions::initMeanTorque
(
    const PtrList<body>& bodies
)
{
    if (!anyTorque_)
    {
        meanTorque_.setSize(bodies.size());
        meanTorque_ = Zero;
        return;
    }
    List<vector> F;
    contactForces(bodies, F);
    meanTorque_ = torque_;
}


void Foam::fbm::particleCollisions::move
(
    PtrList<body>& bodies,
    const rigidBodyMotion& motion,
    const scalar dt
)
{
    const label n = nSubCycles(dt);
    if (n > maxSubCycles_)
    {
        FatalIOErrorInFunction(dict_)
            << "The fluid time step " << dt << " needs " << n
            << " collision sub-steps of at most " << dtSubMax_
            << ", more than maxSubCycles " << maxSubCycles_ << nl
            << "    Lower maxDeltaT, soften the contact law or raise"
            << " maxSubCycles" << exit(FatalIOError);
    }
    const scalar dtSub = dt/n;
    if (friction_.valid())
    {
        friction_->setSubStep(dtSub);
    }
    minPairGap_ = GREAT;
    minWallGap_ = GREAT;

    Info<< "fbm: collisions: " << n << " sub-steps of " << dtSub << nl;

    // The state the sub-steps advance, in arrays (bodies that do not move
    // keep theirs)
    boolList moves(bodies.size());
    forAll(bodies, i)
    {
        body& b = bodies[i];
        moves[i] = b.moves();
        if (moves[i]) b.beginSubCycles();
        X_[i] = b.centre();
        R_[i] = b.shape().radius();
        U_[i] = b.U();
        translates_[i] = b.translates();
        if (translates_[i])
        {
            motion.heldTranslation(b, Fheld_[i], Flag_[i], Meff_[i]);
        }
    }

    // Velocity Verlet: half kick with the contact forces at the start,
    // drift, half kick with those at the end (which start the next
    // sub-step); the held forces give the same update as
    // rigidBodyMotion::move. The kick is rigidBodyMotion::kick's
    const scalar h = 0.5*dtSub;
    const vector& mask = motion.planeMask();
    auto kick = [&](const List<vector>& F)
    {
        forAll(X_, i)
        {
            if (!translates_[i]) continue;
            U_[i] += h*rigidBodyMotion::acceleration
            (
                Fheld_[i], F[i], Flag_[i], Meff_[i], mask
            );
        }
    };

    // Non-round bodies: their rotation in the sub-steps, with the contact
    // torque
    auto kickRotation = [&](const List<vector>& T)
    {
        if (!anyTorque_) return;
        forAll(bodies, i)
        {
            if (subRotates_[i] && moves[i])
            {
                motion.angularSubKick(bodies[i], h, T[i]);
            }
        }
    };

    // The narrow phase's warm start holds within this step's sub-steps
    warmStart_.clear();
    inMove_ = useWarmStart_;
    nNarrow_ = 0;
    nNarrowIter_ = 0;

    List<vector> F(bodies.size(), Zero);
    List<vector>& T = torque_;
    arrayForces(bodies, F, T, 0);
    // The mean force is kept only once initMeanForce() asked for it
    const bool keepMean = (meanForce_.size() == bodies.size());
    if (keepMean)
    {
        meanForce_ = (0.5/n)*F;
        meanTorque_ = (0.5/n)*T;
    }
    for (label step = 0; step < n; ++step)
    {
        kick(F);
        kickRotation(T);
        forAll(X_, i)
        {
            if (moves[i]) X_[i] += dtSub*U_[i];
        }
        if (anyTorque_)
        {
            forAll(bodies, i)
            {
                if (subRotates_[i] && moves[i])
                {
                    motion.rotationDrift(bodies[i], dtSub);
                }
            }
        }

        arrayForces(bodies, F, T, dtSub);
        if (keepMean)
        {
            const scalar w = (step < n - 1 ? 1.0 : 0.5)/n;
            forAll(F, i)
            {
                meanForce_[i] += w*F[i];
            }
            if (anyTorque_)
            {
                forAll(T, i)
                {
                    meanTorque_[i] += w*T[i];
                }
            }
        }

        kick(F);
        kickRotation(T);
    }
    inMove_ = false;
    warmStart_.clear();
    if (nNarrow_ > 0)
    {
        Info<< "fbm: collisions: narrow phase: " << nNarrow_
            << " queries of " << nNarrowIter_/nNarrow_
            << " iterations" << nl;
    }

    forAll(bodies, i)
    {
        if (!moves[i]) continue;
        body& b = bodies[i];
        // The rotation of the round bodies after the sub-steps (that of
        // the others ran in them)
        motion.endTranslationSubCycles
        (
            b, X_[i], U_[i], subRotates_[i] ? 0 : n, dtSub
        );
        motion.endSubCycles(b, dt);
    }
}


void Foam::fbm::particleCollisions::readState(const dictionary& state)
{
    if (friction_.valid())
    {
        friction_->readState(state, bodyNames_, walls_.names());
    }
}


void Foam::fbm::particleCollisions::writeState
(
    const label bi,
    Ostream& os
) const
{
    if (friction_.valid())
    {
        friction_->writeState(bi, bodyNames_, walls_.names(), os);
    }
}


// ************************************************************************* //
