// SPDX-License-Identifier: GPL-3.0-or-later
// multiscaleContact: real contact area of rough surfaces against load, from the command line.
// The interface is fixed (issue 2): scripts rely on --profile/--spectrum, --model, the
// material options, --loads/--load-range, --levels and the CSV columns load and area. --pressures
// (nominal pressures in Pa, each the load P/E') adds a first column nominal_pressure [Pa].
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
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

#include <CLI/CLI.hpp>

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
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

struct Options {
    std::vector<std::string> profiles;
    std::vector<std::string> areals;
    std::vector<std::string> spectra;
    std::vector<double> powerLaw; // b_m, m, fmin, fmax
    std::vector<double> fractal;  // D, G, fmin, fmax
    std::optional<std::string> units;
    std::optional<double> dx;
    std::optional<double> dy;
    std::optional<std::string> direction;
    bool fillInvalid = false;
    std::string synthesize; // "N[,SEED]"
    std::string resample;   // "N[,K]"
    bool periodic = false;
    std::optional<std::string> detrend; // boundaryElement: none | mean | plane
    std::optional<double> hardness;
    bool hardnessFromYield = false;
    std::string pressureMap; // boundaryElement: the pressure field of the highest load, to this file
    std::optional<double> length;
    std::size_t stride = 1;
    std::string model;
    std::vector<double> E;
    std::vector<double> nu;
    std::optional<double> Eprime;
    std::vector<std::string> Sy; // numbers [Pa], or none: the solid does not yield
    std::vector<std::string> loads; // as given: "1e-5,1e-4" (split here, so "" is an error)
    std::string loadRange;
    std::vector<std::string> pressures; // --pressures: nominal pressures F/A_n [Pa], as given
    std::optional<double> D;
    std::optional<double> G;
    std::string fitRange;
    bool levels = false;
    bool conductance = false;
    std::string conductanceLaw; // --conductance-law NAME (implies --conductance)
    std::string vickers;        // "C1,C2"
    bool info = false;
    bool check = false; // --check: the exact model on this surface against every law
    std::optional<double> k1; // --k1, --k2 [W/(m K)]: add the column h [W/(m^2 K)]
    std::optional<double> k2;
};

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
        throw ParameterError(option, "expects N[,SEED]: " + what + " must be a whole number of decimal digits, got '" +
                                         text + "'");
    }
    if (r.ec == std::errc::result_out_of_range) {
        throw ParameterError(option, what + " " + text + " is beyond the largest, 2^64 - 1 = 18446744073709551615");
    }
    return v;
}

// The loads F/(A_n E') to compute: --loads, --load-range, or --pressures [Pa] divided by E' (Ep);
// `given` (optional) receives the --pressures as given, one per load.
std::vector<double> loadsOf(const Options& o, double Ep, std::vector<double>* given = nullptr)
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
                const double load = P / Ep;
                try {
                    out.push_back(checkLoad(load));
                } catch (const ParameterError&) {
                    std::ostringstream os;
                    os << P << " Pa is the load F/(A_n E') = " << load << " with E' = " << Ep
                       << " Pa; loads must be 0 or within [" << limits::minimumLoad << ", " << limits::maximumLoad
                       << "]";
                    throw ParameterError("--pressures", os.str());
                }
                if (given != nullptr) {
                    given->push_back(P);
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

// How to read the --areal files: the same as the boundary condition's `type areal`.
ArealReadOptions arealReadOptions(const Options& o)
{
    ArealReadOptions ro;
    if (o.units) {
        ro.units = parseLengthUnit(*o.units);
    }
    ro.dx = o.dx;
    ro.dy = o.dy;
    ro.fillInvalid = o.fillInvalid;
    return ro;
}

Spectrum surfaceOf(const Options& o)
{
    if (o.profiles.empty() && o.stride != 1) {
        throw ParameterError("--stride", "subsamples a --profile; there is no profile here");
    }
    if (o.profiles.empty() && o.areals.empty() && o.dx) {
        throw ParameterError("--dx",
                             "is the spacing of a one-column --profile or an --areal matrix; there is "
                             "neither here");
    }
    if (o.areals.empty()) {
        if (o.dy) {
            throw ParameterError("--dy",
                                 "is the y spacing of an --areal matrix; there is no areal surface here");
        }
        if (o.direction) {
            throw ParameterError("--direction",
                                 "chooses the line scans of an --areal surface; there is none here");
        }
        if (o.fillInvalid) {
            throw ParameterError("--fill-invalid", "is for an --areal X3P file; there is none here");
        }
    }
    if (!o.areals.empty()) {
        if (o.stride != 1) {
            throw ParameterError("--stride", "subsamples a --profile; an --areal surface is used whole");
        }
        if (o.length) {
            throw ParameterError("--length", "is set by the areal surface itself (nx dx, ny dy); it is for "
                                             "--spectrum, --power-law and --fractal");
        }
        // The same surface as the boundary condition's `type areal` (SurfaceSpec::Kind::areal).
        const ArealReadOptions ro = arealReadOptions(o);
        const ScanDirection direction = parseScanDirection(o.direction.value_or("x"), "--direction");
        std::optional<Spectrum> total;
        for (const std::string& path : o.areals) {
            const Spectrum s = lineScanSpectrum(readAreal(path, ro).detrended(), direction);
            total = total ? Spectrum::combine(*total, s) : s;
        }
        return *total;
    }
    if (!o.profiles.empty() && o.length) {
        throw ParameterError("--length", "is set by the profile itself (N dx); it is for --spectrum, "
                                         "--power-law and --fractal");
    }
    if (!o.profiles.empty()) {
        ProfileReadOptions ro;
        if (o.units) {
            ro.units = parseLengthUnit(*o.units); // "" is an unknown unit, not the default
        }
        ro.spacing = o.dx;
        std::optional<Spectrum> total;
        for (const std::string& path : o.profiles) {
            const Profile p = readProfile(path, ro).subsampled(o.stride);
            const Spectrum s = Spectrum::fromProfile(p);
            total = total ? Spectrum::combine(*total, s) : s;
        }
        return *total;
    }
    if (!o.spectra.empty()) {
        std::optional<Spectrum> total;
        for (const std::string& path : o.spectra) {
            const Spectrum s = readSpectrum(path, o.length);
            total = total ? Spectrum::combine(*total, s) : s;
        }
        return *total;
    }
    if (!o.powerLaw.empty()) {
        const auto& p = o.powerLaw;
        return Spectrum::powerLaw(p[0], p[1], p[2], p[3], o.length.value_or(0.0));
    }
    const auto& p = o.fractal;
    return Spectrum::fractal(p[0], p[1], p[2], p[3], o.length.value_or(0.0));
}

// sigma and the mean absolute slope of the surfaces, for the correlations (the same surfaces
// surfaceOf reads; two combined): a profile's and a map's from their heights, a spectrum's from
// its moments (Roughness.hpp).
SurfaceRoughness roughnessOf(const Options& o)
{
    std::optional<SurfaceRoughness> total;
    const auto add = [&](const SurfaceRoughness& r) { total = total ? combined(*total, r) : r; };
    if (!o.areals.empty()) {
        const ScanDirection direction = parseScanDirection(o.direction.value_or("x"), "--direction");
        for (const std::string& path : o.areals) {
            add(arealRoughness(readAreal(path, arealReadOptions(o)), direction));
        }
    } else if (!o.profiles.empty()) {
        ProfileReadOptions ro;
        if (o.units) {
            ro.units = parseLengthUnit(*o.units);
        }
        ro.spacing = o.dx;
        for (const std::string& path : o.profiles) {
            add(profileRoughness(readProfile(path, ro).subsampled(o.stride)));
        }
    } else if (!o.spectra.empty()) {
        for (const std::string& path : o.spectra) {
            add(spectrumRoughness(readSpectrum(path, o.length)));
        }
    } else {
        add(spectrumRoughness(surfaceOf(o)));
    }
    return *total;
}

// One --Sy item: a yield strength [Pa], or none (the solid does not yield: Material::elastic).
void readYieldStrength(const std::string& item, Material& m)
{
    if (item == "none") {
        m.elastic = true;
        return;
    }
    m.Sy = splitNumbers(item, ',', "--Sy").front();
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
            readYieldStrength(o.Sy[0], y);
        }
        return ContactMaterials::fromReducedModulus(
            *o.Eprime, o.nu.empty() ? std::nullopt : std::optional<double>(o.nu[0]), y.Sy);
    }
    if (o.E.empty()) {
        throw ParameterError("--E", "give --E (with --nu) or --Eprime");
    }
    if (o.nu.size() != o.E.size()) {
        throw ParameterError("--nu", "give one Poisson's ratio per --E value");
    }
    if (!o.Sy.empty() && o.Sy.size() != o.E.size()) {
        throw ParameterError("--Sy", "give one yield strength per --E value");
    }
    std::vector<Material> m(o.E.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
        m[i].E = o.E[i];
        m[i].nu = o.nu[i];
        if (!o.Sy.empty()) {
            readYieldStrength(o.Sy[i], m[i]);
        }
    }
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
        const ArealReadOptions ro = arealReadOptions(o);
        std::optional<ArealSurface> total;
        for (const std::string& path : o.areals) {
            // As read: BoundaryElementModel detrends the composite (--detrend).
            const ArealSurface one = readAreal(path, ro);
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
    // N and SEED as whole numbers, read as integers: a double of 2^64 or more does not convert
    // to a seed (it was undefined behaviour, and gave seed 0's surface).
    const std::size_t comma = o.synthesize.find(',');
    const std::uint64_t nGiven = gridSizeOf(o.synthesize.substr(0, comma), "--synthesize");
    const auto seed = comma == std::string::npos
                          ? std::uint64_t(1)
                          : wholeNumber(o.synthesize.substr(comma + 1), "--synthesize", "the seed SEED");
    const Spectrum lineScan = surfaceOf(o);
    const auto n = static_cast<std::size_t>(nGiven);
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

// The surfaces as SurfaceSpecs (the boundary condition's description of the same options).
std::vector<SurfaceSpec> surfaceSpecsOf(const Options& o)
{
    surfaceOf(o); // every rule of the surface options (and the files readable) before anything else
    std::vector<SurfaceSpec> out;
    const auto add = [&](SurfaceSpec::Kind kind, const std::string& file) {
        SurfaceSpec s;
        s.kind = kind;
        s.file = file;
        if (o.units) {
            s.profileOptions.units = parseLengthUnit(*o.units);
        }
        s.profileOptions.spacing = o.dx;
        s.arealOptions = arealReadOptions(o);
        s.direction = parseScanDirection(o.direction.value_or("x"), "--direction");
        s.stride = o.stride;
        s.length = o.length;
        out.push_back(s);
    };
    for (const std::string& f : o.profiles) {
        add(SurfaceSpec::Kind::profile, f);
    }
    for (const std::string& f : o.areals) {
        add(SurfaceSpec::Kind::areal, f);
    }
    for (const std::string& f : o.spectra) {
        add(SurfaceSpec::Kind::spectrum, f);
    }
    if (!o.powerLaw.empty()) {
        add(SurfaceSpec::Kind::powerLaw, "");
        out.back().parameters = o.powerLaw;
    }
    if (!o.fractal.empty()) {
        add(SurfaceSpec::Kind::fractal, "");
        out.back().parameters = o.fractal;
    }
    return out;
}

// --check: the exact model on this surface at up to 5 of the run's pressures (or 4 across their
// range), every law's ratio to it; the report, then its numbers as CSV, on stdout.
int runCheck(const Options& o)
{
    if (o.levels) {
        throw ParameterError("--check", "checks the conductance; --levels is for the per-level trace");
    }
    if (o.conductance || !o.conductanceLaw.empty()) {
        if (o.conductanceLaw == "all") {
            throw ParameterError("--check", "holds every law to the exact answer already; --conductance-law names "
                                            "the one to judge");
        }
    }
    if (!o.pressureMap.empty()) {
        throw ParameterError("--pressure-map", "is for a boundaryElement curve, not --check");
    }
    if (o.k1 || o.k2) {
        throw ParameterError(o.k1 ? "--k1" : "--k2", "--check compares h_c/k_s, which the conductivities do not change");
    }
    SurfaceCheckInputs in;
    in.surfaces = surfaceSpecsOf(o);
    in.materials = materialsOf(o);
    in.model = o.model;
    if (!isMultiscaleModel(o.model) && o.model != "boundaryElement") {
        throw ParameterError("--check", "takes a multi-scale --model (the laws' area: hertz, jacksonGreen, ...) or "
                                        "boundaryElement, not " + o.model);
    }
    in.conductanceLaw = o.conductanceLaw;
    in.hardness = hardnessOf(o, *in.materials, "--check --hardness-from-yield");
    if (!o.vickers.empty()) {
        const std::vector<double> c = splitNumbers(o.vickers, ',', "--vickers");
        if (c.size() != 2) {
            throw ParameterError("--vickers", "expects C1,C2: c1 [Pa] and c2 of H_v = c1 (d_v/1 um)^c2");
        }
        in.vickers = VickersCoefficients{c[0], c[1]};
    }
    if (o.periodic) {
        in.periodic = true;
    }
    if (o.detrend) {
        in.detrend = parseDetrend(*o.detrend, "--detrend");
    }
    // The pressures [Pa]: --pressures as given (no round trip through the load), or the loads x E'.
    const double Ep = in.materials->reducedModulus();
    std::vector<double> given;
    const std::vector<double> loads = loadsOf(o, Ep, &given);
    std::vector<double> pressures;
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const double P = given.empty() ? loads[i] * Ep : given[i];
        if (P > 0.0) {
            pressures.push_back(P);
        }
    }
    if (pressures.empty()) {
        throw ParameterError("--check", "needs pressures above 0");
    }
    std::sort(pressures.begin(), pressures.end());
    SurfaceCheckOptions so;
    if (!o.resample.empty()) {
        throw ParameterError("--resample", "is for --model boundaryElement; --check chooses its own grids");
    }
    if (!o.synthesize.empty()) {
        const std::size_t comma = o.synthesize.find(',');
        if (comma != std::string::npos) {
            throw ParameterError("--synthesize", "with --check takes the grid size N only (the check solves seeds 1, 2 and 3)");
        }
        so.gridSize = static_cast<std::size_t>(wholeNumber(o.synthesize, "--synthesize", "the grid size N"));
    }
    in.minPressure = pressures.front();
    in.maxPressure = pressures.back();
    if (pressures.size() <= 5) {
        so.pressures = pressures;
    }
    so.log = [](const std::string& line) { std::cerr << "multiscaleContact: " << line << std::endl; };
    const SurfaceCheck c = checkSurface(in, so);
    std::istringstream report(c.report());
    std::ostringstream out;
    for (std::string line; std::getline(report, line);) {
        out << "# " << line << '\n';
    }
    out << c.csv();
    std::cout << out.str();
    return 0;
}

// --model boundaryElement: the curve, one progress line on stderr per load once the run takes
// longer than 2 s, then the whole CSV.
int runBoundaryElement(const Options& o)
{
    if (o.levels) {
        throw ParameterError("--levels", "the per-level trace exists for the multi-scale models only");
    }
    const auto [surface, periodic] = arealSurfaceOf(o);
    const ContactMaterials materials = materialsOf(o);
    BoundaryElementOptions bo;
    bo.periodic = periodic;
    if (o.detrend) {
        bo.detrend = parseDetrend(*o.detrend, "--detrend");
    }
    bo.hardness = hardnessOf(o, materials, "boundaryElement --hardness-from-yield");
    std::vector<double> pressures; // --pressures [Pa]: the first column
    const std::vector<double> loads = loadsOf(o, materials.reducedModulus(), &pressures);
    if (!o.pressureMap.empty()) {
        checkOutputFile(o, o.pressureMap, "--pressure-map"); // before minutes of solving
    }
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // A solve that runs longer than a few seconds says where it is (PolonskyKeer.hpp), and which
    // load it is of (in the order solved, increasing).
    std::size_t current = 1;
    bo.progress = [&](const SolveProgress& s) {
        std::cerr << "multiscaleContact: boundaryElement " << surface.nx() << " x " << surface.ny() << ": ";
        if (std::string(s.stage) != "bonded-patch conductance") {
            std::cerr << "load " << current << " of " << loads.size() << ", ";
        }
        std::cerr << s.stage << " solve: iteration " << s.iteration << ", residual " << s.residual << " (tolerance " << s.tolerance
                  << "), " << s.seconds << " s in this solve; " << seconds() << " s in all" << std::endl;
    };
    const BoundaryElementModel model(surface, materials.reducedModulus(), bo);
    {
        // Before a long run, what to expect (a timed FFT pair times the solves' evaluations).
        const HalfSpaceOperator op(surface.nx(), surface.ny(), surface.dx(), surface.dy(), materials.reducedModulus(),
                                   periodic);
        const double expected = estimatedCurveSeconds(op, loads.size() + (o.pressureMap.empty() ? 0 : 1));
        if (expected > 3.0) {
            std::cerr << "multiscaleContact: boundaryElement " << surface.nx() << " x " << surface.ny() << ": "
                      << loads.size() << " load" << (loads.size() == 1 ? "" : "s") << ", about "
                      << std::setprecision(2) << expected << std::setprecision(6) << " s" << std::endl;
        }
    }
    const std::vector<BoundaryElementPoint> points =
        model.curve(loads, [&](std::size_t done, std::size_t total, const BoundaryElementPoint& p) {
            current = done + 1;
            if (seconds() > 2.0) {
                std::cerr << "multiscaleContact: boundaryElement " << surface.nx() << " x " << surface.ny()
                          << (periodic ? " (periodic)" : " (non-periodic)") << ": load " << done << " of " << total
                          << ", F/(A_n E') = " << p.load << ": A_r/A_n = " << p.areaFraction << ", "
                          << p.iterations << " iterations, residual " << p.residual << "; " << seconds()
                          << " s\n";
            }
        });
    std::ostringstream out;
    out.precision(10);
    const std::optional<double> ks = harmonicConductivityOf(o, true);
    out << (pressures.empty() ? "" : "nominal_pressure,") << "load,area,pressure,separation,h_per_k,"
        << (ks ? "h," : "") << "iterations,residual\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        const BoundaryElementPoint& p = points[i];
        if (!pressures.empty()) {
            out << pressures[i] << ',';
        }
        out << p.load << ',' << p.areaFraction << ',';
        if (p.areaFraction > 0.0) {
            out << p.load / p.areaFraction;
        }
        out << ',' << p.meanSeparation << ',' << p.conductancePerConductivity << ',';
        if (ks) {
            out << *ks * p.conductancePerConductivity << ',';
        }
        out << p.iterations << ',' << p.residual << '\n';
    }
    if (!o.pressureMap.empty()) {
        // The highest load's field again (one more solve, warm-started from nothing): written as
        // a text matrix the areal reader reads back (rows along x, one per line, along y), to a
        // temporary file beside the target, renamed over it once complete: a failed run leaves
        // nothing behind and changes nothing.
        const double top = *std::max_element(loads.begin(), loads.end());
        current = loads.size();
        std::vector<double> pressure;
        model.solve(top, &pressure);
        const std::string temporary = o.pressureMap + ".tmp." + std::to_string(static_cast<long>(::getpid()));
        std::ofstream map(temporary, std::ios::trunc);
        map << "# contact pressure [Pa] of multiscaleContact --model boundaryElement at F/(A_n E') = " << top
            << "; " << surface.nx() << " x " << surface.ny() << " points at dx = " << surface.dx()
            << " m, dy = " << surface.dy() << " m; rows along x, one per line, following each other along y\n";
        map.precision(8);
        for (std::size_t iy = 0; iy < surface.ny(); ++iy) {
            for (std::size_t ix = 0; ix < surface.nx(); ++ix) {
                map << (ix > 0 ? " " : "") << (pressure.empty() ? 0.0 : pressure[iy * surface.nx() + ix]);
            }
            map << '\n';
        }
        map.close();
        if (!map) {
            std::remove(temporary.c_str());
            throw ParameterError("--pressure-map", "writing '" + temporary + "' failed");
        }
        if (std::rename(temporary.c_str(), o.pressureMap.c_str()) != 0) {
            std::remove(temporary.c_str());
            throw ParameterError("--pressure-map", "cannot rename '" + temporary + "' to '" + o.pressureMap + "'");
        }
    }
    std::cout << out.str();
    return 0;
}

int run(const Options& o)
{
    if (o.check) {
        return runCheck(o);
    }
    if (o.model == "boundaryElement") {
        return runBoundaryElement(o);
    }
    const bool cmy = o.conductanceLaw == "cooperMikicYovanovich" || o.conductanceLaw == "all";
    for (const auto& [given, what] : {std::pair<bool, const char*>{!o.synthesize.empty(), "--synthesize"},
                                      {!o.resample.empty(), "--resample"},
                                      {o.periodic, "--periodic"},
                                      {o.detrend.has_value(), "--detrend"},
                                      {o.hardness.has_value() && !cmy, "--hardness"},
                                      {o.hardnessFromYield && !cmy, "--hardness-from-yield"},
                                      {!o.pressureMap.empty(), "--pressure-map"}}) {
        if (given) {
            throw ParameterError(what, std::string("is for --model boundaryElement") +
                                           (std::string(what).rfind("--hardness", 0) == 0
                                                ? " and --conductance-law cooperMikicYovanovich"
                                                : ""));
        }
    }
    if (!o.vickers.empty() && !cmy) {
        throw ParameterError("--vickers", "is for --conductance-law cooperMikicYovanovich");
    }
    const Spectrum spectrum = surfaceOf(o);
    if (o.info) {
        printInfo(spectrum, std::cerr);
    }
    const ContactMaterials materials = materialsOf(o);
    ModelOptions mo;
    if (o.D || o.G) {
        if (!(o.D && o.G)) {
            throw ParameterError("--D/--G", "give both or neither");
        }
        mo.fractal = FractalParameters{*o.D, *o.G};
    } else if (!o.fractal.empty()) {
        mo.fractal = FractalParameters{o.fractal[0], o.fractal[1]};
    } else if (o.model == "majumdarBhushan" && !o.fitRange.empty()) {
        const std::vector<double> r = splitNumbers(o.fitRange, ':', "--fit-range");
        if (r.size() != 2) {
            throw ParameterError("--fit-range", "expects FMIN:FMAX");
        }
        mo.fractal = fitFractal(spectrum, r[0], r[1]);
    }
    std::vector<double> pressures; // --pressures [Pa]: the first column
    const std::vector<double> loads = loadsOf(o, materials.reducedModulus(), &pressures);
    const auto model = makeContactModel(o.model, spectrum, materials, mo);

    // The whole CSV is made before any of it is printed: an error half way leaves stdout empty.
    std::ostringstream out;
    out.precision(10);
    if (o.levels) {
        const auto* ms = dynamic_cast<const MultiscaleModel*>(model.get());
        if (ms == nullptr) {
            throw ParameterError("--levels", "the per-level trace exists for the multi-scale models only");
        }
        const double An = spectrum.nominalArea();
        out << (pressures.empty() ? "" : "nominal_pressure,")
            << "load,level,frequency,amplitude,eta,radius,asperities,asperity_force,area,complete\n";
        for (std::size_t i = 0; i < loads.size(); ++i) {
            const double load = loads[i];
            for (const LevelState& s : ms->trace(load)) {
                if (!pressures.empty()) {
                    out << pressures[i] << ',';
                }
                out << load << ',' << s.index + 1 << ',' << s.frequency << ',' << s.amplitude << ','
                          << s.density << ',' << s.radius << ',' << s.asperities << ',' << s.asperityForce
                    << ',' << s.area / An << ',' << (s.complete ? 1 : 0) << '\n';
            }
        }
        std::cout << out.str();
        return 0;
    }
    const auto* ms = dynamic_cast<const MultiscaleModel*>(model.get());
    const auto* persson = dynamic_cast<const PerssonModel*>(model.get());
    const bool conductance = o.conductance || !o.conductanceLaw.empty();
    const bool allLaws = o.conductanceLaw == "all";
    // persson's own conductance (Barber's relation with its mean separation) unless a law is named.
    const std::string lawName = o.conductanceLaw.empty() || allLaws
                                    ? (persson != nullptr ? "persson" : defaultConductanceLaw())
                                    : o.conductanceLaw;
    ConductanceLawInputs in;
    if (conductance) {
        in.multiscale = ms;
        in.spectrum = &spectrum;
        in.Eprime = materials.reducedModulus();
        if (allLaws || conductanceLawNeedsRoughness(lawName)) {
            in.roughness = roughnessOf(o);
        }
        in.microhardness = hardnessOf(o, materials, "--hardness-from-yield");
        // fittedElastoPlastic's cap: --hardness (or from yield), else 2.84 S_y where --Sy is given.
        in.hardness = conductanceLawHardness(in.microhardness, materials);
        if (!o.vickers.empty()) {
            const std::vector<double> c = splitNumbers(o.vickers, ',', "--vickers");
            if (c.size() != 2) {
                throw ParameterError("--vickers", "expects C1,C2: c1 [Pa] and c2 of H_v = c1 (d_v/1 um)^c2");
            }
            in.vickers = VickersCoefficients{c[0], c[1]};
        }
    }
    // Why a law cannot be built here, or "" when it can.
    const auto missing = [&](const std::string& name) -> std::string {
        if (name == "cooperMikicYovanovich" && !in.microhardness && !in.vickers) {
            return "needs the microhardness: --hardness H_C [Pa], --hardness-from-yield (2.84 S_y) or "
                   "--vickers C1,C2";
        }
        if ((name == "jacksonBhavnaniFerguson" || name == "multiscaleBarber") && ms == nullptr) {
            return "needs a multi-scale model; choose another --conductance-law (mikic, persson, ...)";
        }
        return "";
    };
    std::unique_ptr<ConductanceLaw> law; // the h_per_k column's (none: persson's own)
    if (conductance && !(persson != nullptr && lawName == "persson")) {
        const std::string why = missing(lawName);
        if (!why.empty() && allLaws) {
            // all: h_per_k stays empty where the default law cannot be built; the other columns say.
        } else if (!why.empty()) {
            throw ParameterError(o.conductanceLaw.empty() ? "--conductance" : "--conductance-law " + lawName,
                                 (o.conductanceLaw.empty() ? "the default law " + lawName + " " : "") + why);
        }
        if (why.empty()) {
            law = makeConductanceLaw(lawName, in);
        }
    }
    // --conductance-law all: every law that can be built here, a column h_per_k_NAME each.
    std::vector<std::pair<std::string, std::unique_ptr<ConductanceLaw>>> every;
    if (allLaws) {
        for (const std::string& name : conductanceLawNames()) {
            const std::string why = missing(name);
            if (why.empty()) {
                every.emplace_back(name, makeConductanceLaw(name, in));
            } else {
                std::cerr << "multiscaleContact: --conductance-law all: no column for " << name << ": " << why
                          << '\n';
            }
        }
    }
    if (conductance) {
        // The regime at the run's lightest and heaviest load and the law's measured accuracy there
        // (InterfaceRegime.hpp), on stderr: the hardness the materials give (2.84 S_y) or
        // --hardness; the law held to the capped reference where the area model caps the pressure.
        std::vector<double> positive;
        for (double l : loads) {
            if (l > 0.0) {
                positive.push_back(l);
            }
        }
        if (!positive.empty()) {
            const double Ep = materials.reducedModulus();
            const std::optional<double> H = in.hardness; // conductanceLawHardness
            const std::string shown = law || persson == nullptr ? lawName : std::string("persson");
            const bool capped = heldToCappedReference(o.model, shown, H.has_value());
            const auto [lo, hi] = std::minmax_element(positive.begin(), positive.end());
            const InterfaceRegime r =
                interfaceRegime(spectrum, Ep, H, shown, persson != nullptr ? std::string("persson") : o.model, capped,
                                *lo * Ep, *hi * Ep);
            std::cerr << "multiscaleContact: " << r.describe() << std::endl;
        }
    }
    const std::optional<double> ks = harmonicConductivityOf(o, conductance);
    out << (pressures.empty() ? "" : "nominal_pressure,") << "load,area,pressure" << (conductance ? ",separation,h_per_k" : "")
        << (ks ? ",h" : "");
    for (const auto& [name, l] : every) {
        out << ",h_per_k_" << name;
    }
    out << '\n';
    const double Ep = materials.reducedModulus();
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const double load = loads[i];
        if (!pressures.empty()) {
            out << pressures[i] << ',';
        }
        if (persson != nullptr && conductance) {
            // Persson's theory: the mean separation [m] and Barber's h_c/k_s = -(1/E') dp/du
            // (Persson.hpp), or the named law's; u = inf at load 0, h_per_k = inf beyond double range.
            const PerssonPoint p = persson->evaluate(load);
            out << load << ',' << p.areaFraction << ',';
            if (p.areaFraction > 0.0) {
                out << load / p.areaFraction;
            }
            const double hk = law ? law->perConductivity(load * Ep) : p.conductancePerConductivity;
            out << ',' << p.meanSeparation << ',' << hk;
            if (ks) {
                out << ',' << *ks * hk;
            }
        } else {
            const double a = model->areaFraction(load);
            out << load << ',' << a << ',';
            if (a > 0.0) {
                out << load / a; // F/(A_r E'), seed Eq. 34
            }
            if (conductance) {
                // No mean separation in these models: the law's where it defines one
                // (ConductanceLaw::meanSeparation: persson, multiscaleBarber), else empty.
                out << ',';
                if (law) {
                    const double Y = law->meanSeparation(load * Ep);
                    if (!std::isnan(Y)) {
                        out << Y;
                    }
                }
                out << ',';
                if (law) {
                    out << law->perConductivity(load * Ep); // inf at complete contact
                }
                if (ks) {
                    out << ',';
                    if (law) {
                        out << *ks * law->perConductivity(load * Ep);
                    }
                }
            }
        }
        for (const auto& [name, l] : every) {
            out << ',' << l->perConductivity(load * Ep);
        }
        out << '\n';
    }
    std::cout << out.str();
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{
        "multiscaleContact: real contact area A_r/A_n of a rough surface against a flat, or of two rough\n"
        "surfaces, as a function of the load F/(A_n E'), by the multi-scale model of Jackson & Streator\n"
        "(2006) and the models it is compared with. Prints CSV on stdout: load,area,pressure with\n"
        "load = F/(A_n E'), area = A_r/A_n and pressure = F/(A_r E') (with --pressures, a first column\n"
        "nominal_pressure = F/A_n [Pa]); errors go to stderr, exit 1.",
        "multiscaleContact"};
    Options o;

    auto* surface = app.add_option_group("surface", "exactly one surface description");
    surface
        ->add_option("--profile", o.profiles,
                     "measured profile: columns 'x z', or 'z' with --dx; comma or whitespace separated, "
                     "# comments and one header line allowed, Dektak CSV exports read as is; mean and tilt "
                     "are removed. Give it twice for two rough surfaces")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);
    surface
        ->add_option(
            "--areal", o.areals,
            "measured areal surface (height map): an X3P file (.x3p, ISO 25178-72), or a text matrix "
            "of heights (rows along y, columns along x) with --dx (and --dy, --units); plane removed, "
            "its line scans (--direction) averaged into one spectrum. Twice for two rough surfaces")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);
    surface
        ->add_option("--spectrum", o.spectra,
                     "spectrum table: columns 'frequency [1/m]  amplitude [m]'; twice for two surfaces")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);
    surface
        ->add_option("--power-law", o.powerLaw,
                     "BM,M,FMIN,FMAX: amplitude BM f^-M [m] at f = i/L in [FMIN, FMAX]")
        ->delimiter(',')
        ->expected(4);
    surface
        ->add_option("--fractal", o.fractal,
                     "D,G,FMIN,FMAX: Majumdar-Bhushan (Weierstrass-Mandelbrot) spectrum, G in m")
        ->delimiter(',')
        ->expected(4);
    surface->require_option(1);

    app.add_option("--units", o.units,
                   "units of profile and --areal matrix files: m (default), um or nm; a Dektak export's "
                   "own header (um) is used when this is not given");
    app.add_option("--dx", o.dx,
                   "sample spacing of one-column profiles and of --areal matrices (along x), in --units");
    app.add_option("--dy", o.dy, "spacing along y of an --areal matrix, in --units (default --dx)");
    app.add_option("--direction", o.direction,
                   "line scans of an --areal surface: x (rows, default), y (columns) or both");
    app.add_flag("--fill-invalid", o.fillInvalid,
                 "fill the invalid points of an --areal X3P file with the mean of their valid neighbours "
                 "(default: they are an error)");
    app.add_option("--length", o.length,
                   "scan length L [m] for --spectrum/--power-law/--fractal "
                   "(default 1/lowest frequency); A_n = L^2");
    app.add_option("--stride", o.stride,
                   "use every K-th profile sample (sampling interval K dx; seed Fig. 8)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1000000000)));

    std::vector<std::string> allModels = modelNames();
    allModels.push_back("boundaryElement");
    app.add_option("--model", o.model,
                   "hertz | jgh | jghConsistent | jacksonGreen | truncation (multi-scale, seed §2) | "
                   "greenwoodWilliamson | greenwoodWilliamsonJG | majumdarBhushan | persson (Persson's theory, "
                   "Yang-Persson mean separation, gamma 0.42, on the isotropic 2-D form of the spectrum) | "
                   "boundaryElement (the exact reference: boundary elements on an --areal or --synthesize'd "
                   "surface)")
        ->required()
        ->check(CLI::IsMember(allModels));
    app.add_option("--synthesize", o.synthesize,
                   "N[,SEED]: boundaryElement on an N x N isotropic Gaussian surface synthesized from the "
                   "--profile/--spectrum/--power-law/--fractal (periodic; SEED default 1)");
    app.add_option("--resample", o.resample,
                   "N[,K]: boundaryElement on the --synthesize'd surface put on an N x N grid (its Fourier series "
                   "there: the same surface, finer or coarser), without its wavelengths shorter than L/K if K is "
                   "given (the same surface with fewer levels)");
    app.add_flag("--periodic", o.periodic,
                 "boundaryElement: solve an --areal map as one period of a periodic surface (default: "
                 "non-periodic, zero-padded)");
    app.add_option("--detrend", o.detrend,
                   "boundaryElement: what is removed from the heights before the solve: none, mean or plane "
                   "(default: mean for a periodic solve, which has no trend to remove; plane for a "
                   "non-periodic map, whose fixture tilts it)");
    app.add_option("--hardness", o.hardness, "boundaryElement: perfectly plastic cap p <= H [Pa]");
    app.add_option("--pressure-map", o.pressureMap,
                   "boundaryElement: write the contact pressure [Pa] at the highest load to this file, as a "
                   "text matrix (rows along x, one per line)");
    app.add_flag("--hardness-from-yield", o.hardnessFromYield,
                 "boundaryElement: the cap H = 2.84 S_y (--Sy of the yielding material)");

    auto* E = app.add_option("--E", o.E, "Young's modulus [Pa]; E1,E2 for two solids")
                  ->delimiter(',')
                  ->expected(1, 2);
    app.add_option("--nu", o.nu, "Poisson's ratio; nu1,nu2 with two moduli")->delimiter(',')->expected(1, 2);
    auto* Ep = app.add_option("--Eprime", o.Eprime, "reduced modulus E' [Pa] instead of --E/--nu");
    E->excludes(Ep);
    app.add_option("--Sy", o.Sy,
                   "yield strength [Pa] (jacksonGreen, truncation, greenwoodWilliamsonJG, "
                   "majumdarBhushan); Sy1,Sy2 with two moduli, none for a solid that does not yield "
                   "(Sy1,none)")
        ->delimiter(',')
        ->expected(1, 2);

    auto* loads = app.add_option("--loads", o.loads, "loads F/(A_n E'), comma separated: 0, or 1e-30 to 1e4");
    auto* range = app.add_option("--load-range", o.loadRange, "MIN:MAX:N, N loads log spaced");
    loads->excludes(range);
    auto* pressures = app.add_option("--pressures", o.pressures,
                                     "nominal pressures F/A_n [Pa], comma separated, instead of --loads: each is "
                                     "the load P/E' (E' from --E/--nu or --Eprime); the output gains a first "
                                     "column nominal_pressure [Pa]");
    pressures->excludes(loads);
    pressures->excludes(range);

    app.add_option("--D", o.D, "Majumdar-Bhushan fractal dimension (default: fitted to the spectrum)");
    app.add_option("--G", o.G, "Majumdar-Bhushan fractal roughness [m] (default: fitted)");
    app.add_option("--fit-range", o.fitRange, "FMIN:FMAX [1/m]: frequencies the D,G fit uses (default all)");
    app.add_flag("--levels", o.levels, "print the per-level trace (seed Fig. 5) instead of the load curve");
    app.add_flag(
        "--conductance", o.conductance,
        "add the columns separation and h_per_k: contact conductance over k_s = 2 k1 k2/(k1 + k2), in 1/m, "
        "from the --conductance-law (default: the multi-scale constriction resistances in series, inf at "
        "complete contact, for the multi-scale models; for persson its mean separation [m] and Barber's "
        "h_c/k_s = -(1/E') dp/du); separation [m] is the model's (persson) or the law's (persson, "
        "multiscaleBarber: Barber-consistent with their h_per_k), empty where neither defines one");
    std::string lawNames;
    for (const std::string& n : conductanceLawNames()) {
        lawNames += (lawNames.empty() ? "" : ", ") + n;
    }
    app.add_option("--conductance-law", o.conductanceLaw,
                   "the law of the h_per_k column (implies --conductance): " + lawNames + " (default " +
                       defaultConductanceLaw() + "); 'all': the default's column and one h_per_k_NAME "
                       "column per law that can be built. cooperMikicYovanovich needs the microhardness: "
                       "--hardness H_C, --hardness-from-yield (2.84 S_y) or --vickers C1,C2");
    app.add_option("--vickers", o.vickers,
                   "cooperMikicYovanovich: Vickers coefficients C1 [Pa], C2 of H_v = c1 (d_v/1 um)^c2, the "
                   "microhardness from Song & Yovanovich's correlation");
    app.add_flag("--info", o.info, "print the surface's parameters (McCool, fractal fit) to stderr");
    app.add_option("--k1", o.k1, "conductivity [W/(m K)] of solid 1: with --k2, add the column h = k_s h_per_k "
                                 "[W/(m^2 K)], k_s = 2 k1 k2/(k1 + k2)");
    app.add_option("--k2", o.k2, "conductivity [W/(m K)] of solid 2 (with --k1)");
    app.add_flag("--check", o.check,
                 "check the laws on this surface: the exact model (boundaryElement) on the --areal map, or on "
                 "3 surfaces of 512 x 512 (--synthesize N) synthesized from the profile or spectrum, at the "
                 "given pressures (up to 5) or 4 across their range, within p/(E' h') 1e-4 to 1e-1; capped at "
                 "H where --Sy, --hardness or --hardness-from-yield say, elastic otherwise. Prints every law's "
                 "ratio to the exact h_c/k_s, the closest, and whether the chosen law (--conductance-law, "
                 "default " + defaultConductanceLaw() + ") is within 25 %");

    try {
        app.parse(argc, argv);
        if (o.loads.empty() && o.loadRange.empty() && o.pressures.empty()) {
            throw CLI::RequiredError("--loads, --load-range or --pressures");
        }
    } catch (const CLI::ParseError& e) {
        // CLI11 prints the message (or the help); its own codes (104-114) become the README's 1.
        return app.exit(e) == 0 ? 0 : 1;
    }
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::cerr << "multiscaleContact: error: " << e.what() << '\n';
        return 1;
    }
}
