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

#include "nearestWallFaces.H"
#include "wallPolyPatch.H"
#include "wallDistData.H"
#include "wallPointData.H"
#include "SubList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::nearestWallFaces::nearestWallFaces(const fvMesh& mesh)
:
    mesh_(mesh),
    remote_(false)
{
    update();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::nearestWallFaces::numberWallFaces()
{
    const polyBoundaryMesh& bm = mesh_.boundaryMesh();

    DynamicList<label> walls;
    label n = 0;
    forAll(bm, patchi)
    {
        if (isA<wallPolyPatch>(bm[patchi]))
        {
            walls.append(patchi);
            n += bm[patchi].size();
        }
    }
    wallPatches_.transfer(walls);
    wallFaces_ = globalIndex(n);
}


Foam::tmp<Foam::volScalarField> Foam::nearestWallFaces::wallFaceLabels()
const
{
    tmp<volScalarField> tface
    (
        new volScalarField
        (
            IOobject
            (
                "nearestWallFace",
                mesh_.time().timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh_,
            dimensionedScalar("nearestWallFace", dimless, -1)
        )
    );
    label k = wallFaces_.offset(Pstream::myProcNo());
    for (const label patchi : wallPatches_)
    {
        scalarField& f = tface.ref().boundaryFieldRef()[patchi];
        forAll(f, i)
        {
            f[i] = k++;
        }
    }
    return tface;
}


void Foam::nearestWallFaces::nearestFaces
(
    const volScalarField& wave,
    const volScalarField& face
)
{
    const polyBoundaryMesh& bm = mesh_.boundaryMesh();

    // A cell or face that the wave did not reach keeps the distance GREAT
    const label start = wallFaces_.offset(Pstream::myProcNo());
    const label end = start + wallFaces_.localSize();
    bool remote = false;
    auto index = [&](const scalar yi, const scalar fi)
    {
        if (yi > 0.5*GREAT || fi < 0)
        {
            return label(-1);
        }
        const label i = label(fi + 0.5);
        remote = remote || i < start || i >= end;
        return i;
    };

    cellFace_.setSize(mesh_.nCells());
    forAll(cellFace_, celli)
    {
        cellFace_[celli] = index(wave[celli], face[celli]);
    }
    patchFace_.setSize(bm.size());
    forAll(bm, patchi)
    {
        const scalarField& yp = wave.boundaryField()[patchi];
        const scalarField& fp = face.boundaryField()[patchi];
        labelList& pf = patchFace_[patchi];
        pf.setSize(yp.size());
        forAll(pf, i)
        {
            pf[i] = index(yp[i], fp[i]);
        }
    }
    remote_ = returnReduce(remote, orOp<bool>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::nearestWallFaces::update()
{
    numberWallFaces();

    // Each wall face carries its global index through the mesh wave
    tmp<volScalarField> tface(wallFaceLabels());
    volScalarField& face = tface.ref();
    const wallDistData<wallPointData<scalar>> wave(mesh_, face);

    y_.reset
    (
        new volScalarField
        (
            IOobject
            (
                "nearestWallDistance",
                mesh_.time().timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            wave
        )
    );
    nearestFaces(wave, face);
}


Foam::scalarField Foam::nearestWallFaces::gather
(
    const scalarField& local
) const
{
    scalarField all(wallFaces_.size(), Zero);
    if (!remote_)
    {
        SubList<scalar>(all, local.size(), wallFaces_.offset
        (
            Pstream::myProcNo()
        )) = local;
        return all;
    }

    List<scalarField> procs(Pstream::nProcs());
    procs[Pstream::myProcNo()] = local;
    Pstream::gatherList(procs);
    Pstream::scatterList(procs);
    forAll(procs, proci)
    {
        SubList<scalar>(all, procs[proci].size(), wallFaces_.offset(proci))
            = procs[proci];
    }
    return all;
}


// ************************************************************************* //
