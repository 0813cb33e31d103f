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

#include "oscillating.H"
#include "polyMesh.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace prescribedMotions
{
    defineTypeNameAndDebug(oscillating, 0);
    addToRunTimeSelectionTable(prescribedMotion, oscillating, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::prescribedMotions::oscillating::oscillating
(
    const dictionary& dict,
    const point& centre0,
    const polyMesh& mesh
)
:
    prescribedMotion(centre0),
    amplitude_(dict.get<vector>("amplitude")),
    omega_
    (
        constant::mathematical::twoPi
       *dict.getCheck<scalar>
        (
            "frequency",
            [](scalar f){ return f > 0 && f < GREAT; }
        )
    ),
    phase_(dict.getOrDefault<scalar>("phase", 0))
{
    if (!std::isfinite(mag(amplitude_)) || mag(amplitude_) > GREAT)
    {
        FatalIOErrorInFunction(dict)
            << "amplitude " << amplitude_ << " is not a finite length"
            << exit(FatalIOError);
    }
    if (!std::isfinite(phase_))
    {
        FatalIOErrorInFunction(dict)
            << "phase " << phase_ << " is not finite" << exit(FatalIOError);
    }

    // A 2D mesh: the motion stays in the plane
    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0 && amplitude_[d] != 0)
        {
            FatalIOErrorInFunction(dict)
                << "amplitude " << amplitude_ << " has a component in the"
                << " empty direction of this 2D mesh" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fbm::prescribedMotions::oscillating::displacement
(
    const scalar t
) const
{
    return amplitude_*(Foam::sin(omega_*t + phase_) - Foam::sin(phase_));
}


Foam::vector Foam::fbm::prescribedMotions::oscillating::velocity
(
    const scalar t
) const
{
    return (omega_*Foam::cos(omega_*t + phase_))*amplitude_;
}


Foam::scalar Foam::fbm::prescribedMotions::oscillating::maxSpeed() const
{
    return omega_*mag(amplitude_);
}


// ************************************************************************* //
