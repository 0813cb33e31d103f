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

#include "wallPlanes.H"
#include "polyMesh.H"
#include "wallPolyPatch.H"
#include "SubField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::wallPlanes::wallPlanes(const polyMesh& mesh)
:
    names_(),
    points_(),
    normals_()
{
    const scalar tol = 1e-6;

    // Length scale for the offset check: the mesh bounding box diagonal
    const scalar L = mag(mesh.bounds().span());

    DynamicList<word> names;
    DynamicList<point> points;
    DynamicList<vector> normals;

    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!isA<wallPolyPatch>(pp))
        {
            continue;
        }

        const vectorField Sf(pp.faceAreas());
        const pointField Cf(pp.faceCentres());

        // Mean normal and area-weighted centre over all processors
        vector sumSf(sum(Sf));
        scalar sumA(sum(mag(Sf)));
        vector sumACf(Zero);
        forAll(Sf, facei)
        {
            sumACf += mag(Sf[facei])*Cf[facei];
        }
        reduce(sumSf, sumOp<vector>());
        reduce(sumA, sumOp<scalar>());
        reduce(sumACf, sumOp<vector>());

        if (sumA < VSMALL)
        {
            continue;
        }

        const vector n(sumSf/max(mag(sumSf), VSMALL));
        const point p(sumACf/sumA);

        // Largest deviation of a face normal and of a face centre
        scalar maxAngle = 0;
        scalar maxOffset = 0;
        forAll(Sf, facei)
        {
            const scalar A = mag(Sf[facei]);
            if (A < VSMALL) continue;
            maxAngle = max(maxAngle, 1 - ((Sf[facei]/A) & n));
            maxOffset = max(maxOffset, mag((Cf[facei] - p) & n));
        }
        reduce(maxAngle, maxOp<scalar>());
        reduce(maxOffset, maxOp<scalar>());

        if (maxAngle > tol || maxOffset > tol*L)
        {
            FatalErrorInFunction
                << "Wall patch " << pp.name() << " is not planar (largest"
                << " 1 - cos(angle) of a face normal to the mean normal "
                << maxAngle << ", largest face-centre offset from the"
                << " plane " << maxOffset << ")" << nl
                << "    The particle-wall contact needs planar walls: put"
                << " each plane in its own wall patch" << exit(FatalError);
        }

        names.append(pp.name());
        points.append(p);
        normals.append(n);
    }

    names_.transfer(names);
    points_.transfer(points);
    normals_.transfer(normals);

    Info<< "fbm: " << names_.size() << " planar walls for the contact:";
    forAll(names_, i)
    {
        Info<< ' ' << names_[i] << " (normal " << normals_[i] << ")";
    }
    Info<< nl;
}


// ************************************************************************* //
