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

#include "viscousStepLimit.H"
#include "fictitiousBoundary.H"
#include "fvMatrices.H"
#include "volFields.H"
#include "emptyFvPatch.H"
#include "fluidRate.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fbm::viscousStepLimit::viscousStepLimit
(
    const dictionary& coeffs,
    const word& coupling,
    const scalar defaultRatio
)
:
    coupling_(coupling),
    maxRatio_(defaultRatio),
    dtLimit_(VGREAT),
    warned_(false)
{
    const bool given = coeffs.found("maxViscousRatio");
    if (given)
    {
        maxRatio_ = coeffs.getCheck<scalar>
        (
            "maxViscousRatio", [](scalar r){ return r > 0; }
        );
    }

    Info<< "fbm: coupling " << coupling_ << ": ";
    if (active())
    {
        Info<< "maxViscousRatio " << Foam::name(maxRatio_)
            << (given ? "" : " (default)") << nl;
    }
    else
    {
        Info<< "no viscous step limit (maxViscousRatio not given)" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fbm::viscousStepLimit::estimate
(
    const volScalarField& nuEff,
    const fictitiousBoundary& fb,
    const boolList& selected
)
{
    if (!active() || dtLimit_ < VGREAT)
    {
        return;
    }

    const fvMesh& mesh = nuEff.mesh();
    const cellList& cellFaces = mesh.cells();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const scalarField& w = mesh.weights();
    const scalarField& magSf = mesh.magSf();
    const scalarField& delta = mesh.nonOrthDeltaCoeffs();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const scalarField& nu = nuEff.primitiveField();
    const scalarField& id = fb.bodyID();
    const scalarField& V = mesh.V();

    // Over the bodies' cells, the viscous part of the diagonal per unit
    // time step, sum nu_f |S_f| delta_f / V
    scalar ratioPerDt = 0;
    for (const label celli : fb.activeCells())
    {
        const label bi = label(id[celli]);
        if (bi < 0 || !selected[bi]) continue;

        scalar sum = 0;
        for (const label facei : cellFaces[celli])
        {
            if (mesh.isInternalFace(facei))
            {
                const scalar nuf =
                    w[facei]*nu[own[facei]] + (1 - w[facei])*nu[nei[facei]];
                sum += nuf*magSf[facei]*delta[facei];
                continue;
            }
            const label patchi = patches.whichPatch(facei);
            const fvPatch& fp = mesh.boundary()[patchi];
            if (isA<emptyFvPatch>(fp)) continue;
            const label i = facei - fp.start();
            sum +=
                nuEff.boundaryField()[patchi][i]
               *mesh.magSf().boundaryField()[patchi][i]
               *mesh.nonOrthDeltaCoeffs().boundaryField()[patchi][i];
        }
        ratioPerDt = max(ratioPerDt, sum/V[celli]);
    }
    reduce(ratioPerDt, maxOp<scalar>());

    if (ratioPerDt > VSMALL)
    {
        dtLimit_ = maxRatio_/ratioPerDt;
        Info<< "fbm: coupling " << coupling_ << ": first step at most "
            << dtLimit_ << " (viscous limit estimated from nuEff)" << nl;
    }
}


void Foam::fbm::viscousStepLimit::update
(
    const fvMatrix<vector>& UEqn,
    const fictitiousBoundary& fb,
    const boolList& selected,
    const fluidRate* rate
)
{
    if (!active())
    {
        return;
    }

    const fvMesh& mesh = UEqn.psi().mesh();
    const scalarField& diag = UEqn.diag();
    const scalarField& lambda = fb.lambda();
    const scalarField& id = fb.bodyID();
    const scalarField& V = mesh.V();
    const scalar dt = mesh.time().deltaTValue();

    // The inertial part of the diagonal is c V/dt: c = 1 + w of the
    // fluid's time scheme (1 for Euler, 1.5 for backward at a constant
    // step)
    const scalar c = 1 + (rate ? rate->weight() : 0);

    // Over the bodies' cells, the ratio of the diagonal's viscous and
    // convective part to its inertial part c V/dt
    scalar ratio = 0;
    for (const label celli : fb.activeCells())
    {
        const label bi = label(id[celli]);
        if (bi < 0 || !selected[bi]) continue;
        ratio = max(ratio, (diag[celli] - lambda[celli])*dt/(c*V[celli]) - 1);
    }
    reduce(ratio, maxOp<scalar>());

    dtLimit_ = (ratio > SMALL) ? maxRatio_*dt/ratio : VGREAT;
    if (dt > 1.01*dtLimit_ && !warned_)
    {
        WarningInFunction
            << "coupling " << coupling_ << " at time "
            << mesh.time().timeName() << ": the step " << dt
            << " is above its viscous stability limit " << dtLimit_
            << " (the viscous and convective part of the momentum"
            << " matrix's diagonal is " << ratio << " times its inertial"
            << " part in the bodies' cells; at most " << maxRatio_
            << "): the force may oscillate and grow. With"
            << " adjustTimeStep yes the step is kept below the limit" << endl;
        warned_ = true;
    }
}


void Foam::fbm::viscousStepLimit::read(const dictionary& bodyState)
{
    if (!active())
    {
        return;
    }
    dtLimit_ = bodyState.getCheck<scalar>
    (
        "viscousDeltaT", [](scalar dt){ return dt > 0; }
    );
}


void Foam::fbm::viscousStepLimit::write(Ostream& os) const
{
    if (dtLimit_ < VGREAT)
    {
        os.writeEntry("viscousDeltaT", dtLimit_);
    }
}


// ************************************************************************* //
