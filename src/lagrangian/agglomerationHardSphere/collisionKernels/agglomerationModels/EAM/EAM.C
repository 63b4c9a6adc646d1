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

#include "EAM.H"
#include "tensor.H"
#include "addToRunTimeSelectionTable.H"
#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace agglomerationModels
{
    defineTypeNameAndDebug(EAM, 0);
    addToRunTimeSelectionTable(agglomerationModel, EAM, dictionary);
}
}


const Foam::Enum<Foam::agglomerationModels::EAM::projectionType>
Foam::agglomerationModels::EAM::projectionTypeNames
({
    { projectionType::PAPER, "paper" },
    { projectionType::FULL, "full" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerationModels::EAM::EAM
(
    const word& type,
    const dictionary& dict,
    const hardSphereMaterial& material,
    const collisionCoefficients& coeffs,
    const bool alletto2014
)
:
    agglomerationModel(type, dict, material, coeffs),
    impactVelocity_(readImpactVelocity()),
    tangentialProjection_
    (
        projectionTypeNames.getOrDefault
        (
            "tangentialProjection",
            coeffDict_,
            projectionType::PAPER
        )
    ),
    alletto2014_(alletto2014),
    branchNames_
    (
        alletto2014
      ? wordList({"eq21", "caseI", "caseII", "caseIIIrebound"})
      : wordList({"eq21", "eq65", "caseI", "caseII"})
    ),
    valueNames_
    (
        alletto2014
      ? wordList
        ({
            "dEvdW", "EkinPlus", "ErotPlus", "ErotAg", "kn2", "kt2",
            "deltaL", "komega2", "spinClamped"
        })
      : wordList
        ({
            "dEvdW", "EkinPlus", "ErotPlus", "ErotAg", "kn2", "kt2",
            "deltaL"
        })
    ),
    counterNames_
    (
        alletto2014
      ? wordList({"nCaseII", "nSpinClamped"})
      : wordList({"nCaseII"})
    ),
    branchCode_(-1)
{
    const char* family[] =
        {"eq21", "eq65", "caseI", "caseII", "caseIIIrebound"};
    forAll(branchCode_, b)
    {
        branchCode_[b] = branchNames_.find(family[b]);
    }

    if (coeffDict_.found("variant", keyType::LITERAL))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Entry 'variant' in dictionary " << coeffDict_.name()
            << " is not an option of this library: Alletto's original"
            << " model is agglomerationModel EAMAlletto2014" << nl
            << "    Valid entries: (impactVelocity tangentialProjection)"
            << exit(FatalIOError);
    }
    checkCoeffs({"impactVelocity", "tangentialProjection"});

    Info<< "    " << type << ": impactVelocity "
        << impactVelocityTypeNames[impactVelocity_]
        << ", tangentialProjection "
        << projectionTypeNames[tangentialProjection_] << endl;
}


Foam::agglomerationModels::EAM::EAM
(
    const dictionary& dict,
    const hardSphereMaterial& material,
    const collisionCoefficients& coeffs
)
:
    EAM(typeName, dict, material, coeffs, false)
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::agglomerationModels::EAM::dumbbellRotationalEnergy
(
    const vector& L,
    const vector& n,
    const scalar I1,
    const scalar I2,
    const scalar mHat,
    const scalar ell
)
{
    // Closed form of AB16 Eqs. 38-46 (doc/models.md 2.3)
    const scalar Ln2 = sqr(L & n);
    return
        0.5
       *(
            Ln2/(I1 + I2)
          + max(magSqr(L) - Ln2, scalar(0))/(I1 + I2 + mHat*ell*ell)
        );
}


Foam::scalar Foam::agglomerationModels::EAM::dumbbellRotationalEnergySolve
(
    const vector& L,
    const vector& n,
    const scalar I1,
    const scalar I2,
    const scalar mHat,
    const scalar ell
)
{
    // AB16 Eqs. 42-43: I_ag = (I1 + I2) 1 + mHat ell^2 (1 - n n)
    const tensor Iag = (I1 + I2)*I + mHat*ell*ell*(I - sqr(n));

    // AB16 Eqs. 44-46: solve I_ag omega_ag = L
    const vector omegaAg = inv(Iag) & L;

    return 0.5*(omegaAg & L);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::agglomerationModels::EAM::collide
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    // 1. Collision without cohesion (AB16 Sec. 2.2.1)
    reboundWithoutCohesion(pair, p1, p2, outcome);

    // 2.-3. What decides: the energies and factors (AB16 Eqs. 22, 37-46,
    //    55, 58)
    const cohesionEnergies e = energies(pair, p1, p2, outcome);

    // 4. Agglomeration: AB16 Eq. 21, or Eq. 65 (corrected model only)
    if (e.dE >= e.EkinPlus + e.ErotPlus - e.ErotAg)
    {
        outcome.agglomerates = true;
        outcome.branch = branchCode_[EQ21];
        return;
    }
    if (!alletto2014_ && e.kn2 <= 0 && e.kt2 < 0)
    {
        outcome.agglomerates = true;
        outcome.branch = branchCode_[EQ65];
        return;
    }

    // 5. Rebound with cohesion (AB16 Eqs. 47-59; Alletto: Eqs. 60-64)
    reboundWithCohesion(pair, e, outcome);
}


Foam::agglomerationModels::EAM::cohesionEnergies
Foam::agglomerationModels::EAM::energies
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    const hardSphereState& p1Plus = outcome.p1;
    const hardSphereState& p2Plus = outcome.p2;
    const vector& n = pair.n();
    const scalar mHat = pair.mHat();
    const scalar I1 = p1.inertia();
    const scalar I2 = p2.inertia();
    cohesionEnergies e;

    // 2. van-der-Waals energy difference (AB16 Eq. 37)
    const scalar vE = impactSpeed(impactVelocity_, pair);

    e.dE =
        material_.vanDerWaalsEnergy
        (
            coeffs_.en(), p1.d, p1.rho, p2.d, p2.rho, vE
        );

    // 3. Energies after the collision (AB16 Eq. 22) and of the would-be
    //    agglomerate (AB16 Eqs. 38-46; pre-collision L, Eq. 41)
    const vector w = p2Plus.U - p1Plus.U;
    e.EkinPlus = 0.5*mHat*magSqr(w);
    e.ErotPlus =
        0.5*I1*magSqr(p1Plus.omega) + 0.5*I2*magSqr(p2Plus.omega);
    const vector L = pair.angularMomentum(p1, p2);
    e.ErotAg = dumbbellRotationalEnergy(L, n, I1, I2, mHat, pair.ell());

    e.tE = cohesionTangent(pair, w);
    e.wn = w & n;
    e.wt = w & e.tE;
    e.En = 0.5*mHat*e.wn*e.wn;
    e.Et = 0.5*mHat*e.wt*e.wt;

    // AB16 Eq. 55 (En > 0 since e_n > 0 and u_n < 0)
    e.kn2 = 1 - e.dE/e.En;
    e.kt2 = tangentialFactorSqr(e);

    scalarList& value = outcome.values;
    value[DE_VDW] = e.dE;
    value[EKIN_PLUS] = e.EkinPlus;
    value[EROT_PLUS] = e.ErotPlus;
    value[EROT_AG] = e.ErotAg;
    value[KN2] = e.kn2;
    value[KT2] = e.kt2;
    return e;
}


Foam::vector Foam::agglomerationModels::EAM::cohesionTangent
(
    const binaryCollision& pair,
    const vector& w
) const
{
    // doc/models.md 2.5, A4
    if (tangentialProjection_ == projectionType::PAPER)
    {
        return pair.t();
    }
    const vector& n = pair.n();
    const vector wt = w - (w & n)*n;
    const scalar magWt = mag(wt);
    if (magWt > 0)
    {
        return wt/magWt;
    }
    return Zero;
}


Foam::scalar Foam::agglomerationModels::EAM::tangentialFactorSqr
(
    const cohesionEnergies& e
)
{
    // AB16 Eq. 58, only if kn2 <= 0 (doc/models.md 2.4; NaN otherwise,
    // a NaN kn2 included)
    if (!(e.kn2 <= 0))
    {
        return std::numeric_limits<scalar>::quiet_NaN();
    }
    if (e.Et > 0)
    {
        return 1 - (e.dE - e.En)/e.Et;
    }
    return
        e.dE > e.En
      ? -std::numeric_limits<scalar>::infinity()
      : scalar(1);
}


const Foam::wordList& Foam::agglomerationModels::EAM::sumNames() const
{
    static const wordList names({"sumDeltaL"});
    return names;
}


void Foam::agglomerationModels::EAM::count
(
    const collisionOutcome& outcome,
    UList<label>& counts,
    UList<scalar>& sums
) const
{
    if (outcome.branch == branchCode_[CASE_II])
    {
        ++counts[0];
        sums[0] += outcome.values[DELTA_L];
    }
    if (alletto2014_ && outcome.flag(SPIN_CLAMPED))
    {
        ++counts[1];
    }
}


void Foam::agglomerationModels::EAM::writeOptions(Ostream& os) const
{
    agglomerationModel::writeOptions(os);
    os.writeEntry
    (
        "impactVelocity",
        impactVelocityTypeNames[impactVelocity_]
    );
    os.writeEntry
    (
        "tangentialProjection",
        projectionTypeNames[tangentialProjection_]
    );
}


// ************************************************************************* //
