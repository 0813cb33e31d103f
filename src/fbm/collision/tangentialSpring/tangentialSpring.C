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

#include "tangentialSpring.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fbm
{
namespace frictionModels
{
    defineTypeNameAndDebug(tangentialSpring, 0);
    addToRunTimeSelectionTable(frictionModel, tangentialSpring, dictionary);
}
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Whether the body's block d of the restart state holds both entries a and
// b (true) or neither (false); one without the other is an error
bool givenTogether
(
    const Foam::dictionary& d,
    const Foam::word& a,
    const Foam::word& b,
    const Foam::dictionary& state
)
{
    const bool hasA = d.found(a);
    if (hasA != d.found(b))
    {
        FatalIOErrorInFunction(d)
            << "Body " << d.dictName() << " of the restart state "
            << state.name() << " has " << (hasA ? a : b) << " without "
            << (hasA ? b : a) << Foam::exit(Foam::FatalIOError);
    }
    return hasA;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::frictionModels::tangentialSpring::tangentialSpring
(
    const dictionary& dict,
    const vector& planeMask,
    const scalar depth
)
:
    frictionModel(dict, planeMask, depth),
    stiffnessRatio_
    (
        dict.subDict(typeName + "Coeffs").getCheck<scalar>
        (
            "stiffnessRatio", [](scalar r){ return r > 0 && r <= 1; }
        )
    ),
    dampingRatio_
    (
        dict.subDict(typeName + "Coeffs").getCheck<scalar>
        (
            "dampingRatio", [](scalar z){ return z >= 0 && z <= 1; }
        )
    ),
    staticCoeff_
    (
        dict.subDict(typeName + "Coeffs").getOrDefault<scalar>
        (
            "staticFrictionCoeff", mu_
        )
    ),
    springs_(),
    next_(),
    sliding_(),
    nextSliding_(),
    dt_(0),
    nEvaluations_(0),
    byBody_(),
    byBodyEvaluation_(-1)
{
    if (staticCoeff_ < mu_)
    {
        const dictionary& coeffs = dict.subDict(typeName + "Coeffs");
        FatalIOErrorInFunction(coeffs)
            << "staticFrictionCoeff " << staticCoeff_ << " in "
            << coeffs.name() << " is below frictionCoeff " << mu_
            << ": a contact holds at least as much as it carries sliding"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::frictionModels::tangentialSpring::beginForces
(
    const scalar dt
)
{
    dt_ = dt;
    next_.clear();
    nextSliding_.clear();
}


void Foam::fbm::frictionModels::tangentialSpring::endForces()
{
    // Swapped, not transferred: next_ keeps its table for the next
    // evaluation
    springs_.swap(next_);
    sliding_.swap(nextSliding_);
    ++nEvaluations_;
}


Foam::vector Foam::fbm::frictionModels::tangentialSpring::force
(
    const labelPair& contact,
    const vector& v,
    const vector& n,
    const scalar Fn,
    const scalar kn,
    const scalar wt
)
{
    if (Fn <= 0 || kn <= 0)
    {
        return Zero;
    }

    // The spring of the last evaluation turned into the present tangent
    // plane (keeping its length), stretched by the sliding since
    const vector vt(tangential(v, n));
    vector xi(Zero);
    const auto last = springs_.cfind(contact);
    if (last.found())
    {
        const vector& xi0 = *last;
        xi = tangential(xi0, n);
        const scalar magXi = mag(xi);
        if (magXi > VSMALL)
        {
            xi *= mag(xi0)/magXi;
        }
    }
    xi += dt_*vt;

    // The dashpot along the sliding velocity (as the normal one: the
    // absolute stiffness is depth k)
    const scalar kt = stiffnessRatio_*kn;
    scalar c = 0;
    if (dampingRatio_ > 0 && wt > 0)
    {
        c = 2*dampingRatio_*Foam::sqrt(kt*depth_/wt)/depth_;
    }

    vector Ft(-kt*xi - c*vt);

    // Beyond Coulomb's bound the contact slides: the force at the
    // (kinetic) bound, the spring what gives it. A sticking contact holds
    // up to the static bound, a sliding one only to the kinetic one
    const bool slid = hasStatic() && sliding_.found(contact);
    const scalar holds = (slid ? mu_ : staticCoeff_)*Fn;
    const scalar magFt = mag(Ft);
    if (magFt > holds)
    {
        Ft *= mu_*Fn/magFt;
        xi = -(Ft + c*vt)/kt;
        if (hasStatic())
        {
            nextSliding_.set(contact);
        }
    }

    next_.set(contact, xi);
    return Ft;
}


void Foam::fbm::frictionModels::tangentialSpring::writeInfo() const
{
    Info<< "fbm: collisions: Coulomb friction, frictionCoeff " << mu_
        << " (tangentialSpring: stiffnessRatio " << stiffnessRatio_
        << ", dampingRatio " << dampingRatio_ << ", staticFrictionCoeff "
        << staticCoeff_;
    if (!hasStatic())
    {
        Info<< " (= frictionCoeff: no static friction)";
    }
    Info<< "; the springs are part of the restart state)" << nl;
}


void Foam::fbm::frictionModels::tangentialSpring::writeState
(
    const label bi,
    const wordList& bodyNames,
    const wordList& wallNames,
    Ostream& os
) const
{
    // The springs by first body, once per evaluation
    if (byBodyEvaluation_ != nEvaluations_ || byBody_.size() != bodyNames.size())
    {
        byBody_.setSize(bodyNames.size());
        for (auto& l : byBody_)
        {
            l.clear();
        }
        forAllConstIters(springs_, iter)
        {
            const labelPair& c = iter.key();
            byBody_[c.first()].append(Tuple2<label, vector>(c.second(), *iter));
        }
        for (auto& l : byBody_)
        {
            Foam::sort
            (
                l,
                [](const Tuple2<label, vector>& a, const Tuple2<label, vector>& b)
                {
                    return a.first() < b.first();
                }
            );
        }
        byBodyEvaluation_ = nEvaluations_;
    }

    List<Tuple2<word, vector>> pairs;
    List<Tuple2<word, vector>> walls;
    DynamicList<Tuple2<word, vector>> p;
    DynamicList<Tuple2<word, vector>> w;
    for (const Tuple2<label, vector>& s : byBody_[bi])
    {
        if (s.first() >= 0)
        {
            p.append(Tuple2<word, vector>(bodyNames[s.first()], s.second()));
        }
        else
        {
            w.append
            (
                Tuple2<word, vector>(wallNames[-1 - s.first()], s.second())
            );
        }
    }
    pairs.transfer(p);
    walls.transfer(w);
    os.writeEntry("frictionPairs", pairs);
    os.writeEntry("frictionWalls", walls);

    // The sliding contacts among them, by the partner's name
    if (hasStatic())
    {
        DynamicList<word> sp;
        DynamicList<word> sw;
        for (const Tuple2<label, vector>& s : byBody_[bi])
        {
            if (sliding_.found(labelPair(bi, s.first())))
            {
                if (s.first() >= 0)
                {
                    sp.append(bodyNames[s.first()]);
                }
                else
                {
                    sw.append(wallNames[-1 - s.first()]);
                }
            }
        }
        os.writeEntry("frictionPairsSliding", wordList(sp));
        os.writeEntry("frictionWallsSliding", wordList(sw));
    }
}


void Foam::fbm::frictionModels::tangentialSpring::readState
(
    const dictionary& state,
    const wordList& bodyNames,
    const wordList& wallNames
)
{
    HashTable<label> bodyIndex(2*bodyNames.size());
    forAll(bodyNames, i)
    {
        bodyIndex.insert(bodyNames[i], i);
    }
    HashTable<label> wallIndex(2*wallNames.size() + 1);
    forAll(wallNames, i)
    {
        wallIndex.insert(wallNames[i], i);
    }

    // The contact of body bi with the body or wall of that name, as the
    // tables key it (pairs (i, j) with i < j, walls (i, -1 - w)); (-1, -1)
    // for a name the case does not have, or the body itself
    auto contactOf = [&](const label bi, const word& name, const bool isPair)
    {
        const auto found = (isPair ? bodyIndex : wallIndex).cfind(name);
        if (!found.found() || (isPair && *found == bi))
        {
            return labelPair(-1, -1);
        }
        return isPair
          ? labelPair(min(bi, *found), max(bi, *found))
          : labelPair(bi, -1 - *found);
    };

    springs_.clear();
    sliding_.clear();
    label nWith = 0;
    label nWithSliding = 0;
    forAll(bodyNames, bi)
    {
        const dictionary& d = state.subDict(bodyNames[bi]);
        if (!givenTogether(d, "frictionPairs", "frictionWalls", state))
        {
            continue;
        }
        ++nWith;

        for (const word& key : {word("frictionPairs"), word("frictionWalls")})
        {
            const bool isPair = (key == "frictionPairs");
            for (const auto& s : d.get<List<Tuple2<word, vector>>>(key))
            {
                const labelPair c(contactOf(bi, s.first(), isPair));
                if (c.first() < 0)
                {
                    FatalIOErrorInFunction(d)
                        << "Keyword " << key << " of body " << bodyNames[bi]
                        << " in the restart state " << state.name()
                        << " names " << s.first() << ", which is "
                        << (s.first() == bodyNames[bi] ? "the body itself"
                          : isPair ? "not a body of the case"
                          : "not a wall of the case")
                        << exit(FatalIOError);
                }
                // The displacement is that of the first body's point
                // relative to the second's
                springs_.set(c, c.first() == bi ? s.second() : -s.second());
            }
        }

        // Which of them slide (written with a static coefficient only)
        if
        (
            !givenTogether
            (
                d, "frictionPairsSliding", "frictionWallsSliding", state
            )
        )
        {
            continue;
        }
        ++nWithSliding;
        for
        (
            const word& key
          : {word("frictionPairsSliding"), word("frictionWallsSliding")}
        )
        {
            const bool isPair = (key == "frictionPairsSliding");
            for (const word& name : d.get<wordList>(key))
            {
                const labelPair c(contactOf(bi, name, isPair));
                if (!springs_.found(c))
                {
                    FatalIOErrorInFunction(d)
                        << "Keyword " << key << " of body " << bodyNames[bi]
                        << " in the restart state " << state.name()
                        << " names " << name << ", which is not a partner"
                        << " of the body's friction springs ("
                        << (isPair ? "frictionPairs" : "frictionWalls")
                        << ")" << exit(FatalIOError);
                }
                if (hasStatic())
                {
                    sliding_.set(c);
                }
            }
        }
    }

    if (nWithSliding != 0 && nWithSliding != nWith)
    {
        FatalIOErrorInFunction(state)
            << "frictionPairsSliding and frictionWallsSliding given for "
            << nWithSliding << " of the " << nWith << " bodies with friction"
            << " springs in the restart state " << state.name() << ": give"
            << " them for every body or for none" << exit(FatalIOError);
    }
    if (nWith > 0 && hasStatic() && nWithSliding == 0)
    {
        Info<< "fbm: collisions: the restart state has no sliding contacts"
            << " listed (written without staticFrictionCoeff): every"
            << " contact starts sticking" << nl;
    }
    else if (nWithSliding > 0 && !hasStatic())
    {
        Info<< "fbm: collisions: the sliding contacts of the restart state"
            << " are not used (no staticFrictionCoeff above frictionCoeff)"
            << nl;
    }

    if (nWith == 0)
    {
        Info<< "fbm: collisions: the restart state has no friction springs"
            << " (written without tangentialSpring): they start unloaded"
            << nl;
    }
    else if (nWith != bodyNames.size())
    {
        FatalIOErrorInFunction(state)
            << "frictionPairs and frictionWalls given for " << nWith
            << " of the " << bodyNames.size() << " bodies in the restart"
            << " state " << state.name() << ": give them for every body or"
            << " for none" << exit(FatalIOError);
    }
    else
    {
        Info<< "fbm: collisions: " << springs_.size() << " friction springs"
            << " read from the restart state";
        if (hasStatic())
        {
            Info<< ", " << sliding_.size() << " of them sliding";
        }
        Info<< nl;
    }
    ++nEvaluations_;
}


// ************************************************************************* //
