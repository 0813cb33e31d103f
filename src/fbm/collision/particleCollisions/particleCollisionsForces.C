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
    The contact forces of fbm::particleCollisions at one evaluation
    (arrayForces): the pairs and walls of round bodies by the law, those
    of non-round bodies through their closest points and faces (shapePair,
    shapeWall), the dashpot and the friction model at each contact.

\*---------------------------------------------------------------------------*/

#include "particleCollisions.H"
#include "body.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::fbm::particleCollisions::inverseMass
(
    const body& b,
    const label i,
    const vector& r,
    const vector& n
)
{
    scalar w = 0;
    if (translates_[i] && mass_[i] < GREAT)
    {
        w += 1/mass_[i];
    }
    if (b.rotates())
    {
        if (invInertiaStamp_[i] != nForceCalls_)
        {
            invInertia_[i] = inv(b.inertia());
            invInertiaStamp_[i] = nForceCalls_;
        }
        const vector rn(r ^ n);
        w += rn & (invInertia_[i] & rn);
    }
    return w;
}


Foam::vector Foam::fbm::particleCollisions::frictionForce
(
    const body& bi,
    const label i,
    const vector& ri,
    const body* bj,
    const label j,
    const vector& rj,
    const vector& n,
    const scalar Fn,
    const scalar kn
)
{
    vector v(U_[i] + (bi.omega() ^ ri));
    if (bj)
    {
        v -= U_[j] + (bj->omega() ^ rj);
    }
    // The inverse effective mass along the sliding velocity
    const vector vt(friction_->tangential(v, n));
    const scalar magVt = mag(vt);
    scalar wt = 0;
    if (magVt >= VSMALL)
    {
        const vector t(vt/magVt);
        wt = inverseMass(bi, i, ri, t) + (bj ? inverseMass(*bj, j, rj, t) : 0);
    }
    return friction_->force(labelPair(i, j), v, n, Fn, kn, wt);
}


void Foam::fbm::particleCollisions::sharedDashpot
(
    const body& bi,
    const label i,
    const body* bj,
    const label j,
    const vector& n,
    const scalar c,
    const UList<point>& pts,
    const UList<scalar>& wts,
    const vector& offsetI,
    const vector& offsetJ,
    vector& Fd,
    vector& Ti,
    vector& Tj
) const
{
    const scalar sumW = wts.empty() ? scalar(pts.size()) : sum(wts);
    forAll(pts, k)
    {
        const vector rk(cmptMultiply(planeMask_, pts[k] + offsetI));
        vector v(U_[i] + (bi.omega() ^ rk));
        vector rjk(Zero);
        if (bj)
        {
            rjk = cmptMultiply(planeMask_, pts[k] + offsetJ);
            v -= U_[j] + (bj->omega() ^ rjk);
        }
        const scalar wk = wts.empty() ? scalar(1) : wts[k];
        const vector Fk(-(wk/sumW)*c*(v & n)*n);
        Fd += Fk;
        Ti += rk ^ Fk;
        if (bj)
        {
            Tj -= rjk ^ Fk;
        }
    }
}


void Foam::fbm::particleCollisions::shapePair
(
    const PtrList<body>& bodies,
    const label i,
    const label j,
    List<vector>& F,
    List<vector>& T
)
{
    const contactModel& law = *model_;
    const body& bi = bodies[i];
    const body& bj = bodies[j];

    // Within a move(), GJK starts from the pair's last normal if the pair
    // was apart (from an overlap it takes more iterations than from the
    // centres: test convexDistance)
    auto hint = inMove_ ? warmStart_.find(labelPair(i, j)) : warmStart_.end();
    const convexDistance::result c
    (
        narrow_.distance
        (
            bi.shape(), bi.state().Q(), X_[i],
            bj.shape(), bj.state().Q(), X_[j],
            hint.found() ? *hint : vector::zero
        )
    );
    ++nNarrow_;
    nNarrowIter_ += c.iterations;
    const vector next(c.overlap ? vector::zero : vector(-c.normal));
    if (hint.found())
    {
        *hint = next;
    }
    else if (inMove_)
    {
        warmStart_.insert(labelPair(i, j), next);
    }
    minPairGap_ = min(minPairGap_, c.gap);
    if (c.gap > law.range())
    {
        return;
    }

    // Along the normal n (from i to j) at the contact point: the middle of
    // the closest points, or where a body has flat faces the middle of the
    // overlap of the faces that meet (a face lying on a face touches at
    // the middle of the overlap, not at one corner)
    const vector& n = c.normal;
    point pc(0.5*(c.pA + c.pB));
    region_.clear();
    if (bi.shape().hasFlatFaces() || bj.shape().hasFlatFaces())
    {
        const scalar band = 0.5*law.range();
        faceA_.clear();
        faceB_.clear();
        weightA_.clear();
        weightB_.clear();
        bi.shape().supportBand(bi.state().Q(), n, band, faceA_, weightA_);
        bj.shape().supportBand(bj.state().Q(), -n, band, faceB_, weightB_);
        for (point& p : faceA_)
        {
            p += X_[i];
        }
        for (point& p : faceB_)
        {
            p += X_[j];
        }
        pc = contactPatch(n, vector::one - planeMask_).centre
        (
            pc, faceA_, weightA_, faceB_, weightB_, R_[i] + R_[j],
            dampingRatio_ > 0 ? &region_ : nullptr
        );
    }
    const vector ri(cmptMultiply(planeMask_, pc - X_[i]));
    const vector rj(cmptMultiply(planeMask_, pc - X_[j]));
    vector Fi(-law.pairForceAtGap(c.gap, R_[i], R_[j])*n);

    // The dashpot: at the contact point, or where a face meets a face
    // shared among the points that span their overlap (the same force,
    // and a torque against the rocking of one face on the other)
    vector Fd(Zero);
    vector Tdi(Zero);
    vector Tdj(Zero);
    if (dampingRatio_ > 0)
    {
        const scalar w = inverseMass(bi, i, ri, n) + inverseMass(bj, j, rj, n);
        if (w > 0)
        {
            const scalar k = depth_*law.pairStiffness(R_[i], R_[j]);
            const scalar cd = 2*dampingRatio_*Foam::sqrt(k/w)/depth_;
            if (region_.size() > 1)
            {
                sharedDashpot
                (
                    bi, i, &bj, j, n, cd, region_, UList<scalar>(),
                    -X_[i], -X_[j], Fd, Tdi, Tdj
                );
            }
            else
            {
                const vector vi(U_[i] + (bi.omega() ^ ri));
                const vector vj(U_[j] + (bj.omega() ^ rj));
                Fi -= cd*((vi - vj) & n)*n;
            }
        }
    }

    if (friction_.valid())
    {
        Fi += frictionForce
        (
            bi, i, ri, &bj, j, rj, n, max(-((Fi + Fd) & n), 0.0),
            law.pairStiffness(R_[i], R_[j])
        );
    }

    F[i] += Fi;
    F[j] -= Fi;
    T[i] += ri ^ Fi;
    T[j] -= rj ^ Fi;
    if (region_.size() > 1)
    {
        F[i] += Fd;
        F[j] -= Fd;
        T[i] += Tdi;
        T[j] += Tdj;
    }
}


void Foam::fbm::particleCollisions::shapeWall
(
    const PtrList<body>& bodies,
    const label i,
    const label w,
    const scalar d,
    List<vector>& F,
    List<vector>& T
)
{
    const contactModel& law = *model_;
    const body& b = bodies[i];

    // The body's point nearest the wall: its support along the outward
    // normal
    const vector& nw = walls_.normals()[w];
    const vector s(b.shape().support(b.state().Q(), nw));
    const scalar gap = d - (nw & s);
    minWallGap_ = min(minWallGap_, gap);
    if (gap > 0.5*law.range())
    {
        return;
    }

    // The contact point: on a flat face (polygon, triSurface) the middle of
    // its vertices within the range (a face on the wall touches at its
    // middle, not at one corner)
    const vector r
    (
        cmptMultiply
        (
            planeMask_,
            b.shape().planeContact(b.state().Q(), nw, 0.5*law.range())
          + 0.5*gap*nw
        )
    );
    vector Fi(-law.wallForceAtGap(gap, R_[i])*nw);

    // The dashpot shared among a flat face's points with the weights of
    // its contact point: the same force as at the middle, and a torque
    // against the face's rocking, which the middle alone (hardly moving
    // along nw as the face rocks) would not damp
    vector Fd(Zero);
    vector Td(Zero);
    if (dampingRatio_ > 0)
    {
        const scalar wi = inverseMass(b, i, r, nw);
        if (wi > 0)
        {
            const scalar k = depth_*law.wallStiffness(R_[i]);
            const scalar c = 2*dampingRatio_*Foam::sqrt(k/wi)/depth_;
            if (b.shape().hasFlatFaces())
            {
                faceA_.clear();
                weightA_.clear();
                b.shape().supportBand
                (
                    b.state().Q(), nw, 0.5*law.range(), faceA_, weightA_
                );
                vector unused(Zero);
                sharedDashpot
                (
                    b, i, nullptr, -1, nw, c, faceA_, weightA_,
                    0.5*gap*nw, Zero, Fd, Td, unused
                );
            }
            else
            {
                const vector v(U_[i] + (b.omega() ^ r));
                Fi -= c*(v & nw)*nw;
            }
        }
    }

    F[i] += Fi;
    T[i] += r ^ Fi;
    F[i] += Fd;
    T[i] += Td;
    Fi += Fd;

    // Friction at the body's own contact point (the wall is fixed: no
    // counterpart to share the point with)
    if (friction_.valid())
    {
        const vector rs(r - cmptMultiply(planeMask_, 0.5*gap*nw));
        const vector Ft
        (
            frictionForce
            (
                b, i, rs, nullptr, -1 - w, Zero, nw, max(-(Fi & nw), 0.0),
                law.wallStiffness(R_[i])
            )
        );
        F[i] += Ft;
        T[i] += rs ^ Ft;
    }
}


void Foam::fbm::particleCollisions::arrayForces
(
    const PtrList<body>& bodies,
    List<vector>& F,
    List<vector>& T,
    const scalar dtHistory
)
{
    const contactModel& law = *model_;
    const scalar range = law.range();
    if (friction_.valid())
    {
        friction_->beginForces(dtHistory);
    }
    // A new orientation of the bodies: their inverse inertia is
    // recomputed at their first contact
    if (nForceCalls_ == labelMax)
    {
        nForceCalls_ = 0;
        invInertiaStamp_ = -1;
    }
    ++nForceCalls_;

    F.setSize(bodies.size());
    F = Zero;
    T.setSize(bodies.size());
    T = Zero;

    // Pairs
    if (bodies.size() > 1)
    {
        search_.search(X_, R_, range);

        for (const labelPair& ij : search_.pairs())
        {
            const label i = ij.first();
            const label j = ij.second();
            if (!round_[i] || !round_[j])
            {
                shapePair(bodies, i, j, F, T);
                continue;
            }
            const vector Fij(law.pairForce(X_[i], R_[i], X_[j], R_[j]));
            F[i] += Fij;
            F[j] -= Fij;
            vector Fn(Fij);
            minPairGap_ = min
            (
                minPairGap_, mag(X_[i] - X_[j]) - R_[i] - R_[j]
            );

            if (dampingRatio_ > 0)
            {
                const scalar mi = mass_[i];
                const scalar mj = mass_[j];
                if (mi == GREAT && mj == GREAT) continue;
                const scalar mr =
                    (mi == GREAT) ? mj : (mj == GREAT) ? mi : mi*mj/(mi + mj);
                const vector n((X_[i] - X_[j])/max(mag(X_[i] - X_[j]), VSMALL));
                const scalar k = depth_*law.pairStiffness(R_[i], R_[j]);
                // Force per unit depth, as the law's (times depth below)
                const vector Fd
                (
                    -(2*dampingRatio_*Foam::sqrt(k*mr)/depth_)
                   *((U_[i] - U_[j]) & n)*n
                );
                F[i] += Fd;
                F[j] -= Fd;
                Fn += Fd;
            }

            if (friction_.valid())
            {
                // At the middle of the gap on the line of centres, the
                // normal force that of the law and the dashpot above
                const vector d(X_[j] - X_[i]);
                const scalar D = max(mag(d), VSMALL);
                const vector n(d/D);
                const vector ri((R_[i] + 0.5*(D - R_[i] - R_[j]))*n);
                const vector rj(ri + X_[i] - X_[j]);
                const vector Ft
                (
                    frictionForce
                    (
                        bodies[i], i, ri, &bodies[j], j, rj, n,
                        max(-(Fn & n), 0.0), law.pairStiffness(R_[i], R_[j])
                    )
                );
                F[i] += Ft;
                F[j] -= Ft;
                T[i] += ri ^ Ft;
                T[j] -= rj ^ Ft;
            }
        }
    }

    // Walls within reach
    forAll(X_, i)
    {
        if (!translates_[i]) continue;

        const point& X = X_[i];
        const scalar R = R_[i];
        forAll(walls_.names(), w)
        {
            const scalar d = walls_.distance(w, X);
            if (d <= 0)
            {
                FatalErrorInFunction
                    << "Body " << bodies[i].name() << " (centre " << X
                    << ") has"
                    << " crossed the wall " << walls_.names()[w]
                    << ": the contact law is too soft for this impact"
                    << " (lower epsWOverlap) or the run has diverged"
                    << exit(FatalError);
            }
            if (d <= R + 0.5*range)
            {
                if (!round_[i])
                {
                    shapeWall(bodies, i, w, d, F, T);
                    continue;
                }
                minWallGap_ = min(minWallGap_, d - R);
                const point Xw(walls_.image(w, X));
                vector Fd(Zero);
                if (dampingRatio_ > 0)
                {
                    const vector n((X - Xw)/max(mag(X - Xw), VSMALL));
                    const scalar k = depth_*law.wallStiffness(R);
                    Fd =
                      - (2*dampingRatio_*Foam::sqrt(k*mass_[i])/depth_)
                       *(U_[i] & n)*n;
                    F[i] += Fd;
                }
                const vector Fw(law.wallForce(X, R, Xw));
                F[i] += Fw;
                if (friction_.valid())
                {
                    // At the body's surface point nearest the wall (the
                    // wall is fixed: no counterpart to share the point
                    // with)
                    const vector& nw = walls_.normals()[w];
                    const vector r(R*nw);
                    const vector Ft
                    (
                        frictionForce
                        (
                            bodies[i], i, r, nullptr, -1 - w, Zero, nw,
                            max(-((Fw + Fd) & nw), 0.0), law.wallStiffness(R)
                        )
                    );
                    F[i] += Ft;
                    T[i] += r ^ Ft;
                }
            }
        }
    }

    if (friction_.valid())
    {
        friction_->endForces();
    }

    forAll(F, i)
    {
        F[i] = translates_[i] ? depth_*F[i] : vector::zero;
    }
    if (anyTorque_)
    {
        forAll(T, i)
        {
            T[i] =
                (subRotates_[i] && bodies[i].rotates())
              ? depth_*T[i] : vector::zero;
        }
    }
}


// ************************************************************************* //
