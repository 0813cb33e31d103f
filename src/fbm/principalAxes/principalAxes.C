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

#include "principalAxes.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::principalAxes::principalAxes(const symmTensor& S)
:
    values_(Zero),
    axes_(tensor::I)
{
    tensor A(S);
    tensor V(tensor::I);
    const scalar norm = mag(S);
    static const direction pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};

    for (label sweep = 0; sweep < 50; ++sweep)
    {
        const scalar off =
            Foam::sqrt(sqr(A.xy()) + sqr(A.xz()) + sqr(A.yz()));
        if (off <= 1e-15*norm)
        {
            break;
        }
        for (const auto& pq : pairs)
        {
            const direction p = pq[0], q = pq[1];
            if (A(p, q) == 0)
            {
                continue;
            }
            // The rotation in the (p, q) plane that zeroes A(p, q)
            const scalar theta = (A(q, q) - A(p, p))/(2*A(p, q));
            const scalar t =
                sign(theta)/(mag(theta) + Foam::sqrt(sqr(theta) + 1));
            const scalar c = 1/Foam::sqrt(sqr(t) + 1);
            const scalar s = t*c;
            tensor J(tensor::I);
            J(p, p) = c;
            J(q, q) = c;
            J(p, q) = s;
            J(q, p) = -s;
            A = J.T() & A & J;
            A(p, q) = A(q, p) = 0;
            V = V & J;
        }
    }

    // Ascending order, the axes as columns
    FixedList<direction, 3> order({0, 1, 2});
    for (label i = 0; i < 3; ++i)
    {
        for (label j = i + 1; j < 3; ++j)
        {
            if (A(order[j], order[j]) < A(order[i], order[i]))
            {
                Swap(order[i], order[j]);
            }
        }
    }
    for (direction k = 0; k < 3; ++k)
    {
        values_[k] = A(order[k], order[k]);
        for (direction r = 0; r < 3; ++r)
        {
            axes_(r, k) = V(r, order[k]);
        }
    }
    if (det(axes_) < 0)
    {
        for (direction r = 0; r < 3; ++r)
        {
            axes_(r, 2) = -axes_(r, 2);
        }
    }
}


// ************************************************************************* //
