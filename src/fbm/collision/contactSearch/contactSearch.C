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

#include "contactSearch.H"
#include "boundBox.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::contactSearch::contactSearch()
:
    pairs_(),
    nCells_(0, 0, 0),
    cellStart_(),
    cellParticles_(),
    particleCell_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::contactSearch::search
(
    const UList<point>& X,
    const UList<scalar>& R,
    const scalar range
)
{
    pairs_.clear();

    const label n = X.size();
    if (n < 2)
    {
        nCells_ = Vector<label>(0, 0, 0);
        return;
    }

    // Grid over the bounding box of the centres
    boundBox bb(X.first(), X.first());
    scalar Rmax = 0;
    scalar Rmin = GREAT;
    forAll(X, i)
    {
        bb.add(X[i]);
        Rmax = max(Rmax, R[i]);
        Rmin = min(Rmin, R[i]);
    }
    const vector span(bb.span());

    // Particles larger than 4 Rmin are searched by a box query, so that
    // a few big ones do not size the grid: the grid is sized by the
    // largest of the others
    const scalar Rlarge = 4*Rmin;
    scalar Rgrid = 0;
    forAll(X, i)
    {
        if (R[i] <= Rlarge) Rgrid = max(Rgrid, R[i]);
    }

    scalar width = max(2*Rgrid + range, VSMALL);
    const scalar maxCells = 4.0*n + 64;
    while (true)
    {
        // Counted in scalars: no label overflow for a sparse set
        scalar total = 1;
        scalar nd[3];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            nd[d] = max(scalar(1), std::floor(span[d]/width));
            total *= nd[d];
        }
        if (total <= maxCells)
        {
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                nCells_[d] = label(nd[d]);
            }
            break;
        }
        width *= 2;
    }

    // Actual cell widths (>= width)
    vector cellWidth(Zero);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        cellWidth[d] = span[d]/nCells_[d];
    }

    const label nx = nCells_.x();
    const label nxy = nx*nCells_.y();
    const label nTotal = nxy*nCells_.z();

    // Cell of each particle, counting sort
    particleCell_.setSize(n);
    cellStart_.setSize(nTotal + 1);
    cellStart_ = 0;
    forAll(X, i)
    {
        label ijk[3];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            ijk[d] =
                cellWidth[d] > 0
              ? min
                (
                    nCells_[d] - 1,
                    label((X[i][d] - bb.min()[d])/cellWidth[d])
                )
              : 0;
        }
        particleCell_[i] = ijk[0] + nx*ijk[1] + nxy*ijk[2];
        ++cellStart_[particleCell_[i] + 1];
    }
    for (label c = 0; c < nTotal; ++c)
    {
        cellStart_[c + 1] += cellStart_[c];
    }
    cellParticles_.setSize(n);
    {
        labelList fill(SubList<label>(cellStart_, nTotal));
        forAll(X, i)
        {
            cellParticles_[fill[particleCell_[i]]++] = i;
        }
    }

    // Each particle against the particles of the neighbouring cells; a
    // pair is taken once: from the lower cell, or within one cell from the
    // lower index
    forAll(X, i)
    {
        if (R[i] > Rlarge) continue;

        const label ci = particleCell_[i];
        const label k = ci/nxy;
        const label j = (ci - k*nxy)/nx;
        const label l = ci - k*nxy - j*nx;

        for (label kk = max(k - 1, 0); kk <= min(k + 1, nCells_.z() - 1); ++kk)
        for (label jj = max(j - 1, 0); jj <= min(j + 1, nCells_.y() - 1); ++jj)
        for (label ll = max(l - 1, 0); ll <= min(l + 1, nx - 1); ++ll)
        {
            const label cj = ll + nx*jj + nxy*kk;
            if (cj < ci) continue;

            for (label s = cellStart_[cj]; s < cellStart_[cj + 1]; ++s)
            {
                const label p = cellParticles_[s];
                if (cj == ci && p <= i) continue;
                if (R[p] > Rlarge) continue;

                if (mag(X[i] - X[p]) <= R[i] + R[p] + range)
                {
                    pairs_.append(labelPair(min(i, p), max(i, p)));
                }
            }
        }
    }

    // Large particles: every cell within R + Rmax + range; a pair of two
    // large ones is taken from the lower index
    if (Rmax <= Rlarge)
    {
        return;
    }
    forAll(X, i)
    {
        if (R[i] <= Rlarge) continue;

        const scalar reach = R[i] + Rmax + range;
        label lo[3], hi[3];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (cellWidth[d] > 0)
            {
                // Clamped to the grid as scalars: where the centres hardly
                // spread in a direction (a cell width of round-off size)
                // the reach is many cell widths, beyond a label
                const scalar last = nCells_[d] - 1;
                lo[d] = label
                (
                    max
                    (
                        scalar(0),
                        std::floor
                        (
                            (X[i][d] - reach - bb.min()[d])/cellWidth[d]
                        )
                    )
                );
                hi[d] = label
                (
                    min
                    (
                        last,
                        std::floor
                        (
                            (X[i][d] + reach - bb.min()[d])/cellWidth[d]
                        )
                    )
                );
            }
            else
            {
                lo[d] = 0;
                hi[d] = 0;
            }
        }

        for (label kk = lo[2]; kk <= hi[2]; ++kk)
        for (label jj = lo[1]; jj <= hi[1]; ++jj)
        for (label ll = lo[0]; ll <= hi[0]; ++ll)
        {
            const label cj = ll + nx*jj + nxy*kk;
            for (label s = cellStart_[cj]; s < cellStart_[cj + 1]; ++s)
            {
                const label p = cellParticles_[s];
                if (p == i || (R[p] > Rlarge && p < i)) continue;

                if (mag(X[i] - X[p]) <= R[i] + R[p] + range)
                {
                    pairs_.append(labelPair(min(i, p), max(i, p)));
                }
            }
        }
    }
}


Foam::List<Foam::labelPair> Foam::fbm::contactSearch::allPairs
(
    const UList<point>& X,
    const UList<scalar>& R,
    const scalar range
)
{
    DynamicList<labelPair> pairs;
    forAll(X, i)
    {
        for (label j = i + 1; j < X.size(); ++j)
        {
            if (mag(X[i] - X[j]) <= R[i] + R[j] + range)
            {
                pairs.append(labelPair(i, j));
            }
        }
    }
    return List<labelPair>(std::move(pairs));
}


// ************************************************************************* //
