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

#include "fictitiousBoundary.H"
#include "fvMatrices.H"
#include "Time.H"
#include "HashSet.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"
#include "Random.H"
#include "IStringStream.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::fbm::fictitiousBoundary::cloudName_("fbmBodies");

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
    defineTypeNameAndDebug(fictitiousBoundary, 0);
}
}

const Foam::Enum
<
    Foam::fbm::fictitiousBoundary::forcingType
>
Foam::fbm::fictitiousBoundary::forcingTypeNames
({
    { forcingType::volumeFraction, "volumeFraction" },
    { forcingType::linearProfile, "linearProfile" },
});


const Foam::Enum
<
    Foam::fbm::fictitiousBoundary::couplingType
>
Foam::fbm::fictitiousBoundary::couplingTypeNames
({
    { couplingType::explicitForce, "explicit" },
    { couplingType::rigidProjection, "rigidProjection" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::fictitiousBoundary::updateFields()
{
    // projectContacts: the first flow solve takes the contact forces at
    // the initial positions
    if
    (
        projectContacts_ && collisions_.valid()
     && projectedForce_.size() != bodies_.size()
    )
    {
        collisions_->initMeanForce(bodies_);
        projectedForce_ = collisions_->meanForce();
    }

    // Clear the previous footprint
    scalarField& alpha = alpha_.primitiveFieldRef();
    vectorField& Us = Us_.primitiveFieldRef();
    scalarField& id = bodyID_.primitiveFieldRef();
    for (const label celli : activeCells_)
    {
        alpha[celli] = 0;
        Us[celli] = Zero;
        id[celli] = -1;
        distance_[celli] = GREAT;
        lambda_[celli] = 0;
    }

    const vectorField& C = mesh_.C();
    const labelListList& cellCells = mesh_.cellCells();
    labelHashSet active;

    forAll(bodies_, bi)
    {
        body& b = bodies_[bi];
        b.updateCells(mesh_, *cellTree_, cellBb_, nSubdivision_);

        const labelList& cells = b.cells();
        const scalarList& a = b.alpha();
        forAll(cells, i)
        {
            const label celli = cells[i];
            if (forcing_ == forcingType::volumeFraction)
            {
                // The body with the largest fraction gives u_s
                if (a[i] > alpha[celli])
                {
                    Us[celli] = b.velocityAt(C[celli]);
                    id[celli] = bi;
                }
                active.insert(celli);
            }
            alpha[celli] = min(alpha[celli] + a[i], scalar(1));
        }

        if (forcing_ == forcingType::linearProfile)
        {
            // Cells with the centre inside and their face neighbours; the
            // nearest surface gives u_s
            const bodyShape& shape = b.shape();
            auto mark = [&](const label celli, const scalar d)
            {
                if (d < distance_[celli])
                {
                    distance_[celli] = d;
                    Us[celli] = b.velocityAt(C[celli]);
                    id[celli] = bi;
                }
                active.insert(celli);
            };

            for (const label celli : cells)
            {
                const scalar d = shape.signedDistance(C[celli] - b.centre());
                if (d <= 0)
                {
                    mark(celli, d);
                    for (const label nbr : cellCells[celli])
                    {
                        mark
                        (
                            nbr,
                            shape.signedDistance(C[nbr] - b.centre())
                        );
                    }
                }
            }
        }
    }

    if (forcing_ == forcingType::linearProfile && coupled_)
    {
        // Face neighbours across coupled (processor, cyclic) patches of
        // inside cells: this side knows them from the other side's
        // distance and body index
        scalarField nbrId;
        syncTools::swapBoundaryCellList(mesh_, distance_, nbrDistance_);
        syncTools::swapBoundaryCellList(mesh_, id, nbrId);

        const label nInternal = mesh_.nInternalFaces();
        for (const polyPatch& pp : mesh_.boundaryMesh())
        {
            if (!pp.coupled()) continue;

            const labelUList& faceCells = pp.faceCells();
            forAll(faceCells, i)
            {
                const label bFacei = pp.start() + i - nInternal;
                if (nbrDistance_[bFacei] > 0) continue;

                const label celli = faceCells[i];
                const label bj = label(nbrId[bFacei]);
                const body& b = bodies_[bj];
                const scalar d =
                    b.shape().signedDistance(C[celli] - b.centre());
                if (d < distance_[celli])
                {
                    distance_[celli] = d;
                    Us[celli] = b.velocityAt(C[celli]);
                    id[celli] = bj;
                }
                active.insert(celli);
            }
        }
    }

    activeCells_ = active.sortedToc();

    alpha_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();
    bodyID_.correctBoundaryConditions();
}


void Foam::fbm::fictitiousBoundary::createFiles()
{
    if (!Pstream::master())
    {
        return;
    }

    const Time& runTime = mesh_.time();
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"fbmBodies"
       /runTime.timeName(runTime.startTime().value())
    );
    mkDir(dir);

    summaryFile_.reset(new OFstream(dir/"summary.dat"));
    summaryFile_->precision(12);
    summaryFile_()
        << "# All " << bodies_.size() << " bodies: largest speed"
        << " |U| + |omega| R [m/s], translational kinetic energy sum"
        << " M |U|^2/2 [J], mean centre [m], smallest pair gap D - Ri - Rj"
        << " and wall gap d - R over the collision sub-steps [m] (1e15:"
        << " none within reach)" << nl
        << "# Time N maxSpeed kineticEnergy Xx Xy Xz minPairGap minWallGap"
        << endl;

    const label nSel = selected_.size();
    const label nModels = 1 + compareModels_.size();
    files_.setSize(nModels*nSel);
    forAll(files_, filei)
    {
        const label mi = filei/nSel;
        const body& b = bodies_[selected_[filei % nSel]];
        const word suffix
        (
            mi == 0 ? word::null : word("." + compareModels_[mi - 1].type())
        );
        files_.set(filei, new OFstream(dir/(b.name() + suffix + ".dat")));
        OFstream& os = files_[filei];
        os.precision(12);
        os  << "# Body " << b.name() << ": hydrodynamic force [N] and"
            << " torque about the centre [N m], force model "
            << (mi == 0 ? forceModel_->type() : compareModels_[mi - 1].type())
            << nl
            << "# Time Fx Fy Fz Tx Ty Tz";
        if (b.hasCoefficients())
        {
            os  << " Cd Cl";
        }
        os  << " x y z Ux Uy Uz wx wy wz" << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::fictitiousBoundary::fictitiousBoundary(const fvMesh& mesh)
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
    forcing_(forcingTypeNames.get("forcing", *this)),
    nSubdivision_
    (
        getCheckOrDefault<label>
        (
            "nSubdivision", 4, [](label n){ return n >= 0 && n <= 10; }
        )
    ),
    penaltyMax_
    (
        getCheckOrDefault<scalar>
        (
            "penaltyMax", 1e6, [](scalar k){ return k >= 10; }
        )
    ),
    coupling_
    (
        couplingTypeNames.getOrDefault
        (
            "coupling", *this, couplingType::explicitForce
        )
    ),
    addedMassCoeff_
    (
        getCheckOrDefault<scalar>
        (
            "addedMassCoeff", 0, [](scalar c){ return c >= 0; }
        )
    ),
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
    projectContacts_
    (
        getOrDefault<bool>
        (
            "projectContacts",
            coupling_ == couplingType::rigidProjection && isDict("collisions")
        )
    ),
    contactRelaxation_
    (
        getCheckOrDefault<scalar>
        (
            "contactRelaxation", 1, [](scalar b){ return b > 0 && b <= 1; }
        )
    ),
    projectedForce_(),
    g_(Zero),
    bodies_(),
    projected_(),
    cellBb_(mesh.nCells()),
    alpha_
    (
        IOobject
        (
            "alpha.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero)
    ),
    Us_
    (
        IOobject
        (
            "U.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    activeCells_(),
    bodyID_
    (
        IOobject
        (
            "bodyID",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("bodyID", dimless, -1)
    ),
    distance_(mesh.nCells(), GREAT),
    coupled_
    (
        returnReduce
        (
            [&mesh]()
            {
                for (const polyPatch& pp : mesh.boundaryMesh())
                {
                    if (pp.coupled()) return true;
                }
                return false;
            }(),
            orOp<bool>()
        )
    ),
    nbrDistance_(mesh.nFaces() - mesh.nInternalFaces(), GREAT),
    lambda_(mesh.nCells(), Zero),
    scratch_(mesh.nCells(), Zero),
    forceModel_(forceModel::New(*this)),
    compareModels_(),
    collisions_()
{
    // Cell bounding boxes, once
    const pointField& pts = mesh.points();
    const labelListList& cellPts = mesh.cellPoints();
    forAll(cellBb_, celli)
    {
        cellBb_[celli] = boundBox(pts, cellPts[celli], false);
    }

    // Cell octree as polyMesh::cellTree(), but caching the cell boxes. On
    // a one-cell-thick 2D mesh every octant split in the empty direction
    // would cut every cell, the duplicity limit would stop the refinement
    // early and leave leaves of thousands of cells: the tree's box is
    // stretched in that direction (2^maxLevel times the mesh depth, the
    // mesh at its low end) so that the mesh stays in one octant at every
    // level.
    {
        const label maxLevel = 10;
        treeBoundBox overallBb(pts);
        Random rndGen(261782);
        overallBb = overallBb.extend(rndGen, 1e-4);
        overallBb.min() -= point::uniform(ROOTVSMALL);
        overallBb.max() += point::uniform(ROOTVSMALL);

        const Vector<label>& sd = mesh.solutionD();
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (sd[d] < 0)
            {
                overallBb.max()[d] = overallBb.min()[d]
                  + pow(2.0, scalar(maxLevel + 1))*overallBb.span()[d];
            }
        }

        cellTree_.reset
        (
            new indexedOctree<treeDataCell>
            (
                treeDataCell(true, mesh, polyMesh::CELL_TETS),
                overallBb,
                maxLevel,
                10,             // leafsize
                5.0             // duplicity
            )
        );
    }

    readBodies();
    selectBodies();

    projected_.setSize(bodies_.size(), false);
    if (!projectContacts_ && found("contactRelaxation"))
    {
        FatalIOErrorInFunction(*this)
            << "contactRelaxation without projectContacts in "
            << objectPath() << nl
            << "    It relaxes the contact forces that projectContacts puts"
            << " into the flow solve: remove it or set projectContacts yes"
            << exit(FatalIOError);
    }
    if (projectContacts_ && coupling_ != couplingType::rigidProjection)
    {
        FatalIOErrorInFunction(*this)
            << "projectContacts yes with coupling "
            << couplingTypeNames[coupling_] << " in " << objectPath() << nl
            << "    The contact forces go into the flow solve of coupling"
            << " rigidProjection only: remove projectContacts or set it to"
            << " no" << exit(FatalIOError);
    }
    if (coupling_ == couplingType::rigidProjection)
    {
        forAll(bodies_, bi)
        {
            projected_[bi] =
                bodies_[bi].translates() || bodies_[bi].rotates();
        }

        // The added mass is in the fluid solve: no virtual-mass term
        if (addedMassCoeff_ != 0)
        {
            FatalIOErrorInFunction(*this)
                << "addedMassCoeff " << addedMassCoeff_ << " with coupling"
                << " rigidProjection in " << objectPath() << nl
                << "    The rigid projection carries the added mass in the"
                << " fluid solve; addedMassCoeff is for the explicit"
                << " coupling only: remove it or set it to 0"
                << exit(FatalIOError);
        }

        // The extra inertia of the bodies is an implicit Euler term
        const word ddtU(mesh.ddtScheme("ddt(U)")[0].wordToken());
        if (ddtU != "Euler")
        {
            FatalIOErrorInFunction(mesh.schemesDict())
                << "coupling rigidProjection (" << objectPath() << ")"
                << " needs ddtSchemes Euler for ddt(U), not " << ddtU
                << exit(FatalIOError);
        }
    }

    // Restart: the state written at the start time overrides the initial
    // state of constant/fbmProperties
    IOobject stateIO
    (
        "fbmBodies",
        mesh.time().timeName(),
        "uniform",
        mesh,
        IOobject::READ_IF_PRESENT,
        IOobject::NO_WRITE,
        false
    );
    // projectContacts: the mean contact force of the step that led to the
    // restart time, when the earlier run wrote it (contactForce)
    List<vector> restartContactForce;
    if (stateIO.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary state(stateIO);
        label nContact = 0;
        for (body& b : bodies_)
        {
            const dictionary& bd = state.subDict(b.name());
            b.readState(bd);
            if (bd.found("contactForce")) ++nContact;
        }
        if (projectContacts_ && nContact == bodies_.size())
        {
            restartContactForce.setSize(bodies_.size());
            forAll(bodies_, bi)
            {
                restartContactForce[bi] =
                    state.subDict(bodies_[bi].name()).get<vector>
                    (
                        "contactForce"
                    );
            }
        }
        else if (nContact && nContact != bodies_.size())
        {
            FatalIOErrorInFunction(state)
                << "contactForce given for " << nContact << " of the "
                << bodies_.size() << " bodies in " << state.objectPath()
                << nl << "    Give it for every body or for none"
                << exit(FatalIOError);
        }
        Info<< "fbm: body state read from " << state.objectPath() << nl;
    }

    // Gravity, for bodies that translate
    for (const body& b : bodies_)
    {
        if (!b.translates()) continue;

        IOobject gIO
        (
            "g",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
        {
            FatalIOErrorInFunction(b.dict())
                << "Body " << b.name() << " translates, but there is no"
                << " gravity file " << gIO.objectPath() << exit(FatalIOError);
        }
        g_ = uniformDimensionedVectorField(gIO).value();
        break;
    }

    // Density ratios the plain explicit coupling cannot take (one warning
    // for the first such body, with the count)
    {
        label nLight = 0;
        const body* first = nullptr;
        for (const body& b : bodies_)
        {
            if
            (
                b.translates() && addedMassCoeff_ == 0
             && coupling_ == couplingType::explicitForce
             && b.rho() < 1.2*rhoFluid_
            )
            {
                if (!nLight) first = &b;
                ++nLight;
            }
        }
        if (nLight)
        {
            WarningInFunction
                << "Body " << first->name() << ": density ratio "
                << first->rho()/rhoFluid_ << " with the explicit coupling"
                << " and addedMassCoeff 0 in " << objectPath() << nl
                << "    is likely to oscillate or diverge (lagged added"
                << " mass); set addedMassCoeff 0.5 to 1";
            if (nLight > 1)
            {
                Info<< " (" << nLight << " such bodies)";
            }
            Info<< endl;
        }
    }

    Info<< "fbm: " << bodies_.size() << " bodies, rhoFluid " << rhoFluid_
        << ", forcing " << forcingTypeNames[forcing_]
        << ", coupling " << couplingTypeNames[coupling_]
        << (projectContacts_ ? " (projectContacts)" : "")
        << ", nSubdivision " << nSubdivision_
        << ", penaltyMax " << penaltyMax_ << nl;
    if (projectContacts_)
    {
        Info<< "fbm: projectContacts: contactRelaxation "
            << contactRelaxation_ << nl;
    }

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
    }

    if (isDict("collisions"))
    {
        collisions_.reset
        (
            new particleCollisions(subDict("collisions"), mesh, bodies_)
        );
        if (restartContactForce.size())
        {
            collisions_->setMeanForce(restartContactForce);
            projectedForce_ = restartContactForce;
            Info<< "fbm: projectContacts: contact forces of the last step"
                << " read with the body state" << nl;
        }
    }

    updateFields();

    checkCoveredVolumes();

    createFiles();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarList Foam::fbm::fictitiousBoundary::coveredVolumes() const
{
    scalarList vol(bodies_.size());
    forAll(bodies_, bi)
    {
        vol[bi] = bodies_[bi].localCoveredVolume(mesh_);
    }
    Pstream::listCombineGather(vol, plusEqOp<scalar>());
    Pstream::listCombineScatter(vol);
    return vol;
}


Foam::scalar Foam::fbm::fictitiousBoundary::maxDeltaT() const
{
    if (maxBodyCo_ >= VGREAT)
    {
        return VGREAT;
    }

    const Vector<label>& solD = mesh_.solutionD();

    // Smallest cell size (in the solved directions) under each body, all
    // bodies in one reduction
    scalarList h(bodies_.size(), VGREAT);
    forAll(bodies_, bi)
    {
        for (const label celli : bodies_[bi].cells())
        {
            const vector span(cellBb_[celli].span());
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (solD[d] > 0)
                {
                    h[bi] = min(h[bi], span[d]);
                }
            }
        }
    }
    Pstream::listCombineGather(h, minEqOp<scalar>());
    Pstream::listCombineScatter(h);

    scalar dtMax = VGREAT;
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        const scalar speed =
            mag(b.U()) + mag(b.omega())*b.shape().radius();

        if (speed > VSMALL && h[bi] < VGREAT)
        {
            dtMax = min(dtMax, maxBodyCo_*h[bi]/speed);
        }
    }

    return dtMax;
}


void Foam::fbm::fictitiousBoundary::checkSpeed(const body& b) const
{
    const scalar speed = mag(b.U()) + mag(b.omega())*b.shape().radius();
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


bool Foam::fbm::fictitiousBoundary::moveBodies()
{
    times_.newStep();

    // rigidProjection: the bodies move after the flow (correctForces)
    if (coupling_ == couplingType::rigidProjection)
    {
        return true;
    }

    return advanceBodies();
}


bool Foam::fbm::fictitiousBoundary::advanceBodies()
{
    bool moved = false;
    const scalar dt = mesh_.time().deltaTValue();

    if (collisions_.valid())
    {
        phaseTimes::scope motionTime(times_, phaseTimes::motion);
        collisions_->move(bodies_, g_, rhoFluid_, addedMassCoeff_, dt);
        relaxProjectedForce();
        for (const body& b : bodies_)
        {
            if (!b.moves()) continue;
            moved = true;
            checkSpeed(b);
        }
    }
    else
    {
        phaseTimes::scope motionTime(times_, phaseTimes::motion);
        for (body& b : bodies_)
        {
            if (!b.moves()) continue;

            b.move(g_, rhoFluid_, addedMassCoeff_, dt);
            moved = true;
            checkSpeed(b);
        }
    }

    if (!moved)
    {
        return true;
    }

    phaseTimes::scope cellsTime(times_, phaseTimes::cells);
    updateFields();

    // With collisions the walls are handled by the contact
    if (collisions_.valid())
    {
        return true;
    }

    // A body whose covered volume falls short of its own has reached the
    // boundary of the domain
    const scalarList vol(coveredVolumes());
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


void Foam::fbm::fictitiousBoundary::writeState() const
{
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath()/"uniform");
    mkDir(dir);

    OFstream os(dir/"fbmBodies");
    os.precision(17);
    IOobject io
    (
        "fbmBodies",
        runTime.timeName(),
        "uniform",
        mesh_,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
    io.writeHeader(os, IOdictionary::typeName);

    // The entries are built through string streams of the default
    // precision (controlDict's writePrecision): full precision for an
    // exact restart whatever that is
    const unsigned oldPrecision = IOstream::defaultPrecision(17);
    // projectContacts: the contact forces the next flow solve takes, so
    // that a restart repeats an uninterrupted run
    const List<vector>* Fc = projectedContactForces();
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        dictionary d;
        b.writeState(d);
        if (Fc)
        {
            d.add("contactForce", (*Fc)[bi]);
        }
        os.beginBlock(b.name());
        d.write(os, false);
        os.endBlock();
    }
    IOstream::defaultPrecision(oldPrecision);
    IOobject::writeEndDivider(os);
}


void Foam::fbm::fictitiousBoundary::writeCloudHeader
(
    OFstream& os,
    const word& name,
    const word& className,
    const label size
) const
{
    IOobject io
    (
        name,
        mesh_.time().timeName(),
        "lagrangian"/cloudName_,
        mesh_,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
    os.precision(12);
    io.writeHeader(os, className);
    os  << size << nl << token::BEGIN_LIST << nl;
}


void Foam::fbm::fictitiousBoundary::writeCloudFooter(OFstream& os)
{
    os  << token::END_LIST << nl;
    IOobject::writeEndDivider(os);
}


void Foam::fbm::fictitiousBoundary::writeCloud() const
{
    const Time& runTime = mesh_.time();
    const word& cloudName = cloudName_;

    // Bodies whose centre lies in this processor's cells
    DynamicList<label> mine(bodies_.size());
    DynamicList<label> cells(bodies_.size());
    forAll(bodies_, bi)
    {
        const label celli =
            body::findCell(mesh_, *cellTree_, bodies_[bi].centre());
        if (celli != -1)
        {
            mine.append(bi);
            cells.append(celli);
        }
    }

    const fileName dir(runTime.timePath()/"lagrangian"/cloudName);
    mkDir(dir);

    // positions (legacy format: centre and cell), then one field a file
    {
        OFstream os(dir/"positions");
        writeCloudHeader(os, "positions", "Cloud<passiveParticle>", mine.size());
        forAll(mine, i)
        {
            os  << bodies_[mine[i]].centre() << ' ' << cells[i] << nl;
        }
        writeCloudFooter(os);
    }

    scalarField d(mine.size()), rho(mine.size());
    labelField id(mine.size());
    vectorField U(mine.size()), omega(mine.size()), F(mine.size());
    forAll(mine, i)
    {
        const body& b = bodies_[mine[i]];
        d[i] = b.shape().diameter();
        rho[i] = b.rho();
        id[i] = mine[i];
        U[i] = b.U();
        omega[i] = b.omega();
        F[i] = b.force();
    }
    writeCloudField(dir, "d", d);
    writeCloudField(dir, "rho", rho);
    writeCloudField(dir, "id", id);
    writeCloudField(dir, "U", U);
    writeCloudField(dir, "omega", omega);
    writeCloudField(dir, "F", F);

    // For foamToVTK
    const fileName propsDir(runTime.timePath()/"uniform"/"lagrangian"/cloudName);
    mkDir(propsDir);
    OFstream os(propsDir/"cloudProperties");
    IOobject io
    (
        "cloudProperties",
        runTime.timeName(),
        "uniform"/("lagrangian"/cloudName),
        mesh_,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
    io.writeHeader(os, IOdictionary::typeName);
    os.writeEntry("geometry", word("positions"));
    IOobject::writeEndDivider(os);
}


void Foam::fbm::fictitiousBoundary::constrain(fvMatrix<vector>& UEqn) const
{
    phaseTimes::scope forcingTime(times_, phaseTimes::forcing);

    scalarField& diag = UEqn.diag();
    vectorField& source = UEqn.source();
    const scalarField& alpha = alpha_;
    const vectorField& Us = Us_;

    const cellList& cellFaces = mesh_.cells();
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    // The diagonal a_P of a cell as in a serial run: faces on coupled
    // patches (processor, cyclic) keep their coefficients in
    // internalCoeffs, not in diag; added once per call, patch by patch
    scalarField diagCoupled;
    if (coupled_)
    {
        diagCoupled = diag;
        forAll(patches, patchi)
        {
            if (!patches[patchi].coupled()) continue;

            const labelUList& faceCells = patches[patchi].faceCells();
            const Field<vector>& ic = UEqn.internalCoeffs()[patchi];
            forAll(faceCells, i)
            {
                diagCoupled[faceCells[i]] += ic[i].component(0);
            }
        }
    }
    const scalarField& aPs = coupled_ ? diagCoupled : diag;

    if (forcing_ == forcingType::volumeFraction)
    {
        for (const label celli : activeCells_)
        {
            const scalar a = alpha[celli];
            const scalar k =
                (a < 1) ? min(a/(1 - a), penaltyMax_) : penaltyMax_;
            lambda_[celli] = k*aPs[celli];
        }
    }
    else
    {
        const lduMatrix& m = UEqn;
        const scalarField& upper = m.upper();
        const scalarField& lower = m.lower();
        const labelUList& own = mesh_.faceOwner();
        const labelUList& nei = mesh_.faceNeighbour();

        for (const label celli : activeCells_)
        {
            const scalar d = distance_[celli];
            const scalar aP = aPs[celli];
            scalar k = penaltyMax_;

            if (d > 0)
            {
                // S = sum over inside neighbours of a_N/a_P |d_N|
                scalar S = 0;
                for (const label facei : cellFaces[celli])
                {
                    if (facei < nInternal)
                    {
                        const bool isOwner = (own[facei] == celli);
                        const label nbr = isOwner ? nei[facei] : own[facei];
                        if (distance_[nbr] <= 0)
                        {
                            const scalar aN =
                                -(isOwner ? upper[facei] : lower[facei]);
                            S += max(aN, scalar(0))*(-distance_[nbr]);
                        }
                    }
                    else if (coupled_)
                    {
                        // The neighbour on the other side of a coupled
                        // face: its coefficient is in boundaryCoeffs
                        const label patchi = patches.whichPatch(facei);
                        const scalar dN = nbrDistance_[facei - nInternal];
                        if (patches[patchi].coupled() && dN <= 0)
                        {
                            const scalar aN = UEqn.boundaryCoeffs()[patchi]
                                [facei - patches[patchi].start()]
                               .component(0);
                            S += max(aN, scalar(0))*(-dN);
                        }
                    }
                }
                S /= aP;
                k = (S > 0) ? min(S/d, penaltyMax_) : 0;
            }
            lambda_[celli] = k*aP;
        }
    }

    if (coupling_ == couplingType::rigidProjection)
    {
        // The cells of the projected bodies: no penalty, but the body's
        // extra inertia (rho_s/rho_f - 1) alpha (du/dt - g) with implicit
        // Euler, so the fluid solve treats them as a heavier fluid
        const scalarField& id = bodyID_;
        const scalarField& V = mesh_.V();
        const vectorField& U0 = UEqn.psi().oldTime().primitiveField();
        const scalar dt = mesh_.time().deltaTValue();

        // projectContacts: the contact force of the last step on the body,
        // spread over its cells as alpha V Fc/(rho_f V_b)
        const List<vector>* Fc = projectedContactForces();
        scalarList rhoVb;
        if (Fc)
        {
            rhoVb.setSize(bodies_.size());
            forAll(rhoVb, bi)
            {
                rhoVb[bi] = rhoFluid_*bodies_[bi].shape().volume();
            }
        }

        for (const label celli : activeCells_)
        {
            const label bi = label(id[celli]);
            if (bi < 0 || !projected_[bi]) continue;

            lambda_[celli] = 0;
            const scalar c =
                (bodies_[bi].rho()/rhoFluid_ - 1)*alpha[celli]*V[celli]/dt;
            diag[celli] += c;
            source[celli] += c*(U0[celli] + dt*g_);
            if (Fc)
            {
                source[celli] += alpha[celli]*V[celli]*(*Fc)[bi]/rhoVb[bi];
            }
        }
    }

    for (const label celli : activeCells_)
    {
        diag[celli] += lambda_[celli];
        source[celli] += lambda_[celli]*Us[celli];
    }
}


const Foam::List<Foam::vector>*
Foam::fbm::fictitiousBoundary::projectedContactForces() const
{
    if
    (
        projectContacts_ && collisions_.valid()
     && projectedForce_.size() == bodies_.size()
    )
    {
        return &projectedForce_;
    }
    return nullptr;
}


void Foam::fbm::fictitiousBoundary::relaxProjectedForce()
{
    if (!projectContacts_ || projectedForce_.size() != bodies_.size())
    {
        return;
    }
    const List<vector>& Fc = collisions_->meanForce();
    if (contactRelaxation_ == 1)
    {
        projectedForce_ = Fc;
    }
    else
    {
        forAll(projectedForce_, bi)
        {
            projectedForce_[bi] +=
                contactRelaxation_*(Fc[bi] - projectedForce_[bi]);
        }
    }
}


void Foam::fbm::fictitiousBoundary::projectionForces
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
    const vectorField& u = U.primitiveField();
    const vectorField& u0 = U.oldTime().primitiveField();
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V();

    const label nb = bodies_.size();
    List<vector> dP(nb, Zero), dL(nb, Zero), Ku(nb, Zero), Lu(nb, Zero);
    scalarList K(nb, Zero);
    List<symmTensor> KJ(nb, Zero);
    forAll(bodies_, bi)
    {
        if (!projected_[bi]) continue;

        const body& b = bodies_[bi];
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
        Pstream::listCombineGather(*l, plusEqOp<vector>());
        Pstream::listCombineScatter(*l);
    }
    Pstream::listCombineGather(K, plusEqOp<scalar>());
    Pstream::listCombineScatter(K);
    Pstream::listCombineGather(KJ, plusEqOp<symmTensor>());
    Pstream::listCombineScatter(KJ);

    // The body's new velocity conserves the momentum of the body and of
    // the fluid share the blend moves:
    //     M U + rho_f (K U - Ku) = M U^0 + rho_s dP,
    // and likewise, per principal axis, its angular velocity. The force
    // is the body's rate of change of momentum less its submerged weight,
    // which fbm::body adds back.
    const List<vector>* Fc = projectedContactForces();

    const scalar dt = mesh_.time().deltaTValue();
    forAll(bodies_, bi)
    {
        if (!projected_[bi]) continue;

        const body& b = bodies_[bi];
        const scalar Vb = b.shape().volume();
        const scalar M = b.rho()*Vb;

        const vector Unew
        (
            (M*b.U() + b.rho()*dP[bi] + rhoFluid_*Ku[bi])
           /(M + rhoFluid_*K[bi])
        );
        force[bi] = M*(Unew - b.U())/dt - (M - rhoFluid_*Vb)*g_;
        if (Fc)
        {
            // The contacts act again in the sub-steps that follow
            force[bi] -= (*Fc)[bi];
        }

        const symmTensor I(b.inertia());
        const vector Lnew(b.rho()*dL[bi] + rhoFluid_*Lu[bi]);
        vector wNew(b.omega());
        const direction diagCmpt[3] =
            { symmTensor::XX, symmTensor::YY, symmTensor::ZZ };
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            const scalar Idd = I.component(diagCmpt[d]);
            if (Idd <= 0) continue;
            const scalar Kdd = rhoFluid_*KJ[bi].component(diagCmpt[d]);
            wNew[d] = (Idd*b.omega()[d] + Lnew[d])/(Idd + Kdd);
        }
        torque[bi] = (I & (wNew - b.omega()))/dt;
    }
}


void Foam::fbm::fictitiousBoundary::rigidify
(
    volVectorField& U,
    const labelList& cells,
    const scalarList& alpha,
    const labelList& id,
    const List<point>& centres
) const
{
    vectorField& u = U.primitiveFieldRef();
    const vectorField& C = mesh_.C().primitiveField();

    forAll(cells, i)
    {
        const label bi = id[i];
        if (bi < 0 || !projected_[bi]) continue;

        const body& b = bodies_[bi];
        const label celli = cells[i];
        const vector Ub(b.U() + (b.omega() ^ (C[celli] - centres[bi])));
        u[celli] = (1 - alpha[i])*u[celli] + alpha[i]*Ub;
    }
    U.correctBoundaryConditions();
}


void Foam::fbm::fictitiousBoundary::calcForces
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
    model.calcForces(*this, U, p, nuEff, force, torque);

    // Sum the processors' parts
    Pstream::listCombineGather(force, plusEqOp<vector>());
    Pstream::listCombineScatter(force);
    Pstream::listCombineGather(torque, plusEqOp<vector>());
    Pstream::listCombineScatter(torque);
}


void Foam::fbm::fictitiousBoundary::writeLine
(
    OFstream& os,
    const body& b,
    const vector& F,
    const vector& T
) const
{
    os  << mesh_.time().value()
        << ' ' << F.x() << ' ' << F.y() << ' ' << F.z()
        << ' ' << T.x() << ' ' << T.y() << ' ' << T.z();
    if (b.hasCoefficients())
    {
        os  << ' ' << b.Cd(rhoFluid_, F) << ' ' << b.Cl(rhoFluid_, F);
    }
    const point& X = b.centre();
    const vector& V = b.U();
    const vector& w = b.omega();
    os  << ' ' << X.x() << ' ' << X.y() << ' ' << X.z()
        << ' ' << V.x() << ' ' << V.y() << ' ' << V.z()
        << ' ' << w.x() << ' ' << w.y() << ' ' << w.z() << endl;
}


bool Foam::fbm::fictitiousBoundary::correctForces
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

    const bool project = (coupling_ == couplingType::rigidProjection);

    List<vector> force, torque;
    {
        phaseTimes::scope forcesTime(times_, phaseTimes::forces);
        if (project && !projected_.found(false))
        {
            // Every body is projected: the force model's values would all
            // be replaced below (it costs a pass over the covered cells
            // and a reduction of 2N vectors a step)
            force.setSize(bodies_.size(), Zero);
            torque.setSize(bodies_.size(), Zero);
        }
        else
        {
            calcForces(forceModel_(), U, p, nuEff, force, torque);
        }
        if (project)
        {
            projectionForces(U, force, torque);
        }
    }

    forAll(bodies_, bi)
    {
        bodies_[bi].setForce(force[bi], torque[bi]);
    }

    // rigidProjection: the bodies move over the step with these forces
    // (and the contacts), and the flow in them takes their rigid motion
    bool inside = true;
    if (project)
    {
        // The footprint the flow was solved with: the flow there takes
        // the bodies' new velocities (the cells a body moves into keep
        // their fluid velocity; the next step accelerates them and
        // charges the body)
        const labelList cells(activeCells_);
        scalarList alpha(cells.size());
        labelList id(cells.size());
        forAll(cells, i)
        {
            alpha[i] = alpha_[cells[i]];
            id[i] = label(bodyID_[cells[i]]);
        }
        List<point> centres(bodies_.size());
        forAll(bodies_, bi)
        {
            centres[bi] = bodies_[bi].centre();
        }

        inside = advanceBodies();

        phaseTimes::scope forcingTime(times_, phaseTimes::forcing);
        rigidify(U, cells, alpha, id, centres);
    }

    {
        phaseTimes::scope outputTime(times_, phaseTimes::output);

        forAll(selected_, si)
        {
            const body& b = bodies_[selected_[si]];

            Info<< "fbm: " << b.name() << " F = " << b.force()
                << " T = " << b.torque();
            if (b.hasCoefficients())
            {
                Info<< " Cd = " << b.Cd(rhoFluid_)
                    << " Cl = " << b.Cl(rhoFluid_);
            }
            Info<< nl;

            if (Pstream::master())
            {
                writeLine(files_[si], b, b.force(), b.torque());
            }
        }

        writeSummary();

        if (mesh_.time().writeTime())
        {
            writeState();
            writeCloud();
        }

        // Force models computed for comparison only: counted as output
        forAll(compareModels_, mi)
        {
            calcForces(compareModels_[mi], U, p, nuEff, force, torque);
            if (Pstream::master())
            {
                forAll(selected_, si)
                {
                    const label bi = selected_[si];
                    writeLine
                    (
                        files_[(mi + 1)*selected_.size() + si],
                        bodies_[bi], force[bi], torque[bi]
                    );
                }
            }
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
