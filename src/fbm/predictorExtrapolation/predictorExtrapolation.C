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

#include "predictorExtrapolation.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

template<class FieldType>
Foam::tmp<FieldType> Foam::fbm::predictorExtrapolation::extrapolated
(
    const FieldType& f,
    const bool firstIter
) const
{
    if (!extrapolate_ || !firstIter)
    {
        return tmp<FieldType>(f);
    }

    // Before the first outer iteration changes f, f.oldTime() is f^n; its
    // old time, kept from here on, is f^{n-1} (f^n itself in the first
    // step of a run that has no f_0 to read)
    const Time& runTime = f.time();
    const scalar w = runTime.deltaTValue()/runTime.deltaT0Value();
    const FieldType& f0 = f.oldTime();
    const FieldType& f00 = f0.oldTime();

    return tmp<FieldType>::New(f.name(), f0 + w*(f0 - f00));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::predictorExtrapolation::predictorExtrapolation
(
    const dictionary& pimpleDict,
    const volScalarField& p,
    const surfaceScalarField& phi
)
:
    extrapolate_(pimpleDict.getOrDefault<bool>("extrapolatePredictor", false)),
    extrapolatePressure_(extrapolate_)
{
    if (!extrapolate_)
    {
        if (pimpleDict.found("extrapolatePressure"))
        {
            FatalIOErrorInFunction(pimpleDict)
                << "extrapolatePressure without extrapolatePredictor yes in "
                << pimpleDict.name() << nl
                << "    It chooses whether the extrapolated predictor"
                << " extrapolates the pressure too: remove it or set"
                << " extrapolatePredictor yes"
                << exit(FatalIOError);
        }
        return;
    }

    extrapolatePressure_ =
        pimpleDict.getOrDefault<bool>("extrapolatePressure", false);
    if (extrapolatePressure_)
    {
        Info<< "fbm: extrapolatePredictor: flux and pressure of the first"
            << " momentum predictor extrapolated in time" << nl;
    }
    else
    {
        Info<< "fbm: extrapolatePredictor: flux of the first momentum"
            << " predictor extrapolated in time, its pressure lagged"
            << " (extrapolatePressure no"
            << (pimpleDict.found("extrapolatePressure") ? "" : ", the default")
            << ")" << nl;
    }

    const Time& runTime = p.time();
    if (runTime.value() > 0 && (!p.nOldTimes() || !phi.nOldTimes()))
    {
        Info<< "fbm: extrapolatePredictor: no " << p.name() << "_0 or "
            << phi.name() << "_0 in time " << runTime.timeName()
            << ": the first step takes the lagged flux and pressure" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField>
Foam::fbm::predictorExtrapolation::flux
(
    const surfaceScalarField& phi,
    const bool firstIter
) const
{
    return extrapolated(phi, firstIter);
}


Foam::tmp<Foam::volScalarField>
Foam::fbm::predictorExtrapolation::pressure
(
    const volScalarField& p,
    const bool firstIter
) const
{
    return extrapolated(p, firstIter && extrapolatePressure_);
}


// ************************************************************************* //
