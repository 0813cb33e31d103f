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

#include "domainBoundary.H"
#include "polyMesh.H"
#include "wallPolyPatch.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::domainBoundary::domainBoundary(const polyMesh& mesh)
:
    mesh_(mesh),
    patches_(),
    isWall_(),
    bb_()
{
    DynamicList<label> patches;
    DynamicList<bool> isWall;
    DynamicList<boundBox> bb;

    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if
        (
            pp.coupled()
         || isA<emptyPolyPatch>(pp)
         || isA<wedgePolyPatch>(pp)
        )
        {
            continue;
        }
        patches.append(pp.index());
        isWall.append(isA<wallPolyPatch>(pp));
        bb.append(pp.size() ? boundBox(pp.localPoints(), false) : boundBox());
    }

    patches_.transfer(patches);
    isWall_.transfer(isWall);
    bb_.transfer(bb);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fbm::domainBoundary::hasOpen() const
{
    for (const bool w : isWall_)
    {
        if (!w) return true;
    }
    return false;
}


const Foam::word& Foam::fbm::domainBoundary::patchName
(
    const label patchi
) const
{
    return mesh_.boundaryMesh()[patchi].name();
}


bool Foam::fbm::domainBoundary::isWall(const label patchi) const
{
    return isA<wallPolyPatch>(mesh_.boundaryMesh()[patchi]);
}


void Foam::fbm::domainBoundary::crossed
(
    const PtrList<body>& bodies,
    const boolList& check,
    const patchKind kind,
    labelList& patch,
    scalarList& depth
) const
{
    const scalar tol = 1e-6;
    const pointField& points = mesh_.points();

    patch.setSize(bodies.size());
    depth.setSize(bodies.size());
    patch = -1;
    depth = 0;

    forAll(bodies, bi)
    {
        if (!check[bi]) continue;

        const body& b = bodies[bi];
        const point& X = b.centre();
        const scalar R = b.shape().radius();

        forAll(patches_, i)
        {
            if (!takes(i, kind)) continue;

            const polyPatch& pp = mesh_.boundaryMesh()[patches_[i]];
            if (pp.empty() || !bb_[i].overlaps(X, sqr(R))) continue;

            for (const face& f : pp)
            {
                const point xf(f.nearestPoint(X, points).rawPoint());
                const scalar d = -b.shape().signedDistance(xf - X);
                if (d > tol*R && d > depth[bi])
                {
                    depth[bi] = d;
                    patch[bi] = patches_[i];
                }
            }
        }
    }

    if (Pstream::parRun())
    {
        // The deepest over the processors, and the patch of that depth
        scalarList localDepth(depth);
        Pstream::listCombineGather(depth, maxEqOp<scalar>());
        Pstream::listCombineScatter(depth);
        forAll(patch, bi)
        {
            if (localDepth[bi] < depth[bi])
            {
                patch[bi] = -1;
            }
        }
        Pstream::listCombineGather(patch, maxEqOp<label>());
        Pstream::listCombineScatter(patch);
    }
}


Foam::label Foam::fbm::domainBoundary::nearestPatch(const point& p) const
{
    const pointField& points = mesh_.points();

    scalar dMin = GREAT;
    label nearest = -1;
    forAll(patches_, i)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patches_[i]];
        for (const face& f : pp)
        {
            const scalar d = f.nearestPoint(p, points).distance();
            if (d < dMin)
            {
                dMin = d;
                nearest = patches_[i];
            }
        }
    }

    const scalar dGlobal = returnReduce(dMin, minOp<scalar>());
    if (dMin > dGlobal)
    {
        nearest = -1;
    }
    return returnReduce(nearest, maxOp<label>());
}


// ************************************************************************* //
