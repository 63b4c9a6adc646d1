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

#include "globalPatchTriangles.H"
#include "triPointRef.H"
#include "Pstream.H"
#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::globalPatchTriangles::gather
(
    const polyMesh& mesh,
    const label patchi,
    const scalarField& faceWeights,
    DynamicList<point>& pts,
    DynamicList<label>& procs,
    DynamicList<label>& faces,
    DynamicList<scalar>& weights
)
{
    const polyPatch& pp = mesh.boundaryMesh()[patchi];
    const pointField& meshPoints = mesh.points();

    // This rank's triangles: a fan about each face's first point
    DynamicList<point> localPoints;
    DynamicList<label> localFaces;
    DynamicList<scalar> localWeights;
    forAll(pp, facei)
    {
        const face& f = pp[facei];
        for (label i = 1; i + 1 < f.size(); ++i)
        {
            localPoints.append(meshPoints[f[0]]);
            localPoints.append(meshPoints[f[i]]);
            localPoints.append(meshPoints[f[i + 1]]);
            localFaces.append(facei);
            localWeights.append
            (
                faceWeights.empty() ? scalar(1) : faceWeights[facei]
            );
        }
    }

    // All ranks' triangles on every rank
    List<List<point>> allPoints(Pstream::nProcs());
    List<labelList> allFaces(Pstream::nProcs());
    List<scalarList> allWeights(Pstream::nProcs());
    allPoints[Pstream::myProcNo()] = localPoints;
    allFaces[Pstream::myProcNo()] = localFaces;
    allWeights[Pstream::myProcNo()] = localWeights;
    Pstream::gatherList(allPoints);
    Pstream::scatterList(allPoints);
    Pstream::gatherList(allFaces);
    Pstream::scatterList(allFaces);
    Pstream::gatherList(allWeights);
    Pstream::scatterList(allWeights);

    forAll(allFaces, proci)
    {
        pts.append(allPoints[proci]);
        procs.append(labelList(allFaces[proci].size(), proci));
        faces.append(allFaces[proci]);
        weights.append(allWeights[proci]);
    }
}


Foam::labelList Foam::globalPatchTriangles::centroidOrder
(
    const UList<point>& pts
)
{
    // x, then y, then z: the same on every rank and in every decomposition
    const label n = pts.size()/3;
    pointField centroids(n);
    for (label t = 0; t < n; ++t)
    {
        centroids[t] = (pts[3*t] + pts[3*t + 1] + pts[3*t + 2])/3;
    }
    labelList order(identity(n));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&centroids](const label a, const label b)
        {
            const point& pa = centroids[a];
            const point& pb = centroids[b];
            if (pa.x() != pb.x()) return pa.x() < pb.x();
            if (pa.y() != pb.y()) return pa.y() < pb.y();
            return pa.z() < pb.z();
        }
    );
    return order;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::globalPatchTriangles::globalPatchTriangles
(
    const polyMesh& mesh,
    const label patchi,
    const scalarField& faceWeights
)
{
    DynamicList<point> pts;
    DynamicList<label> procs;
    DynamicList<label> faces;
    DynamicList<scalar> weights;
    gather(mesh, patchi, faceWeights, pts, procs, faces, weights);

    // The triangles in the order of their centroids, with the cumulative
    // weighted area
    const labelList order(centroidOrder(pts));
    const label n = faces.size();
    points_.setSize(3*n);
    cumulativeArea_.setSize(n);
    proc_.setSize(n);
    face_.setSize(n);
    scalar sum = 0;
    forAll(order, i)
    {
        const label t = order[i];
        for (label k = 0; k < 3; ++k)
        {
            points_[3*i + k] = pts[3*t + k];
        }
        sum +=
            weights[t]
           *triPointRef(pts[3*t], pts[3*t + 1], pts[3*t + 2]).mag();
        cumulativeArea_[i] = sum;
        proc_[i] = procs[t];
        face_[i] = faces[t];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::globalPatchTriangles::pick
(
    const scalar u,
    const scalar v,
    const scalar w,
    point& p
) const
{
    // The first triangle whose cumulative area exceeds u times the total
    const scalar target = u*area();
    const label i = min
    (
        label
        (
            std::upper_bound
            (
                cumulativeArea_.begin(), cumulativeArea_.end(), target
            )
          - cumulativeArea_.begin()
        ),
        size() - 1
    );

    const point& a = points_[3*i];
    const point& b = points_[3*i + 1];
    const point& c = points_[3*i + 2];
    const scalar r = sqrt(v);
    p = (1 - r)*a + r*(1 - w)*b + r*w*c;

    return proc_[i] == Pstream::myProcNo() ? face_[i] : -1;
}


// ************************************************************************* //
