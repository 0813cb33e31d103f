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
#include "bodyInput.H"
#include "fvMatrices.H"
#include "Time.H"
#include "uniformDimensionedFields.H"

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
        return uniformDimensionedVectorField(gIO).value();
    }
    return Zero;
}


void Foam::fbm::bodySystem::checkCoveredVolumes() const
{
    // Each body must lie in the fluid domain: its covered volume must be
    // its own (a body cut by the boundary is an input error)
    const scalarList vol(fb_.coveredVolumes());
    const scalar hMax = fb_.largestCellSize();

    scalar worst = 0;
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        const scalar Vb = b.shape().volume();
        const scalar tol = fb_.volumeTolerance(b, hMax);
        const scalar err = mag(vol[bi] - Vb)/Vb;
        worst = max(worst, err);

        if (bi < 100)
        {
            Info<< "    " << b.name() << ": " << b.shape().type()
                << " centre " << b.centre() << " volume " << Vb
                << ", covered volume " << vol[bi] << " ("
                << returnReduce(b.cells().size(), sumOp<label>())
                << " cells)" << nl;
        }

        if (err > tol)
        {
            FatalIOErrorInFunction(*this)
                << "Body " << b.name() << " (centre " << b.centre()
                << ") is not wholly inside the mesh: covered volume "
                << vol[bi] << " against " << Vb << " for the shape"
                << " (tolerance " << tol << " relative)"
                << exit(FatalIOError);
        }
    }
    if (bodies_.size())
    {
        Info<< "fbm: " << bodies_.size() << " bodies inside the mesh,"
            << " largest relative covered-volume error " << worst << nl;
    }
    Info<< endl;
}


void Foam::fbm::bodySystem::checkSpeed(const body& b) const
{
    const scalar speed = b.maxSpeed();
    if (!std::isfinite(speed) || speed > maxSpeed_)
    {
        FatalErrorInFunction
            << "Body " << b.name() << " at time "
            << mesh_.time().timeName() << ": speed " << speed
            << " (U " << b.U() << ", omega " << b.omega()
            << ") is not finite or exceeds maxSpeed " << maxSpeed_
            << " of " << objectPath() << nl
            << "    The run stops; the last written time is the last"
            << " good state. Reduce the time step or set addedMassCoeff."
            << exit(FatalError);
    }
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
    forceModel_(forceModel::New(*this)),
    compareModels_(),
    coupling_(),
    motion_(),
    collisions_(),
    output_(),
    times_()
{
    List<const dictionary*> sources;
    bodyInput::read(*this, mesh, fb_.cellTree(), bodies_, sources);

    coupling_ = couplingModel::New(*this, *this);

    // Restart: the state written at the start time overrides the initial
    // state of constant/fbmProperties
    readState();
    setPrescribedMotions(false);

    motion_.reset
    (
        new rigidBodyMotion
        (
            readGravity(), rhoFluid_, coupling_->addedMassCoeff(), mesh
        )
    );

    Info<< "fbm: " << bodies_.size() << " bodies, rhoFluid " << rhoFluid_
        << ", forcing "
        << fictitiousBoundary::forcingTypeNames[fb_.forcing()]
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
    }

    coupling_->start();

    fb_.update();

    checkCoveredVolumes();

    output_.reset(new bodyOutput(*this, sources, modelNames));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fbm::footprint Foam::fbm::bodySystem::bodyFootprint() const
{
    return footprint
    (
        mesh_, bodies_, rhoFluid_, fb_.alpha(), fb_.Us(), fb_.bodyID(),
        fb_.activeCells(), fb_.lambda()
    );
}


Foam::scalar Foam::fbm::bodySystem::maxDeltaT() const
{
    if (maxBodyCo_ >= VGREAT)
    {
        return VGREAT;
    }

    // Smallest cell size under each body, all bodies in one reduction
    const scalarList h(fb_.smallestCellSizes());

    scalar dtMax = VGREAT;
    forAll(bodies_, bi)
    {
        const scalar speed = bodies_[bi].maxSpeed();
        if (speed > VSMALL && h[bi] < VGREAT)
        {
            dtMax = min(dtMax, maxBodyCo_*h[bi]/speed);
        }
    }

    return dtMax;
}


bool Foam::fbm::bodySystem::moveBodies()
{
    times_.newStep();
    return coupling_->beforeFlow();
}


void Foam::fbm::bodySystem::constrain(fvMatrix<vector>& UEqn) const
{
    phaseTimes::scope forcingTime(times_, phaseTimes::forcing);
    fb_.constrain(UEqn, coupling_->penalised());
    coupling_->constrain(UEqn);
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
        for (body& b : bodies_)
        {
            if (!b.moves()) continue;

            if (!collisions_.valid())
            {
                motion_->move(b, dt);
            }
            moved = true;
            checkSpeed(b);
        }
    }

    if (!moved)
    {
        return true;
    }
    setPrescribedMotions(true);

    phaseTimes::scope cellsTime(times_, phaseTimes::cells);
    fb_.update();

    // With collisions the walls are handled by the contact
    if (collisions_.valid())
    {
        return true;
    }

    // A body whose covered volume falls short of its own has reached the
    // boundary of the domain
    const scalarList vol(fb_.coveredVolumes());
    bool inside = true;
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        if (!b.moves()) continue;

        if (vol[bi] < (1 - 1e-3)*b.shape().volume())
        {
            Info<< "fbm: body " << b.name() << " reaches the domain boundary"
                << " at time " << mesh_.time().timeName() << " (centre "
                << b.centre() << "): no contact model, the run ends" << nl;
            inside = false;
        }
    }

    return inside;
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
    Pstream::listCombineGather(force, plusEqOp<vector>());
    Pstream::listCombineScatter(force);
    Pstream::listCombineGather(torque, plusEqOp<vector>());
    Pstream::listCombineScatter(torque);
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

    List<vector> force(bodies_.size(), Zero);
    List<vector> torque(bodies_.size(), Zero);
    if (coupling_->needsForceModel())
    {
        phaseTimes::scope forcesTime(times_, phaseTimes::forces);
        calcForces(forceModel_(), U, p, nuEff, force, torque);
    }

    const bool inside = coupling_->afterFlow(U, force, torque);

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
