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

#include "MAM.H"
#include "hardSphereInput.H"
#include "addToRunTimeSelectionTable.H"

using namespace Foam::hardSphereInput;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace agglomerationModels
{
    defineTypeNameAndDebug(MAM, 0);
    addToRunTimeSelectionTable(agglomerationModel, MAM, dictionary);
}
}


const Foam::scalar Foam::agglomerationModels::MAM::CH = 1.4341328496;


const Foam::Enum<Foam::agglomerationModels::MAM::closureType>
Foam::agglomerationModels::MAM::closureTypeNames
({
    { closureType::TABLE4, "table4" },
    { closureType::HERTZ_REBOUND, "hertzRebound" },
});


const Foam::Enum<Foam::agglomerationModels::MAM::frictionTimeType>
Foam::agglomerationModels::MAM::frictionTimeTypeNames
({
    { frictionTimeType::HERTZ_PLUS_DIF, "hertzPlusDif" },
    { frictionTimeType::HERTZ, "hertz" },
});


const Foam::Enum<Foam::agglomerationModels::MAM::slidingCriterionType>
Foam::agglomerationModels::MAM::slidingCriterionTypeNames
({
    { slidingCriterionType::SLIP_STOPS, "slipStops" },
    { slidingCriterionType::NONE, "none" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerationModels::MAM::MAM
(
    const dictionary& dict,
    const hardSphereMaterial& material,
    const collisionCoefficients& coeffs
)
:
    agglomerationModel(typeName, dict, material, coeffs),
    impactVelocity_(readImpactVelocity()),
    closure_
    (
        closureTypeNames.getOrDefault
        (
            "closure",
            coeffDict_,
            closureType::TABLE4
        )
    ),
    Cg_(2.3421),
    ag_(0.3),
    frictionContactTime_
    (
        frictionTimeTypeNames.getOrDefault
        (
            "frictionContactTime",
            coeffDict_,
            frictionTimeType::HERTZ_PLUS_DIF
        )
    ),
    slidingCriterion_
    (
        slidingCriterionTypeNames.getOrDefault
        (
            "slidingCriterion",
            coeffDict_,
            slidingCriterionType::SLIP_STOPS
        )
    )
{
    checkCoeffs
    ({
        "impactVelocity", "closure", "table4Coeffs", "frictionContactTime",
        "slidingCriterion"
    });

    if (coeffDict_.found("table4Coeffs"))
    {
        const dictionary& t4 = coeffDict_.subDict("table4Coeffs");
        hardSphereInput::checkKeys(t4, {"Cg", "ag"});
        Cg_ = getInRange(t4, "Cg", open(0), open(GREAT));
        ag_ = getInRange(t4, "ag", open(0), open(GREAT));
    }

    Info<< "    MAM: impactVelocity "
        << impactVelocityTypeNames[impactVelocity_]
        << ", closure " << closureTypeNames[closure_];
    if (closure_ == closureType::TABLE4)
    {
        Info<< " (Cg " << Cg_ << ", ag " << ag_ << ")";
    }
    Info<< ", frictionContactTime "
        << frictionTimeTypeNames[frictionContactTime_]
        << ", slidingCriterion "
        << slidingCriterionTypeNames[slidingCriterion_] << endl;

    // doc/models.md 5.3, A13
    if (coeffs_.muKin() <= coeffs_.muSt()/(1 + coeffs_.et()))
    {
        Info<< "    MAM: muKin <= muSt/(1 + et): with these coefficients"
            << " only sticking collisions can agglomerate"
            << " (doc/models.md 5.3, A13)" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::agglomerationModels::MAM::g(const scalar en) const
{
    if (closure_ == closureType::TABLE4)
    {
        return Cg_*(std::pow(en, -ag_) - 1);
    }

    return CH*(std::pow(en, -0.2) - 1);
}


Foam::scalar Foam::agglomerationModels::MAM::hertzTimeScale
(
    const scalar mHat,
    const scalar d1,
    const scalar d2,
    const scalar v
) const
{
    // AB16 Eq. 71 (reconstructed, doc/models.md 3.2)
    const scalar RHat = 0.5*d1*d2/(d1 + d2);
    const scalar EHat = material_.EHat();
    return std::pow(mHat*mHat/(RHat*EHat*EHat*v), 0.2);
}


Foam::scalar Foam::agglomerationModels::MAM::vanDerWaalsForce
(
    const scalar d1,
    const scalar d2
) const
{
    return material_.vanDerWaalsForce(d1, d2);
}


const Foam::wordList&
Foam::agglomerationModels::MAM::branchNames() const
{
    static const wordList names({"rebound", "agglomerate"});
    return names;
}


const Foam::wordList&
Foam::agglomerationModels::MAM::valueNames() const
{
    static const wordList names
    ({
        "fnc", "fncStar", "tStar", "critI", "critII"
    });
    return names;
}


const Foam::wordList&
Foam::agglomerationModels::MAM::counterNames() const
{
    static const wordList names({"nMAMslidingCritII"});
    return names;
}


void Foam::agglomerationModels::MAM::count
(
    const collisionOutcome& outcome,
    UList<label>& counts,
    UList<scalar>&
) const
{
    if
    (
        !outcome.isSticking()
     && outcome.flag(CRIT_I)
     && outcome.flag(CRIT_II)
    )
    {
        ++counts[0];
    }
}


void Foam::agglomerationModels::MAM::collide
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    const scalar en = coeffs_.en();
    const scalar mHat = pair.mHat();
    const scalar magUn = -pair.un();

    // AB16 Eq. 5
    const scalar fna = pair.fna(en);

    // AB16 Eqs. 67-74 (reconstructed)
    const scalar vM = impactSpeed(impactVelocity_, pair);
    const scalar tStar = hertzTimeScale(mHat, p1.d, p2.d, vM);
    const scalar dtComp = CH*tStar;
    const scalar dtDif = g(en)*tStar;
    const scalar dt =
        frictionContactTime_ == frictionTimeType::HERTZ_PLUS_DIF
      ? 2*dtComp + dtDif
      : 2*dtComp;

    const scalar F = vanDerWaalsForce(p1.d, p2.d);
    const scalar fnc = F*dt/mHat;
    const scalar fncStar = F*dtDif/mHat;

    // AB16 Eq. 76 and Eq. 75 (i), (ii)
    const scalar fF = fna + fnc;
    const bool isSticking = pair.sticking(coeffs_, fF);
    const bool critI = fncStar >= en*magUn;
    const bool critII = pair.s() <= 3.5*coeffs_.muKin()*fF;

    outcome.type =
        isSticking ? collisionOutcome::STICKING : collisionOutcome::SLIDING;
    outcome.fna = fna;
    outcome.values[FNC] = fnc;
    outcome.values[FNC_STAR] = fncStar;
    outcome.values[T_STAR] = tStar;
    outcome.setFlag(CRIT_I, critI);
    outcome.setFlag(CRIT_II, critII);
    outcome.p1 = p1;
    outcome.p2 = p2;

    if
    (
        critI
     && (
            isSticking
         || critII
         || slidingCriterion_ == slidingCriterionType::NONE
        )
    )
    {
        outcome.agglomerates = true;
        outcome.branch = AGGLOMERATE;
        return;
    }

    // AB16 Eqs. 77-79: rebound with the cohesive impulses
    bool stick = isSticking;
    const vector fHat = pair.impulse(coeffs_, fna - fncStar, fF, stick);

    outcome.agglomerates = false;
    outcome.branch = REBOUND;
    pair.apply(fHat, outcome.p1, outcome.p2);
}


void Foam::agglomerationModels::MAM::writeOptions(Ostream& os) const
{
    agglomerationModel::writeOptions(os);
    os.writeEntry("impactVelocity", impactVelocityTypeNames[impactVelocity_]);
    os.writeEntry("closure", closureTypeNames[closure_]);
    os.writeEntry("Cg", Cg_);
    os.writeEntry("ag", ag_);
    os.writeEntry
    (
        "frictionContactTime",
        frictionTimeTypeNames[frictionContactTime_]
    );
    os.writeEntry
    (
        "slidingCriterion",
        slidingCriterionTypeNames[slidingCriterion_]
    );
}


// ************************************************************************* //
