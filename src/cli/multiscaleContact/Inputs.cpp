// SPDX-License-Identifier: GPL-3.0-or-later
#include "Inputs.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SpecSource.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

std::vector<double> splitNumbers(const std::string& text, char sep, const std::string& option)
{
    std::vector<double> out;
    if (text.empty() || text.back() == sep) {
        throw ParameterError(option, "'" + text + "' has an empty item; give numbers separated by '" +
                                         std::string(1, sep) + "'");
    }
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, sep)) {
        double v = 0.0;
        if (!parseNumber(item, v) || !std::isfinite(v)) {
            throw ParameterError(option, "'" + item + "' is not a finite number");
        }
        out.push_back(v);
    }
    return out;
}

// The loads F/(A_n E') to compute: --loads, --load-range, or --pressures [Pa] divided by E' (Ep);
// `given` (optional) receives the --pressures as given, one per load.
std::vector<double> loadsOf(const Options& o, double Ep, std::vector<double>* given)
{
    if (!o.pressures.empty()) {
        std::vector<double> out;
        for (const std::string& text : o.pressures) {
            for (double P : splitNumbers(text, ',', "--pressures")) {
                if (P < 0.0) {
                    std::ostringstream os;
                    os << "the nominal pressure F/A_n must be >= 0 Pa, got " << P;
                    throw ParameterError("--pressures", os.str());
                }
                try {
                    out.push_back(loadOfPressure(P, Ep));
                } catch (const ParameterError& e) {
                    throw ParameterError("--pressures", e.message());
                }
                if (given != nullptr) {
                    given->push_back(P == 0.0 ? 0.0 : P); // -0 is 0
                }
            }
        }
        return out;
    }
    if (!o.loadRange.empty()) {
        const std::vector<double> r = splitNumbers(o.loadRange, ':', "--load-range");
        if (r.size() != 3) {
            throw ParameterError("--load-range", "expects MIN:MAX:N");
        }
        const double lo = r[0];
        const double hi = r[1];
        const double n = r[2];
        if (!(lo > 0.0) || !(hi >= lo) || n < 1 || n != std::floor(n) || n > 1e6) {
            throw ParameterError("--load-range", "needs 0 < MIN <= MAX and a whole N from 1 to 1000000");
        }
        checkLoad(lo); // both ends within the accepted loads before any row is computed
        checkLoad(hi);
        std::vector<double> out;
        const auto count = static_cast<std::size_t>(n);
        for (std::size_t i = 0; i < count; ++i) {
            out.push_back(count == 1 ? lo : lo * std::pow(hi / lo, double(i) / double(count - 1)));
        }
        return out;
    }
    std::vector<double> out;
    for (const std::string& text : o.loads) {
        for (double l : splitNumbers(text, ',', "--loads")) {
            out.push_back(checkLoad(l));
        }
    }
    return out;
}

namespace {

// How an entry of a solid is written on the command line (the reader names it so).
std::string solidOption(const std::string& key)
{
    return "--" + key;
}

} // namespace

std::vector<Material> solidsOf(const Options& o)
{
    if (o.E.empty()) {
        throw ParameterError("--E", "give --E (with --nu) or --Eprime");
    }
    if (o.nu.size() != o.E.size()) {
        throw ParameterError("--nu", "give one Poisson's ratio per --E value");
    }
    if (!o.Sy.empty() && o.Sy.size() != o.E.size()) {
        throw ParameterError("--Sy", "give one yield strength per --E value");
    }
    // Each solid through the core's reader of a solid (InterfaceSpecReader.hpp: the rules of
    // E, nu and Sy, "none" included), named "solid 1", "solid 2" and its options.
    std::vector<Material> m;
    for (std::size_t i = 0; i < o.E.size(); ++i) {
        // (one solid is against a rigid flat: "material", as ContactMaterials::againstRigidFlat)
        SpecValues solid(o.E.size() == 1 ? "material" : "solid " + std::to_string(i + 1), solidOption);
        solid.set("E", o.E[i]).set("nu", o.nu[i]);
        if (!o.Sy.empty()) {
            solid.set("Sy", o.Sy[i]);
        }
        m.push_back(readMaterial(solid));
    }
    return m;
}

std::pair<std::size_t, std::uint64_t> synthesisOf(const Options& o)
{
    // N and SEED as whole numbers, read as integers: a double of 2^64 or more does not convert
    // to a seed (it was undefined behaviour, and gave seed 0's surface).
    const std::size_t comma = o.synthesize.find(',');
    const std::uint64_t n = gridSizeOf(o.synthesize.substr(0, comma), "--synthesize");
    const auto seed = comma == std::string::npos
                          ? std::uint64_t(1)
                          : parseWholeNumber(o.synthesize.substr(comma + 1), "--synthesize", "the seed SEED");
    return {static_cast<std::size_t>(n), seed};
}

ContactMaterials materialsOf(const Options& o)
{
    if (!o.pressures.empty() && !o.Eprime && o.E.empty()) {
        throw ParameterError("--pressures", "needs E' [Pa] to turn the pressures into loads F/(A_n E'): give "
                                            "--E (with --nu) or --Eprime");
    }
    if (o.Eprime) {
        if (o.nu.size() > 1 || o.Sy.size() > 1) {
            throw ParameterError("--Eprime",
                                 "takes one --nu and one --Sy (of the material that yields first)");
        }
        Material y;
        if (!o.Sy.empty()) {
            SpecValues solid("the yielding solid", solidOption);
            solid.set("Sy", o.Sy[0]);
            readYieldStrength(solid, y);
        }
        return ContactMaterials::fromReducedModulus(
            *o.Eprime, o.nu.empty() ? std::nullopt : std::optional<double>(o.nu[0]), y.Sy);
    }
    const std::vector<Material> m = solidsOf(o);
    return m.size() == 1 ? ContactMaterials::againstRigidFlat(m[0])
                         : ContactMaterials::pair(m[0], m[1], "solid 1", "solid 2");
}

// --hardness H or --hardness-from-yield (H = 2.84 S_y): the boundary-element cap and the CMY
// microhardness alike; none when neither is given.
std::optional<double> hardnessOf(const Options& o, const ContactMaterials& materials, const std::string& who)
{
    if (o.hardness && o.hardnessFromYield) {
        throw ParameterError("--hardness", "give a hardness or --hardness-from-yield, not both");
    }
    if (o.hardness) {
        return limits::requireInRange("--hardness", *o.hardness, limits::minimumHardness, limits::maximumHardness, "Pa");
    }
    if (o.hardnessFromYield) {
        return materials.hardness(who);
    }
    return std::nullopt;
}

// The grid size N of --synthesize N[,SEED] or --resample N[,K]: a whole number, even, within
// the synthesis limits; ParameterError naming the option otherwise.
std::uint64_t gridSizeOf(const std::string& text, const std::string& option)
{
    const std::uint64_t n = parseWholeNumber(text, option, "the grid size N");
    if (n < limits::minimumSynthesisSize || n > limits::maximumSynthesisSize || n % 2 != 0) {
        std::ostringstream os;
        os << "the grid size N must be even and within [" << limits::minimumSynthesisSize << ", "
           << limits::maximumSynthesisSize << "], got " << text;
        throw ParameterError(option, os.str());
    }
    return n;
}

// The areal surface of --model boundaryElement: the --areal map (the composite of two), or one
// synthesized from the 1-D description (--synthesize N[,SEED]); and whether it is periodic.
std::pair<ArealSurface, bool> arealSurfaceOf(const Options& o)
{
    if (!o.areals.empty()) {
        if (!o.synthesize.empty()) {
            throw ParameterError("--synthesize", "makes an areal surface from a profile or spectrum; --areal is one");
        }
        if (o.direction) {
            throw ParameterError("--direction", "chooses line scans for the line-scan models; boundaryElement "
                                                "uses the whole map");
        }
        std::optional<ArealSurface> total;
        for (const SurfaceSpec& spec : surfaceSpecsOf(o)) {
            if (spec.kind != SurfaceSpec::Kind::areal) {
                throw ParameterError("--model boundaryElement", "solves --areal maps, or a surface --synthesize'd "
                                                                "from a profile or spectrum; not both");
            }
            // As read: BoundaryElementModel detrends the composite (--detrend).
            const ArealSurface one = readAreal(spec.file, spec.arealOptions);
            total = total ? compositeSurface(*total, one) : one;
        }
        if (!o.resample.empty()) {
            throw ParameterError("--resample", "puts a --synthesize'd (periodic) surface on another grid; an --areal "
                                               "map is solved as measured");
        }
        return {*total, o.periodic};
    }
    if (o.synthesize.empty()) {
        throw ParameterError("--model boundaryElement",
                             "needs an areal surface: --areal FILE, or --synthesize N[,SEED] with a profile or "
                             "spectrum");
    }
    const auto [n, seed] = synthesisOf(o);
    const Spectrum lineScan = surfaceOf(o);
    // A synthesized surface is periodic: it is solved so (the option is for measured maps).
    ArealSurface synthesized = synthesizeIsotropic(lineScan, n, seed, "synthesized from " + lineScan.source());
    if (o.resample.empty()) {
        return {std::move(synthesized), true};
    }
    // --resample N[,K]: the same surface (its Fourier series) on N x N, without wavelengths
    // shorter than L/K if K is given.
    const std::size_t rc = o.resample.find(',');
    const std::uint64_t m = gridSizeOf(o.resample.substr(0, rc), "--resample");
    std::optional<double> levels;
    if (rc != std::string::npos) {
        const std::uint64_t k = parseWholeNumber(o.resample.substr(rc + 1), "--resample", "the levels kept K");
        if (k < 1) {
            throw ParameterError("--resample", "keeps at least 1 level (K >= 1), got " + o.resample.substr(rc + 1));
        }
        levels = static_cast<double>(k);
    }
    return {resampledPeriodic(synthesized, static_cast<std::size_t>(m), levels), true};
}

// An output file of --pressure-map: not one of the inputs (it would replace the map being
// solved), not a directory, in a directory that can be written to. Checked before any solve.
bool isPressureMap(const std::string& start)
{
    return start.rfind(pressureMapHeader, 0) == 0;
}

void checkOutputFile(const Options& o, const std::string& path, const std::string& option)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    for (const std::vector<std::string>* inputs : {&o.areals, &o.profiles, &o.profilesAlong, &o.spectra}) {
        for (const std::string& input : *inputs) {
            if (fs::equivalent(fs::path(path), fs::path(input), ec)) {
                throw ParameterError(option, "'" + path + "' is an input of this run (" + input +
                                                 "); it would be overwritten: name another file");
            }
        }
    }
    if (fs::is_directory(fs::path(path), ec)) {
        throw ParameterError(option, "'" + path + "' is a directory; name a file");
    }
    requireReplaceable(path, option, "pressure map of multiscaleContact", isPressureMap);
    const fs::path parent = fs::path(path).parent_path();
    const std::string directory = parent.empty() ? "." : parent.string();
    if (::access(directory.c_str(), W_OK | X_OK) != 0) {
        throw ParameterError(option, "cannot write into the directory '" + directory + "' of '" + path +
                                         "' (missing, or not writable)");
    }
}

// --k1 --k2: k_s = 2 k1 k2/(k1 + k2) [W/(m K)], for the column h = k_s h_c/k_s [W/(m^2 K)] after
// h_per_k; none without them. `conductance`: the run has an h_per_k column.
std::optional<double> harmonicConductivityOf(const Options& o, bool conductance)
{
    if (!o.k1 && !o.k2) {
        return std::nullopt;
    }
    if (!(o.k1 && o.k2)) {
        throw ParameterError(o.k1 ? "--k2" : "--k1", "give both conductivities, --k1 and --k2 [W/(m K)]");
    }
    if (!conductance) {
        throw ParameterError("--k1", "turns h_per_k into h [W/(m^2 K)]: add --conductance (or a --conductance-law)");
    }
    for (const auto& [k, what] : {std::pair<double, const char*>{*o.k1, "--k1"}, {*o.k2, "--k2"}}) {
        limits::requireInRange(what, k, limits::minimumConductivity, limits::maximumConductivity, "W/(m K)");
    }
    return harmonicMeanConductivity(*o.k1, *o.k2);
}

namespace {

// How an entry of a specification's settings is written on the command line.
std::string settingOption(const std::string& key)
{
    static const std::pair<const char*, const char*> options[] = {
        {"conductance", "--conductance-law"}, {"microhardness", "--hardness"}, {"hardnessFromYield", "--hardness-from-yield"},
        {"seed", "--synthesize"}};
    for (const auto& [entry, option] : options) {
        if (key == entry) {
            return option;
        }
    }
    return "--" + key;
}

} // namespace

InterfaceSpec interfaceSpecOf(const Options& o)
{
    InterfaceSpec spec;
    spec.surfaces = surfaceSpecsOf(o);
    const bool exact = o.model == "boundaryElement";
    SpecValues v("the command line", settingOption);
    v.set("model", o.model);
    if (!exact && o.conductanceLaw != "all") {
        // The law of the run's h_per_k, named: what --vickers and the model's rules are held to.
        v.set("conductance", o.conductanceLaw.empty() ? defaultConductanceLaw() : o.conductanceLaw);
    } else if (exact && !o.conductanceLaw.empty()) {
        v.set("conductance", o.conductanceLaw);
    }
    if (!o.vickers.empty()) {
        v.set("vickers", splitNumbers(o.vickers, ',', "--vickers"));
    }
    if (o.hardness) {
        v.set(exact ? "hardness" : "microhardness", *o.hardness, "--hardness");
    }
    if (o.hardnessFromYield && exact) {
        v.set("hardnessFromYield", true); // else the laws' H_c = 2.84 S_y (hardnessOf)
    }
    if (!o.synthesize.empty() && !o.check) {
        const auto [n, seed] = synthesisOf(o);
        v.set("synthesize", std::uint64_t(n)).set("seed", seed);
    }
    if (o.periodic) {
        v.set("periodic", true);
    }
    if (o.mirror) {
        v.set("mirror", true);
    }
    if (o.detrend) {
        v.set("detrend", *o.detrend);
    }
    if (o.check) {
        v.set("check", true);
    }
    readInterfaceSettings(v, spec);
    return spec;
}

SurfaceCheckInputs interfaceInputsOf(const Options& o, const std::string& who)
{
    const InterfaceSpec spec = interfaceSpecOf(o);
    SurfaceCheckInputs in;
    in.surfaces = spec.surfaces;
    in.materials = materialsOf(o);
    in.model = o.model;
    if (!isMultiscaleModel(o.model) && o.model != "boundaryElement") {
        throw ParameterError(who, "takes a multi-scale --model (the laws' area: hertz, jacksonGreen, ...) or "
                                  "boundaryElement, not " + o.model);
    }
    in.conductanceLaw = o.conductanceLaw == "all" ? std::string() : o.conductanceLaw;
    in.hardness = hardnessOf(o, *in.materials, who + " --hardness-from-yield");
    in.vickers = spec.vickers;
    in.periodic = spec.periodic;
    in.mirror = spec.mirror;
    in.detrend = spec.detrend;
    return in;
}

} // namespace multiscaleContact
