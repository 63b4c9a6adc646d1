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

#include "thresholdStick.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace agglomerationModels
{
    defineTypeNameAndDebug(thresholdStick, 0);
    addToRunTimeSelectionTable
    (
        agglomerationModel,
        thresholdStick,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerationModels::thresholdStick::thresholdStick
(
    const dictionary& dict,
    const hardSphereMaterial& material,
    const collisionCoefficients& coeffs
)
:
    agglomerationModel(typeName, dict, material, coeffs),
    vStick_(coeffDict_.get<scalar>("vStick"))
{
    checkCoeffs({"vStick"});
    if (!(vStick_ > 0))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "vStick = " << vStick_ << ": it must be > 0 [m/s]"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::wordList&
Foam::agglomerationModels::thresholdStick::branchNames() const
{
    static const wordList names({"rebound", "stick"});
    return names;
}


const Foam::wordList&
Foam::agglomerationModels::thresholdStick::valueNames() const
{
    static const wordList names({"impactSpeed"});
    return names;
}


const Foam::wordList&
Foam::agglomerationModels::thresholdStick::counterNames() const
{
    static const wordList names({"nFastRebounds"});
    return names;
}


const Foam::wordList&
Foam::agglomerationModels::thresholdStick::sumNames() const
{
    static const wordList names({"sumStickSpeed"});
    return names;
}


void Foam::agglomerationModels::thresholdStick::count
(
    const collisionOutcome& outcome,
    UList<label>& counts,
    UList<scalar>& sums
) const
{
    if (outcome.agglomerates)
    {
        sums[0] += outcome.values[0];
    }
    else if (outcome.values[0] > 2*vStick_)
    {
        ++counts[0];
    }
}


void Foam::agglomerationModels::thresholdStick::collide
(
    const binaryCollision& pair,
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    reboundWithoutCohesion(pair, p1, p2, outcome);
    outcome.values[0] = -pair.un();
    outcome.agglomerates = -pair.un() <= vStick_;
    outcome.branch = outcome.agglomerates ? 1 : 0;
}


// ************************************************************************* //
