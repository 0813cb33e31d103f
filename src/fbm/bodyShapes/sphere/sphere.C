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

#include "sphere.H"
#include "polyMesh.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace bodyShapes
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(bodyShape, sphere, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyShapes::sphere::sphere
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    radius_(readLength(dict, "radius", mesh))
{
    checkMesh(mesh, &dict);
}


Foam::fbm::bodyShapes::sphere::sphere
(
    const scalar radius,
    const polyMesh& mesh
)
:
    bodyShape(mesh),
    radius_(radius)
{
    checkMesh(mesh, nullptr);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::bodyShapes::sphere::checkMesh
(
    const polyMesh& mesh,
    const dictionary* dict
)
{
    if (mesh.nSolutionD() != 3)
    {
        const string msg
        (
            "A sphere needs a 3D mesh, this mesh has "
          + Foam::name(mesh.nSolutionD())
          + " solution directions: use 'type circle;' in 2D"
        );
        if (dict)
        {
            FatalIOErrorInFunction(*dict) << msg.c_str() << exit(FatalIOError);
        }
        FatalErrorInFunction << msg.c_str() << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::bodyShapes::sphere::signedDistance
(
    const vector& r
) const
{
    return mag(r) - radius_;
}


Foam::vector Foam::fbm::bodyShapes::sphere::normal(const vector& r) const
{
    const scalar m = mag(r);
    if (m < VSMALL)
    {
        return vector(1, 1, 1)/sqrt(3.0);
    }
    return r/m;
}


Foam::vector Foam::fbm::bodyShapes::sphere::halfExtent() const
{
    return vector(radius_, radius_, radius_);
}


Foam::scalar Foam::fbm::bodyShapes::sphere::volume() const
{
    return 4.0/3.0*constant::mathematical::pi*pow3(radius_);
}


Foam::symmTensor Foam::fbm::bodyShapes::sphere::inertiaPerDensity() const
{
    return symmTensor::I*(0.4*volume()*sqr(radius_));
}


Foam::vector Foam::fbm::bodyShapes::sphere::support
(
    const tensor&,
    const vector& d
) const
{
    const scalar m = mag(d);
    return m > 0 ? (radius_/m)*d : vector::zero;
}


// ************************************************************************* //
