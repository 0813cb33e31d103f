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

#include "triSurfaceShape.H"
#include "polyMesh.H"
#include "Time.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace bodyShapes
{
    defineTypeNameAndDebug(triSurfaceShape, 0);
    addToRunTimeSelectionTable(bodyShape, triSurfaceShape, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShapes::triSurfaceShape::triSurfaceShape
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    surf_(),
    search_(),
    centroid_(Zero),
    volume_(0),
    inertia_(Zero),
    radius_(0)
{
    FixedList<direction, 2> axes;
    checkDimension(mesh, dict, 3, axes);

    const word body(dict.dictName());
    const fileName name(dict.get<fileName>("file"));
    const scalar scale =
        dict.getCheckOrDefault<scalar>
        (
            "scale", 1, [](scalar s){ return s > 0; }
        );
    // In the case folder (a decomposed case: the undecomposed one)
    const fileName path
    (
        mesh.time().globalPath()/mesh.time().constant()/"triSurface"/name
    );
    if (!isFile(path))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' of body " << body << ": no surface file "
            << path << exit(FatalIOError);
    }
    triSurface surf(path);
    surf.scalePoints(scale);

    // Closed: every edge shared by exactly two triangles
    label nOpen = 0;
    for (const labelList& ef : surf.edgeFaces())
    {
        if (ef.size() != 2) ++nOpen;
    }
    if (surf.size() < 4 || nOpen)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' of body " << body << ": the surface " << path
            << " is not closed (" << nOpen << " of " << surf.nEdges()
            << " edges are not shared by exactly two triangles, "
            << surf.size() << " triangles)" << exit(FatalIOError);
    }

    // Volume, first and second moments: signed tetrahedra with the origin
    // (about the first point, for round-off)
    const pointField& pts = surf.points();
    const point p0(pts[0]);
    scalar V = 0;
    vector m1(Zero);
    symmTensor m2(Zero);
    for (const labelledTri& t : surf)
    {
        const vector a(pts[t[0]] - p0), b(pts[t[1]] - p0), c(pts[t[2]] - p0);
        const scalar Vt = (a & (b ^ c))/6;
        const vector s(a + b + c);
        V += Vt;
        m1 += Vt*s/4;
        m2 += Vt/20*(sqr(a) + sqr(b) + sqr(c) + sqr(s));
    }
    if (V < 0)
    {
        // Inward normals: turn every triangle
        List<labelledTri> tris(surf);
        for (labelledTri& t : tris)
        {
            std::swap(t[1], t[2]);
        }
        surf = triSurface(tris, surf.patches(), pointField(pts));
        V = -V;
        m1 = -m1;
        m2 = -m2;
    }
    if (V <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' of body " << body << ": the surface " << path
            << " encloses no volume" << exit(FatalIOError);
    }
    const vector c(m1/V);
    const symmTensor S(m2 - V*sqr(c));
    volume_ = V;
    centroid_ = p0 + c;
    inertia_ = tr(S)*symmTensor::I - S;

    // About the centroid
    pointField shifted(surf.points() - centroid_);
    radius_ = max(mag(shifted));
    surf_.reset(new triSurface(surf, surf.patches(), shifted));
    search_.reset(new triSurfaceSearch(surf_()));
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::pointIndexHit Foam::fbm::bodyShapes::triSurfaceShape::nearest
(
    const point& p,
    bool& inside
) const
{
    const indexedOctree<treeDataTriSurface>& tree = search_->tree();
    inside = (tree.getVolumeType(p) == volumeType::INSIDE);
    return tree.findNearest(p, sqr(mag(p) + 2*radius_));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::triSurfaceShape::signedDistance
(
    const vector& r
) const
{
    const point p(toBody(r));
    bool inside;
    const pointIndexHit hit(nearest(p, inside));
    const scalar d = mag(p - hit.hitPoint());
    return inside ? -d : d;
}


Foam::vector Foam::fbm::bodyShapes::triSurfaceShape::normal
(
    const vector& r
) const
{
    const point p(toBody(r));
    bool inside;
    const pointIndexHit hit(nearest(p, inside));
    const vector d(p - hit.hitPoint());
    const scalar m = mag(d);
    if (m > 1e-9*radius_)
    {
        return toLab(inside ? -d/m : d/m);
    }
    return toLab(surf_->faceNormals()[hit.index()]);
}


Foam::vector Foam::fbm::bodyShapes::triSurfaceShape::halfExtent() const
{
    vector h(Zero);
    for (const point& p : surf_->points())
    {
        h = max(h, cmptMag(toLab(p)));
    }
    return h;
}


Foam::scalar Foam::fbm::bodyShapes::triSurfaceShape::diameter() const
{
    return 2*Foam::cbrt(3*volume_/(4*constant::mathematical::pi));
}


Foam::vector Foam::fbm::bodyShapes::triSurfaceShape::support
(
    const tensor& Q,
    const vector& d
) const
{
    // The points of the faces (body frame): the support of their convex
    // hull, also for a surface that is not convex
    return Q & supportPoint(surf_->localPoints(), vector(Q.T() & d));
}


Foam::vector Foam::fbm::bodyShapes::triSurfaceShape::planeContact
(
    const tensor& Q,
    const vector& d,
    const scalar band
) const
{
    return Q & bandMiddle(surf_->localPoints(), vector(Q.T() & d), band);
}



void Foam::fbm::bodyShapes::triSurfaceShape::supportBand
(
    const tensor& Q,
    const vector& d,
    const scalar band,
    DynamicList<vector>& pts,
    DynamicList<scalar>& weights
) const
{
    DynamicList<vector> sel;
    bandPoints(surf_->localPoints(), vector(Q.T() & d), band, sel, weights);
    for (const vector& p : sel)
    {
        pts.append(Q & p);
    }
}

// ************************************************************************* //
