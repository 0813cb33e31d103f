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

#include "bodyState.H"
#include "dictionary.H"
#include "Ostream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::fbm::bodyState::maxEntry = 1e100;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyState::bodyState
(
    const point& centre,
    const vector& U,
    const vector& omega
)
:
    centre_(centre),
    U_(U),
    omega_(omega),
    Q_(tensor::I),
    theta_(Zero),
    a_(Zero),
    omegaDot_(Zero),
    a0_(Zero),
    omegaDot0_(Zero),
    a00_(Zero),
    omegaDot00_(Zero),
    force_(Zero),
    torque_(Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::bodyState::beginStep()
{
    a00_ = a0_;
    omegaDot00_ = omegaDot0_;
    a0_ = a_;
    omegaDot0_ = omegaDot_;
}


void Foam::fbm::bodyState::rotate(const vector& phi)
{
    theta_ += phi;
    const scalar angle = mag(phi);
    if (angle > VSMALL)
    {
        const vector k(phi/angle);
        const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
        const tensor R(tensor::I + Foam::sin(angle)*K
          + (1 - Foam::cos(angle))*(K & K));
        Q_ = R & Q_;
    }
}


void Foam::fbm::bodyState::setOrientation
(
    const tensor& Q,
    const vector& dTheta
)
{
    Q_ = 0.5*(Q & (3*tensor::I - (Q.T() & Q)));
    theta_ += dTheta;
}


template<class Type>
Type Foam::fbm::bodyState::readEntry
(
    const dictionary& dict,
    const word& key
)
{
    const Type value(dict.get<Type>(key));
    for (direction d = 0; d < pTraits<Type>::nComponents; ++d)
    {
        const scalar x = component(value, d);
        if (!std::isfinite(x) || mag(x) > maxEntry)
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' " << value << " of the restart"
                << " state " << dict.name() << ": component " << x
                << " is out of range (a state entry lies within +-"
                << maxEntry << ")" << exit(FatalIOError);
        }
    }
    return value;
}


bool Foam::fbm::bodyState::read(const dictionary& dict)
{
    centre_ = readEntry<point>(dict, "centre");
    U_ = readEntry<vector>(dict, "U");
    omega_ = readEntry<vector>(dict, "omega");
    Q_ = readEntry<tensor>(dict, "Q");
    theta_ = readEntry<vector>(dict, "theta");
    a_ = readEntry<vector>(dict, "acceleration");
    omegaDot_ = readEntry<vector>(dict, "angularAcceleration");
    const bool previous =
        dict.found("acceleration0") || dict.found("angularAcceleration0");
    a0_ = previous ? readEntry<vector>(dict, "acceleration0") : a_;
    omegaDot0_ =
        previous
      ? readEntry<vector>(dict, "angularAcceleration0")
      : omegaDot_;
    a00_ = a0_;
    omegaDot00_ = omegaDot0_;
    force_ = readEntry<vector>(dict, "force");
    torque_ = readEntry<vector>(dict, "torque");

    // The orientation is a rotation
    if (mag((Q_ & Q_.T()) - tensor::I) > 1e-6 || det(Q_) < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'Q' " << Q_ << " of the restart state " << dict.name()
            << " is not a rotation (Q Q^T = I, det Q = 1)"
            << exit(FatalIOError);
    }

    return previous;
}


void Foam::fbm::bodyState::write(Ostream& os) const
{
    os.writeEntry("centre", centre_);
    os.writeEntry("U", U_);
    os.writeEntry("omega", omega_);
    os.writeEntry("Q", Q_);
    os.writeEntry("theta", theta_);
    os.writeEntry("acceleration", a_);
    os.writeEntry("angularAcceleration", omegaDot_);
    os.writeEntry("acceleration0", a0_);
    os.writeEntry("angularAcceleration0", omegaDot0_);
    os.writeEntry("force", force_);
    os.writeEntry("torque", torque_);
}


// ************************************************************************* //
