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

#include "bodyOutput.H"
#include "bodySystem.H"
#include "Time.H"
#include "wordRes.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "passiveParticleCloud.H"
#include "IOPosition.H"
#include "quaternion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::fbm::bodyOutput::outputName("fbmBodies");


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fbm::bodyOutput::selectBodies(const dictionary& dict)
{
    // Every body when there are at most this many, else none, unless
    // bodyFiles selects them
    const label maxAuto = 100;
    const PtrList<body>& bodies = system_.bodies();

    DynamicList<label> sel;
    if (dict.found("bodyFiles"))
    {
        const wordRes patterns(dict.get<wordRes>("bodyFiles"));
        forAll(bodies, bi)
        {
            if (patterns.match(bodies[bi].name()))
            {
                sel.append(bi);
            }
        }
    }
    else if (bodies.size() <= maxAuto)
    {
        sel = identity(bodies.size());
    }
    selected_.transfer(sel);

    if (selected_.size() < bodies.size())
    {
        Info<< "fbm: per-body output (log line, <body>.dat) for "
            << selected_.size() << " of " << bodies.size() << " bodies"
            << (dict.found("bodyFiles") ? " (bodyFiles)" : "")
            << "; all bodies in summary.dat and the fbmBodies cloud" << nl;
    }
}


void Foam::fbm::bodyOutput::readCoefficients
(
    const List<const dictionary*>& sources
)
{
    const label n = selected_.size();
    hasCoeffs_.setSize(n, false);
    coeffDenom_.setSize(n, 1);
    dragDir_.setSize(n, vector(1, 0, 0));
    liftDir_.setSize(n, vector(0, 1, 0));

    forAll(selected_, si)
    {
        const label bi = selected_[si];
        const dictionary* cDict = sources[bi]->findDict("coefficients");
        if (!cDict)
        {
            continue;
        }

        const scalar magUInf =
            cDict->getCheck<scalar>("magUInf", [](scalar u){ return u > 0; });
        const scalar Aref =
            cDict->getCheck<scalar>("Aref", [](scalar a){ return a > 0; });
        vector dragDir(cDict->get<vector>("dragDir"));
        vector liftDir(cDict->get<vector>("liftDir"));
        if (mag(dragDir) < SMALL || mag(liftDir) < SMALL)
        {
            FatalIOErrorInFunction(*cDict)
                << "Body " << system_.bodies()[bi].name() << ": dragDir and"
                << " liftDir must be non-zero vectors" << exit(FatalIOError);
        }
        hasCoeffs_[si] = true;
        coeffDenom_[si] = 0.5*system_.rhoFluid()*sqr(magUInf)*Aref;
        dragDir_[si] = dragDir/mag(dragDir);
        liftDir_[si] = liftDir/mag(liftDir);
    }
}


Foam::autoPtr<Foam::OFstream> Foam::fbm::bodyOutput::newFile
(
    const word& name
) const
{
    autoPtr<OFstream> osPtr(createFile(name));
    if (osPtr.valid())
    {
        // General format with 12 digits (writeFile's default is a fixed
        // width scientific format)
        osPtr->stdStream().unsetf(std::ios_base::floatfield);
        osPtr->width(0);
        osPtr->precision(12);
    }
    return osPtr;
}


void Foam::fbm::bodyOutput::createFiles(const wordList& modelNames)
{
    if (!Pstream::master())
    {
        return;
    }

    const PtrList<body>& bodies = system_.bodies();

    summaryFile_ = newFile("summary");
    summaryFile_()
        << "# All " << bodies.size() << " bodies: largest speed"
        << " |U| + |omega| R [m/s], translational kinetic energy sum"
        << " M |U|^2/2 [J], mean centre [m], smallest pair gap D - Ri - Rj"
        << " and wall gap d - R over the collision sub-steps [m] (1e15:"
        << " none within reach)" << nl
        << "# Time N maxSpeed kineticEnergy Xx Xy Xz minPairGap minWallGap"
        << endl;

    const label nSel = selected_.size();
    files_.setSize(modelNames.size()*nSel);
    forAll(files_, filei)
    {
        const label mi = filei/nSel;
        const label si = filei % nSel;
        const body& b = bodies[selected_[si]];
        const word suffix(mi == 0 ? word::null : word("." + modelNames[mi]));
        files_.set(filei, newFile(b.name() + suffix));
        OFstream& os = files_[filei];
        os  << "# Body " << b.name() << ": hydrodynamic force [N] and"
            << " torque about the centre [N m], force model "
            << modelNames[mi] << nl
            << "# Time Fx Fy Fz Tx Ty Tz";
        if (hasCoeffs_[si])
        {
            os  << " Cd Cl";
        }
        os  << " x y z Ux Uy Uz wx wy wz";
        if (!b.shape().isotropic())
        {
            // Orientation: the accumulated rotation angle about the empty
            // direction (2D), the unit quaternion of Q (3D)
            os  << (system_.mesh().nSolutionD() == 2
                    ? " angle" : " qw qx qy qz");
        }
        os  << endl;
    }
}


void Foam::fbm::bodyOutput::writeLine
(
    OFstream& os,
    const label si,
    const vector& F,
    const vector& T
) const
{
    const body& b = system_.bodies()[selected_[si]];
    os  << fileObr_.time().value()
        << ' ' << F.x() << ' ' << F.y() << ' ' << F.z()
        << ' ' << T.x() << ' ' << T.y() << ' ' << T.z();
    if (hasCoeffs_[si])
    {
        os  << ' ' << (F & dragDir_[si])/coeffDenom_[si]
            << ' ' << (F & liftDir_[si])/coeffDenom_[si];
    }
    const point& X = b.centre();
    const vector& V = b.U();
    const vector& w = b.omega();
    os  << ' ' << X.x() << ' ' << X.y() << ' ' << X.z()
        << ' ' << V.x() << ' ' << V.y() << ' ' << V.z()
        << ' ' << w.x() << ' ' << w.y() << ' ' << w.z();
    if (!b.shape().isotropic())
    {
        const Vector<label>& sd = system_.mesh().solutionD();
        if (system_.mesh().nSolutionD() == 2)
        {
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (sd[d] < 0) os << ' ' << b.state().theta()[d];
            }
        }
        else
        {
            quaternion q(b.state().Q());
            if (q.w() < 0) q = -q;
            os  << ' ' << q.w() << ' ' << q.v().x() << ' ' << q.v().y()
                << ' ' << q.v().z();
        }
    }
    os  << endl;
}


void Foam::fbm::bodyOutput::writeSummary()
{
    if (!summaryFile_.valid())
    {
        return;
    }

    const PtrList<body>& bodies = system_.bodies();
    scalar maxSpeed = 0;
    scalar Ek = 0;
    vector Xmean(Zero);
    for (const body& b : bodies)
    {
        maxSpeed = max(maxSpeed, b.maxSpeed());
        Ek += 0.5*b.mass()*magSqr(b.U());
        Xmean += b.centre();
    }
    Xmean /= max(bodies.size(), 1);

    scalar pairGap = GREAT;
    scalar wallGap = GREAT;
    if (system_.hasCollisions())
    {
        pairGap = system_.collisions().minPairGap();
        wallGap = system_.collisions().minWallGap();
    }

    OFstream& os = summaryFile_();
    os  << fileObr_.time().value() << ' ' << bodies.size()
        << ' ' << maxSpeed << ' ' << Ek
        << ' ' << Xmean.x() << ' ' << Xmean.y() << ' ' << Xmean.z()
        << ' ' << pairGap << ' ' << wallGap << endl;
}


void Foam::fbm::bodyOutput::writeCloud() const
{
    const fvMesh& mesh = system_.mesh();
    const PtrList<body>& bodies = system_.bodies();
    const indexedOctree<treeDataCell>& tree = system_.fb().cellTree();

    // The bodies whose centre lies in this processor's cells
    passiveParticleCloud cloud(mesh, outputName, IDLList<passiveParticle>());
    DynamicList<label> mine(bodies.size());
    forAll(bodies, bi)
    {
        const point& X = bodies[bi].centre();
        const label celli = body::findCell(mesh, tree, X);
        if (celli != -1)
        {
            mine.append(bi);
            cloud.addParticle(new passiveParticle(mesh, X, celli));
        }
    }

    const label n = mine.size();
    scalarField d(n), rho(n);
    labelField id(n);
    vectorField U(n), omega(n), F(n);
    forAll(mine, i)
    {
        const body& b = bodies[mine[i]];
        d[i] = b.shape().diameter();
        rho[i] = b.rho();
        id[i] = mine[i];
        U[i] = b.U();
        omega[i] = b.omega();
        F[i] = b.force();
    }

    // ASCII whatever the case's writeFormat (the post-processing scripts
    // read it); the legacy positions format, which ParaView reads
    auto write = [](const regIOobject& io)
    {
        io.writeObject
        (
            IOstream::ASCII,
            IOstream::currentVersion,
            IOstream::UNCOMPRESSED,
            true
        );
    };
    write
    (
        IOPosition<passiveParticleCloud>
        (
            cloud, cloud::geometryType::POSITIONS
        )
    );
    write(IOField<scalar>(cloud.fieldIOobject("d", IOobject::NO_READ), d));
    write
    (
        IOField<scalar>(cloud.fieldIOobject("rho", IOobject::NO_READ), rho)
    );
    write(IOField<label>(cloud.fieldIOobject("id", IOobject::NO_READ), id));
    write(IOField<vector>(cloud.fieldIOobject("U", IOobject::NO_READ), U));
    write
    (
        IOField<vector>
        (
            cloud.fieldIOobject("omega", IOobject::NO_READ), omega
        )
    );
    write(IOField<vector>(cloud.fieldIOobject("F", IOobject::NO_READ), F));

    // The orientation Q (body frame to lab frame), when some body's shape
    // is not isotropic (the clouds of circles and spheres are unchanged)
    bool oriented = false;
    for (const body& b : bodies)
    {
        oriented = oriented || !b.shape().isotropic();
    }
    if (oriented)
    {
        tensorField Q(n);
        forAll(mine, i)
        {
            Q[i] = bodies[mine[i]].state().Q();
        }
        write
        (
            IOField<tensor>
            (
                cloud.fieldIOobject("orientation", IOobject::NO_READ), Q
            )
        );
    }

    // For foamToVTK: the cloud's geometry is the positions file
    IOdictionary props
    (
        IOobject
        (
            passiveParticleCloud::cloudPropertiesName,
            mesh.time().timeName(),
            "uniform"/cloud::prefix/outputName,
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    props.add
    (
        "geometry",
        cloud::geometryTypeNames[cloud::geometryType::POSITIONS]
    );
    write(props);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::bodyOutput::bodyOutput
(
    const bodySystem& system,
    const List<const dictionary*>& sources,
    const wordList& modelNames
)
:
    functionObjects::writeFile(system.mesh(), outputName),
    system_(system)
{
    selectBodies(system);
    readCoefficients(sources);
    createFiles(modelNames);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::bodyOutput::write()
{
    const PtrList<body>& bodies = system_.bodies();
    forAll(selected_, si)
    {
        const body& b = bodies[selected_[si]];

        Info<< "fbm: " << b.name() << " F = " << b.force()
            << " T = " << b.torque();
        if (hasCoeffs_[si])
        {
            Info<< " Cd = " << (b.force() & dragDir_[si])/coeffDenom_[si]
                << " Cl = " << (b.force() & liftDir_[si])/coeffDenom_[si];
        }
        Info<< nl;

        if (Pstream::master())
        {
            writeLine(files_[si], si, b.force(), b.torque());
        }
    }

    writeSummary();

    if (fileObr_.time().writeTime())
    {
        writeCloud();
    }
}


void Foam::fbm::bodyOutput::writeForces
(
    const label mi,
    const List<vector>& force,
    const List<vector>& torque
)
{
    if (!Pstream::master())
    {
        return;
    }
    forAll(selected_, si)
    {
        const label bi = selected_[si];
        writeLine
        (
            files_[mi*selected_.size() + si], si, force[bi], torque[bi]
        );
    }
}


// ************************************************************************* //
