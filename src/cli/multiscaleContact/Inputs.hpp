// SPDX-License-Identifier: GPL-3.0-or-later
// multiscaleContact's options turned into the core's objects: the loads, the surfaces, their
// roughness, the materials, the cap, the grid sizes. Each error is a ParameterError naming the
// option (exit status 1, docs/cli.md), raised before anything is solved.
#pragma once

#include "Options.hpp"

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace multiscaleContact {

using roughContact::ArealReadOptions;
using roughContact::ArealSurface;
using roughContact::ContactMaterials;
using roughContact::HeightSkewness;
using roughContact::Material;
using roughContact::Spectrum;
using roughContact::SurfaceRoughness;
using roughContact::SurfaceSpec;

std::vector<double> splitNumbers(const std::string& text, char sep, const std::string& option);

// The loads F/(A_n E') to compute: --loads, --load-range, or --pressures [Pa] divided by E' (Ep);
// `given` (optional) receives the --pressures as given, one per load.
std::vector<double> loadsOf(const Options& o, double Ep, std::vector<double>* given = nullptr);

Spectrum surfaceOf(const Options& o);

// sigma and the mean absolute slope of the surfaces, for the correlations (the same surfaces
// surfaceOf reads; two combined): a profile's and a map's from their heights, a spectrum's from
// its moments (Roughness.hpp).
SurfaceRoughness roughnessOf(const Options& o);
// The heights' skewness of the same surfaces (equivalentSkewness): a profile's or a map's; none
// for a spectrum (Gaussian heights). For the regime's line (InterfaceRegime::skewness).
std::optional<HeightSkewness> skewnessOf(const Options& o);

// The solids of --E, --nu, --Sy (one or two; one of each per --E value); ParameterError naming the
// option otherwise.
std::vector<Material> solidsOf(const Options& o);

// --synthesize N[,SEED]: the grid size N and the seed (default 1).
std::pair<std::size_t, std::uint64_t> synthesisOf(const Options& o);

ContactMaterials materialsOf(const Options& o);

// --hardness H or --hardness-from-yield (H = 2.84 S_y): the boundary-element cap and the CMY
// microhardness alike; none when neither is given.
std::optional<double> hardnessOf(const Options& o, const ContactMaterials& materials, const std::string& who);

void printInfo(const Spectrum& s, std::ostream& os);

// The grid size N of --synthesize N[,SEED] or --resample N[,K]: a whole number, even, within
// the synthesis limits; ParameterError naming the option otherwise.
std::uint64_t gridSizeOf(const std::string& text, const std::string& option);

// The areal surface of --model boundaryElement: the --areal map (the composite of two), or one
// synthesized from the 1-D description (--synthesize N[,SEED]); and whether it is periodic.
std::pair<ArealSurface, bool> arealSurfaceOf(const Options& o);

// The first line of the pressure map --pressure-map writes (the rest of it follows); a file that
// begins with it is one this tool wrote (isPressureMap), which it may replace.
inline constexpr const char* pressureMapHeader =
    "# contact pressure [Pa] of multiscaleContact --model boundaryElement";
bool isPressureMap(const std::string& start);

// An output file of --pressure-map: not one of the inputs (it would replace the map being
// solved), not a directory, nothing but a pressure map this tool wrote (io/Files.hpp's rules for
// a writer), in a directory that can be written to. Checked before any solve.
void checkOutputFile(const Options& o, const std::string& path, const std::string& option);

// --k1 --k2: k_s = 2 k1 k2/(k1 + k2) [W/(m K)], for the column h = k_s h_c/k_s [W/(m^2 K)] after
// h_per_k; none without them. `conductance`: the run has an h_per_k column.
std::optional<double> harmonicConductivityOf(const Options& o, bool conductance);

// The surfaces as SurfaceSpecs (the boundary condition's description of the same options).
std::vector<SurfaceSpec> surfaceSpecsOf(const Options& o);

// The options as a contact specification, read by the core's reader of a specification's settings
// (readInterfaceSettings) from them as its entries, each named by its option: the surfaces
// (surfaceSpecsOf); --model; the law (--conductance-law, else the default where a multi-scale or
// correlation model's curve is asked: the law the run's h_per_k is; none for boundaryElement and
// for all); --vickers; --hardness (boundaryElement's cap, else the laws' microhardness);
// --hardness-from-yield (boundaryElement's); --synthesize N[,SEED]; --periodic, --mirror,
// --detrend; --check. The reader ends with the model's rules with the entries of another
// (InterfaceSpec::checkEntries), so each stands once for the CLI, the condition and Python. The
// solids are not in it (materialsOf: --Eprime and one solid against a flat are the CLI's).
roughContact::InterfaceSpec interfaceSpecOf(const Options& o);

// The interface as the check and the picture see it (SurfaceCheckInputs): the surfaces, the
// materials, the --model (a multi-scale model or boundaryElement), the --conductance-law, the cap
// (--hardness, --hardness-from-yield) and --vickers; `who` names the option that asks in errors.
roughContact::SurfaceCheckInputs interfaceInputsOf(const Options& o, const std::string& who);

} // namespace multiscaleContact
