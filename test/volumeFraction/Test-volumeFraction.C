/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

Application
    Test-volumeFraction

Description
    The solid volume fraction summed over the cells, sum(alpha V), against
    the shape's exact volume (pi R^2 depth for a circle, 4/3 pi R^3 for a
    sphere), and alpha within [0, 1]. The relative tolerance is an option
    (the runner gives a tighter one on finer meshes). For a circle, an
    ellipse and a polygon, whose fractions are exact, also each cell
    against the adaptive sampling of fbm::bodyShape at depth 10.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "bodySystem.H"
#include "fbmTest.H"

int main(int argc, char *argv[])
{
    argList::addOption("tol", "scalar", "relative tolerance on the volume");
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar tol = args.get<scalar>("tol");

    fbm::bodySystem fb(mesh);

    for (const fbm::body& b : fb.bodies())
    {
        scalar vol = 0;
        scalar aMin = 1, aMax = 0;
        forAll(b.cells(), i)
        {
            const scalar a = b.alpha()[i];
            vol += a*mesh.V()[b.cells()[i]];
            aMin = min(aMin, a);
            aMax = max(aMax, a);
        }
        const scalar V = b.shape().volume();

        const scalar h =
            mesh.nSolutionD() == 2
          ? Foam::sqrt(mesh.V()[0]/mesh.bounds().span().z())
          : Foam::cbrt(mesh.V()[0]);
        Info<< b.name() << ": " << mesh.nCells() << " cells, R/h = "
            << b.shape().radius()/h << nl;
        fbmTest::check("relative volume error", (vol - V)/V, 0, tol);
        fbmTest::check("min alpha >= 0", min(aMin, scalar(0)), 0, 0);
        fbmTest::check("max alpha <= 1", max(aMax, scalar(1)), 1, 0);

        // A circle's, an ellipse's and a polygon's fraction is exact per
        // cell: against the adaptive sampling of the base class at depth 10
        // (leaf h/1024, planar leaves: error about (h/1024)^2 kappa h per
        // cell on a curve of curvature kappa, (h/1024)^2 at a corner)
        const word type(b.shape().type());
        if (type == "circle" || type == "ellipse" || type == "polygon")
        {
            scalar worst = 0;
            forAll(b.cells(), i)
            {
                boundBox bb
                (
                    mesh.points(), mesh.cellPoints()[b.cells()[i]], false
                );
                bb.min() -= b.centre();
                bb.max() -= b.centre();
                worst = max
                (
                    worst,
                    mag
                    (
                        b.alpha()[i]
                      - b.shape().sampleFraction(bb, 10)
                    )
                );
            }
            fbmTest::check
            (
                type + ": largest cell difference to sampling", worst, 0, 1e-5
            );
        }

        // The total field agrees with the body's list
        fbmTest::check
        (
            "sum(alpha.solid V) = body volume",
            (gSum(fb.fb().alpha().primitiveField()*mesh.V()) - vol)/V, 0, 1e-12
        );
    }

    return fbmTest::result();
}


// ************************************************************************* //
