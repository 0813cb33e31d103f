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

#include "fluidRate.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::fluidRate::fluidRate(const fvMesh& mesh, const bool bodiesMove)
:
    time_(mesh.time()),
    scheme_(scheme::Euler),
    index_(time_.timeIndex()),
    deltaT0Last_(time_.deltaT0Value()),
    deltaT00_(-1)
{
    ITstream& is = mesh.ddtScheme("ddt(U)");
    const word name(is);
    if (name == "backward")
    {
        scheme_ = scheme::backward;
    }
    else if (name != "Euler" && bodiesMove)
    {
        const dictionary& schemes = mesh.schemesDict();
        FatalIOErrorInFunction(schemes.subDict("ddtSchemes"))
            << "ddt scheme '" << name << "' for ddt(U) in "
            << schemes.name() << ": with moving bodies fbmFoam takes"
            << " Euler or backward (the bodies' added-mass and enclosed-"
            << "fluid terms follow the fluid's time scheme)"
            << exit(FatalIOError);
    }
}


Foam::fbm::fluidRate::fluidRate(const Time& time, const scheme s)
:
    time_(time),
    scheme_(s),
    index_(time_.timeIndex()),
    deltaT0Last_(time_.deltaT0Value()),
    deltaT00_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::fluidRate::beginStep()
{
    // deltaT0 at the last step's index is the step before the last one;
    // in the first step of a run, deltaT0 of the start time (Time reads
    // it from uniform/time at a restart), kept by the constructor
    const label k = time_.timeIndex();
    deltaT00_ = (k == index_ + 1) ? deltaT0Last_ : -1;
    deltaT0Last_ = time_.deltaT0Value();
    index_ = k;
}


Foam::scalar Foam::fbm::fluidRate::weight0() const
{
    // The last step (index k - 1) stepped with Euler below index 2
    if (scheme_ == scheme::Euler || time_.timeIndex() < 3)
    {
        return 0;
    }
    if (index_ != time_.timeIndex() || deltaT00_ <= 0)
    {
        return weight();
    }
    const scalar dt0 = time_.deltaT0Value();
    return dt0/(dt0 + deltaT00_);
}


Foam::scalar Foam::fbm::fluidRate::weight() const
{
    // backwardDdtScheme: Euler while timeIndex < 2
    if (scheme_ == scheme::Euler || time_.timeIndex() < 2)
    {
        return 0;
    }
    const scalar dt = time_.deltaTValue();
    const scalar dt0 = time_.deltaT0Value();
    return dt/(dt + dt0);
}


// ************************************************************************* //
