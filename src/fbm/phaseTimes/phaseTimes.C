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

#include "phaseTimes.H"
#include "Ostream.H"
#include "Pstream.H"
#include "scalarList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const char* const Foam::fbm::phaseTimes::profilingNames[nPhases] =
    {"fbm::motion", "fbm::cells", "fbm::forcing", "fbm::forces", "fbm::output"};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::phaseTimes::phaseTimes()
:
    seconds_(Zero),
    nSteps_(0),
    start_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::phaseTimes::newStep()
{
    if (nSteps_ == 0)
    {
        start_ = std::chrono::steady_clock::now();
    }
    ++nSteps_;
}


void Foam::fbm::phaseTimes::add
(
    const phase p,
    const std::chrono::steady_clock::time_point& start
)
{
    if (nSteps_ > 0)
    {
        seconds_[p] +=
            std::chrono::duration<scalar>
            (
                std::chrono::steady_clock::now() - start
            ).count();
    }
}


void Foam::fbm::phaseTimes::report(Ostream& os) const
{
    if (nSteps_ == 0)
    {
        return;
    }

    static const char* names[nPhases] =
        {"motion/DEM", "cells", "forcing", "forces", "output"};

    const scalar total =
        std::chrono::duration<scalar>
        (
            std::chrono::steady_clock::now() - start_
        ).count();

    scalar bodies = 0;
    for (const scalar s : seconds_)
    {
        bodies += s;
    }

    // The largest over the processors: the master's and the slowest's
    // phases
    scalarList most(nPhases + 1);
    forAll(seconds_, i)
    {
        most[i] = seconds_[i];
    }
    most[nPhases] = bodies;
    Pstream::listCombineGather(most, maxEqOp<scalar>());

    const unsigned oldPrecision = os.precision(3);
    const scalar n(nSteps_);
    auto share = [&](const scalar s)
    {
        os  << s/n << " s (" << label(100*s/max(total, VSMALL) + 0.5)
            << " %)";
    };

    os  << "fbm: wall time per step over " << nSteps_ << " steps: "
        << total/n << " s; fluid ";
    share(total - bodies);
    os  << ", bodies ";
    share(bodies);
    os  << ":";
    forAll(seconds_, i)
    {
        os  << ' ' << names[i] << ' ';
        share(seconds_[i]);
    }
    if (Pstream::parRun())
    {
        os  << "; largest over processors: bodies " << most[nPhases]/n
            << " s";
        forAll(seconds_, i)
        {
            os  << ", " << names[i] << ' ' << most[i]/n;
        }
    }
    os  << endl;
    os.precision(oldPrecision);
}


// ************************************************************************* //
