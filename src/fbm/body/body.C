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

#include "body.H"
#include "fvMesh.H"
#include "treeBoundBox.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "HashSet.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// The cells of the octree whose boxes overlap searchBox, appended to cells
// (a cell in several leaves appears several times). The same walk as
// indexedOctree::findBox, which collects into a hash set sized by the whole
// mesh (nCells/100 buckets, allocated and cleared on every call: with
// 10,000 bodies on a million cells that was most of the cost of finding
// the covered cells).
void findCells
(
    const Foam::indexedOctree<Foam::treeDataCell>& tree,
    const Foam::label nodei,
    const Foam::treeBoundBox& searchBox,
    Foam::DynamicList<Foam::label>& cells
)
{
    typedef Foam::indexedOctree<Foam::treeDataCell> octree;

    const octree::node& nod = tree.nodes()[nodei];
    for (Foam::direction octant = 0; octant < 8; ++octant)
    {
        const Foam::labelBits index = nod.subNodes_[octant];

        if (octree::isNode(index))
        {
            const Foam::label sub = octree::getNode(index);
            if (tree.nodes()[sub].bb_.overlaps(searchBox))
            {
                findCells(tree, sub, searchBox, cells);
            }
        }
        else if (octree::isContent(index))
        {
            if (nod.bb_.subBbox(octant).overlaps(searchBox))
            {
                for
                (
                    const Foam::label celli
                  : tree.contents()[octree::getContent(index)]
                )
                {
                    if (tree.shapes().overlaps(celli, searchBox))
                    {
                        cells.append(celli);
                    }
                }
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::body::body
(
    const word& name,
    const dictionary& dict,
    const fvMesh& mesh,
    const indexedOctree<treeDataCell>* tree
)
:
    name_(name),
    dict_(dict),
    shape_(bodyShape::New(dict, mesh)),
    rho_(dict.getCheck<scalar>("rho", [](scalar r){ return r > 0; })),
    centre_(dict.get<point>("centre")),
    U_(dict.get<vector>("U")),
    omega_(dict.get<vector>("omega")),
    translate_(dict.get<bool>("translate")),
    rotate_(dict.get<bool>("rotate")),
    Q_(tensor::I),
    theta_(Zero),
    a_(Zero),
    omegaDot_(Zero),
    planeMask_(1, 1, 1),
    coeffs_(dict.found("coefficients")),
    magUInf_(1),
    Aref_(1),
    dragDir_(1, 0, 0),
    liftDir_(0, 1, 0),
    bandValid_(false),
    force_(Zero),
    torque_(Zero),
    U0_(Zero),
    omega0_(Zero),
    aHeld_(Zero),
    omegaDotHeld_(Zero)
{
    if (coeffs_)
    {
        const dictionary& cDict = dict.subDict("coefficients");
        magUInf_ =
            cDict.getCheck<scalar>("magUInf", [](scalar u){ return u > 0; });
        Aref_ = cDict.getCheck<scalar>("Aref", [](scalar a){ return a > 0; });
        dragDir_ = cDict.get<vector>("dragDir");
        liftDir_ = cDict.get<vector>("liftDir");
        if (mag(dragDir_) < SMALL || mag(liftDir_) < SMALL)
        {
            FatalIOErrorInFunction(cDict)
                << "Body " << name_ << ": dragDir and liftDir must be"
                << " non-zero vectors" << exit(FatalIOError);
        }
        dragDir_ /= mag(dragDir_);
        liftDir_ /= mag(liftDir_);
    }

    // In 2D the centre's empty component is put mid-depth; the motion
    // must stay in the plane
    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0)
        {
            centre_[d] = mesh.bounds().centre()[d];
            planeMask_[d] = 0;

            if (mag(U_[d]) > 0)
            {
                FatalIOErrorInFunction(dict)
                    << "Body " << name_ << ": U " << U_ << " has a component"
                    << " in the empty direction of this 2D mesh"
                    << exit(FatalIOError);
            }
        }
        else if (mesh.nSolutionD() == 2 && mag(omega_[d]) > 0)
        {
            FatalIOErrorInFunction(dict)
                << "Body " << name_ << ": omega " << omega_ << " must be"
                << " along the empty direction of this 2D mesh"
                << exit(FatalIOError);
        }
    }

    // The centre must lie in the mesh (on some processor). The cell test
    // uses the mesh's tet decomposition, which is built collectively: build
    // it on every processor first, not only where the centre has candidate
    // cells (that deadlocked a decomposed run)
    (void)mesh.tetBasePtIs();
    const bool found =
    (
        (tree ? findCell(mesh, *tree, centre_) : mesh.findCell(centre_))
     != -1
    );
    if (!returnReduce(found, orOp<bool>()))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << name_ << ": centre " << centre_
            << " is outside the mesh (bounds " << mesh.bounds() << ")"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::label Foam::fbm::body::findCell
(
    const fvMesh& mesh,
    const indexedOctree<treeDataCell>& tree,
    const point& p
)
{
    const vector eps(vector::uniform(ROOTVSMALL));
    DynamicList<label> candidates;
    if (tree.nodes().size())
    {
        findCells(tree, 0, treeBoundBox(p - eps, p + eps), candidates);
    }
    for (const label celli : candidates)
    {
        if (mesh.pointInCell(p, celli, polyMesh::CELL_TETS))
        {
            return celli;
        }
    }
    return -1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::body::Cd
(
    const scalar rhoFluid,
    const vector& F
) const
{
    return (F & dragDir_)/(0.5*rhoFluid*sqr(magUInf_)*Aref_);
}


Foam::scalar Foam::fbm::body::Cl
(
    const scalar rhoFluid,
    const vector& F
) const
{
    return (F & liftDir_)/(0.5*rhoFluid*sqr(magUInf_)*Aref_);
}


Foam::symmTensor Foam::fbm::body::inertia() const
{
    // Q I0 Q^T; circles and spheres are axisymmetric, so this is I0
    return symm(Q_ & (rho_*shape_->inertiaPerDensity()) & Q_.T());
}


Foam::vector Foam::fbm::body::linearAcceleration
(
    const vector& g,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const vector& contactForce,
    const vector& aLag
) const
{
    const scalar V = shape_->volume();
    const scalar M = rho_*V;
    const scalar Mf = rhoFluid*V;

    // Summed in this order (heldTranslation and fbm::particleCollisions
    // repeat it)
    const vector Fnet
    (
        (M - Mf)*g + force_ + contactForce + addedMassCoeff*Mf*aLag
    );
    return cmptMultiply(planeMask_, Fnet/(M + addedMassCoeff*Mf));
}


void Foam::fbm::body::heldTranslation
(
    const vector& g,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    vector& Fheld,
    vector& Flag,
    scalar& Meff,
    vector& mask
) const
{
    // The terms of linearAcceleration with aLag = aHeld_
    const scalar V = shape_->volume();
    const scalar M = rho_*V;
    const scalar Mf = rhoFluid*V;

    Fheld = (M - Mf)*g + force_;
    Flag = addedMassCoeff*Mf*aHeld_;
    Meff = M + addedMassCoeff*Mf;
    mask = planeMask_;
}


Foam::vector Foam::fbm::body::angularAcceleration
(
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const vector& omegaDotLag
) const
{
    // Same virtual-mass stabilisation as the translation, with the
    // inertia of the enclosed fluid I_f = (rho_f/rho_s) I
    const symmTensor I(inertia());
    const symmTensor If((rhoFluid/rho_)*I);
    vector wDot
    (
        inv(I + addedMassCoeff*If)
      & (
            torque_ - (omega_ ^ (I & omega_))
          + addedMassCoeff*(If & omegaDotLag)
        )
    );
    if (cmptMin(planeMask_) == 0)
    {
        // 2D: rotation about the empty direction only
        wDot = wDot - cmptMultiply(planeMask_, wDot);
    }
    return wDot;
}


void Foam::fbm::body::rotateBy(const vector& phi)
{
    theta_ += phi;
    const scalar angle = mag(phi);
    if (angle > VSMALL)
    {
        const vector k(phi/angle);
        const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
        const tensor R(tensor::I + Foam::sin(angle)*K
          + (1 - Foam::cos(angle))*(K & K));
        Q_ = R & Q_;
    }
}


void Foam::fbm::body::move
(
    const vector& g,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const scalar dt
)
{
    if (translate_)
    {
        // No contact force: adding a zero vector leaves the sum
        // bit-identical
        const vector aNew
        (
            linearAcceleration(g, rhoFluid, addedMassCoeff, Zero, a_)
        );
        const vector U0(U_);
        U_ += dt*aNew;
        centre_ += 0.5*dt*(U0 + U_);
        a_ = aNew;
    }
    else
    {
        // Prescribed (held) velocity: the body moves with it
        centre_ += dt*U_;
    }

    if (rotate_)
    {
        const vector wDot
        (
            angularAcceleration(rhoFluid, addedMassCoeff, omegaDot_)
        );
        const vector w0(omega_);
        omega_ += dt*wDot;
        omegaDot_ = wDot;

        // Rotate the orientation by the mean angular velocity of the step
        rotateBy(0.5*dt*(w0 + omega_));
    }
    else
    {
        rotateBy(dt*omega_);
    }
}


void Foam::fbm::body::beginSubCycles()
{
    U0_ = U_;
    omega0_ = omega_;
    aHeld_ = a_;
    omegaDotHeld_ = omegaDot_;
}


void Foam::fbm::body::kick
(
    const vector& g,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const scalar dt,
    const vector& contactForce
)
{
    if (translate_)
    {
        U_ += dt*linearAcceleration
        (
            g, rhoFluid, addedMassCoeff, contactForce, aHeld_
        );
    }
    if (rotate_)
    {
        omega_ += dt*angularAcceleration
        (
            rhoFluid, addedMassCoeff, omegaDotHeld_
        );
    }
}


void Foam::fbm::body::drift(const scalar dt)
{
    // Integrated or prescribed (held) velocities alike
    centre_ += dt*U_;
    rotateBy(dt*omega_);
}


void Foam::fbm::body::endTranslationSubCycles
(
    const point& centre,
    const vector& U,
    const scalar rhoFluid,
    const scalar addedMassCoeff,
    const label n,
    const scalar dtSub
)
{
    centre_ = centre;
    U_ = U;

    // The rotation part of kick() and drift(), sub-step by sub-step
    if (!rotate_ && magSqr(omega_) == 0)
    {
        return;
    }
    const scalar h = 0.5*dtSub;
    for (label step = 0; step < n; ++step)
    {
        if (rotate_)
        {
            omega_ += h*angularAcceleration
            (
                rhoFluid, addedMassCoeff, omegaDotHeld_
            );
        }
        rotateBy(dtSub*omega_);
        if (rotate_)
        {
            omega_ += h*angularAcceleration
            (
                rhoFluid, addedMassCoeff, omegaDotHeld_
            );
        }
    }
}


void Foam::fbm::body::endSubCycles(const scalar dt)
{
    if (translate_)
    {
        a_ = (U_ - U0_)/dt;
    }
    if (rotate_)
    {
        omegaDot_ = (omega_ - omega0_)/dt;
    }
}


void Foam::fbm::body::readState(const dictionary& dict)
{
    centre_ = dict.get<point>("centre");
    U_ = dict.get<vector>("U");
    omega_ = dict.get<vector>("omega");
    Q_ = dict.get<tensor>("Q");
    theta_ = dict.get<vector>("theta");
    a_ = dict.get<vector>("acceleration");
    omegaDot_ = dict.get<vector>("angularAcceleration");
    force_ = dict.get<vector>("force");
    torque_ = dict.get<vector>("torque");
}


void Foam::fbm::body::writeState(dictionary& dict) const
{
    dict.add("centre", centre_);
    dict.add("U", U_);
    dict.add("omega", omega_);
    dict.add("Q", Q_);
    dict.add("theta", theta_);
    dict.add("acceleration", a_);
    dict.add("angularAcceleration", omegaDot_);
    dict.add("force", force_);
    dict.add("torque", torque_);
}


Foam::scalar Foam::fbm::body::localCoveredVolume(const fvMesh& mesh) const
{
    scalar vol = 0;
    forAll(cells_, i)
    {
        vol += alpha_[i]*mesh.V()[cells_[i]];
    }
    return vol;
}


const Foam::labelList& Foam::fbm::body::bandCells(const fvMesh& mesh) const
{
    if (bandValid_)
    {
        return bandCells_;
    }

    // Band where grad(alpha) is non-zero: every cell whose alpha differs
    // from a face neighbour's, and those neighbours
    Map<scalar> alphaOf(2*cells_.size());
    forAll(cells_, i)
    {
        alphaOf.insert(cells_[i], alpha_[i]);
    }

    const labelListList& cellCells = mesh.cellCells();
    labelHashSet band(2*cells_.size());
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        bool edge = (alpha_[i] < 1);
        if (!edge)
        {
            for (const label nbr : cellCells[celli])
            {
                if (alphaOf.lookup(nbr, 0) != alpha_[i])
                {
                    edge = true;
                    break;
                }
            }
        }
        if (edge)
        {
            band.insert(celli);
            band.insert(cellCells[celli]);
        }
    }
    bandCells_ = band.sortedToc();
    bandValid_ = true;

    return bandCells_;
}


void Foam::fbm::body::updateCells
(
    const fvMesh& mesh,
    const indexedOctree<treeDataCell>& tree,
    const List<boundBox>& cellBb,
    const label nSubdivision
)
{
    // Candidate cells: those whose bounding box meets the body's
    const vector h(shape_->halfExtent());
    boundBox bb(centre_ - h, centre_ + h);
    const boundBox& meshBb = mesh.bounds();
    bb.min() = max(bb.min(), meshBb.min() - meshBb.span()*1e-6);
    bb.max() = min(bb.max(), meshBb.max() + meshBb.span()*1e-6);

    DynamicList<label> candidates;
    if (tree.nodes().size())
    {
        findCells(tree, 0, treeBoundBox(bb.min(), bb.max()), candidates);
        Foam::sort(candidates);
        label n = 0;
        forAll(candidates, i)
        {
            if (i == 0 || candidates[i] != candidates[n - 1])
            {
                candidates[n++] = candidates[i];
            }
        }
        candidates.resize(n);
    }

    DynamicList<label> cells(candidates.size());
    DynamicList<scalar> alpha(candidates.size());

    for (const label celli : candidates)
    {
        const boundBox& cbb = cellBb[celli];
        const scalar a = shape_->boxFraction
        (
            boundBox(cbb.min() - centre_, cbb.max() - centre_),
            nSubdivision
        );
        if (a > 0)
        {
            cells.append(celli);
            alpha.append(a);
        }
    }

    cells_.transfer(cells);
    alpha_.transfer(alpha);

    bandValid_ = false;
}


// ************************************************************************* //
