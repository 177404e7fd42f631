// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/SurfaceCheck.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

namespace roughContact {

namespace {

/// The clipped range of the check in p/(E' h') (SurfaceCheck.hpp says why).
constexpr double lightestLoadPerGradient = 1e-4;
constexpr double heaviestLoadPerGradient = 1e-1;
/// Capped: the heaviest checked pressure, as a fraction of H (at H every point flows).
constexpr double heaviestPerHardness = 0.9;

// v with d significant digits.
std::string withDigits(double v, int d)
{
    std::ostringstream os;
    os << std::setprecision(d) << v;
    return os.str();
}

std::string number(double v)
{
    return withDigits(v, 4);
}

// The light-load period's range, 1 to Spectrum::maximumPeriodMultiple scan lengths (the one place
// of the rule: the front-ends' checkedLightLoadPeriods and checkSurface's own options).
void requireLightLoadPeriods(std::uint64_t periods, const std::string& name)
{
    if (periods < 1 || periods > Spectrum::maximumPeriodMultiple) {
        throw ParameterError(name, "must be 1 to " + std::to_string(Spectrum::maximumPeriodMultiple) +
                                       " scan lengths, got " + std::to_string(periods));
    }
}

} // namespace

std::size_t checkedLightLoadPeriods(std::uint64_t periods, const std::vector<SurfaceSpec>& surfaces,
                                    const std::string& name)
{
    for (const SurfaceSpec& s : surfaces) {
        if (s.kind == SurfaceSpec::Kind::areal) {
            throw ParameterError(name, "is for a profile or spectrum, whose surfaces the check synthesizes; an "
                                       "areal map is solved as itself");
        }
    }
    requireLightLoadPeriods(periods, name);
    return static_cast<std::size_t>(periods);
}

const CheckedLaw& SurfaceCheck::chosen() const
{
    for (const CheckedLaw& l : laws) {
        if (l.name == chosenLaw) {
            return l;
        }
    }
    throw ParameterError("conductance", "the chosen law '" + chosenLaw + "' is not among the checked laws");
}

std::vector<double> SurfaceCheck::chosenMisses() const
{
    std::vector<double> out;
    const CheckedLaw& l = chosen();
    for (std::size_t i = 0; i < l.ratio.size(); ++i) {
        if (!(std::fabs(l.ratio[i] - 1.0) <= checkTolerance)) {
            out.push_back(pressures[i]);
        }
    }
    return out;
}

std::string SurfaceCheck::report() const
{
    std::ostringstream os;
    os << "check of the surface: " << surface << "; " << regime << ", E' = " << number(reducedModulus)
       << " Pa, h' = " << number(gradient) << "\n";
    if (levelsKept < levelsGiven && onePeriodPressures > 0) {
        os << "  the check holds the surface's " << levelsKept << " longest levels of " << levelsGiven
           << " (the finest a " << "grid resolves with 8 cells a wavelength); the laws are held to "
              "the exact answer on that surface\n";
    }
    if (lightLoadPeriods > 1) {
        os << "  below p/(E' h') = " << smallCellLoadPerGradient << " the check solves periods of " << lightLoadPeriods
           << " scan lengths on the same grid: the surface's " << lightLevelsKept
           << " longest levels on that period (wavelengths down to 8 cells), the laws held to them there\n";
    }
    if (!dropped.empty()) {
        // With as many digits as it takes to tell each dropped pressure from the range's ends (a
        // load typed at an end, such as p/(E' h') = 1e-4 with h' rounded, falls just outside).
        const auto apart = [&](int d) {
            for (double P : dropped) {
                const std::string p = withDigits(P, d);
                if (p == withDigits(lowestCheckable, d) || p == withDigits(highestCheckable, d)) {
                    return false;
                }
            }
            return true;
        };
        int digits = 4; // number()'s
        while (digits < std::numeric_limits<double>::max_digits10 && !apart(digits)) {
            ++digits;
        }
        os << "  not checked:";
        for (double P : dropped) {
            os << " " << withDigits(P, digits);
        }
        os << " Pa (outside the checked range " << withDigits(lowestCheckable, digits) << " to "
           << withDigits(highestCheckable, digits)
           << " Pa: p/(E' h') within [1e-4, 1e-1]" << (hardness ? ", at most 0.9 H" : "") << ")\n";
    }
    const std::size_t width = 13;
    os << "  " << std::left << std::setw(26) << "P [Pa]";
    for (double P : pressures) {
        os << std::right << std::setw(width) << number(P);
    }
    os << "\n  " << std::left << std::setw(26) << "p/(E' h')";
    for (double P : pressures) {
        os << std::right << std::setw(width) << number(P / (reducedModulus * gradient));
    }
    os << "\n  " << std::left << std::setw(26) << "exact A_r/A_n";
    for (double a : exactArea) {
        os << std::right << std::setw(width) << number(a);
    }
    os << "\n  " << std::left << std::setw(26) << "exact h_c/k_s [1/m]";
    for (double h : exactHPerK) {
        os << std::right << std::setw(width) << number(h);
    }
    os << "\n  " << std::left << std::setw(26) << "  seeds' spread";
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        std::ostringstream spread;
        spread << std::fixed << std::setprecision(2) << exactHPerKLow[i] / exactHPerK[i] << "-"
               << exactHPerKHigh[i] / exactHPerK[i];
        os << std::right << std::setw(width) << (exactHPerKLow[i] == exactHPerKHigh[i] ? std::string("-") : spread.str());
    }
    os << "\n  law / exact:\n";
    for (const CheckedLaw& l : laws) {
        os << "  " << (l.name == chosenLaw ? "* " : "  ") << std::left << std::setw(24) << l.name;
        if (!l.unavailable.empty()) {
            os << "  (not checked: " << l.unavailable << ")\n";
            continue;
        }
        for (double r : l.ratio) {
            os << std::right << std::setw(width) << number(r);
        }
        os << "\n";
    }
    for (const CheckedLaw& l : laws) {
        if (l.name == closestLaw) {
            os << "  closest: " << closestLaw << " (off by a factor of at most " << number(l.worstFactor) << ")\n";
        }
    }
    const std::vector<double> misses = chosenMisses();
    os << "  the chosen law (*) " << chosenLaw;
    if (misses.empty()) {
        os << " is within " << int(checkTolerance * 100 + 0.5) << " % of the exact conductance at every checked pressure";
    } else {
        os << " misses the exact conductance by more than " << int(checkTolerance * 100 + 0.5) << " % at "
           << misses.size() << " of " << pressures.size() << " checked pressures";
    }
    os << " (" << number(seconds) << " s)\n";
    if (!exactWarning.empty()) {
        os << "  warning: " << exactWarning << "\n";
    }
    if (!smallCellNote.empty()) {
        os << "  note: " << smallCellNote << "\n";
    }
    return os.str();
}

std::string SurfaceCheck::csv() const
{
    std::ostringstream os;
    os << "nominal_pressure,nominal_pressure_per_Eprime,area_exact,h_per_k_exact,h_per_k_exact_min,h_per_k_exact_max";
    for (const CheckedLaw& l : laws) {
        if (l.unavailable.empty()) {
            os << ",ratio_" << l.name;
        }
    }
    os << '\n';
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        os << formatNumber(pressures[i]) << ',' << formatNumber(pressures[i] / reducedModulus) << ','
           << formatNumber(exactArea[i]) << ',' << formatNumber(exactHPerK[i]) << ','
           << formatNumber(exactHPerKLow[i]) << ',' << formatNumber(exactHPerKHigh[i]);
        for (const CheckedLaw& l : laws) {
            if (l.unavailable.empty()) {
                os << ',' << formatNumber(l.ratio[i]);
            }
        }
        os << '\n';
    }
    return os.str();
}

SurfaceCheckInputs checkInputsOf(const InterfaceSpec& spec)
{
    SurfaceCheckInputs in;
    in.surfaces = spec.surfaces;
    in.materials = ContactMaterials::pair(spec.side1, spec.side2, "side1", "side2");
    in.model = spec.model;
    in.conductanceLaw = spec.model == "boundaryElement" ? std::string() : spec.conductanceLaw;
    in.microhardness = spec.microhardness;
    in.vickers = spec.vickers;
    if (spec.hardness && spec.hardnessFromYield) {
        throw ParameterError("hardness", "give a hardness or hardnessFromYield, not both");
    }
    if (spec.hardness) {
        in.hardness = limits::requireInRange("hardness", *spec.hardness, limits::minimumHardness,
                                             limits::maximumHardness, "Pa");
    } else if (spec.hardnessFromYield) {
        in.hardness = in.materials->hardness("check hardnessFromYield");
    }
    in.periodic = spec.periodic;
    in.mirror = spec.mirror;
    in.detrend = spec.detrend;
    // The table's range (ContactInterface.hpp, BoundaryElementTable.hpp defaults).
    const double Ep = in.materials->reducedModulus();
    const bool bem = spec.model == "boundaryElement";
    in.minPressure = spec.minPressure.value_or(bem ? 1e-6 * Ep : 1e-9 * Ep);
    in.maxPressure = spec.maxPressure.value_or(bem ? 0.1 * Ep : Ep);
    return in;
}

SurfaceCheck checkSurface(const InterfaceSpec& spec, const SurfaceCheckOptions& options)
{
    return checkSurface(checkInputsOf(spec), options);
}

SurfaceCheck checkSurface(const SurfaceCheckInputs& spec, const SurfaceCheckOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    const auto log = [&](const std::string& line) {
        if (options.log) {
            options.log(line);
        }
    };
    if (options.pressureCount < 1 || options.pressureCount > 5) {
        throw ParameterError("check pressures", "check 1 to 5 pressures, not " + std::to_string(options.pressureCount));
    }
    if (options.seeds.empty()) {
        throw ParameterError("check seeds", "give at least one seed");
    }
    SurfaceCheck out;
    if (!spec.materials) {
        throw ParameterError("materials", "the check needs the materials of the two solids");
    }
    const ContactMaterials& materials = *spec.materials;
    const double Ep = materials.reducedModulus();
    out.reducedModulus = Ep;
    if (spec.hardness) {
        out.hardness = spec.hardness;
    } else if (materials.hasYieldStrength()) {
        out.hardness = materials.hardness("check");
    }
    out.regime = out.hardness ? "capped at H = " + number(*out.hardness) + " Pa" : std::string("elastic");

    // The surfaces solved, and the spectrum the laws see: one part, or for a 1-D description two
    // (the pressures at p/(E' h') >= smallCellLoadPerGradient on periods of one scan length, the
    // lighter ones on periods of options.lightLoadPeriods scan lengths).
    struct Part {
        Spectrum lawSpectrum;
        std::vector<ArealSurface> solved;
        std::vector<std::size_t> at; // indices into out.pressures
    };
    const Spectrum given = equivalentSurface(spec.surfaces);
    out.levelsGiven = given.size();
    const bool areal = spec.surfaces.front().kind == SurfaceSpec::Kind::areal;
    std::vector<Part> parts;
    bool periodic = true;
    bool mirrored = false;
    std::optional<Detrend> detrend = spec.detrend;
    const std::size_t n = options.gridSize;
    // The shortest wavelength 8 cells (SurfaceCheck.hpp); the lowest level always stays.
    const auto cut = [n](const Spectrum& s) {
        return s.truncated(std::max(double(n / 8) / s.length(), s.frequencies().front()) * (1.0 + 1e-12));
    };
    if (areal) {
        for (const SurfaceSpec& s : spec.surfaces) {
            if (s.kind != SurfaceSpec::Kind::areal) {
                throw ParameterError("surfaces", "check two areal maps or two 1-D descriptions, not one of each");
            }
        }
        parts.push_back({given, {arealComposite(spec.surfaces)}, {}}); // as the boundaryElement model reads it
        periodic = spec.periodic.value_or(false);
        mirrored = spec.mirror.value_or(false);
        const ArealSurface& map = parts[0].solved[0];
        std::ostringstream os;
        os << "the map " << map.source() << " (" << map.nx() << " x " << map.ny()
           << (mirrored ? ", mirrored)" : periodic ? ", periodic)" : ", non-periodic)");
        out.surface = os.str();
    } else {
        if (spec.mirror.value_or(false)) {
            throw ParameterError("mirror", "is for areal maps; a surface synthesized from a 1-D description is "
                                           "periodic already");
        }
        limits::requireSynthesisSize("check grid", n);
        requireLightLoadPeriods(options.lightLoadPeriods, "check light-load periods");
        parts.push_back({cut(given), {}, {}});
    }
    out.levelsKept = parts[0].lawSpectrum.size();
    out.gradient = arealRmsGradient(spectralMoments(parts[0].lawSpectrum));

    // The pressures: the table's range clipped to where the exact model and the laws are compared.
    double lo = spec.minPressure;
    double hi = spec.maxPressure;
    lo = std::max(lo, lightestLoadPerGradient * Ep * out.gradient);
    hi = std::min(hi, heaviestLoadPerGradient * Ep * out.gradient);
    if (out.hardness) {
        hi = std::min(hi, heaviestPerHardness * *out.hardness);
    }
    out.lowestCheckable = lo;
    out.highestCheckable = hi;
    const auto describeRange = [&] {
        std::ostringstream os;
        os << "p/(E' h') within [" << lightestLoadPerGradient << ", " << heaviestLoadPerGradient << "] is "
           << lightestLoadPerGradient * Ep * out.gradient << " to " << heaviestLoadPerGradient * Ep * out.gradient
           << " Pa here (E' = " << Ep << " Pa, h' = " << out.gradient << ")"
           << (out.hardness ? ", and at most 0.9 H = " + number(heaviestPerHardness * *out.hardness) + " Pa" : "");
        return os.str();
    };
    if (!options.pressures.empty()) {
        for (double P : options.pressures) {
            if (std::isfinite(P) && P >= lo * (1 - 1e-12) && P <= hi * (1 + 1e-12)) {
                out.pressures.push_back(P);
            } else {
                out.dropped.push_back(P);
            }
        }
        std::sort(out.pressures.begin(), out.pressures.end());
        out.pressures.erase(std::unique(out.pressures.begin(), out.pressures.end()), out.pressures.end());
        if (out.pressures.size() > 5) {
            throw ParameterError("check pressures", "check at most 5 pressures");
        }
        if (out.pressures.empty()) {
            throw ParameterError("check pressures", "none of the pressures given lies in the checked range: " +
                                                        describeRange());
        }
    } else {
        if (!(hi > lo)) {
            throw ParameterError("check", "the table's pressure range [" + number(spec.minPressure) + ", " +
                                              number(spec.maxPressure) +
                                              "] Pa has no part where the exact model is checked: " + describeRange());
        }
        const std::size_t k = options.pressureCount;
        for (std::size_t i = 0; i < k; ++i) {
            out.pressures.push_back(k == 1 ? std::sqrt(lo * hi) : lo * std::pow(hi / lo, double(i) / double(k - 1)));
        }
    }

    // The parts' pressures and surfaces: a profile's or spectrum's lighter pressures on periods
    // of lightLoadPeriods scan lengths (the same grid, so the levels cut at that period's
    // gridSize/8; Spectrum::onPeriod).
    const std::size_t periods = areal ? 1 : options.lightLoadPeriods;
    std::vector<std::size_t> light;
    for (std::size_t i = 0; i < out.pressures.size(); ++i) {
        // Below the threshold by more than rounding: a pressure spaced onto p/(E' h') = 1e-3 itself
        // (4 across 1e-4 to 1e-1) is a heavy one whatever its last digit.
        const bool isLight =
            !areal && out.pressures[i] < smallCellLoadPerGradient * Ep * out.gradient * (1.0 - 1e-9);
        (isLight ? light : parts[0].at).push_back(i);
    }
    if (!light.empty() && periods > 1) {
        // Only the levels up to the longer period's cut are needed, and three beyond it so that the
        // bins and the interpolation up to the cut are the whole spectrum's (a long profile's
        // spectrum on a longer period would otherwise hold `periods` times all its levels).
        const std::vector<double>& f = given.frequencies();
        const double top = double(n / 8) / (given.length() * double(periods));
        const std::size_t needed =
            static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), top * (1.0 + 1e-12)) - f.begin()) + 3;
        const Spectrum levels = needed < f.size() ? given.truncated(f[needed - 1]) : given;
        parts.push_back({cut(levels.onPeriod(periods)), {}, light});
        out.lightLoadPeriods = periods;
        out.lightLevelsKept = parts.back().lawSpectrum.size();
    } else {
        parts[0].at.insert(parts[0].at.end(), light.begin(), light.end());
        std::sort(parts[0].at.begin(), parts[0].at.end());
    }
    out.onePeriodPressures = parts[0].at.size();
    if (parts[0].at.empty()) {
        parts.erase(parts.begin());
    }
    if (!areal) {
        for (Part& part : parts) {
            for (std::uint64_t seed : options.seeds) {
                part.solved.push_back(synthesizeIsotropic(part.lawSpectrum, n, seed, "synthesized from " + given.source()));
            }
        }
        std::ostringstream os;
        os << options.seeds.size() << (options.seeds.size() == 1 ? " seed" : " seeds") << " of " << n << " x " << n
           << " synthesized from " << given.source();
        if (out.lightLoadPeriods > 1) {
            os << " (below p/(E' h') = " << smallCellLoadPerGradient << " on periods of " << out.lightLoadPeriods
               << " scan lengths)";
        }
        out.surface = os.str();
    }

    if (!light.empty()) {
        double heaviest = 0.0;
        for (std::size_t i : light) {
            heaviest = std::max(heaviest, out.pressures[i]);
        }
        std::ostringstream os;
        os << "below p/(E' h') = " << smallCellLoadPerGradient << " (" << light.size()
           << " of the checked pressures, up to " << number(heaviest) << " Pa) the exact answer is a periodic cell "
           << (out.lightLoadPeriods > 1 ? std::to_string(out.lightLoadPeriods) + " scan lengths" : std::string("one scan length"))
           << " on a side, which may conduct more than a large joint of this finish (on periods of 8 scan lengths the "
              "exact answer at p/(E' h') = 1e-4 was down to about a quarter of one scan length's where the longest "
              "wave holds most of the heights, about the same where the spectrum rolls off well below it; less apart "
              "by 1e-3): there the exact answer below may be too high for a large joint, and the laws' ratios to it "
              "too low (the default law is fitted on periods of 8 scan lengths; docs/checking.md)";
        out.smallCellNote = os.str();
    }

    // Every law on each part's spectrum: the spec's multi-scale model's area, or the default
    // elasto-plastic (capped) or elastic one.
    const std::string areaModel =
        isMultiscaleModel(spec.model) ? spec.model : (out.hardness ? std::string("jacksonGreen") : std::string("hertz"));
    out.chosenLaw = spec.conductanceLaw.empty() ? defaultConductanceLaw() : spec.conductanceLaw;
    if (!isConductanceLaw(out.chosenLaw)) {
        throw ParameterError("conductance", "unknown law '" + out.chosenLaw + "'");
    }
    // Every law built before the minutes of solving (a law that cannot be built here is named
    // then, and the chosen one must be buildable). The laws hold pointers into their inputs.
    const std::optional<double> microhardness = spec.microhardness ? spec.microhardness : out.hardness;
    std::vector<std::unique_ptr<MultiscaleModel>> multiscales;
    std::vector<std::vector<std::pair<std::string, std::unique_ptr<ConductanceLaw>>>> laws(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
        multiscales.push_back(std::make_unique<MultiscaleModel>(parts[k].lawSpectrum, Ep,
                                                                makeAsperityModel(areaModel, materials)));
        ConductanceLawInputs in;
        in.multiscale = multiscales.back().get();
        in.spectrum = &parts[k].lawSpectrum;
        in.Eprime = Ep;
        in.roughness = areal ? equivalentRoughness(spec.surfaces) : spectrumRoughness(parts[k].lawSpectrum);
        // The surfaces checked on are the map's heights, or Gaussian ones synthesized from a spectrum.
        if (areal) {
            in.skewness = equivalentSkewness(spec.surfaces);
        }
        in.microhardness = microhardness;
        in.hardness = in.microhardness;
        in.vickers = spec.vickers;
        for (const std::string& name : conductanceLawNames()) {
            if (name == "cooperMikicYovanovich" && !in.microhardness && !in.vickers) {
                if (name == out.chosenLaw) {
                    throw ParameterError("conductance", "the chosen law cooperMikicYovanovich needs a microhardness "
                                                        "(or Vickers coefficients), and the materials here give no "
                                                        "hardness: give one, or choose another law");
                }
                laws[k].emplace_back(name, nullptr);
                continue;
            }
            laws[k].emplace_back(name, makeConductanceLaw(name, in));
        }
    }

    // The exact conductance on every solved surface.
    BoundaryElementOptions bo;
    bo.periodic = periodic;
    bo.mirrored = mirrored;
    bo.hardness = out.hardness;
    bo.detrend = detrend;
    const std::size_t count = out.pressures.size();
    std::vector<double> logSum(count, 0.0);
    std::vector<double> areaSum(count, 0.0);
    out.exactHPerKLow.assign(count, std::numeric_limits<double>::infinity());
    out.exactHPerKHigh.assign(count, 0.0);
    log("check: the exact model on " + out.surface + ", " + out.regime + ", at " +
        (count == 1 ? "1 pressure, " + number(out.pressures.front()) + " Pa"
                    : std::to_string(count) + " pressures from " + number(out.pressures.front()) + " to " +
                          number(out.pressures.back()) + " Pa"));
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    std::size_t surfaces = 0;
    for (const Part& part : parts) {
        surfaces += part.solved.size();
    }
    std::size_t done = 0;
    for (const Part& part : parts) {
        std::vector<double> loads;
        for (std::size_t i : part.at) {
            loads.push_back(checkLoad(out.pressures[i] / Ep));
        }
        for (const ArealSurface& surface : part.solved) {
            ++done;
            const BoundaryElementModel model(surface, Ep, bo);
            const std::vector<BoundaryElementPoint> points =
                model.curve(loads, [&](std::size_t k, std::size_t total, const BoundaryElementPoint& p) {
                    std::ostringstream os;
                    os << "check: surface " << done << " of " << surfaces << ", pressure " << k << " of " << total
                       << ": A_r/A_n = " << number(p.areaFraction)
                       << ", h_c/k_s = " << number(p.conductancePerConductivity) << " 1/m; " << number(seconds())
                       << " s";
                    log(os.str());
                });
            if (const std::string warning =
                    patchCorrectionWarning(points, Ep, "mirror true; in the contact entry, --mirror with --check, "
                                                   "mirror=True in Python");
                !warning.empty()) {
                out.exactWarning = warning + "; nor are the laws' ratios there";
            }
            for (std::size_t j = 0; j < part.at.size(); ++j) {
                const std::size_t i = part.at[j];
                const double h = points[j].conductancePerConductivity;
                if (!(h > 0.0) || !std::isfinite(h)) {
                    // A padded map's spots conducting as the bonded map (h infinite below complete
                    // contact) is the patch correction's failure, which the warning says.
                    const bool patch = points[j].patchCorrectionGain > patchCorrectionGainLimit;
                    throw ParameterError("check", "the exact conductance at " + number(out.pressures[i]) + " Pa is " +
                                                      number(h) + " 1/m (" +
                                                      (patch ? out.exactWarning
                                                             : std::string("no contact, or complete contact")) +
                                                      "): check other pressures");
                }
                logSum[i] += std::log(h);
                areaSum[i] += points[j].areaFraction;
                out.exactHPerKLow[i] = std::min(out.exactHPerKLow[i], h);
                out.exactHPerKHigh[i] = std::max(out.exactHPerKHigh[i], h);
            }
        }
    }
    out.exactHPerK.assign(count, 0.0);
    out.exactArea.assign(count, 0.0);
    for (const Part& part : parts) { // every pressure is in one part, solved on its surfaces (>= 1 seed)
        const double solved = double(part.solved.size());
        for (std::size_t i : part.at) {
            out.exactHPerK[i] = std::exp(logSum[i] / solved);
            out.exactArea[i] = areaSum[i] / solved;
        }
    }

    double best = std::numeric_limits<double>::infinity();
    for (std::size_t l = 0; l < conductanceLawNames().size(); ++l) {
        CheckedLaw checked;
        checked.name = laws[0][l].first;
        if (!laws[0][l].second) {
            checked.unavailable = "needs a microhardness; the surfaces here stay elastic";
            out.laws.push_back(checked);
            continue;
        }
        checked.hPerK.assign(count, 0.0);
        checked.ratio.assign(count, 0.0);
        for (std::size_t k = 0; k < parts.size(); ++k) {
            for (std::size_t i : parts[k].at) {
                checked.hPerK[i] = laws[k][l].second->perConductivity(out.pressures[i]);
                checked.ratio[i] = checked.hPerK[i] / out.exactHPerK[i];
            }
        }
        for (double r : checked.ratio) {
            const double factor = r >= 1.0 ? r : 1.0 / r;
            checked.worstFactor =
                std::max(checked.worstFactor, std::isnan(factor) ? std::numeric_limits<double>::infinity() : factor);
        }
        if (checked.worstFactor < best) {
            best = checked.worstFactor;
            out.closestLaw = checked.name;
        }
        out.laws.push_back(checked);
    }
    out.seconds = seconds();
    return out;
}

} // namespace roughContact
