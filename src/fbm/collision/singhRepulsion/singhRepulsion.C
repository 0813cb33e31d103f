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

#include "singhRepulsion.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace contactModels
{
    defineTypeNameAndDebug(singhRepulsion, 0);
    addToRunTimeSelectionTable(contactModel, singhRepulsion, dictionary);
}
}
}

const Foam::Enum<Foam::fbm::contactModels::singhRepulsion::overlapForm>
Foam::fbm::contactModels::singhRepulsion::overlapFormNames
({
    { overlapForm::linear, "linear" },
    { overlapForm::rangePlusLinear, "rangePlusLinear" },
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fbm::contactModels::singhRepulsion::readCoeff
(
    const word& key,
    const label power,
    const wordList& inH,
    const bool allowZero
) const
{
    const scalar value =
        allowZero
      ? coeffDict_.getCheck<scalar>(key, [](scalar x){ return x >= 0; })
      : coeffDict_.getCheck<scalar>(key, [](scalar x){ return x > 0; });

    return inH.found(key) ? value*pow(h_, power) : value;
}


Foam::scalar Foam::fbm::contactModels::singhRepulsion::factor
(
    const scalar D,
    const scalar s,
    const scalar eps,
    const scalar epsOverlap
) const
{
    if (D > s + range_)
    {
        return 0;
    }
    else if (D >= s)
    {
        return sqr(s + range_ - D)/eps;
    }
    else if (overlap_ == overlapForm::linear)
    {
        return (s - D)/epsOverlap;
    }

    return sqr(s + range_ - D)/eps + (s - D)/epsOverlap;
}


Foam::scalar Foam::fbm::contactModels::singhRepulsion::stiffness
(
    const scalar s,
    const scalar eps,
    const scalar epsOverlap
) const
{
    // Over D in [s/2, s + rho] (overlaps up to half the contact distance),
    // radial |dF/dD| and transverse |F|/D, u = s + rho - D

    // Range term: radial u (2 (s + rho) - 3u)/eps, transverse u^2/eps
    const scalar uMax =
        (overlap_ == overlapForm::linear) ? range_ : range_ + 0.5*s;
    const scalar u = min(uMax, (s + range_)/3);
    const scalar kRange =
        max(u*(2*(s + range_) - 3*u), sqr(uMax))/eps;

    // Linear term: radial |s - 2D|/eps' <= s/eps', transverse
    // (s - D)/eps' <= s/(2 eps')
    const scalar kOverlap = s/epsOverlap;

    if (overlap_ == overlapForm::linear)
    {
        return max(kRange, kOverlap);
    }

    return kRange + kOverlap;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::contactModels::singhRepulsion::singhRepulsion
(
    const dictionary& dict,
    const word& modelType,
    const scalar h
)
:
    contactModel(dict, modelType, h),
    overlap_(overlapFormNames.get("overlapForce", coeffDict_)),
    range_(0),
    epsP_(0),
    epsPOverlap_(0),
    epsW_(0),
    epsWOverlap_(0)
{
    const wordList inH
    (
        coeffDict_.getOrDefault<wordList>("unitsOfH", wordList())
    );

    const wordList known
    ({"range", "epsP", "epsPOverlap", "epsW", "epsWOverlap"});

    for (const word& key : inH)
    {
        if (!known.found(key))
        {
            FatalIOErrorInFunction(coeffDict_)
                << "Unknown coefficient '" << key << "' in unitsOfH "
                << inH << nl << "    Valid: " << known
                << exit(FatalIOError);
        }
    }

    range_ = readCoeff("range", 1, inH, true);
    epsP_ = readCoeff("epsP", 2, inH, false);
    epsPOverlap_ = readCoeff("epsPOverlap", 1, inH, false);
    epsW_ = readCoeff("epsW", 2, inH, false);
    epsWOverlap_ = readCoeff("epsWOverlap", 1, inH, false);

    Info<< "    singhRepulsion: overlapForce " << overlapFormNames[overlap_]
        << ", h " << h_ << " (unitsOfH " << inH << ")" << nl
        << "        range " << range_ << ", epsP " << epsP_
        << ", epsPOverlap " << epsPOverlap_ << ", epsW " << epsW_
        << ", epsWOverlap " << epsWOverlap_ << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fbm::contactModels::singhRepulsion::pairForce
(
    const point& Xi,
    const scalar Ri,
    const point& Xj,
    const scalar Rj
) const
{
    const vector d(Xi - Xj);
    return factor(mag(d), Ri + Rj, epsP_, epsPOverlap_)*d;
}


Foam::vector Foam::fbm::contactModels::singhRepulsion::wallForce
(
    const point& Xi,
    const scalar Ri,
    const point& Xw
) const
{
    const vector d(Xi - Xw);
    return factor(mag(d), 2*Ri, epsW_, epsWOverlap_)*d;
}


Foam::scalar Foam::fbm::contactModels::singhRepulsion::pairForceAtGap
(
    const scalar gap,
    const scalar Ri,
    const scalar Rj
) const
{
    const scalar s = Ri + Rj;
    const scalar D = max(s + gap, scalar(0));
    return factor(D, s, epsP_, epsPOverlap_)*D;
}


Foam::scalar Foam::fbm::contactModels::singhRepulsion::wallForceAtGap
(
    const scalar gap,
    const scalar Ri
) const
{
    const scalar s = 2*Ri;
    const scalar D = max(2*(Ri + gap), scalar(0));
    return factor(D, s, epsW_, epsWOverlap_)*D;
}


Foam::scalar Foam::fbm::contactModels::singhRepulsion::pairStiffness
(
    const scalar Ri,
    const scalar Rj
) const
{
    return stiffness(Ri + Rj, epsP_, epsPOverlap_);
}


Foam::scalar Foam::fbm::contactModels::singhRepulsion::wallStiffness(const scalar Ri) const
{
    // D' = 2 x wall distance: a displacement x changes D' by 2x
    return 2*stiffness(2*Ri, epsW_, epsWOverlap_);
}


// ************************************************************************* //
