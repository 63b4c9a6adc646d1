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

#include "hardSphereWallInteraction.H"
#include "wallPolyPatch.H"
#include "particleKeyedModel.H"
#include "hardSphereInput.H"
#include "randomStreams.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::hardSphereWallInteraction::contactType>
Foam::hardSphereWallInteraction::contactNames
({
    { contactType::RADIUS, "radius" },
    { contactType::CENTRE, "centre" },
});


const Foam::Enum<Foam::hardSphereWallInteraction::correctionType>
Foam::hardSphereWallInteraction::correctionNames
({
    { correctionType::REFLECT, "reflect" },
    { correctionType::NONE, "none" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::hardSphereWallInteraction::resultType
Foam::hardSphereWallInteraction::contact
(
    const label patchi,
    const label patchFacei,
    const vector& nw,
    particle& p,
    const scalar eventFraction
) const
{
    const vector& Uw = Uc_.boundaryField()[patchi][patchFacei];
    const wallCollisionModel& model = models_[patchi];
    keyedRandom rnd
    (
        randomSeed_, randomStreams::wallImpact, p.origProc, p.origId,
        mesh_.time().timeIndex(), eventFraction
    );

    if (model.deposits(nw, Uw, p.d, p.U, rnd))
    {
        balance_.lose
        (
            cloudMassBalance::DEPOSITED, patchi, patchFacei, p.nPrimary,
            p.mass
        );
        p.deposited = true;
        return DEPOSIT;
    }

    if (((p.U - Uw) & nw) >= 0)
    {
        return OVERLAP;
    }

    p.impactSpeed = -((p.U - Uw) & nw);
    model.impact(nw, Uw, p.d, p.U, p.omega, rnd);

    if (reflectSGS_ && p.UTurb)
    {
        particleKeyedModel::reflect(*p.UTurb, nw);
    }
    return IMPACT;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::hardSphereWallInteraction::hardSphereWallInteraction
(
    const dictionary& dict,
    const volVectorField& Uc,
    const particleKeyedModel* keyedDispersion,
    cloudMassBalance& balance
)
:
    mesh_(Uc.mesh()),
    Uc_(Uc),
    balance_(balance),
    models_(),
    contact_(contactNames.getOrDefault("wallContact", dict, RADIUS)),
    correction_
    (
        correctionNames.getOrDefault("wallPositionCorrection", dict, REFLECT)
    ),
    randomSeed_(hardSphereInput::getSeed(dict)),
    reflectSGS_(keyedDispersion && keyedDispersion->reflectAtWalls())
{
    // One wall model per wall patch
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    models_.setSize(pbm.size());

    const dictionary& wallsDict = dict.subDict("walls");

    forAll(pbm, patchi)
    {
        if (!isA<wallPolyPatch>(pbm[patchi]))
        {
            continue;
        }

        const entry* ePtr =
            wallsDict.findEntry(pbm[patchi].name(), keyType::REGEX);

        if (!ePtr || !ePtr->isDict())
        {
            FatalIOErrorInFunction(wallsDict)
                << "No wall model for the wall patch "
                << pbm[patchi].name() << ": add a dictionary entry "
                << pbm[patchi].name() << " (or a matching regular"
                << " expression) to walls. Wall models: "
                << wallCollisionModel::
                   dictionaryConstructorTablePtr_->sortedToc()
                << exit(FatalIOError);
        }

        Info<< "    Wall patch " << pbm[patchi].name() << ": wallModel "
            << ePtr->dict().get<word>("wallModel") << endl;

        models_.set(patchi, wallCollisionModel::New(ePtr->dict()));
        if (models_[patchi].depositing())
        {
            balance_.depositsOn(patchi);
        }
    }

    // Every entry of walls names at least one wall patch and is a valid
    // wall model: a misspelt patch name would otherwise leave its patch
    // to another entry (or ".*") silently
    wordList wallNames;
    forAll(pbm, patchi)
    {
        if (isA<wallPolyPatch>(pbm[patchi]))
        {
            wallNames.append(pbm[patchi].name());
        }
    }
    for (const entry& e : wallsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(wallsDict)
                << "walls entry " << e.keyword() << " is not a dictionary"
                << " with a wallModel" << exit(FatalIOError);
        }
        bool matches = false;
        for (const word& w : wallNames)
        {
            matches = matches || e.keyword().match(w);
        }
        if (!matches)
        {
            FatalIOErrorInFunction(wallsDict)
                << "walls entry " << e.keyword() << " matches no wall"
                << " patch; the wall patches are " << wallNames
                << exit(FatalIOError);
        }
        wallCollisionModel::New(e.dict());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::hardSphereWallInteraction::wallFaces
(
    const polyMesh& mesh
)
{
    DynamicList<label> faces;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wallPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                faces.append(pp.start() + i);
            }
        }
    }
    return labelList(std::move(faces));
}


Foam::hardSphereWallInteraction::resultType
Foam::hardSphereWallInteraction::contactAtRadius
(
    const point& x,
    const labelUList& wallFaces,
    const scalar dt,
    particle& p,
    bool& moved,
    point& xNew
) const
{
    moved = false;

    if (wallFaces.empty())
    {
        return NO_CONTACT;
    }

    const scalar r = 0.5*p.d;

    // Nearest wall face
    scalar h = GREAT;
    label nearestFace = -1;
    point nearest(Zero);
    for (const label facei : wallFaces)
    {
        const pointHit ph =
            mesh_.faces()[facei].nearestPoint(x, mesh_.points());

        if (ph.distance() < h)
        {
            h = ph.distance();
            nearestFace = facei;
            nearest = ph.rawPoint();
        }
    }

    if (h >= r)
    {
        return NO_CONTACT;
    }

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const label patchi = pbm.whichPatch(nearestFace);
    const polyPatch& pp = pbm[patchi];
    const label patchFacei = pp.whichFace(nearestFace);

    vector nw(x - nearest);
    if (h > SMALL*r)
    {
        nw /= h;
    }
    else
    {
        nw = -pp.faceNormals()[patchFacei];
    }

    const vector U0(p.U);
    const resultType result = contact(patchi, patchFacei, nw, p, 2.0);

    if (result == DEPOSIT || correction_ != REFLECT)
    {
        return result;
    }

    moved = true;
    if (result == IMPACT)
    {
        // Back to the contact, then on with the new velocity
        const vector& Uw = Uc_.boundaryField()[patchi][patchFacei];
        const scalar un = (U0 - Uw) & nw;
        const scalar tau = min((r - h)/(-un), dt);
        xNew = x + tau*(p.U - U0);
    }
    else
    {
        // Overlapping without approaching: out to one radius
        xNew = x + (r - h)*nw;
    }
    return result;
}


Foam::hardSphereWallInteraction::resultType
Foam::hardSphereWallInteraction::hitCentre
(
    const label facei,
    particle& p,
    const scalar f
) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const label patchi = pbm.whichPatch(facei);
    const polyPatch& pp = pbm[patchi];
    const label patchFacei = pp.whichFace(facei);

    const resultType result =
        contact(patchi, patchFacei, -pp.faceNormals()[patchFacei], p, f);

    // Moving away from the face: nothing happens
    return result == OVERLAP ? NO_CONTACT : result;
}


void Foam::hardSphereWallInteraction::info(Ostream& os) const
{
    os  << "wallContact " << contactNames[contact_]
        << ", wallPositionCorrection " << correctionNames[correction_];
}


// ************************************************************************* //
