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
    autoPtr<bodyShape>&& shape,
    const scalar rho,
    const bodyState& state,
    const bool translate,
    const bool rotate
)
:
    name_(name),
    shape_(std::move(shape)),
    rho_(rho),
    translate_(translate),
    rotate_(rotate),
    state_(state),
    motion_(nullptr),
    bandValid_(false),
    U0_(Zero),
    omega0_(Zero),
    aHeld_(Zero),
    omegaDotHeld_(Zero)
{}


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

void Foam::fbm::body::setMotion
(
    autoPtr<prescribedMotion>&& motion,
    const scalar t
)
{
    if (translate_)
    {
        FatalErrorInFunction
            << "Body " << name_ << ": a prescribed motion needs translate no"
            << abort(FatalError);
    }
    motion_ = std::move(motion);
    motion_->set(t, state_);
}


Foam::symmTensor Foam::fbm::body::inertia() const
{
    // Q I0 Q^T; circles and spheres are axisymmetric, so this is I0
    const tensor& Q = state_.Q();
    return symm(Q & (rho_*shape_->inertiaPerDensity()) & Q.T());
}


void Foam::fbm::body::beginSubCycles()
{
    U0_ = U();
    omega0_ = omega();
    aHeld_ = state_.acceleration();
    omegaDotHeld_ = state_.angularAcceleration();
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
    const point& X = centre();
    const vector h(shape_->halfExtent());
    boundBox bb(X - h, X + h);
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
            boundBox(cbb.min() - X, cbb.max() - X),
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
