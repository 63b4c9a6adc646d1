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

#include "hardSphereCollisionKernel.H"
#include "hardSphereInput.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardSphereCollisionKernel::hardSphereCollisionKernel
(
    const dictionary& dict
)
:
    material_(dict.subDict("material")),
    coeffs_(dict.subDict("particleCollision")),
    agglomeration_(agglomerationModel::New(dict, material_, coeffs_)),
    structure_(),
    capAgglomerateSpin_(dict.getOrDefault<bool>("capAgglomerateSpin", false))
{
    hardSphereInput::checkKeys
    (
        dict.subDict("particleCollision"),
        {"en", "et", "muSt", "muKin"}
    );

    if (dict.found("structureModel") || agglomeration_->cohesive())
    {
        structure_ = structureModel::New(dict, material_);
    }

    if (capAgglomerateSpin_)
    {
        Info<< "    capAgglomerateSpin true: agglomerate spin is capped so"
            << " that kinetic energy does not grow (NOT the paper's model;"
            << " breaks angular-momentum conservation)" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::hardSphereCollisionKernel::keys(const dictionary& dict)
{
    wordList valid
    ({
        "material", "particleCollision", "agglomerationModel",
        "structureModel", "capAgglomerateSpin"
    });
    for (const word model : {"agglomerationModel", "structureModel"})
    {
        word type;
        if (dict.readIfPresent(model, type))
        {
            valid.append(type + "Coeffs");
        }
    }
    return valid;
}



const Foam::structureModel&
Foam::hardSphereCollisionKernel::structure() const
{
    if (!structure_.valid())
    {
        FatalErrorInFunction
            << "No structureModel selected" << abort(FatalError);
    }
    return *structure_;
}


void Foam::hardSphereCollisionKernel::collide
(
    const hardSphereState& p1,
    const hardSphereState& p2,
    collisionOutcome& outcome
) const
{
    const binaryCollision pair(p1, p2);

    if (!pair.approaching())
    {
        FatalErrorInFunction
            << "The particles are not approaching: u_n = (u2 - u1).n = "
            << pair.un() << " >= 0. A collision needs u_n < 0."
            << abort(FatalError);
    }

    outcome.reset(agglomeration_->valueNames().size());
    agglomeration_->collide(pair, p1, p2, outcome);

    if (outcome.agglomerates)
    {
        structure().form(pair, p1, p2, capAgglomerateSpin_, outcome);
    }
}


Foam::collisionOutcome Foam::hardSphereCollisionKernel::collide
(
    const hardSphereState& p1,
    const hardSphereState& p2
) const
{
    collisionOutcome outcome;
    collide(p1, p2, outcome);
    return outcome;
}


// ************************************************************************* //
