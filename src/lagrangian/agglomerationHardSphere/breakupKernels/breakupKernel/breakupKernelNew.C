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

#include "breakupKernel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::wordList Foam::breakupKernel::types()
{
    return dictionaryConstructorTablePtr_->sortedToc();
}


Foam::autoPtr<Foam::breakupKernel> Foam::breakupKernel::New
(
    const word& type,
    const dictionary& coeffs,
    const hardSphereCollisionKernel& collision
)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(coeffs)
            << "Unknown break-up model " << type << nl << "Valid models: "
            << "none " << types() << exit(FatalIOError);
    }

    autoPtr<breakupKernel> kernel(cstrIter()(coeffs, collision));

    if (kernel->fields().size() > maxFields)
    {
        FatalErrorInFunction
            << "Break-up model " << type << " names the values "
            << kernel->fields() << ": at most " << maxFields
            << " fit the event record" << exit(FatalError);
    }

    return kernel;
}


// ************************************************************************* //
