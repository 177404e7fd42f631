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
#include <charconv>
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

// A whole number 0 .. 2^64 - 1 written in decimal digits ("--synthesize 8,SEED"); ParameterError
// naming the option and the item otherwise (a sign, a fraction, an exponent, more than 2^64 - 1).
std::uint64_t wholeNumber(const std::string& text, const std::string& option, const std::string& what)
{
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const std::from_chars_result r = std::from_chars(text.data(), end, v);
    if (text.empty() || r.ptr != end || r.ec == std::errc::invalid_argument) {
        throw ParameterError(option, what + " must be a whole number of decimal digits, got '" + text + "'");
    }
    if (r.ec == std::errc::result_out_of_range) {
        throw ParameterError(option, what + " " + text + " is beyond the largest, 2^64 - 1 = 18446744073709551615");
    }
    return v;
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

Spectrum surfaceOf(const Options& o)
{
    return equivalentSurface(surfaceSpecsOf(o));
}

// sigma and the mean absolute slope of the surfaces, for the correlations (the same surfaces
// surfaceOf reads; two combined): a profile's and a map's from their heights, a spectrum's from
// its moments (Roughness.hpp).
SurfaceRoughness roughnessOf(const Options& o)
{
    return equivalentRoughness(surfaceSpecsOf(o));
}

// The heights' skewness of the same surfaces (equivalentSkewness): none for a spectrum.
std::optional<HeightSkewness> skewnessOf(const Options& o)
{
    return equivalentSkewness(surfaceSpecsOf(o));
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
                          : wholeNumber(o.synthesize.substr(comma + 1), "--synthesize", "the seed SEED");
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

void printInfo(const Spectrum& s, std::ostream& os)
{
    os << "# surface: " << s.source() << "\n# levels: " << s.size() << ", f = " << s.frequencies().front()
       << " .. " << s.frequencies().back() << " 1/m, L = " << s.length() << " m, A_n = " << s.nominalArea()
       << " m^2\n# rms height (Parseval): " << std::sqrt(s.profileVariance()) << " m\n";
    try {
        const SummitParameters p = mcCoolParameters(s);
        os << "# McCool: eta = " << p.eta << " 1/m^2, R = " << p.R << " m, sigma_s = " << p.sigmaS
           << " m, alpha = " << p.alpha << "\n";
    } catch (const std::exception& e) {
        os << "# McCool: " << e.what() << "\n";
    }
    try {
        const FractalParameters f = fitFractal(s);
        os << "# fractal fit: D = " << f.D << ", G = " << f.G << " m\n";
    } catch (const std::exception& e) {
        os << "# fractal fit: " << e.what() << "\n";
    }
}

// The grid size N of --synthesize N[,SEED] or --resample N[,K]: a whole number, even, within
// the synthesis limits; ParameterError naming the option otherwise.
std::uint64_t gridSizeOf(const std::string& text, const std::string& option)
{
    const std::uint64_t n = wholeNumber(text, option, "the grid size N");
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
    if (o.mirror) {
        throw ParameterError("--mirror", "is for --areal maps; a --synthesize'd surface is periodic already");
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
        const std::uint64_t k = wholeNumber(o.resample.substr(rc + 1), "--resample", "the levels kept K");
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
    for (const std::vector<std::string>* inputs : {&o.areals, &o.profiles, &o.spectra}) {
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

// The surfaces as SurfaceSpecs, read by the core's reader of a surface (InterfaceSpecReader.hpp)
// from the options as a dictionary's entries, each named by its option. An option goes to the
// surfaces whose type takes it (--units to a profile and an areal map, not to a spectrum beside
// them); one that no surface takes is the core's error for the first surface.
std::vector<SurfaceSpec> surfaceSpecsOf(const Options& o)
{
    struct Given {
        std::string key;       ///< the entry's name in a dictionary
        std::string arealKey;  ///< ... for an areal surface (--dx: a profile's spacing, a map's dx)
        SpecValues::Value value;
        std::string option;
    };
    std::vector<Given> given;
    if (o.units) {
        given.push_back({"units", "units", *o.units, "--units"});
    }
    if (o.dx) {
        given.push_back({"spacing", "dx", *o.dx, "--dx"});
    }
    if (o.dy) {
        given.push_back({"dy", "dy", *o.dy, "--dy"});
    }
    if (o.fillInvalid) {
        given.push_back({"fillInvalid", "fillInvalid", true, "--fill-invalid"});
    }
    if (o.direction) {
        given.push_back({"direction", "direction", *o.direction, "--direction"});
    }
    if (o.stride != 1) {
        given.push_back({"stride", "stride", std::uint64_t(o.stride), "--stride"});
    }
    if (o.length) {
        given.push_back({"length", "length", *o.length, "--length"});
    }

    std::vector<SpecValues> surfaces;
    const auto add = [&](const char* type, const std::string& option, const std::string& file) {
        SpecValues v(option + " " + file);
        v.set("type", std::string(type), option);
        if (!file.empty()) {
            v.set("file", file, option);
        }
        surfaces.push_back(v);
        return &surfaces.back();
    };
    for (const std::string& f : o.profiles) {
        add("profile", "--profile", f);
    }
    for (const std::string& f : o.areals) {
        add("areal", "--areal", f);
    }
    for (const std::string& f : o.spectra) {
        add("spectrum", "--spectrum", f);
    }
    if (!o.powerLaw.empty()) {
        SpecValues* v = add("powerLaw", "--power-law", "");
        const char* keys[] = {"bm", "m", "fmin", "fmax"};
        for (std::size_t i = 0; i < o.powerLaw.size() && i < 4; ++i) {
            v->set(keys[i], o.powerLaw[i], "--power-law");
        }
    }
    if (!o.roughness.empty()) {
        SpecValues* v = add("roughness", "--roughness", "");
        const char* keys[] = {"Rq", "slope", "cutoff", "shortCutoff"};
        for (std::size_t i = 0; i < o.roughness.size() && i < 4; ++i) {
            // RQ, CUTOFF and SHORTCUTOFF are lengths (SI, or with a unit: 0.8um); SLOPE a number
            const std::string& item = o.roughness[i];
            double value = 0.0;
            if (i == 1) {
                if (!parseNumber(item, value)) {
                    throw ParameterError("--roughness", "SLOPE (the rms slope, a number) is '" + item + "'");
                }
            } else {
                value = parseQuantity(item, Quantity::length, "--roughness");
            }
            v->set(keys[i], value, "--roughness");
        }
        // A length without a unit beside lengths with one is most likely a slip (0.8um,0.1,0.8
        // meant 0.8 mm, not 0.8 m): said, and read as written (SI).
        const char* names[] = {"RQ", "SLOPE", "CUTOFF", "SHORTCUTOFF"};
        double plain = 0.0;
        bool anyUnit = false;
        for (std::size_t i = 0; i < o.roughness.size() && i < 4; ++i) {
            anyUnit = anyUnit || (i != 1 && !parseNumber(o.roughness[i], plain));
        }
        for (std::size_t i = 0; anyUnit && i < o.roughness.size() && i < 4; ++i) {
            if (i != 1 && parseNumber(o.roughness[i], plain)) {
                std::cerr << "multiscaleContact: warning: --roughness: " << names[i] << " '" << o.roughness[i]
                          << "' has no unit and is read as " << o.roughness[i]
                          << " m, while another length there has one; give it a unit (0.8mm, 2.5um) if another "
                             "was meant\n";
            }
        }
    }
    if (!o.fractal.empty()) {
        SpecValues* v = add("fractal", "--fractal", "");
        const char* keys[] = {"D", "G", "fmin", "fmax"};
        for (std::size_t i = 0; i < o.fractal.size() && i < 4; ++i) {
            v->set(keys[i], o.fractal[i], "--fractal");
        }
    }
    for (const Given& g : given) {
        bool taken = false;
        for (SpecValues& v : surfaces) {
            const SurfaceSpec::Kind kind = parseSurfaceKind(v.word("type"));
            const std::string& key = kind == SurfaceSpec::Kind::areal ? g.arealKey : g.key;
            const std::vector<std::string>& entries = surfaceEntries(kind);
            if (std::find(entries.begin(), entries.end(), key) != entries.end()) {
                v.set(key, g.value, g.option);
                taken = true;
            }
        }
        if (!taken && !surfaces.empty()) {
            SpecValues first = surfaces.front();
            first.set(g.key, g.value, g.option);
            readSurfaceSpec(first); // throws: no surface of this run takes the option
        }
    }
    std::vector<SurfaceSpec> out;
    for (const SpecValues& v : surfaces) {
        out.push_back(readSurfaceSpec(v));
    }
    return out;
}

namespace {

// How an entry of the gap is written on the command line (the reader names it so).
std::string gapOption(const std::string& key)
{
    return key == "pressure" ? "--gas-pressure" : "--" + key;
}

} // namespace

std::optional<GapInputs> gapOf(const Options& o)
{
    const bool given =
        !o.gas.empty() || o.gasPressure.has_value() || !o.accommodation.empty() || !o.emissivity.empty();
    if (!given) {
        for (const auto& [set, what] : {std::pair<bool, const char*>{!o.temperature.empty(), "--temperature"},
                                        {o.gapWidth.has_value(), "--gap-width"}}) {
            if (set) {
                throw ParameterError(what, "is for the gap beside the contact: add --gas NAME and/or --emissivity "
                                           "E1,E2");
            }
        }
        return std::nullopt;
    }
    // The options as the condition's gap sub-dictionary, through the core's reader.
    SpecValues v("gap", gapOption);
    if (!o.gas.empty()) {
        v.set("gas", o.gas);
    }
    if (o.gasPressure) {
        v.set("pressure", *o.gasPressure);
    }
    if (!o.accommodation.empty()) {
        v.set("accommodation", splitNumbers(o.accommodation, ',', "--accommodation"));
    }
    if (!o.emissivity.empty()) {
        v.set("emissivity", splitNumbers(o.emissivity, ',', "--emissivity"));
    }
    GapInputs g;
    g.spec = readGapSpec(v);
    if (o.temperature.empty()) {
        throw ParameterError("--temperature", std::string("the gap's conductance (") +
                                                  (g.spec.gas ? "--gas" : "--emissivity") +
                                                  ") is taken at the interface temperature: give --temperature T [K]");
    }
    const std::vector<double> T = splitNumbers(o.temperature, ',', "--temperature");
    if (T.size() > 2) {
        throw ParameterError("--temperature", "expects T or T1,T2 [K], the two faces' temperatures");
    }
    for (double t : T) {
        limits::requireInRange("--temperature", t, limits::minimumTemperature, limits::maximumTemperature, "K");
    }
    g.T1 = T.front();
    g.T2 = T.back();
    if (o.gapWidth) {
        g.width = limits::requireInRange("--gap-width", *o.gapWidth, 0.0, limits::maximumLength, "m");
    }
    return g;
}

InterfaceGap interfaceGapOf(const Options& o, const GapInputs& g, const ContactMaterials& materials,
                            std::function<double(double)> separation, double firstTouchPressure)
{
    double sigma = 0.0;
    double Hc = 0.0;
    if (!separation) {
        // The correlation's inputs, as ContactInterface::buildGap takes them: the surfaces'
        // combined rms height and the microhardness (--hardness, else 2.84 S_y).
        sigma = roughnessOf(o).sigma;
        const std::optional<double> H = hardnessOf(o, materials, "--hardness-from-yield");
        if (H) {
            Hc = *H;
        } else {
            try {
                Hc = materials.hardness("the gap's separation");
            } catch (const ParameterError&) {
                throw ParameterError(g.spec.gas ? "--gas" : "--emissivity",
                                     "the gap's separation Y (the plastic Gaussian correlation of sigma and P/H_c; "
                                     "this model and law define no mean separation) needs the microhardness H_c: "
                                     "give --Sy (H_c = 2.84 S_y), --hardness H_C or --hardness-from-yield");
            }
        }
    }
    return InterfaceGap(g.spec, std::move(separation), sigma, Hc, firstTouchPressure);
}

GapRow gapRowOf(const InterfaceGap& gap, const GapInputs& g, double P, bool complete)
{
    GapRow row;
    if (complete) {
        return row; // no gap: Y 0, h_g = h_r = 0 (h infinite)
    }
    double Y = 0.0;
    if (P > 0.0) {
        Y = gap.separation(P);
        row.separation = Y;
    } else if (g.width) {
        Y = *g.width;
        row.separation = Y;
    } else if (gap.hasGas()) {
        throw ParameterError("--gap-width", "at load 0 the surfaces do not touch, and the gas conductance "
                                            "k_g/(Y + M) needs their separation Y: give --gap-width W [m]");
    } else {
        row.separation = std::numeric_limits<double>::quiet_NaN(); // radiation alone needs none
    }
    row.h = gap.conductances(Y, g.T1, g.T2);
    return row;
}

void writeGapCells(std::ostream& out, const InterfaceGap& gap, const GapInputs& g, double P, bool complete,
                   const std::optional<double>& ks, double hPerK)
{
    const GapRow row = gapRowOf(gap, g, P, complete);
    out << ',';
    if (!std::isnan(row.separation)) {
        out << row.separation;
    }
    out << ',' << row.h.gas << ',' << row.h.radiative;
    if (ks) {
        out << ',';
        if (!std::isnan(hPerK)) {
            out << *ks * hPerK + row.h.gas + row.h.radiative; // inf at complete contact
        }
    }
}

SurfaceCheckInputs interfaceInputsOf(const Options& o, const std::string& who)
{
    SurfaceCheckInputs in;
    in.surfaces = surfaceSpecsOf(o);
    in.materials = materialsOf(o);
    in.model = o.model;
    if (!isMultiscaleModel(o.model) && o.model != "boundaryElement") {
        throw ParameterError(who, "takes a multi-scale --model (the laws' area: hertz, jacksonGreen, ...) or "
                                  "boundaryElement, not " + o.model);
    }
    in.conductanceLaw = o.conductanceLaw == "all" ? std::string() : o.conductanceLaw;
    in.hardness = hardnessOf(o, *in.materials, who + " --hardness-from-yield");
    if (!o.vickers.empty()) {
        const std::vector<double> c = splitNumbers(o.vickers, ',', "--vickers");
        if (c.size() != 2) {
            throw ParameterError("--vickers", "expects C1,C2: c1 [Pa] and c2 of H_v = c1 (d_v/1 um)^c2");
        }
        in.vickers = VickersCoefficients{c[0], c[1]};
    }
    return in;
}

} // namespace multiscaleContact
