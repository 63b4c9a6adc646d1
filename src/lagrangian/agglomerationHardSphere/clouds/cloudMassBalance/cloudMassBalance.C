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

#include "cloudMassBalance.H"
#include "cloud.H"
#include "localIOdictionary.H"
#include "PstreamReduceOps.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::cloudMassBalance::lossType>
Foam::cloudMassBalance::lossNames
({
    { lossType::DEPOSITED, "deposited" },
    { lossType::ESCAPED, "escaped" },
});


const Foam::word Foam::cloudMassBalance::recordName("cloudMassBalance");


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::cloudMassBalance::recordIO
(
    const IOobject::readOption r
) const
{
    return IOobject
    (
        recordName,
        mesh_.time().timeName(),
        "uniform"/cloud::prefix/cloudName_,
        mesh_,
        r,
        IOobject::NO_WRITE,
        false
    );
}


void Foam::cloudMassBalance::read()
{
    const IOobject io(recordIO(IOobject::MUST_READ));
    if
    (
        !isFile(io.objectPath())
     && !isFile(io.objectPath() + ".gz")
    )
    {
        return;
    }

    const localIOdictionary record(io);
    massStart_ = record.get<scalar>("massStart");
    nPrimariesStart_ = record.get<label>("nPrimariesStart");
    restarted_ = true;

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(lossNames, typei)
    {
        const dictionary& dict = record.subDict(lossNames.names()[typei]);
        for (const entry& e : dict)
        {
            const label patchi = pbm.findPatchID(e.keyword());
            if (patchi < 0 || patchi >= pbm.nNonProcessor() || !e.isDict())
            {
                FatalIOErrorInFunction(dict)
                    << "Cloud " << cloudName_ << ": the record names '"
                    << e.keyword() << "', which is not a patch of the"
                    << " mesh; the patches are " << pbm.names()
                    << exit(FatalIOError);
            }
            nParcels0_[typei][patchi] = e.dict().get<label>("nParcels");
            nPrimaries0_[typei][patchi] = e.dict().get<label>("nPrimaries");
            mass0_[typei][patchi] = e.dict().get<scalar>("mass");
        }
    }
}


template<class Type>
Type Foam::cloudMassBalance::total
(
    const FixedList<List<Type>, 2>& local,
    const FixedList<List<Type>, 2>& start
)
{
    Type sum = 0;
    Type sum0 = 0;
    forAll(local, typei)
    {
        forAll(local[typei], patchi)
        {
            sum += local[typei][patchi];
            sum0 += start[typei][patchi];
        }
    }
    return sum0 + returnReduce(sum, sumOp<Type>());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cloudMassBalance::cloudMassBalance
(
    const fvMesh& mesh,
    const word& cloudName
)
:
    mesh_(mesh),
    cloudName_(cloudName),
    massStart_(0),
    nPrimariesStart_(0),
    restarted_(false)
{
    // The patches every rank has (processor patches come after them)
    const label nPatches = mesh.boundaryMesh().nNonProcessor();
    forAll(nParcels_, typei)
    {
        nParcels0_[typei].setSize(nPatches, 0);
        nPrimaries0_[typei].setSize(nPatches, 0);
        mass0_[typei].setSize(nPatches, 0);
        nParcels_[typei].setSize(nPatches, 0);
        nPrimaries_[typei].setSize(nPatches, 0);
        mass_[typei].setSize(nPatches, 0);
    }
    read();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cloudMassBalance::depositsOn(const label)
{
    if (depositedMass_.valid())
    {
        return;
    }
    depositedMass_.reset
    (
        new volScalarField
        (
            IOobject
            (
                cloudName_ + ":depositedMass",
                mesh_.time().timeName(),
                mesh_,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            ),
            mesh_,
            dimensionedScalar(dimMass, Zero),
            calculatedFvPatchScalarField::typeName
        )
    );
}


void Foam::cloudMassBalance::lose
(
    const lossType type,
    const label patchi,
    const label patchFacei,
    const label nPrimary,
    const scalar mass
)
{
    ++nParcels_[type][patchi];
    nPrimaries_[type][patchi] += nPrimary;
    mass_[type][patchi] += mass;

    if (type == DEPOSITED && depositedMass_.valid() && patchFacei >= 0)
    {
        depositedMass_->boundaryFieldRef()[patchi][patchFacei] += mass;
    }
}


Foam::scalar Foam::cloudMassBalance::lostMass() const
{
    return total(mass_, mass0_);
}


Foam::label Foam::cloudMassBalance::lostPrimaries() const
{
    return total(nPrimaries_, nPrimaries0_);
}


void Foam::cloudMassBalance::check
(
    const scalar massInFlight,
    const label nPrimariesInFlight,
    const scalar massInjected,
    const label nInjected
) const
{
    const scalar lost = lostMass();
    const label nLost = lostPrimaries();
    const scalar error = massInFlight + lost - massInjected - massStart_;
    const label nError =
        nPrimariesInFlight + nLost - nInjected - nPrimariesStart_;
    const scalar entered = max(massStart_ + massInjected, VSMALL);

    if (nError == 0 && mag(error) <= 1e-11*entered)
    {
        return;
    }

    FatalErrorInFunction
        << "Cloud " << cloudName_ << ": mass balance broken at time "
        << mesh_.time().timeName() << nl
        << "    at the start " << massStart_ << " kg (" << nPrimariesStart_
        << " primaries), injected " << massInjected << " kg (" << nInjected
        << ")" << nl
        << "    in flight " << massInFlight << " kg (" << nPrimariesInFlight
        << "), deposited and escaped " << lost << " kg (" << nLost << ")"
        << nl << "    missing " << -error << " kg (" << -nError
        << " primaries)"
        << (restarted_ ? ": the particles of the start time disagree with"
            " its record " : "")
        << (restarted_ ? recordIO(IOobject::NO_READ).objectPath() : "")
        << exit(FatalError);
}


void Foam::cloudMassBalance::write() const
{
    localIOdictionary record(recordIO(IOobject::NO_READ));
    record.add("massStart", massStart_);
    record.add("nPrimariesStart", nPrimariesStart_);

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(lossNames, typei)
    {
        labelList nParcels(nParcels_[typei]);
        labelList nPrimaries(nPrimaries_[typei]);
        scalarList mass(mass_[typei]);
        Pstream::listCombineGather(nParcels, plusEqOp<label>());
        Pstream::listCombineScatter(nParcels);
        Pstream::listCombineGather(nPrimaries, plusEqOp<label>());
        Pstream::listCombineScatter(nPrimaries);
        Pstream::listCombineGather(mass, plusEqOp<scalar>());
        Pstream::listCombineScatter(mass);

        dictionary dict;
        forAll(nParcels, patchi)
        {
            const label n = nParcels0_[typei][patchi] + nParcels[patchi];
            if (n == 0)
            {
                continue;
            }
            dictionary patchDict;
            patchDict.add("nParcels", n);
            patchDict.add
            (
                "nPrimaries", nPrimaries0_[typei][patchi] + nPrimaries[patchi]
            );
            patchDict.add("mass", mass0_[typei][patchi] + mass[patchi]);
            dict.add(pbm[patchi].name(), patchDict);
        }
        record.add(lossNames.names()[typei], dict);
    }

    record.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        mesh_.time().writeCompression(),
        true
    );
}


void Foam::cloudMassBalance::info(Ostream& os) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(lossNames, typei)
    {
        forAll(nParcels_[typei], patchi)
        {
            const label n =
                nParcels0_[typei][patchi]
              + returnReduce(nParcels_[typei][patchi], sumOp<label>());
            const scalar m =
                mass0_[typei][patchi]
              + returnReduce(mass_[typei][patchi], sumOp<scalar>());
            if (n > 0)
            {
                os  << "    Cloud " << cloudName_ << ": " << n
                    << " parcels (" << m << " kg) "
                    << lossNames.names()[typei] << " at "
                    << pbm[patchi].name() << endl;
            }
        }
    }
}


// ************************************************************************* //
