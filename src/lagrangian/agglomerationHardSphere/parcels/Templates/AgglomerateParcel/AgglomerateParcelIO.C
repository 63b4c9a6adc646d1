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

#include "AgglomerateParcel.H"
#include "agglomerateParcelFieldIO.H"
#include "IOPosition.H"
#include "IOstreams.H"
#include "IOField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::AgglomerateParcel<ParcelType>::propertyList_ =
    Foam::AgglomerateParcel<ParcelType>::propertyList();


template<class ParcelType>
const std::size_t Foam::AgglomerateParcel<ParcelType>::sizeofFields
(
    sizeof(AgglomerateParcel<ParcelType>) - sizeof(ParcelType)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::AgglomerateParcel<ParcelType>::AgglomerateParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    omega_(Zero),
    lastContactTime_(-GREAT),
    nPrimary_(1),
    lastPartnerProc_(-1),
    lastPartnerId_(-1),
    stage_()
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is  >> omega_ >> lastContactTime_ >> nPrimary_
                >> lastPartnerProc_ >> lastPartnerId_ >> stage_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native label or scalar size

            is.beginRawRead();

            readRawScalar(is, omega_.data(), vector::nComponents);
            readRawScalar(is, &lastContactTime_);
            readRawLabel(is, &nPrimary_);
            readRawLabel(is, &lastPartnerProc_);
            readRawLabel(is, &lastPartnerId_);
            stage_.readRaw(is);

            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&omega_), sizeofFields);
        }
    }
    else
    {
        // Fields come from the separate field files (readFields)
        stage_.reset(this->position());
    }

    is.check(FUNCTION_NAME);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class CloudType>
void Foam::AgglomerateParcel<ParcelType>::readOtherPositionForm(CloudType& c)
{
    if (c.size())
    {
        return;
    }

    for
    (
        const cloud::geometryType geom
      : {cloud::geometryType::COORDINATES, cloud::geometryType::POSITIONS}
    )
    {
        IOPosition<Cloud<AgglomerateParcel<ParcelType>>> ioP(c, geom);
        if (!ioP.headerOk())
        {
            continue;
        }
        Istream& is = ioP.readStream("", true);
        ioP.readData(is, c);
        ioP.close();

        if (c.size())
        {
            Pout<< "    Cloud " << c.name() << ": read " << c.size()
                << " particles from " << ioP.objectPath() << endl;
            break;
        }
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::AgglomerateParcel<ParcelType>::readFields(CloudType& c)
{
    readOtherPositionForm(c);
    ParcelType::readFields(c);

    // Optional: a stock kinematic cloud result still loads, as primaries
    // at rest in rotation without a previous partner
    using agglomerateParcelIO::readOptional;

    tmp<IOField<vector>> omega = readOptional<vector>(c, "omega");
    tmp<IOField<label>> nPrimary = readOptional<label>(c, "nPrimary");
    tmp<IOField<label>> lastProc = readOptional<label>(c, "lastPartnerProc");
    tmp<IOField<label>> lastId = readOptional<label>(c, "lastPartnerId");
    tmp<IOField<scalar>> lastTime =
        readOptional<scalar>(c, "lastContactTime");

    // No particle read, but particle fields on file: a position file (or
    // its list) is missing or empty
    if (c.size() == 0)
    {
        IOobject io(c.fieldIOobject("d", IOobject::READ_IF_PRESENT));
        if (io.typeHeaderOk<IOField<scalar>>(true))
        {
            const IOField<scalar> d(io);
            if (d.size())
            {
                FatalErrorInFunction
                    << "Cloud " << c.name() << ": " << d.objectPath()
                    << " lists " << d.size() << " particles, but no"
                    << " particle position was read (the coordinates or"
                    << " positions file is missing or empty)"
                    << exit(FatalError);
            }
        }
    }

    label i = 0;
    for (AgglomerateParcel<ParcelType>& p : c)
    {
        p.omega_ = omega().size() ? omega()[i] : Zero;
        p.nPrimary_ = nPrimary().size() ? nPrimary()[i] : 1;
        p.lastPartnerProc_ = lastProc().size() ? lastProc()[i] : -1;
        p.lastPartnerId_ = lastId().size() ? lastId()[i] : -1;
        p.lastContactTime_ = lastTime().size() ? lastTime()[i] : -GREAT;
        p.stage_.reset(p.position());

        // Particle fields, checked when read
        using agglomerateParcelIO::checkValue;
        using agglomerateParcelIO::finite;
        checkValue(c, p.nPrimary_ >= 1, "nPrimary", i, p.nPrimary_, ">= 1");
        checkValue
        (
            c, std::isfinite(p.d()) && p.d() > 0, "d", i, p.d(),
            "finite, > 0"
        );
        checkValue
        (
            c, std::isfinite(p.rho()) && p.rho() > 0, "rho", i, p.rho(),
            "finite, > 0"
        );
        checkValue(c, finite(p.U()), "U", i, p.U(), "finite");
        checkValue(c, finite(p.omega_), "omega", i, p.omega_, "finite");

        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::AgglomerateParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();

    IOField<vector> omega(c.fieldIOobject("omega", IOobject::NO_READ), np);
    IOField<label> nPrimary
    (
        c.fieldIOobject("nPrimary", IOobject::NO_READ),
        np
    );
    IOField<label> lastProc
    (
        c.fieldIOobject("lastPartnerProc", IOobject::NO_READ),
        np
    );
    IOField<label> lastId
    (
        c.fieldIOobject("lastPartnerId", IOobject::NO_READ),
        np
    );
    IOField<scalar> lastTime
    (
        c.fieldIOobject("lastContactTime", IOobject::NO_READ),
        np
    );

    label i = 0;
    for (const AgglomerateParcel<ParcelType>& p : c)
    {
        omega[i] = p.omega_;
        nPrimary[i] = p.nPrimary_;
        lastProc[i] = p.lastPartnerProc_;
        lastId[i] = p.lastPartnerId_;
        lastTime[i] = p.lastContactTime_;

        ++i;
    }

    omega.write(np > 0);
    nPrimary.write(np > 0);
    lastProc.write(np > 0);
    lastId.write(np > 0);
    lastTime.write(np > 0);
}


template<class ParcelType>
void Foam::AgglomerateParcel<ParcelType>::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    ParcelType::writeProperties(os, filters, delim, namesOnly);

    #undef  writeProp
    #define writeProp(Name, Value)                                            \
        ParcelType::writeProperty(os, Name, Value, namesOnly, delim, filters)

    writeProp("omega", omega_);
    writeProp("nPrimary", nPrimary_);
    writeProp("lastPartnerProc", lastPartnerProc_);
    writeProp("lastPartnerId", lastPartnerId_);
    writeProp("lastContactTime", lastContactTime_);

    #undef writeProp
}


template<class ParcelType>
template<class CloudType>
void Foam::AgglomerateParcel<ParcelType>::readObjects
(
    CloudType& c,
    const objectRegistry& obr
)
{
    ParcelType::readObjects(c, obr);

    if (!c.size()) return;

    const auto& omega = cloud::lookupIOField<vector>("omega", obr);
    const auto& nPrimary = cloud::lookupIOField<label>("nPrimary", obr);
    const auto& lastProc =
        cloud::lookupIOField<label>("lastPartnerProc", obr);
    const auto& lastId = cloud::lookupIOField<label>("lastPartnerId", obr);
    const auto& lastTime =
        cloud::lookupIOField<scalar>("lastContactTime", obr);

    label i = 0;
    for (AgglomerateParcel<ParcelType>& p : c)
    {
        p.omega_ = omega[i];
        p.nPrimary_ = nPrimary[i];
        p.lastPartnerProc_ = lastProc[i];
        p.lastPartnerId_ = lastId[i];
        p.lastContactTime_ = lastTime[i];

        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::AgglomerateParcel<ParcelType>::writeObjects
(
    const CloudType& c,
    objectRegistry& obr
)
{
    ParcelType::writeObjects(c, obr);

    const label np = c.size();

    auto& omega = cloud::createIOField<vector>("omega", np, obr);
    auto& nPrimary = cloud::createIOField<label>("nPrimary", np, obr);
    auto& lastProc = cloud::createIOField<label>("lastPartnerProc", np, obr);
    auto& lastId = cloud::createIOField<label>("lastPartnerId", np, obr);
    auto& lastTime =
        cloud::createIOField<scalar>("lastContactTime", np, obr);

    label i = 0;
    for (const AgglomerateParcel<ParcelType>& p : c)
    {
        omega[i] = p.omega_;
        nPrimary[i] = p.nPrimary_;
        lastProc[i] = p.lastPartnerProc_;
        lastId[i] = p.lastPartnerId_;
        lastTime[i] = p.lastContactTime_;

        ++i;
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const AgglomerateParcel<ParcelType>& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const ParcelType&>(p)
            << token::SPACE << p.omega()
            << token::SPACE << p.lastContactTime()
            << token::SPACE << p.nPrimary()
            << token::SPACE << p.lastPartner().first()
            << token::SPACE << p.lastPartner().second()
            << token::SPACE << p.stage_;
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.omega_),
            AgglomerateParcel<ParcelType>::sizeofFields
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
