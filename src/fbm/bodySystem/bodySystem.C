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

#include "bodySystem.H"
#include "sumOverProcessors.H"
#include "bodyInput.H"
#include "fvMatrices.H"
#include "Time.H"
#include "uniformDimensionedFields.H"
#include "contactSearch.H"
#include "convexDistance.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(bodySystem, 0);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::fbm::bodySystem::readGravity() const
{
    for (const body& b : bodies_)
    {
        if (!b.translates()) continue;

        IOobject gIO
        (
            "g",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
        {
            FatalIOErrorInFunction(*this)
                << "Body " << b.name() << " translates, but there is no"
                << " gravity file " << gIO.objectPath() << exit(FatalIOError);
        }
        const vector g(uniformDimensionedVectorField(gIO).value());

        // A 2D mesh solves no motion along its empty direction: gravity
        // there would be dropped (a body under gravity along it alone
        // never moves)
        const Vector<label>& sd = mesh_.solutionD();
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (sd[d] < 0 && mag(g[d]) > 0)
            {
                FatalIOErrorInFunction(gIO.objectPath())
                    << "Keyword value of " << gIO.objectPath() << ": gravity "
                    << g << " has a component along the empty direction of"
                    << " this 2D mesh, which is not solved (body " << b.name()
                    << " translates); put gravity in the plane of the mesh"
                    << exit(FatalIOError);
            }
        }
        return g;
    }
    return Zero;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodySystem::bodySystem(const fvMesh& mesh)
:
    IOdictionary
    (
        IOobject
        (
            "fbmProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    mesh_(mesh),
    rhoFluid_(getCheck<scalar>("rhoFluid", [](scalar r){ return r > 0; })),
    maxSpeed_
    (
        getCheckOrDefault<scalar>("maxSpeed", 1e3, [](scalar u){ return u > 0; })
    ),
    maxBodyCo_
    (
        getCheckOrDefault<scalar>
        (
            "maxBodyCo", VGREAT, [](scalar c){ return c > 0; }
        )
    ),
    bodies_(),
    fb_(mesh, *this, bodies_),
    boundary_(mesh),
    forceModel_(forceModel::New(*this)),
    compareModels_(),
    coupling_(),
    rate_(),
    motion_(),
    collisions_(),
    output_(),
    times_(),
    lastAcceleration_(),
    nGrowing_()
{
    List<const dictionary*> sources;
    bodyInput::read(*this, mesh, fb_.cellTree(), bodies_, sources);
    checkDensities(sources);

    coupling_ = couplingModel::New(*this, *this);

    // Restart: the state written at the start time overrides the initial
    // state of constant/fbmProperties
    readState();
    setPrescribedMotions(false);

    rate_.reset(new fluidRate(mesh, anyMoves()));

    motion_.reset
    (
        new rigidBodyMotion
        (
            readGravity(), rhoFluid_, coupling_->addedMassCoeff(), mesh,
            rate_.get()
        )
    );

    lastAcceleration_.setSize(bodies_.size());
    nGrowing_.setSize(bodies_.size(), 0);
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        lastAcceleration_[bi] = Pair<vector>
        (
            b.state().acceleration(),
            b.shape().radius()*b.state().angularAcceleration()
        );
    }

    Info<< "fbm: " << bodies_.size() << " bodies, rhoFluid " << rhoFluid_
        << ", forcing "
        << fb_.forcing().type()
        << ", coupling " << coupling_->description().c_str()
        << ", nSubdivision " << fb_.nSubdivision()
        << ", penaltyMax " << fb_.penaltyMax() << nl;

    wordList modelNames(1, forceModel_->type());
    const wordList extra
    (
        getOrDefault<wordList>("compareForceModels", wordList())
    );
    compareModels_.setSize(extra.size());
    forAll(extra, i)
    {
        dictionary d;
        d.add("forceModel", extra[i]);
        d.name() = this->name();
        compareModels_.set(i, forceModel::New(d));
        modelNames.append(compareModels_[i].type());
    }

    if (isDict("collisions"))
    {
        collisions_.reset
        (
            new particleCollisions(subDict("collisions"), mesh, bodies_)
        );
        readCollisionState();
    }

    coupling_->start();

    fb_.update();

    checkStart();
    checkCoveredVolumes();

    output_.reset(new bodyOutput(*this, sources, modelNames));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fbm::footprint Foam::fbm::bodySystem::bodyFootprint() const
{
    return footprint
    (
        mesh_, bodies_, rhoFluid_, fb_.alpha(), fb_.Us(), fb_.bodyID(),
        fb_.activeCells(), fb_.lambda(),
        coupling_->directForce(), coupling_->directTorque(), rate_.get()
    );
}


Foam::scalar Foam::fbm::bodySystem::maxDeltaT() const
{
    // The coupling's own stability limit (fbm::viscousStepLimit)
    scalar dtMax = coupling_->maxDeltaT();
    deltaTLimit_ = "coupling " + coupling_->type();
    if (maxBodyCo_ >= VGREAT)
    {
        return dtMax;
    }

    // Smallest cell size under each body, all bodies in one reduction
    const scalarList h(fb_.smallestCellSizes());

    forAll(bodies_, bi)
    {
        const scalar speed = bodies_[bi].maxSpeed();
        if (speed > VSMALL && h[bi] < VGREAT && maxBodyCo_*h[bi]/speed < dtMax)
        {
            dtMax = maxBodyCo_*h[bi]/speed;
            deltaTLimit_ = "maxBodyCo";
        }
    }

    return dtMax;
}


bool Foam::fbm::bodySystem::anyMoves() const
{
    for (const body& b : bodies_)
    {
        if (b.moves())
        {
            return true;
        }
    }
    return false;
}


bool Foam::fbm::bodySystem::moveBodies()
{
    times_.newStep();
    if (rate_.valid())
    {
        rate_->beginStep();
    }
    for (body& b : bodies_)
    {
        b.state().beginStep();
    }
    return coupling_->beforeFlow();
}


void Foam::fbm::bodySystem::constrain(fvMatrix<vector>& UEqn) const
{
    phaseTimes::scope forcingTime(times_, phaseTimes::forcing);
    fb_.constrain(UEqn, coupling_->penalised());
    coupling_->constrain(UEqn);
}


void Foam::fbm::bodySystem::constrainPressureStep
(
    const volScalarField& rAU,
    volScalarField& rAtU,
    volVectorField& HbyA,
    surfaceScalarField& phiHbyA,
    const volScalarField& p
)
{
    if (bodies_.empty())
    {
        return;
    }
    phaseTimes::scope forcingTime(times_, phaseTimes::forcing);
    coupling_->constrainPressureStep(rAU, rAtU, HbyA, phiHbyA, p);
}


void Foam::fbm::bodySystem::correctVelocity(volVectorField& U)
{
    if (!bodies_.empty())
    {
        coupling_->correctVelocity(U);
    }
}


void Foam::fbm::bodySystem::solvePressure
(
    fvScalarMatrix& pEqn,
    volScalarField& p,
    const volScalarField& rAtU,
    const dictionary& solverDict,
    const label refCell
)
{
    if (bodies_.empty())
    {
        pEqn.solve(solverDict);
        return;
    }
    coupling_->solvePressure
    (
        pEqn, p, rAtU, solverDict, refCell
    );
}


void Foam::fbm::bodySystem::setPrescribedMotions(const bool step)
{
    // Exact positions and velocities at the current time, whatever the
    // motion or the contact sub-steps did with the held velocity. After a
    // step the acceleration is the step's velocity change over dt: the
    // rate of change of the enclosed fluid's momentum that
    // forceModels::momentumExchange adds
    const scalar t = mesh_.time().value();
    const scalar dt = mesh_.time().deltaTValue();
    for (body& b : bodies_)
    {
        if (b.motion())
        {
            bodyState& s = b.state();
            const vector U0(s.U());
            b.motion()->set(t, s);
            if (step)
            {
                s.acceleration() = (s.U() - U0)/dt;
            }
        }
    }
}


bool Foam::fbm::bodySystem::advance()
{
    bool moved = false;
    const scalar dt = mesh_.time().deltaTValue();

    {
        phaseTimes::scope motionTime(times_, phaseTimes::motion);
        if (collisions_.valid())
        {
            collisions_->move(bodies_, *motion_, dt);
        }
        forAll(bodies_, bi)
        {
            body& b = bodies_[bi];
            if (!b.moves()) continue;

            if (!collisions_.valid())
            {
                motion_->move(b, dt);
            }
            moved = true;
            checkSpeed(b);
            checkRunaway(bi);
        }
    }

    if (!moved)
    {
        return true;
    }
    setPrescribedMotions(true);

    phaseTimes::scope cellsTime(times_, phaseTimes::cells);
    fb_.update();

    return checkBoundary(fb_.coveredVolumes());
}


void Foam::fbm::bodySystem::calcForces
(
    const forceModel& model,
    const volVectorField& U,
    const volScalarField& p,
    const volScalarField& nuEff,
    List<vector>& force,
    List<vector>& torque
) const
{
    force.setSize(bodies_.size());
    torque.setSize(bodies_.size());
    force = Zero;
    torque = Zero;
    model.calcForces(bodyFootprint(), U, p, nuEff, force, torque);

    // Sum the processors' parts
    sumOverProcessors(force);
    sumOverProcessors(torque);
}


bool Foam::fbm::bodySystem::correctForces
(
    volVectorField& U,
    const volScalarField& p,
    const volScalarField& nuEff
)
{
    if (bodies_.empty())
    {
        return true;
    }

    {
        phaseTimes::scope forcingTime(times_, phaseTimes::forcing);
        coupling_->beforeForces(U, p);
    }

    List<vector> force(bodies_.size(), Zero);
    List<vector> torque(bodies_.size(), Zero);
    if (coupling_->needsForceModel())
    {
        phaseTimes::scope forcesTime(times_, phaseTimes::forces);
        calcForces(forceModel_(), U, p, nuEff, force, torque);
    }

    const bool inside = coupling_->afterFlow(U, force, torque);
    if (!inside)
    {
        // A body reached a wall: this state is not written
        return false;
    }

    {
        phaseTimes::scope outputTime(times_, phaseTimes::output);

        output_->write();
        if (mesh_.time().writeTime())
        {
            writeState();
        }

        // Force models computed for comparison only: counted as output
        forAll(compareModels_, mi)
        {
            calcForces(compareModels_[mi], U, p, nuEff, force, torque);
            output_->writeForces(mi + 1, force, torque);
        }
    }

    // The cost split at write times and after the last step
    const Time& runTime = mesh_.time();
    if
    (
        runTime.writeTime()
     || runTime.value() > runTime.endTime().value() - 0.5*runTime.deltaTValue()
    )
    {
        times_.report(Info);
    }

    return inside;
}


// ************************************************************************* //
