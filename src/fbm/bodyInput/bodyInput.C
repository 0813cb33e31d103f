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

#include "bodyInput.H"
#include "fvMesh.H"
#include "HashSet.H"
#include "ITstream.H"
#include "IFstream.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "circle.H"
#include "sphere.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::fbm::bodyInput::readParticleList
(
    const dictionary& listDict,
    pointField& centres,
    scalarField& radii,
    scalarField& rho
)
{
    const word listName(listDict.dictName());
    const bool hasRho = listDict.found("rho");
    const scalar rhoShared = hasRho ? listDict.get<scalar>("rho") : -1;

    // particles ( (x y z) radius [rho]  ... ); an optional count in front
    ITstream& is = listDict.lookup("particles");
    // The next token (one looked at and kept first), or an undefined one
    // at the end: never a read beyond the end of the entry
    token kept;
    auto next = [&is, &kept](token& t)
    {
        if (kept.good())
        {
            t = kept;
            kept.reset();
        }
        else if (is.eof())
        {
            t.reset();
        }
        else
        {
            is >> t;
        }
    };

    token tok;
    next(tok);
    label count = -1;
    if (tok.isLabel())
    {
        count = tok.labelToken();
        next(tok);
    }
    if
    (
        !tok.good() || !tok.isPunctuation()
     || tok.pToken() != token::BEGIN_LIST
    )
    {
        OSstream& msg = FatalIOErrorInFunction(listDict);
        msg << "Keyword particles of " << listName << ": expected a list"
            << " ( (x y z) radius [rho] ... ), found ";
        if (tok.good())
        {
            msg << tok.info();
        }
        else
        {
            msg << "nothing";
        }
        if (count >= 0)
        {
            msg << " after the count " << count;
        }
        msg << exit(FatalIOError);
    }

    DynamicList<point> X;
    DynamicList<scalar> R;
    DynamicList<scalar> rhos;
    while (true)
    {
        next(tok);
        if (!tok.good() || is.bad())
        {
            FatalIOErrorInFunction(listDict)
                << "Keyword particles of " << listName << ": the list ends"
                << " before its closing ')' (after " << X.size()
                << " particles)" << exit(FatalIOError);
        }
        if (tok.isPunctuation() && tok.pToken() == token::END_LIST)
        {
            break;
        }
        if (!tok.isPunctuation() || tok.pToken() != token::BEGIN_LIST)
        {
            OSstream& msg = FatalIOErrorInFunction(listDict);
            msg << "Keyword particles of " << listName << ", particle "
                << X.size() << ": expected its centre (x y z), found "
                << tok.info() << nl;
            if (X.size())
            {
                msg << "    An extra column after particle " << X.size() - 1
                    << " (centre " << X.last() << ", radius " << R.last()
                    << ", density " << rhos.last() << ")?";
            }
            msg << " Each particle is (x y z) radius [rho]"
                << exit(FatalIOError);
        }
        is.putBack(tok);

        point x;
        scalar r = -1;
        is >> x;
        next(tok);
        if (tok.isNumber())
        {
            r = tok.number();
            next(tok);
        }
        scalar rhoi = rhoShared;
        if (tok.isNumber())
        {
            rhoi = tok.number();
        }
        else
        {
            kept = tok;
        }
        is.check(FUNCTION_NAME);

        if (!(r > 0) || !(rhoi > 0))
        {
            FatalIOErrorInFunction(listDict)
                << "Keyword particles of " << listName << ", particle "
                << X.size() << " (centre " << x << "): radius " << r
                << " and density " << rhoi << " must be positive"
                << (hasRho ? "" : " (the list has no shared rho)")
                << exit(FatalIOError);
        }
        X.append(x);
        R.append(r);
        rhos.append(rhoi);
    }

    if (X.empty())
    {
        FatalIOErrorInFunction(listDict)
            << "Keyword particles of " << listName << ": the list is empty"
            << " (a list needs at least one particle)" << exit(FatalIOError);
    }

    centres.transfer(X);
    radii.transfer(R);
    rho.transfer(rhos);
}


void Foam::fbm::bodyInput::checkDuplicates(const dictionary& fbmDict)
{
    // A dictionary merges entries of the same name (two bodies of one name
    // would become one with mixed keywords): read the file again with
    // duplicates an error, and name both
    const entry::inputMode oldMode = entry::globalInputMode;
    const bool oldThrow = FatalIOError.throwExceptions();
    entry::globalInputMode = entry::inputMode::ERROR;

    string message;
    label line = -1;
    try
    {
        // dictionary::read, not the constructor (which resets the mode)
        IFstream is(fbmDict.name());
        dictionary d;
        d.name() = is.name();
        d.read(is);
    }
    catch (const IOerror& err)
    {
        message = err.message();
        line = err.ioStartLineNumber();
    }
    entry::globalInputMode = oldMode;
    FatalIOError.throwExceptions(oldThrow);

    if (line < 0 && message.empty())
    {
        return;
    }

    // "duplicate entry: NAME" (any other read error was reported by the
    // first read already)
    const std::string::size_type pos = message.find("duplicate entry: ");
    if (pos == std::string::npos)
    {
        return;
    }
    const word key(message.substr(pos + 17).c_str());

    // A body, or another entry
    bool isBody = false;
    for (const word container : {"bodies", "particleLists"})
    {
        const dictionary* dictPtr = fbmDict.findDict(container);
        isBody = isBody || (dictPtr && dictPtr->isDict(key));
    }

    FatalIOErrorInFunction(fbmDict)
        << (isBody ? "Body " : "Entry ") << key << " is defined twice in "
        << fbmDict.name() << " (the second time at line " << line << ")"
        << (isBody ? ": a dictionary would merge the two into one body;"
            " give each body its own name" : ": remove one")
        << exit(FatalIOError);
}


Foam::point Foam::fbm::bodyInput::midPlane
(
    const polyMesh& mesh,
    const point& p
)
{
    point q(p);
    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0)
        {
            q[d] = mesh.bounds().centre()[d];
        }
    }
    return q;
}


Foam::autoPtr<Foam::fbm::body> Foam::fbm::bodyInput::newRoundBody
(
    const word& name,
    const scalar radius,
    const scalar rho,
    const bodyState& state,
    const bool translate,
    const bool rotate,
    const polyMesh& mesh
)
{
    autoPtr<bodyShape> shape;
    if (mesh.nSolutionD() == 3)
    {
        shape.reset(new bodyShapes::sphere(radius, mesh));
    }
    else
    {
        shape.reset(new bodyShapes::circle(radius, mesh));
    }
    bodyState s(state);
    s.centre() = midPlane(mesh, s.centre());
    return autoPtr<body>
    (
        new body(name, std::move(shape), rho, s, translate, rotate)
    );
}


Foam::autoPtr<Foam::fbm::body> Foam::fbm::bodyInput::newBody
(
    const word& name,
    const dictionary& dict,
    const fvMesh& mesh,
    const indexedOctree<treeDataCell>& tree
)
{
    autoPtr<bodyShape> shape(bodyShape::New(dict, mesh));
    const scalar rho =
        dict.getCheck<scalar>("rho", [](scalar r){ return r >= 0; });
    const point centre0(midPlane(mesh, dict.get<point>("centre")));
    const vector omega(dict.get<vector>("omega"));
    const bool translate = dict.get<bool>("translate");
    const bool rotate = dict.get<bool>("rotate");

    // A prescribed motion sets the translation: its centre at the start
    // time, and U
    autoPtr<prescribedMotion> motion;
    point centre(centre0);
    vector U(Zero);
    if (dict.found("motion"))
    {
        if (translate)
        {
            FatalIOErrorInFunction(dict)
                << "Body " << name << ": a prescribed motion with translate"
                << " yes; set translate no" << exit(FatalIOError);
        }
        if (dict.found("U"))
        {
            FatalIOErrorInFunction(dict)
                << "Body " << name << ": U is given, but the velocity comes"
                << " from its motion dictionary; remove U"
                << exit(FatalIOError);
        }
        motion = prescribedMotion::New(dict.subDict("motion"), centre0, mesh);
        const scalar t = mesh.time().value();
        centre = centre0 + motion->displacement(t);
        U = motion->velocity(t);
    }
    else
    {
        U = dict.get<vector>("U");
    }

    // In 2D the centre's empty component is put mid-depth (above); the
    // motion must stay in the plane
    const Vector<label>& sd = mesh.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sd[d] < 0)
        {
            if (mag(U[d]) > 0)
            {
                FatalIOErrorInFunction(dict)
                    << "Body " << name << ": U " << U << " has a component"
                    << " in the empty direction of this 2D mesh"
                    << exit(FatalIOError);
            }
        }
        else if (mesh.nSolutionD() == 2 && mag(omega[d]) > 0)
        {
            FatalIOErrorInFunction(dict)
                << "Body " << name << ": omega " << omega << " must be"
                << " along the empty direction of this 2D mesh"
                << exit(FatalIOError);
        }
    }

    // Initial orientation (optional): a rotation tensor, body frame to
    // lab frame; in 2D a rotation about the empty direction
    const bool oriented = dict.found("orientation");
    const tensor Q0(dict.getOrDefault<tensor>("orientation", tensor::I));
    if (oriented)
    {
        if (mag((Q0.T() & Q0) - tensor::I) > 1e-6 || det(Q0) <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "Body " << name << ": orientation " << Q0 << " is not a"
                << " rotation tensor (orthogonal with determinant +1, to"
                << " 1e-6)" << exit(FatalIOError);
        }
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            vector e(Zero);
            e[d] = 1;
            if (sd[d] < 0 && mag((Q0 & e) - e) > 1e-6)
            {
                FatalIOErrorInFunction(dict)
                    << "Body " << name << ": orientation " << Q0 << " must"
                    << " be a rotation about the empty direction of this 2D"
                    << " mesh" << exit(FatalIOError);
            }
        }
    }

    // The centre must lie in the mesh (on some processor). The cell test
    // uses the mesh's tet decomposition, which is built collectively: build
    // it on every processor first, not only where the centre has candidate
    // cells (that deadlocked a decomposed run)
    (void)mesh.tetBasePtIs();
    const bool found = (body::findCell(mesh, tree, centre) != -1);
    if (!returnReduce(found, orOp<bool>()))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << name << ": centre " << centre
            << " is outside the mesh (bounds " << mesh.bounds() << ")"
            << exit(FatalIOError);
    }

    bodyState state(centre, U, omega);
    if (oriented)
    {
        state.setOrientation(Q0, Zero);
    }
    autoPtr<body> b
    (
        new body(name, std::move(shape), rho, state, translate, rotate)
    );
    if (motion.valid())
    {
        b->setMotion(std::move(motion), mesh.time().value());
    }
    return b;
}


void Foam::fbm::bodyInput::read
(
    const dictionary& fbmDict,
    const fvMesh& mesh,
    const indexedOctree<treeDataCell>& tree,
    PtrList<body>& bodies,
    List<const dictionary*>& sources
)
{
    if (!fbmDict.found("bodies") && !fbmDict.found("particleLists"))
    {
        FatalIOErrorInFunction(fbmDict)
            << "Neither bodies nor particleLists in " << fbmDict.name()
            << exit(FatalIOError);
    }

    // Both containers are dictionaries of dictionaries
    for (const word key : {"bodies", "particleLists"})
    {
        if (fbmDict.found(key) && !fbmDict.isDict(key))
        {
            FatalIOErrorInFunction(fbmDict)
                << "Keyword " << key << " in " << fbmDict.name()
                << " is not a dictionary: expected " << key
                << " { <name> { type ...; ... } ... }"
                << exit(FatalIOError);
        }
    }

    checkDuplicates(fbmDict);

    DynamicList<body*> all;
    DynamicList<const dictionary*> from;
    wordHashSet names;

    const dictionary* bodiesDict = fbmDict.findDict("bodies");
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
            names.insert(e.keyword());
            all.append(newBody(e.keyword(), e.dict(), mesh, tree).ptr());
            from.append(&e.dict());
        }
    }

    const dictionary* lists = fbmDict.findDict("particleLists");
    if (lists)
    {
        for (const entry& e : *lists)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(*lists)
                    << "Entry '" << e.keyword() << "' in particleLists is"
                    << " not a dictionary" << exit(FatalIOError);
            }
            const dictionary& listDict = e.dict();
            const word& listName = e.keyword();

            pointField X;
            scalarField R, rho;
            readParticleList(listDict, X, R, rho);

            // Each particle: the list's shared entries with its centre,
            // radius and density
            dictionary base(listDict);
            base.remove("particles");
            forAll(X, i)
            {
                const word name(listName + Foam::name(i));
                dictionary d(base);
                d.name() = listDict.name() + ".particles." + Foam::name(i);
                d.set("centre", X[i]);
                d.set("radius", R[i]);
                d.set("rho", rho[i]);
                if (!names.insert(name))
                {
                    FatalIOErrorInFunction(d)
                        << "Body name " << name << " of particleLists is"
                        << " already used in " << fbmDict.name()
                        << exit(FatalIOError);
                }
                all.append(newBody(name, d, mesh, tree).ptr());
                from.append(&listDict);
            }

            Info<< "fbm: particle list " << listName << ": " << X.size()
                << " bodies " << listName << "0 - " << listName
                << X.size() - 1 << nl;
        }
    }

    if (all.empty())
    {
        FatalIOErrorInFunction(fbmDict)
            << "No bodies in " << fbmDict.name() << ": bodies and"
            << " particleLists are empty" << exit(FatalIOError);
    }

    bodies.setSize(all.size());
    forAll(all, bi)
    {
        bodies.set(bi, all[bi]);
    }
    sources = from;
}


// ************************************************************************* //
