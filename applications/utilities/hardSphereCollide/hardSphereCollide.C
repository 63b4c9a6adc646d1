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

Application
    hardSphereCollide

Group
    grpLagrangianUtilities

Description
    Resolves one binary hard-sphere collision with the agglomeration and
    structure models of the agglomerationHardSphere library and prints the
    outcome as JSON on standard output: collision type (sticking/sliding),
    model branch (agglomerate / rebound case), post-collision states or the
    agglomerate, and the intermediate quantities: fna, dKEformation and
    spinCapped for every model, then those the agglomeration model names
    (agglomerationModel::valueNames(); null where not computed, flags as
    0/1).

    Needs no case. The dictionary holds the kernel input (see
    hardSphereCollisionKernel) and the two particles:
    \verbatim
    material            { H 6.3e-20; E 7.2e10; nu 0.17; sigmaY 1.1e9;
                          delta0 2e-10; rho0 2200; }
    particleCollision   { en 0.97; et 0.44; muSt 0.94; muKin 0.092; }
    agglomerationModel  EAM;
    structureModel      CSM;
    particle1
    {
        position    (0 0 0);        // [m]
        U           (5e-4 0 0);     // [m/s]
        omega       (0 0 0);        // [1/s]
        d           12e-6;          // [m]
        rho         2200;           // [kg/m3]
        nPrimary    1;
    }
    particle2 { position (12e-6 0 0); U (-5e-4 0 0); omega (0 0 0);
                d 12e-6; rho 2200; nPrimary 1; }
    contactTolerance    1e-6;       // optional: |dist - (d1+d2)/2|/((d1+d2)/2)
    \endverbatim

    The particles must touch (within contactTolerance) and approach each
    other; otherwise the utility stops with a message.

Usage
    hardSphereCollide <dictFile>

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "hardSphereCollisionKernel.H"
#include "hardSphereInput.H"
#include <iostream>
#include <iomanip>
#include <sstream>
#include <cmath>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

std::string num(const scalar v)
{
    if (std::isnan(v))
    {
        return "null";
    }
    if (std::isinf(v))
    {
        return v > 0 ? "\"inf\"" : "\"-inf\"";
    }
    std::ostringstream os;
    os << std::setprecision(17) << v;
    return os.str();
}


std::string vec(const vector& v)
{
    return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
}


std::string state(const hardSphereState& p, const std::string& indent)
{
    std::ostringstream os;
    os  << "{" << '\n'
        << indent << "  \"position\": " << vec(p.x) << ",\n"
        << indent << "  \"U\": " << vec(p.U) << ",\n"
        << indent << "  \"omega\": " << vec(p.omega) << ",\n"
        << indent << "  \"d\": " << num(p.d) << ",\n"
        << indent << "  \"rho\": " << num(p.rho) << ",\n"
        << indent << "  \"nPrimary\": " << p.nPrimary << ",\n"
        << indent << "  \"mass\": " << num(p.mass()) << "\n"
        << indent << "}";
    return os.str();
}


hardSphereState readParticle(const dictionary& dict, const word& name)
{
    using namespace hardSphereInput;
    const dictionary& pd = dict.subDict(name);
    checkKeys(pd, {"position", "U", "omega", "d", "rho", "nPrimary"});

    const scalar d = getInRange(pd, "d", open(0), open(GREAT));
    const scalar rho = getInRange(pd, "rho", open(0), open(GREAT));
    const label nPrimary = pd.getOrDefault<label>("nPrimary", 1);
    if (nPrimary < 1)
    {
        FatalIOErrorInFunction(pd)
            << "Entry 'nPrimary' = " << nPrimary << " must be >= 1"
            << exit(FatalIOError);
    }

    return hardSphereState
    (
        pd.get<point>("position"),
        pd.get<vector>("U"),
        pd.getOrDefault<vector>("omega", Zero),
        d,
        rho,
        nPrimary
    );
}

//- Stop unless the particles touch (within contactTolerance of the
//  contact distance) and approach each other
void checkContact
(
    const dictionary& dict,
    const hardSphereState& p1,
    const hardSphereState& p2,
    const binaryCollision& pair
)
{
    const scalar ell = 0.5*(p1.d + p2.d);
    const scalar dist = mag(p2.x - p1.x);
    const scalar tol =
        dict.getOrDefault<scalar>("contactTolerance", 1e-6);
    if (!(dist > 0) || mag(dist - ell) > tol*ell)
    {
        FatalIOErrorInFunction(dict)
            << "The particles are not in contact: centre distance "
            << dist << " m, contact distance (d1 + d2)/2 = " << ell
            << " m (gap " << dist - ell << " m, relative "
            << (dist - ell)/ell << ", contactTolerance " << tol << ")." << nl
            << "    Place particle2 at particle1.position + (d1 + d2)/2 n."
            << exit(FatalIOError);
    }
    if (!pair.approaching())
    {
        FatalIOErrorInFunction(dict)
            << "The particles are not approaching: u_n = (U2 - U1).n = "
            << pair.un() << " m/s >= 0 with n = " << pair.n()
            << " pointing from particle1 to particle2." << nl
            << "    A collision needs u_n < 0."
            << exit(FatalIOError);
    }
}


//- The intermediates of the outcome as JSON entries: those of every
//  model, then the model's own
void writeIntermediates
(
    std::ostream& os,
    const agglomerationModel& model,
    const collisionOutcome& out
)
{
    const FixedList<scalar, 3> common(out.commonValues());
    wordList names(collisionOutcome::commonValueNames);
    names.append(model.valueNames());
    os  << "  \"intermediates\": {\n";
    forAll(names, i)
    {
        const scalar v =
            i < common.size() ? common[i] : out.values[i - common.size()];
        os  << "    \"" << names[i].c_str() << "\": " << num(v)
            << (i + 1 < names.size() ? ",\n" : "\n");
    }
    os  << "  },\n";
}


//- The mass, momentum and kinetic energy before and after as JSON
void writeBalance
(
    std::ostream& os,
    const hardSphereState& p1,
    const hardSphereState& p2,
    const collisionOutcome& out
)
{
    const scalar mBefore = p1.mass() + p2.mass();
    const vector PBefore = p1.momentum() + p2.momentum();
    vector PAfter(Zero);
    scalar mAfter = 0;
    scalar KEafter = 0;
    if (out.agglomerates)
    {
        PAfter = out.agglomerate.momentum();
        mAfter = out.agglomerate.mass();
        KEafter = out.agglomerate.kineticEnergy();
    }
    else
    {
        PAfter = out.p1.momentum() + out.p2.momentum();
        mAfter = out.p1.mass() + out.p2.mass();
        KEafter = out.p1.kineticEnergy() + out.p2.kineticEnergy();
    }
    os  << "  \"balance\": {\n"
        << "    \"massBefore\": " << num(mBefore) << ",\n"
        << "    \"massAfter\": " << num(mAfter) << ",\n"
        << "    \"momentumBefore\": " << vec(PBefore) << ",\n"
        << "    \"momentumAfter\": " << vec(PAfter) << ",\n"
        << "    \"kineticEnergyBefore\": "
        << num(p1.kineticEnergy() + p2.kineticEnergy()) << ",\n"
        << "    \"kineticEnergyAfter\": " << num(KEafter) << "\n"
        << "  }\n";
}


//- The outcome of the collision of p1 and p2 as the JSON document
std::string outcomeJson
(
    const hardSphereCollisionKernel& kernel,
    const hardSphereState& p1,
    const hardSphereState& p2,
    const binaryCollision& pair,
    const collisionOutcome& out
)
{
    std::ostringstream os;
    os  << "{\n"
        << "  \"agglomerationModel\": \""
        << kernel.agglomeration().type() << "\",\n"
        << "  \"structureModel\": "
        << (kernel.hasStructure()
            ? "\"" + std::string(kernel.structure().type()) + "\""
            : std::string("null")) << ",\n"
        << "  \"collisionType\": \""
        << collisionOutcome::collisionTypeNames[out.type] << "\",\n"
        << "  \"branch\": \""
        << kernel.agglomeration().branchNames()[out.branch].c_str()
        << "\",\n"
        << "  \"agglomerate\": " << (out.agglomerates ? "true" : "false")
        << ",\n"
        << "  \"normal\": " << vec(pair.n()) << ",\n"
        << "  \"impactNormalVelocity\": " << num(pair.un()) << ",\n"
        << "  \"slip\": " << num(pair.s()) << ",\n";

    if (out.agglomerates)
    {
        os  << "  \"particles\": null,\n"
            << "  \"agglomerateState\": " << state(out.agglomerate, "  ")
            << ",\n";
    }
    else
    {
        os  << "  \"particles\": [" << state(out.p1, "    ") << ", "
            << state(out.p2, "    ") << "],\n"
            << "  \"agglomerateState\": null,\n";
    }
    writeIntermediates(os, kernel.agglomeration(), out);
    writeBalance(os, p1, p2, out);
    os  << "}\n";
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Resolve one binary hard-sphere collision (with the selected"
        " agglomeration and structure models) and print the outcome as JSON"
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    argList::noCheckProcessorDirectories();
    argList::addArgument("dictFile");

    argList args(argc, argv, false, true, false);

    // Exactly one argument: the dictionary file
    if (args.size() != 2)
    {
        FatalErrorInFunction
            << "hardSphereCollide needs exactly one argument, the dictionary"
            << " file (dictFile); found " << args.size() - 1 << nl
            << "    Usage: hardSphereCollide <dictFile>"
            << exit(FatalError);
    }

    const fileName dictFile(args.get<fileName>(1));
    IFstream is(dictFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read dictionary file " << dictFile
            << exit(FatalError);
    }
    const dictionary dict(is);

    wordList valid(hardSphereCollisionKernel::keys(dict));
    valid.append(wordList({"particle1", "particle2", "contactTolerance"}));
    hardSphereInput::checkKeys(dict, valid);

    // Messages of the model constructors go to stderr; stdout is JSON only
    const int infoLevel = messageStream::level;
    messageStream::level = 0;
    const hardSphereCollisionKernel kernel(dict);
    messageStream::level = infoLevel;

    const hardSphereState p1(readParticle(dict, "particle1"));
    const hardSphereState p2(readParticle(dict, "particle2"));

    const binaryCollision pair(p1, p2);
    checkContact(dict, p1, p2, pair);

    const collisionOutcome out(kernel.collide(p1, p2));
    std::cout << outcomeJson(kernel, p1, p2, pair, out) << std::flush;

    return 0;
}


// ************************************************************************* //
