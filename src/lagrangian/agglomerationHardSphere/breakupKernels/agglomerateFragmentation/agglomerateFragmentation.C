/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           | www.openfoam.com
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2026 agglomerationHardSphere project contributors
-------------------------------------------------------------------------------
License
    This file is part of the agglomerationHardSphere extension of OpenFOAM.

    It is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.

\*---------------------------------------------------------------------------*/

#include "agglomerateFragmentation.H"
#include "hardSphereInput.H"
#include "tensor.H"
#include "mathematicalConstants.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A unit vector uniform on the sphere
Foam::vector randomUnit(Foam::keyedRandom& rnd)
{
    const Foam::scalar z = 2*rnd.sample01() - 1;
    const Foam::scalar phi =
        Foam::constant::mathematical::twoPi*rnd.sample01();
    const Foam::scalar r = std::sqrt(Foam::max(1 - z*z, Foam::scalar(0)));
    return Foam::vector(r*std::cos(phi), r*std::sin(phi), z);
}


//- log of the beta function
Foam::scalar lnBeta(const Foam::scalar a, const Foam::scalar b)
{
    return std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::agglomerateFragmentation::maxTries;

const Foam::Enum<Foam::agglomerateFragmentation::modeType>
Foam::agglomerateFragmentation::modeTypeNames
({
    { modeType::EROSION, "erosion" },
    { modeType::BINARY, "binary" },
    { modeType::BETA, "beta" },
});

const Foam::Enum<Foam::agglomerateFragmentation::directionType>
Foam::agglomerateFragmentation::directionTypeNames
({
    { directionType::EXTENSIONAL, "extensional" },
    { directionType::DEFORMATION_PLANE, "deformationPlane" },
});

const Foam::Enum<Foam::agglomerateFragmentation::spinType>
Foam::agglomerateFragmentation::spinTypeNames
({
    { spinType::CONSERVE_L, "conserveL" },
    { spinType::RIGID_BODY, "rigidBody" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerateFragmentation::agglomerateFragmentation
(
    const dictionary& dict,
    const structureModel& structure,
    const scalar rho0
)
:
    structure_(structure),
    rho0_(rho0),
    mode_(modeTypeNames.get("mode", dict)),
    betaAlpha_(0),
    direction_(directionTypeNames.get("direction", dict)),
    gap_
    (
        hardSphereInput::getInRange
        (
            dict, "gap", hardSphereInput::closed(0),
            hardSphereInput::closed(1)
        )
    ),
    spin_(spinTypeNames.get("spin", dict)),
    tries_(dict.get<label>("tries"))
{
    if (tries_ < 1 || tries_ > maxTries)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'tries' " << tries_ << " in " << dict.name()
            << " is out of range: valid 1-" << maxTries << " (the"
            << " directions tried against overlaps with neighbours,"
            << " doc/breakup.md 3.2)" << exit(FatalIOError);
    }
    wordList valid({"mode", "direction", "gap", "spin", "tries"});
    if (mode_ == modeType::BETA)
    {
        valid.append("betaAlpha");
        betaAlpha_ =
            hardSphereInput::getInRange
            (
                dict, "betaAlpha", hardSphereInput::open(0),
                hardSphereInput::open(GREAT)
            );
    }
    hardSphereInput::checkKeys(dict, valid);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::agglomerateFragmentation::betaProbability
(
    const label k,
    const label nPrimary
) const
{
    const label N = nPrimary;
    if (k < 1 || k > N - 1)
    {
        return 0;
    }
    const scalar a = betaAlpha_;
    auto lnP = [&](const label j)
    {
        return
            std::lgamma(N + 1.0) - std::lgamma(j + 1.0)
          - std::lgamma(N - j + 1.0)
          + lnBeta(j + a, N - j + a) - lnBeta(a, a);
    };
    // Kept to 1 <= k <= N - 1: a split into nothing is no break-up [rec]
    const scalar kept = 1 - 2*std::exp(lnP(0));
    return std::exp(lnP(k))/kept;
}


Foam::label Foam::agglomerateFragmentation::fragmentSize
(
    const label nPrimary,
    keyedRandom& rnd
) const
{
    if (mode_ == modeType::EROSION)
    {
        return 1;
    }
    if (mode_ == modeType::BINARY)
    {
        return nPrimary/2;
    }

    // Inverse of the cumulative law
    const scalar u = rnd.sample01();
    scalar sum = 0;
    for (label k = 1; k < nPrimary - 1; ++k)
    {
        sum += betaProbability(k, nPrimary);
        if (u <= sum)
        {
            return k;
        }
    }
    return nPrimary - 1;
}


Foam::vector Foam::agglomerateFragmentation::inPlane
(
    const symmTensor& S,
    keyedRandom& rnd
)
{
    // Rows of the eigenvectors in the order of ascending eigenvalues
    const tensor V(eigenVectors(S));
    const scalar phi = constant::mathematical::twoPi*rnd.sample01();
    return std::cos(phi)*V.z() + std::sin(phi)*V.x();
}


Foam::vector Foam::agglomerateFragmentation::unitDirection
(
    vector e,
    const vector& omega,
    const bool byRotation,
    keyedRandom& rnd
)
{
    if (byRotation && mag(omega) > VSMALL)
    {
        const vector w(omega/mag(omega));
        e -= (e & w)*w;
        while (mag(e) < 1e-6)
        {
            e = randomUnit(rnd);
            e -= (e & w)*w;
        }
    }
    return e/mag(e);
}


Foam::vector Foam::agglomerateFragmentation::direction
(
    const symmTensor& S,
    const vector& omega,
    const bool byRotation,
    keyedRandom& rnd
) const
{
    vector e(Zero);
    if (mag(S) > VSMALL)
    {
        if (direction_ == directionType::DEFORMATION_PLANE)
        {
            e = inPlane(S, rnd);
        }
        else
        {
            // The most extensional eigenvector, its sign at random
            e = (rnd.sample01() < 0.5 ? -1 : 1)*eigenVectors(S).z();
        }
    }
    else
    {
        e = randomUnit(rnd);
    }
    return unitDirection(e, omega, byRotation, rnd);
}


Foam::vector Foam::agglomerateFragmentation::retryDirection
(
    const vector& e0,
    const symmTensor& S,
    const vector& omega,
    const bool byRotation,
    const label attempt,
    keyedRandom& rnd
) const
{
    if (attempt < 0 || attempt >= tries_)
    {
        FatalErrorInFunction
            << "Placement try " << attempt << " of " << tries_
            << abort(FatalError);
    }
    if (attempt == 0)
    {
        return e0;
    }
    if (attempt == 1)
    {
        return -e0;
    }

    // The further tries: at random in the deformation plane
    // (doc/breakup.md 3.2), at random where the strain rate vanishes
    return unitDirection
    (
        mag(S) > VSMALL ? inPlane(S, rnd) : randomUnit(rnd),
        omega, byRotation, rnd
    );
}


Foam::agglomerateFragmentation::fragments
Foam::agglomerateFragmentation::split
(
    const hardSphereState& parent,
    const label N1,
    const vector& e
) const
{
    using constant::mathematical::pi;

    const label N = parent.nPrimary;
    if (N < 2 || N1 < 1 || N1 > N - 1)
    {
        FatalErrorInFunction
            << "Cannot split " << N << " primaries into " << N1 << " and "
            << N - N1 << abort(FatalError);
    }

    // Sizes from the integer split (doc/breakup.md 3.1): m_i = N_i m_p
    const scalar M = parent.mass();
    const scalar dp = parent.primaryDiameter(rho0_);
    fragments f;
    hardSphereState* frag[2] = {&f.a, &f.b};
    const label Ni[2] = {N1, N - N1};
    for (label i = 0; i < 2; ++i)
    {
        hardSphereState& s = *frag[i];
        s.nPrimary = Ni[i];
        s.rho = structure_.density(Ni[i]);
        s.d = std::cbrt(6*(M*Ni[i]/N)/(pi*s.rho));
    }
    const scalar m1 = f.a.mass();
    const scalar m2 = f.b.mass();
    const scalar m12 = m1 + m2;

    // Placement on the line through the centre of mass [rec]
    const scalar s = 0.5*(f.a.d + f.b.d) + gap_*dp;
    const vector r1(-(m2/m12)*s*e);
    const vector r2((m1/m12)*s*e);
    f.a.x = parent.x + r1;
    f.b.x = parent.x + r2;

    // Spin and velocities [rec, doc/breakup.md 3.3]
    vector omegaNew(parent.omega);
    if (spin_ == spinType::CONSERVE_L)
    {
        const tensor J =
            (f.a.inertia() + f.b.inertia())*tensor::I
          + m1*(magSqr(r1)*tensor::I - sqr(r1))
          + m2*(magSqr(r2)*tensor::I - sqr(r2));
        omegaNew = inv(J) & (parent.inertia()*parent.omega);
    }
    f.a.omega = omegaNew;
    f.b.omega = omegaNew;
    f.a.U = parent.U + (omegaNew ^ r1);
    f.b.U = parent.U + (omegaNew ^ r2);

    f.dKE = f.a.kineticEnergy() + f.b.kineticEnergy()
          - parent.kineticEnergy();
    return f;
}


void Foam::agglomerateFragmentation::write(Ostream& os) const
{
    os  << "fragmentation: mode " << modeTypeNames[mode_];
    if (mode_ == modeType::BETA)
    {
        os  << " (betaAlpha " << betaAlpha_ << ")";
    }
    os  << ", direction " << directionTypeNames[direction_] << ", gap "
        << gap_ << ", spin " << spinTypeNames[spin_] << ", tries "
        << tries_;
}


// ************************************************************************* //
