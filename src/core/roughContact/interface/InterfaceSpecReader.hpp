// SPDX-License-Identifier: GPL-3.0-or-later
// The one reader of a contact specification: a SpecSource (the OpenFOAM dictionary, the CLI's
// options, Python's arguments) into an InterfaceSpec. Every rule about the entries lives here
// or in the checks it calls, once:
//  - which entries each part has (surfaceEntries, materialEntries, gapEntries, gasEntries,
//    interfaceEntries); an entry not among them is an error naming it, and saying which surface
//    type it belongs to when it belongs to another (a profile's stride on an areal map);
//  - the names of words (surface types, units, scan directions, detrending, gases, "Sy none");
//  - defaults (stride 1, gas pressure one standard atmosphere, fillInvalid no, ...);
//  - whole numbers (stride, synthesize, seed, pointsPerDecade, which goes to the table of the
//    model named), lists of two (accommodation, emissivity, vickers), scan length > 0;
//  - the value checks of each part (checkMaterial, checkGapSpec), whose errors name the part.
// The rules of a model with the entries of another (boundaryElement's synthesize, periodic,
// hardness; a conductance law or vickers beside it; mirror of a map) are
// InterfaceSpec::checkEntries (ContactInterface.hpp), which the reader ends with, naming the
// entry as the source writes it; ContactInterface runs them too, for a spec built in C++.
// Every error is a ParameterError whose parameter() is the source's name of the entry.
#pragma once

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/interface/SpecSource.hpp"
#include "roughContact/material/Materials.hpp"

#include <string>
#include <vector>

namespace roughContact {

/// The surface types' names as written (profile, spectrum, powerLaw, fractal, areal).
const std::vector<std::string>& surfaceTypeNames();
/// The kind of a surface type's name; ParameterError naming `what` and listing the names.
SurfaceSpec::Kind parseSurfaceKind(const std::string& text, const std::string& what = "type");
/// The entries a surface of this kind takes (type first).
const std::vector<std::string>& surfaceEntries(SurfaceSpec::Kind kind);
/// The entries of a solid (E, nu, Sy), of the gap, of a gas given by its properties, and of a
/// whole contact specification.
const std::vector<std::string>& materialEntries();
const std::vector<std::string>& gapEntries();
const std::vector<std::string>& gasEntries();
const std::vector<std::string>& interfaceEntries();

SurfaceSpec readSurfaceSpec(const SpecSource& source);
/// E, nu and Sy: a yield strength [Pa] or the word none (Material::elastic); checkMaterial
/// naming source.context().
Material readMaterial(const SpecSource& source);
/// The entry Sy alone into m: a yield strength [Pa] (m.Sy), or the word none (m.elastic); any
/// other word is a ParameterError naming the entry. (readMaterial's, for a front-end that has
/// S_y without E and nu: the CLI's --Eprime.)
void readYieldStrength(const SpecSource& source, Material& m);
/// gas (a name of gasByName, or a sub-specification of its properties), pressure [Pa] (default
/// standardAtmosphere), accommodation (a1 a2), emissivity (e1 e2); checkGapSpec.
GapSpec readGapSpec(const SpecSource& source);
/// The whole specification: model; surface (one equivalent surface) or surfaces (one per side,
/// side1's first); side1, side2; the rest optional (InterfaceSpec, and check).
InterfaceSpec readInterfaceSpec(const SpecSource& source);
/// The entries of a specification besides its parts (surface/surfaces, side1, side2, gap): model,
/// conductance, microhardness, vickers, the table's range and points, the boundary-element
/// entries and check, into `spec` (readInterfaceSpec's; for a front-end that holds the parts as
/// objects: Python, the CLI). Does not check that every entry is known; ends with
/// spec.checkEntries(), so `spec`'s parts (surfaces) are to be set before.
void readInterfaceSettings(const SpecSource& source, InterfaceSpec& spec);

} // namespace roughContact
