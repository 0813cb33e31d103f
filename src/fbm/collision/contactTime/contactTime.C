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

#include "contactTime.H"
#include "DynamicList.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::contactTime::contactTime
(
    const contactModel& law,
    const scalar depth,
    const UList<scalar>& radii,
    const UList<scalar>& masses,
    const UList<bool>& translates
)
:
    anyMoving_(false),
    nClasses_(0),
    kPmax_(0),
    kWmax_(0),
    mMin_(GREAT),
    omega2_(0)
{
    const label maxClasses = 64;
    DynamicList<scalar> classR;
    DynamicList<scalar> classM;
    bool tooMany = false;
    scalar Rmax = 0;
    forAll(radii, i)
    {
        const scalar R = radii[i];
        const scalar m = masses[i];
        Rmax = max(Rmax, R);
        if (translates[i] || (m < GREAT))
        {
            anyMoving_ = true;
            mMin_ = min(mMin_, m);
        }
        if (tooMany) continue;

        bool found = false;
        forAll(classR, c)
        {
            if (classR[c] == R && classM[c] == m)
            {
                found = true;
                break;
            }
        }
        if (!found)
        {
            classR.append(R);
            classM.append(m);
            tooMany = (classR.size() > maxClasses);
        }
    }
    nClasses_ = tooMany ? 0 : classR.size();

    if (!anyMoving_)
    {
        return;
    }
    if (tooMany)
    {
        kPmax_ = depth*law.pairStiffness(Rmax, Rmax);
        kWmax_ = depth*law.wallStiffness(Rmax);
        omega2_ = max(kPmax_/(0.5*mMin_), kWmax_/mMin_);
        return;
    }
    forAll(classR, a)
    {
        const scalar ma = classM[a];
        if (ma < GREAT)
        {
            const scalar kW = depth*law.wallStiffness(classR[a]);
            kWmax_ = max(kWmax_, kW);
            omega2_ = max(omega2_, kW/ma);
        }
        for (label b = a; b < classR.size(); ++b)
        {
            const scalar mb = classM[b];
            if (ma == GREAT && mb == GREAT) continue;

            const scalar mRed =
                (ma == mb) ? 0.5*ma
              : (ma == GREAT) ? mb
              : (mb == GREAT) ? ma
              : ma*mb/(ma + mb);
            const scalar kP = depth*law.pairStiffness(classR[a], classR[b]);
            kPmax_ = max(kPmax_, kP);
            omega2_ = max(omega2_, kP/mRed);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fbm::contactTime::tc() const
{
    return constant::mathematical::pi/Foam::sqrt(omega2_);
}


// ************************************************************************* //
