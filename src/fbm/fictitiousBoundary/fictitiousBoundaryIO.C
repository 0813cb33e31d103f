/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fbmFoam: fictitious boundary method for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fbmFoam, distributed under GPL-3.0-or-later.

Description
    Reading the bodies (bodies and particleLists), the selection of the
    bodies with per-body output, the covered-volume check and the summary
    line of fbm::fictitiousBoundary.

\*---------------------------------------------------------------------------*/

#include "fictitiousBoundary.H"
#include "Time.H"
#include "HashSet.H"
#include "ITstream.H"

// * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * * //

void Foam::fbm::fictitiousBoundary::readParticleList
(
    const dictionary& listDict,
    DynamicList<dictionary*>& dicts,
    DynamicList<word>& names
)
{
    const word listName(listDict.dictName());

    // The shared entries: everything but the particles
    dictionary base(listDict);
    base.remove("particles");
    const bool hasRho = base.found("rho");
    const scalar rhoShared = hasRho ? base.get<scalar>("rho") : -1;

    // particles ( (x y z) radius [rho]  ... ); an optional count in front
    ITstream& is = listDict.lookup("particles");
    token tok(is);
    if (tok.isLabel())
    {
        is >> tok;
    }
    if (!tok.isPunctuation() || tok.pToken() != token::BEGIN_LIST)
    {
        FatalIOErrorInFunction(listDict)
            << "Keyword particles of " << listName << ": expected a list"
            << " ( (x y z) radius [rho] ... ), found " << tok.info()
            << exit(FatalIOError);
    }

    label n = 0;
    while (true)
    {
        is >> tok;
        if (!tok.good() || is.bad())
        {
            FatalIOErrorInFunction(listDict)
                << "Keyword particles of " << listName << ": the list ends"
                << " before its closing ')' (after " << n << " particles)"
                << exit(FatalIOError);
        }
        if (tok.isPunctuation() && tok.pToken() == token::END_LIST)
        {
            break;
        }
        is.putBack(tok);

        point X;
        scalar r = -1;
        is >> X;
        is >> tok;
        if (tok.isNumber())
        {
            r = tok.number();
        }
        is >> tok;
        scalar rho = rhoShared;
        if (tok.isNumber())
        {
            rho = tok.number();
        }
        else
        {
            is.putBack(tok);
        }
        is.check(FUNCTION_NAME);

        if (!(r > 0) || !(rho > 0))
        {
            FatalIOErrorInFunction(listDict)
                << "Keyword particles of " << listName << ", particle " << n
                << " (centre " << X << "): radius " << r << " and density "
                << rho << " must be positive"
                << (hasRho ? "" : " (the list has no shared rho)")
                << exit(FatalIOError);
        }

        dictionary* d = new dictionary(base);
        d->name() = listDict.name() + ".particles." + Foam::name(n);
        d->set("centre", X);
        d->set("radius", r);
        d->set("rho", rho);
        dicts.append(d);
        names.append(word(listName + Foam::name(n)));
        ++n;
    }

    Info<< "fbm: particle list " << listName << ": " << n << " bodies "
        << listName << "0 - " << listName << n - 1 << nl;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::fictitiousBoundary::readBodies()
{
    if (!found("bodies") && !found("particleLists"))
    {
        FatalIOErrorInFunction(*this)
            << "Neither bodies nor particleLists in " << objectPath()
            << exit(FatalIOError);
    }

    // Bodies of the lists: their dictionaries are kept in listDicts_
    DynamicList<dictionary*> dicts;
    DynamicList<word> listNames;
    if (found("particleLists"))
    {
        const dictionary& lists = subDict("particleLists");
        for (const entry& e : lists)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(lists)
                    << "Entry '" << e.keyword() << "' in particleLists is not"
                    << " a dictionary" << exit(FatalIOError);
            }
            readParticleList(e.dict(), dicts, listNames);
        }
    }

    label n = 0;
    const dictionary* bodiesDict = findDict("bodies");
    if (bodiesDict)
    {
        for (const entry& e : *bodiesDict)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(*bodiesDict)
                    << "Entry '" << e.keyword() << "' in bodies is not a"
                    << " dictionary" << exit(FatalIOError);
            }
            ++n;
        }
    }

    bodies_.setSize(n + dicts.size());
    listDicts_.setSize(dicts.size());
    wordHashSet names(2*bodies_.size());

    n = 0;
    if (bodiesDict)
    {
        for (const entry& e : *bodiesDict)
        {
            names.insert(e.keyword());
            bodies_.set
            (
                n++, new body(e.keyword(), e.dict(), mesh_, cellTree_.get())
            );
        }
    }

    forAll(dicts, i)
    {
        listDicts_.set(i, dicts[i]);
        if (!names.insert(listNames[i]))
        {
            FatalIOErrorInFunction(*dicts[i])
                << "Body name " << listNames[i] << " of particleLists is"
                << " already used in " << objectPath() << exit(FatalIOError);
        }
        bodies_.set
        (
            n++, new body(listNames[i], *dicts[i], mesh_, cellTree_.get())
        );
    }
}


void Foam::fbm::fictitiousBoundary::selectBodies()
{
    // Every body when there are at most this many, else none, unless
    // bodyFiles selects them
    const label maxAuto = 100;

    DynamicList<label> sel;
    if (found("bodyFiles"))
    {
        const wordRes patterns(get<wordRes>("bodyFiles"));
        forAll(bodies_, bi)
        {
            if (patterns.match(bodies_[bi].name()))
            {
                sel.append(bi);
            }
        }
    }
    else if (bodies_.size() <= maxAuto)
    {
        sel = identity(bodies_.size());
    }
    selected_.transfer(sel);

    if (selected_.size() < bodies_.size())
    {
        Info<< "fbm: per-body output (log line, <body>.dat) for "
            << selected_.size() << " of " << bodies_.size() << " bodies"
            << (found("bodyFiles") ? " (bodyFiles)" : "")
            << "; all bodies in summary.dat and the fbmBodies cloud" << nl;
    }
}


void Foam::fbm::fictitiousBoundary::checkCoveredVolumes() const
{
    // Each body must lie in the fluid domain: its covered volume must be
    // its own (a body cut by the boundary is an input error). The sub-cell
    // sampling of a cut cell (leaf size delta = h/2^nSubdivision) is
    // accurate to about (delta/R)^2 relative: the tolerance is that or
    // 1e-3, whichever is larger.
    const scalarList vol(coveredVolumes());

    // Largest cell size over the solution directions
    const Vector<label>& sd = mesh_.solutionD();
    scalar h = 0;
    for (const boundBox& bb : cellBb_)
    {
        const vector span(bb.span());
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (sd[d] > 0) h = max(h, span[d]);
        }
    }
    reduce(h, maxOp<scalar>());
    const scalar delta = h/pow(2.0, scalar(nSubdivision_));

    scalar worst = 0;
    forAll(bodies_, bi)
    {
        const body& b = bodies_[bi];
        const scalar Vb = b.shape().volume();
        const scalar tol = max(1e-3, sqr(delta/b.shape().radius()));
        const scalar err = mag(vol[bi] - Vb)/Vb;
        worst = max(worst, err);

        if (bi < 100 || selected_.found(bi))
        {
            Info<< "    " << b.name() << ": " << b.shape().type()
                << " centre " << b.centre() << " volume " << Vb
                << ", covered volume " << vol[bi] << " ("
                << returnReduce(b.cells().size(), sumOp<label>())
                << " cells)" << nl;
        }

        if (err > tol)
        {
            FatalIOErrorInFunction(b.dict())
                << "Body " << b.name() << " (centre " << b.centre()
                << ") is not wholly inside the mesh: covered volume "
                << vol[bi] << " against " << Vb << " for the shape"
                << " (tolerance " << tol << " relative)"
                << exit(FatalIOError);
        }
    }
    if (bodies_.size())
    {
        Info<< "fbm: " << bodies_.size() << " bodies inside the mesh,"
            << " largest relative covered-volume error " << worst << nl;
    }
    Info<< endl;
}


void Foam::fbm::fictitiousBoundary::writeSummary()
{
    if (!Pstream::master() || !summaryFile_.valid())
    {
        return;
    }

    scalar maxSpeed = 0;
    scalar Ek = 0;
    vector Xmean(Zero);
    for (const body& b : bodies_)
    {
        maxSpeed = max
        (
            maxSpeed, mag(b.U()) + mag(b.omega())*b.shape().radius()
        );
        Ek += 0.5*b.mass()*magSqr(b.U());
        Xmean += b.centre();
    }
    Xmean /= max(bodies_.size(), 1);

    scalar pairGap = GREAT;
    scalar wallGap = GREAT;
    if (collisions_.valid())
    {
        pairGap = collisions_->minPairGap();
        wallGap = collisions_->minWallGap();
    }

    OFstream& os = summaryFile_();
    os  << mesh_.time().value() << ' ' << bodies_.size()
        << ' ' << maxSpeed << ' ' << Ek
        << ' ' << Xmean.x() << ' ' << Xmean.y() << ' ' << Xmean.z()
        << ' ' << pairGap << ' ' << wallGap << endl;
}


// ************************************************************************* //
