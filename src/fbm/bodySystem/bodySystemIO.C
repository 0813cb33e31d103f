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

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::bodySystem::readState()
{
    IOobject stateIO
    (
        "fbmBodies",
        mesh_.time().timeName(),
        "uniform",
        mesh_,
        IOobject::READ_IF_PRESENT,
        IOobject::NO_WRITE,
        false
    );
    if (!stateIO.typeHeaderOk<IOdictionary>(true))
    {
        return;
    }

    const IOdictionary state(stateIO);
    for (body& b : bodies_)
    {
        b.state().read(state.subDict(b.name()));
    }
    coupling_->readState(state);
    Info<< "fbm: body state read from " << state.objectPath() << nl;
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
        os.endBlock();
    }
    IOobject::writeEndDivider(os);
}


// ************************************************************************* //
