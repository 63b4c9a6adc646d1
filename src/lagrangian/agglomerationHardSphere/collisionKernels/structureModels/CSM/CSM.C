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

#include "CSM.H"
#include "hardSphereInput.H"
#include "Tuple2.H"
#include "addToRunTimeSelectionTable.H"

using namespace Foam::hardSphereInput;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace structureModels
{
    defineTypeNameAndDebug(CSM, 0);
    addToRunTimeSelectionTable(structureModel, CSM, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace
{
    //- f_pack beyond the table (doc/models.md 4.3)
    const Foam::scalar fPackLargeDefault = 0.52;
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalarList Foam::structureModels::CSM::defaultPackingFractions()
{
    // doc/models.md 4.3: N = 2-4 AB16 (truncated to 5 decimals),
    // N = 5-30 reconstructed (multistart optimisation)
    static const scalar table[] =
    {
        1, 1,
        0.26683, 0.31574, 0.42099, 0.38507, 0.42841, 0.45890, 0.52360,
        0.47106, 0.41216, 0.41239, 0.44653, 0.48374, 0.52095, 0.44686,
        0.45022, 0.47836, 0.49845, 0.48923, 0.47572, 0.47319, 0.47831,
        0.48356, 0.49221, 0.49445, 0.50459, 0.52360, 0.48210, 0.49932,
        0.51654
    };

    const label n = sizeof(table)/sizeof(table[0]);
    scalarList f(n);
    for (label i = 0; i < n; ++i)
    {
        f[i] = table[i];
    }
    return f;
}


Foam::scalar Foam::structureModels::CSM::defaultPackingFraction
(
    const label nPrimary
)
{
    static const scalarList f(defaultPackingFractions());
    if (nPrimary <= 1)
    {
        return 1;
    }
    return nPrimary < f.size() ? f[nPrimary] : fPackLargeDefault;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::structureModels::CSM::CSM
(
    const dictionary& dict,
    const hardSphereMaterial& material
)
:
    structureModel(typeName, dict, material),
    fPack_(defaultPackingFractions()),
    fPackLarge_(fPackLargeDefault)
{
    checkCoeffs({"fPackLarge", "packingFractions"});

    if (coeffDict_.found("fPackLarge"))
    {
        fPackLarge_ = getInRange(coeffDict_, "fPackLarge", open(0), open(1));
    }

    if (coeffDict_.found("packingFractions"))
    {
        const List<Tuple2<label, scalar>> user
        (
            coeffDict_.get<List<Tuple2<label, scalar>>>("packingFractions")
        );

        fPack_.setSize(user.size() + 2);
        fPack_[0] = 1;
        fPack_[1] = 1;
        forAll(user, i)
        {
            if (user[i].first() != i + 2)
            {
                FatalIOErrorInFunction(coeffDict_)
                    << "Entry 'packingFractions' must list N = 2, 3, 4, ..."
                    << " in order without gaps; entry " << i
                    << " has N = " << user[i].first()
                    << " (expected " << i + 2 << ")"
                    << exit(FatalIOError);
            }
            checkInRange
            (
                coeffDict_,
                "packingFractions",
                user[i].second(),
                open(0),
                open(1)
            );
            fPack_[i + 2] = user[i].second();
        }
    }

    // d_ag/d0 = (N/f_pack)^(1/3) must not decrease with N (section 4.3);
    // equal optima (e.g. N = 3, 4) may differ by the 5-decimal rounding
    const label nTable = fPack_.size();
    scalar prev = 1;
    for (label N = 2; N <= nTable; ++N)
    {
        const scalar ratio = std::cbrt(N/packingFraction(N));
        if (ratio < prev*(1 - 1e-4))
        {
            FatalIOErrorInFunction(coeffDict_)
                << "Packing fractions give a decreasing agglomerate"
                << " diameter: d_ag/d0 = " << ratio << " at N = " << N
                << " < " << prev << " at N = " << N - 1 << nl
                << "    Check 'packingFractions' and 'fPackLarge'"
                << exit(FatalIOError);
        }
        prev = ratio;
    }

    Info<< "    CSM: packing fractions tabulated for N = 2.."
        << nTable - 1 << ", fPackLarge " << fPackLarge_ << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::structureModels::CSM::packingFraction
(
    const label nPrimary
) const
{
    if (nPrimary <= 1)
    {
        return 1;
    }
    if (nPrimary < fPack_.size())
    {
        return fPack_[nPrimary];
    }
    return fPackLarge_;
}


// ************************************************************************* //
