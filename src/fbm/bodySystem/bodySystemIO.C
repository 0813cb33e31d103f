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
    The restart state of fbm::bodySystem: <time>/uniform/fbmBodies, one
    sub-dictionary per body with its fbm::bodyState and the coupling's
    entries.

\*---------------------------------------------------------------------------*/

#include "bodySystem.H"
#include "Time.H"
#include "OSspecific.H"
#include "IFstream.H"
#include "HashSet.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

bool Foam::fbm::bodySystem::restarted() const
{
    // The start time continues an earlier run when the case (or this
    // processor's part of it) has an earlier time, or when the start time
    // was written by a solver (uniform/time)
    const Time& runTime = mesh_.time();
    bool restart = isFile(runTime.timePath()/"uniform"/"time");
    for (const instant& t : runTime.times())
    {
        if
        (
            t.name() != runTime.constant()
         && t.value() < runTime.value()
         && !t.equal(runTime.value())
        )
        {
            restart = true;
        }
    }
    return returnReduce(restart, orOp<bool>());
}


void Foam::fbm::bodySystem::readState()
{
    // Each processor reads its own copy (processor*/<time>/uniform), as it
    // wrote it
    const Time& runTime = mesh_.time();
    const fileName stateFile(runTime.timePath()/"uniform"/"fbmBodies");
    const bool present = isFile(stateFile);
    const bool restart = restarted();

    if (!restart && !returnReduce(present, orOp<bool>()))
    {
        // A start at the initial time: the bodies of constant/fbmProperties
        return;
    }

    // A restart needs the state of every body: never the initial state of
    // constant/fbmProperties inside the flow of a later time
    label missing = present ? labelMax : Pstream::myProcNo();
    reduce(missing, minOp<label>());
    if (missing != labelMax)
    {
        fileName missingFile(stateFile);
        if (Pstream::parRun())
        {
            missingFile =
                runTime.rootPath()/runTime.globalCaseName()
               /("processor" + Foam::name(missing))
               /runTime.timeName()/"uniform"/"fbmBodies";
        }
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, missingFile
        )   << "Start time " << runTime.timeName() << " continues an earlier"
            << " run (the case has "
            << (restart ? "earlier times" : "other processors' states")
            << "), but the body state " << missingFile << " is missing"
            << nl << "    The bodies would restart from "
            << objectPath() << " inside the flow of time "
            << runTime.timeName() << ". Start from a time that has its"
            << " state (a complete write time), or from the initial time"
            << exit(FatalIOError);
    }

    IFstream is(stateFile);
    if (!is.good())
    {
        FatalIOErrorInFunction(is)
            << "The body state " << stateFile << " of start time "
            << runTime.timeName() << " cannot be read" << exit(FatalIOError);
    }
    dictionary state(is, true);
    state.name() = stateFile;
    if (!state.found("FoamFile"))
    {
        FatalIOErrorInFunction(state)
            << "The body state " << stateFile << " of start time "
            << runTime.timeName() << " is "
            << (state.empty() ? "empty" : "not one written by fbmFoam")
            << " (no FoamFile header)" << exit(FatalIOError);
    }

    // The cell search uses the tet decomposition, built collectively
    (void)mesh_.tetBasePtIs();
    wordHashSet names;
    label nOlder = 0;
    for (body& b : bodies_)
    {
        names.insert(b.name());
        const dictionary* dictPtr = state.findDict(b.name());
        if (!dictPtr)
        {
            FatalIOErrorInFunction(state)
                << "Body " << b.name() << " has no state in " << stateFile
                << " (start time " << runTime.timeName() << "):"
                << " a restart needs the state of every body of "
                << objectPath() << exit(FatalIOError);
        }
        const dictionary& dict = *dictPtr;
        if (!b.state().read(dict))
        {
            ++nOlder;
        }

        // The state must be one the run could have reached
        const scalar speed = b.maxSpeed();
        if (speed > maxSpeed_)
        {
            FatalIOErrorInFunction(dict)
                << "Body " << b.name() << ": the restart state " << stateFile
                << " has speed " << speed << " (U " << b.U() << ", omega "
                << b.omega() << "), beyond maxSpeed " << maxSpeed_
                << " of " << objectPath() << exit(FatalIOError);
        }
        const bool found =
            (body::findCell(mesh_, fb_.cellTree(), b.centre()) != -1);
        if (!returnReduce(found, orOp<bool>()))
        {
            FatalIOErrorInFunction(dict)
                << "Body " << b.name() << ": the centre " << b.centre()
                << " of the restart state " << stateFile << " is outside"
                << " the mesh (bounds " << mesh_.bounds() << ")"
                << exit(FatalIOError);
        }
    }
    for (const entry& e : state)
    {
        if
        (
            e.isDict() && e.keyword() != "FoamFile"
         && !names.found(e.keyword())
        )
        {
            WarningInFunction
                << "The restart state " << stateFile << " has body "
                << e.keyword() << ", which " << objectPath()
                << " does not define: ignored" << endl;
        }
    }
    coupling_->readState(state);
    stateFile_ = stateFile;
    Info<< "fbm: body state read from " << stateFile << nl;
    if (nOlder)
    {
        Info<< "fbm: " << nOlder << " of " << bodies_.size() << " body states"
            << " in " << stateFile << " have no acceleration0 (written before"
            << " it was kept): the step before the last takes the last"
            << " step's accelerations (only the backward time scheme's"
            << " first step uses them)" << nl;
    }
}


void Foam::fbm::bodySystem::readCollisionState()
{
    if (stateFile_.empty() || !collisions_.valid())
    {
        return;
    }
    // The file readState() read and checked
    IFstream is(stateFile_);
    dictionary state(is, true);
    state.name() = stateFile_;
    collisions_->readState(state);
}


void Foam::fbm::bodySystem::writeState() const
{
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath()/"uniform");
    mkDir(dir);

    // Full precision for an exact restart, whatever writePrecision is
    OFstream os(dir/"fbmBodies");
    os.precision(17);
    IOobject io
    (
        "fbmBodies",
        runTime.timeName(),
        "uniform",
        mesh_,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
    io.writeHeader(os, IOdictionary::typeName);

    forAll(bodies_, bi)
    {
        os.beginBlock(bodies_[bi].name());
        bodies_[bi].state().write(os);
        coupling_->writeState(bi, os);
        if (collisions_.valid())
        {
            collisions_->writeState(bi, os);
        }
        os.endBlock();
    }
    IOobject::writeEndDivider(os);
}


// ************************************************************************* //
