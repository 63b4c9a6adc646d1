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

#include "vanDriestDampedDelta.H"
#include "hardSphereInput.H"
#include "SubList.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace LESModels
{
    defineTypeNameAndDebug(vanDriestDampedDelta, 0);
    addToRunTimeSelectionTable(LESdelta, vanDriestDampedDelta, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::LESModels::vanDriestDampedDelta::calcDelta()
{
    const fvMesh& mesh = turbulenceModel_.mesh();
    if (!walls_ || mesh.changing())
    {
        walls_.reset(new nearestWallFaces(mesh));
    }
    const nearestWallFaces& walls = walls_();

    const volVectorField& U = turbulenceModel_.U();
    const tmp<volScalarField> tnu = turbulenceModel_.nu();
    const volScalarField& nu = tnu();
    const tmp<volScalarField> tnut = turbulenceModel_.nut();

    // Viscous length y* = nu/u_tau at this rank's wall faces, u_tau^2 =
    // (nu + nu_t)|dU/dn|; then at every wall face of all ranks
    scalarField ystarLocal(walls.nLocal());
    label k = 0;
    for (const label patchi : walls.wallPatches())
    {
        const fvPatchVectorField& Uw = U.boundaryField()[patchi];
        const scalarField& nuw = nu.boundaryField()[patchi];
        const scalarField& nutw = tnut().boundaryField()[patchi];
        const scalarField ystar
        (
            nuw/sqrt((nuw + nutw)*mag(Uw.snGrad()) + VSMALL)
        );
        SubList<scalar>(ystarLocal, ystar.size(), k) = ystar;
        k += ystar.size();
    }
    const scalarField ystar(walls.gather(ystarLocal));

    // Damped where y+ = y/y* of the nearest wall face is below the cut-off
    // of OpenFOAM's van Driest wave (500 here); undamped beyond
    const scalar cutOff = 500;
    const scalar Aplus = Aplus_;
    auto damped = [&](const scalar geo, const scalar y, const label face)
    {
        if (face < 0 || !(y/ystar[face] < cutOff))
        {
            return geo;
        }
        return geo*(scalar(1) - exp(-y/ystar[face]/Aplus));
    };

    const volScalarField& geo = geometricDelta_();
    const volScalarField& y = walls.y();
    scalarField& delta = delta_.primitiveFieldRef();
    forAll(delta, celli)
    {
        delta[celli] = damped(geo[celli], y[celli], walls.cellFace()[celli]);
    }
    volScalarField::Boundary& deltaBf = delta_.boundaryFieldRef();
    forAll(deltaBf, patchi)
    {
        const scalarField& geop = geo.boundaryField()[patchi];
        const scalarField& yp = y.boundaryField()[patchi];
        const labelList& facep = walls.patchFace(patchi);
        scalarField dp(geop.size());
        forAll(dp, i)
        {
            dp[i] = damped(geop[i], yp[i], facep[i]);
        }
        deltaBf[patchi] = dp;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::LESModels::vanDriestDampedDelta::vanDriestDampedDelta
(
    const word& name,
    const turbulenceModel& turbulence,
    const dictionary& dict
)
:
    LESdelta(name, turbulence),
    geometricDelta_
    (
        LESdelta::New
        (
            IOobject::groupName("geometricDelta", turbulence.U().group()),
            turbulence,
            dict.subDict(type() + "Coeffs")
        )
    ),
    Aplus_
    (
        dict.subDict(type() + "Coeffs").getOrDefault<scalar>("Aplus", 25)
    ),
    calcInterval_
    (
        dict.subDict(type() + "Coeffs").getOrDefault<label>
        (
            "calcInterval",
            1
        )
    )
{
    const dictionary& coeffs = dict.subDict(type() + "Coeffs");
    hardSphereInput::checkKeys
    (
        coeffs,
        {
            "delta", coeffs.get<word>("delta") + "Coeffs", "Aplus",
            "calcInterval"
        }
    );

    if (Aplus_ <= 0 || calcInterval_ < 1)
    {
        FatalIOErrorInFunction(dict.subDict(type() + "Coeffs"))
            << "Out of range: Aplus " << Aplus_ << ", calcInterval "
            << calcInterval_ << ". Valid ranges: Aplus > 0,"
            << " calcInterval >= 1" << exit(FatalIOError);
    }

    Info<< "    vanDriestDamped delta: Delta_geo (1 - exp(-y+/A+)), A+ = "
        << Aplus_ << endl;

    delta_ = geometricDelta_();

    // The damped width depends on the flow (U and nu_t at the walls), which
    // the turbulence model does not hold yet while it constructs its delta.
    // It is restart state: written at write times and read back here, so
    // that a restarted run continues with the width of the last step
    // (otherwise its first step would use the undamped width).
    IOobject io
    (
        delta_.name(),
        delta_.time().timeName(),
        delta_.mesh(),
        IOobject::MUST_READ,
        IOobject::AUTO_WRITE,
        false
    );
    if (io.typeHeaderOk<volScalarField>(true))
    {
        delta_ = volScalarField(io, delta_.mesh());
        Info<< "    vanDriestDamped delta: read " << delta_.name()
            << " of time " << delta_.time().timeName() << endl;
    }
    delta_.writeOpt() = IOobject::AUTO_WRITE;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::LESModels::vanDriestDampedDelta::read(const dictionary& dict)
{
    const dictionary& coeffsDict = dict.subDict(type() + "Coeffs");

    geometricDelta_().read(coeffsDict);
    coeffsDict.readIfPresent<scalar>("Aplus", Aplus_);
    coeffsDict.readIfPresent<label>("calcInterval", calcInterval_);

    calcDelta();
}


void Foam::LESModels::vanDriestDampedDelta::correct()
{
    if (turbulenceModel_.mesh().time().timeIndex() % calcInterval_ == 0)
    {
        geometricDelta_().correct();
        calcDelta();
    }
}


// ************************************************************************* //
