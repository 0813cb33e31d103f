/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

Description
    The checks of fbm::bodySystem on its bodies: at the start (inside the
    mesh, covered volumes, densities, no overlaps) and while they move
    (boundary patches, speed, runaway).

\*---------------------------------------------------------------------------*/

#include "bodySystem.H"
#include "sumOverProcessors.H"
#include "Time.H"
#include "contactSearch.H"
#include "convexDistance.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

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

        // Beyond the tolerance of a smooth body: the sampling error of a
        // thin one, or a cut. Its surface points tell them apart
        point outside(Zero);
        if (err > tol && fb_.surfaceInside(b, outside))
        {
            Info<< "    " << b.name() << ": covered volume " << vol[bi]
                << " against " << Vb << " for the shape, " << err
                << " relative (tolerance " << tol << " for a smooth body of"
                << " radius " << b.shape().radius() << "): the sampling"
                << " error of a body thin against the cells; its surface"
                << " points lie in the mesh" << nl;
        }
        else if (err > tol)
        {
            OSstream& msg = FatalIOErrorInFunction(*this);
            msg << "Body " << b.name() << " (centre " << b.centre()
                << ") is not wholly inside the mesh: covered volume "
                << vol[bi] << " against " << Vb << " for the shape"
                << " (tolerance " << tol << " relative)";
            if (b.shape().hasSupport())
            {
                msg << "; its surface point " << outside
                    << " lies in no cell";
            }
            if (!stateFile_.empty())
            {
                msg << nl << "    The centre is that of the restart state "
                    << stateFile_;
            }
            msg << exit(FatalIOError);
        }
    }
    if (bodies_.size())
    {
        Info<< "fbm: " << bodies_.size() << " bodies inside the mesh,"
            << " largest relative covered-volume error " << worst << nl;
    }
    Info<< endl;
}


void Foam::fbm::bodySystem::checkDensities
(
    const List<const dictionary*>& sources
) const
{
    // Density ratios from 1e-6 (a gas bubble in a liquid is 1e-3) to 1e6
    // (tungsten in air is 2e4): beyond, the mass or the acceleration of a
    // body is round-off against the fluid's
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        const scalar ratio = b.rho()/rhoFluid_;
        if (!(ratio >= 1e-6 && ratio <= 1e6))
        {
            FatalIOErrorInFunction(*sources[bi])
                << "Body " << b.name() << ": rho " << b.rho() << " in "
                << sources[bi]->name() << " is " << ratio << " times rhoFluid "
                << rhoFluid_ << " of " << objectPath() << nl
                << "    The density ratio rho/rhoFluid lies between 1e-6 and"
                << " 1e6 (magnitudes below 1e-300 are read as 0)"
                << exit(FatalIOError);
        }
    }
}


void Foam::fbm::bodySystem::checkStart() const
{
    // The bodies' state comes from a restart file when readState() read
    // one (on every processor alike)
    const bool restart = !stateFile_.empty();

    // No body may cross a boundary patch (the same test as while moving).
    // A restart state of a run with contacts may hold the free bodies a
    // little into the walls and into each other, as the contact law lets
    // them: there, only the bodies no contact model holds are tested at
    // the walls, and overlaps are not tested
    boolList check(bodies_.size(), true);
    if (restart && collisions_.valid())
    {
        forAll(bodies_, bi)
        {
            check[bi] = !bodies_[bi].translates();
        }
    }
    labelList patch;
    scalarList depth;
    labelList openPatch;
    scalarList openDepth;
    boundary_.crossed(bodies_, check, domainBoundary::walls, patch, depth);
    boundary_.crossed
    (
        bodies_, boolList(bodies_.size(), true), domainBoundary::open,
        openPatch, openDepth
    );
    forAll(bodies_, bi)
    {
        if (openPatch[bi] >= 0)
        {
            patch[bi] = openPatch[bi];
            depth[bi] = openDepth[bi];
        }
        if (patch[bi] < 0) continue;

        const body& b = bodies_[bi];
        FatalIOErrorInFunction(*this)
            << "Body " << b.name() << " (centre " << b.centre() << ", radius "
            << b.shape().radius() << ") is not wholly inside the mesh: it"
            << " crosses the "
            << (boundary_.isWall(patch[bi]) ? "wall" : "open") << " patch "
            << boundary_.patchName(patch[bi]) << " by "
            << depth[bi]
            << (restart ? " in the restart state of this time" : "")
            << exit(FatalIOError);
    }

    // No two bodies may overlap (bounding radii: exact for circles and
    // spheres; a pair with a non-round body whose bounding circles
    // overlap: the signed distance of the shapes, fbm::convexDistance)
    if (restart || bodies_.size() < 2)
    {
        return;
    }
    pointField X(bodies_.size());
    scalarList R(bodies_.size());
    forAll(bodies_, bi)
    {
        X[bi] = bodies_[bi].centre();
        R[bi] = bodies_[bi].shape().radius();
    }
    contactSearch search;
    search.search(X, R, 0);

    vector planeNormal(Zero);
    const Vector<label>& sd = mesh_.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0) planeNormal[d] = 1;
    }
    const convexDistance narrow(planeNormal);

    label nOverlap = 0;
    OStringStream pairs;
    for (const labelPair& ij : search.pairs())
    {
        const label i = ij.first();
        const label j = ij.second();
        const body& bi = bodies_[i];
        const body& bj = bodies_[j];
        const scalar d =
            (bi.shape().isotropic() && bj.shape().isotropic())
          ? R[i] + R[j] - mag(X[i] - X[j])
          : -narrow.distance
            (
                bi.shape(), bi.state().Q(), X[i],
                bj.shape(), bj.state().Q(), X[j]
            ).gap;
        if (d > 1e-6*min(R[i], R[j]))
        {
            if (nOverlap < 10)
            {
                pairs
                    << "    " << bodies_[i].name() << " and "
                    << bodies_[j].name() << ": overlap depth " << d << nl;
            }
            ++nOverlap;
        }
    }
    if (nOverlap)
    {
        FatalIOErrorInFunction(*this)
            << nOverlap << " pairs of bodies overlap at the start"
            << (nOverlap > 10 ? " (the first 10)" : "") << ":" << nl
            << pairs.str().c_str()
            << "    Move them apart (bodies may touch, not overlap)"
            << exit(FatalIOError);
    }
}


bool Foam::fbm::bodySystem::checkBoundary(const scalarList& vol) const
{
    const word& t = mesh_.time().timeName();

    // The moving bodies, and those of them no contact model holds at the
    // walls (prescribed motion, or no contact model at all)
    boolList moving(bodies_.size());
    boolList unheld(bodies_.size());
    forAll(bodies_, bi)
    {
        moving[bi] = bodies_[bi].moves();
        unheld[bi] =
            moving[bi] && !(collisions_.valid() && bodies_[bi].translates());
    }

    labelList patch;
    scalarList depth;

    // Open patches: a body there would leave the domain
    if (boundary_.hasOpen())
    {
        boundary_.crossed(bodies_, moving, domainBoundary::open, patch, depth);
        forAll(bodies_, bi)
        {
            if (patch[bi] < 0) continue;

            const body& b = bodies_[bi];
            FatalErrorInFunction
                << "Body " << b.name() << " at time " << t << " (centre "
                << b.centre() << ", radius " << b.shape().radius()
                << ") reaches the open boundary patch "
                << boundary_.patchName(patch[bi]) << " (overlap " << depth[bi]
                << "): bodies cannot leave the domain" << nl
                << "    The run stops; the last written time is the last"
                << " good state." << exit(FatalError);
        }
    }

    // Walls, for the bodies no contact model holds
    boundary_.crossed(bodies_, unheld, domainBoundary::walls, patch, depth);

    bool inside = true;
    forAll(bodies_, bi)
    {
        if (!moving[bi]) continue;

        const body& b = bodies_[bi];
        const scalar Vb = b.shape().volume();

        // A body whose centre left the mesh in one step crosses no face
        // any more: its covered volume tells
        if (vol[bi] < 0.5*Vb)
        {
            const label pi = boundary_.nearestPatch(b.centre());
            FatalErrorInFunction
                << "Body " << b.name() << " at time " << t << " (centre "
                << b.centre() << ", U " << b.U() << ") has left the mesh"
                << (pi < 0 ? "" : " near patch ")
                << (pi < 0 ? word::null : boundary_.patchName(pi))
                << ": covered volume " << vol[bi] << " of " << Vb << nl
                << "    The run stops; the last written time is the last"
                << " good state. Reduce the time step (maxBodyCo)."
                << exit(FatalError);
        }

        if (!unheld[bi]) continue;

        label pi = patch[bi];
        if (pi < 0 && vol[bi] < (1 - 1e-3)*Vb)
        {
            pi = boundary_.nearestPatch(b.centre());
        }
        if (pi < 0) continue;

        if (!boundary_.isWall(pi))
        {
            FatalErrorInFunction
                << "Body " << b.name() << " at time " << t << " (centre "
                << b.centre() << ") is cut by the boundary near the open"
                << " patch " << boundary_.patchName(pi) << ": covered volume "
                << vol[bi] << " of " << Vb << nl
                << "    The run stops; the last written time is the last"
                << " good state." << exit(FatalError);
        }

        Info<< "fbm: body " << b.name() << " reaches the domain boundary"
            << " (wall patch " << boundary_.patchName(pi) << ") at time " << t
            << " (centre " << b.centre() << "): no contact model holds it,"
            << " the run ends without writing this time; the last written"
            << " time is the last good state" << nl;
        inside = false;
    }

    return inside;
}


void Foam::fbm::bodySystem::checkSpeed(const body& b) const
{
    // Bound the components first: |U| of a runaway body may overflow
    const scalar R = b.shape().radius();
    const scalar cmptU = cmptMax(cmptMag(b.U()));
    const scalar cmptOmega = cmptMax(cmptMag(b.omega()));
    const bool bounded =
        std::isfinite(cmptU) && std::isfinite(cmptOmega)
     && cmptU <= maxSpeed_ && cmptOmega <= maxSpeed_/R;
    const scalar speed = bounded ? b.maxSpeed() : GREAT;
    if (!bounded || speed > maxSpeed_)
    {
        OSstream& msg = FatalErrorInFunction;
        msg << "Body " << b.name() << " at time "
            << mesh_.time().timeName() << ": speed ";
        if (bounded)
        {
            msg << speed;
        }
        else
        {
            msg << "out of range";
        }
        msg << " (U " << b.U() << ", omega " << b.omega()
            << ") is not finite or exceeds maxSpeed " << maxSpeed_
            << " of " << objectPath() << nl
            << "    The run stops; the last written time is the last"
            << " good state. Reduce the time step or set addedMassCoeff."
            << exit(FatalError);
    }
}


void Foam::fbm::bodySystem::checkRunaway(const label bi)
{
    // Only a body lighter than about the fluid it displaces can be
    // outweighed by its lagged added mass (rhoFluid V for a circle, half
    // that for a sphere): the same bodies the explicit coupling warns about
    const body& b = bodies_[bi];
    if (b.rho() >= 1.2*rhoFluid_)
    {
        return;
    }

    const scalar R = b.shape().radius();
    const bodyState& s = b.state();
    const Pair<vector> acc(s.acceleration(), R*s.angularAcceleration());
    const Pair<vector>& old = lastAcceleration_[bi];
    const scalar magAcc =
        Foam::sqrt(magSqr(acc.first()) + magSqr(acc.second()));
    const scalar magOld =
        Foam::sqrt(magSqr(old.first()) + magSqr(old.second()));
    const bool reversed =
        (acc.first() & old.first()) + (acc.second() & old.second()) < 0;

    // Significant: a tenth of gravity, or without gravity a velocity
    // change of 1e-6 maxSpeed in the step
    const scalar g = mag(motion_->g());
    const scalar aMin =
        g > 0 ? 0.1*g : 1e-6*maxSpeed_/mesh_.time().deltaTValue();

    nGrowing_[bi] =
        (reversed && magAcc > magOld && magAcc > aMin) ? nGrowing_[bi] + 1 : 0;
    lastAcceleration_[bi] = acc;

    const label nRunawaySteps = 4;
    if (nGrowing_[bi] >= nRunawaySteps)
    {
        FatalErrorInFunction
            << "Body " << b.name() << " at time "
            << mesh_.time().timeName() << " runs away: its acceleration "
            << acc.first() << " (R omegaDot " << acc.second() << ") has"
            << " reversed and grown in each of the last " << nRunawaySteps
            << " steps (U " << b.U() << ", omega " << b.omega() << ")" << nl
            << "    The coupling is unstable for this body (density ratio "
            << b.rho()/rhoFluid_ << "): the run stops; the last written"
            << " time is the last good state. "
            << (
                   coupling_->type() == "explicit"
                 ? "Set addedMassCoeff (0.5 to 1), coupling semiImplicit"
                   " or coupling rigidProjection in "
                 : "Set coupling rigidProjection in "
               )
            << objectPath() << ", or reduce the time step."
            << exit(FatalError);
    }
}


// ************************************************************************* //
