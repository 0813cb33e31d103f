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
    force_(Zero),
    torque_(Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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


void Foam::fbm::bodyState::read(const dictionary& dict)
{
    centre_ = dict.get<point>("centre");
    U_ = dict.get<vector>("U");
    omega_ = dict.get<vector>("omega");
    Q_ = dict.get<tensor>("Q");
    theta_ = dict.get<vector>("theta");
    a_ = dict.get<vector>("acceleration");
    omegaDot_ = dict.get<vector>("angularAcceleration");
    force_ = dict.get<vector>("force");
    torque_ = dict.get<vector>("torque");
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
    os.writeEntry("force", force_);
    os.writeEntry("torque", torque_);
}


// ************************************************************************* //
