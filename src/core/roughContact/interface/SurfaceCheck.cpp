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
#include <memory>
#include <sstream>

namespace roughContact {

namespace {

/// The clipped range of the check in p/(E' h') (SurfaceCheck.hpp says why).
constexpr double lightestLoadPerGradient = 1e-4;
constexpr double heaviestLoadPerGradient = 1e-1;
/// Capped: the heaviest checked pressure, as a fraction of H (at H every point flows).
constexpr double heaviestPerHardness = 0.9;

std::string number(double v)
{
    std::ostringstream os;
    os << std::setprecision(4) << v;
    return os.str();
}

} // namespace

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
    if (levelsKept < levelsGiven) {
        os << "  the check holds the surface's " << levelsKept << " longest levels of " << levelsGiven
           << " (the finest a " << "grid resolves with 8 cells a wavelength); the laws are held to "
              "the exact answer on that surface\n";
    }
    if (!dropped.empty()) {
        os << "  not checked:";
        for (double P : dropped) {
            os << " " << number(P);
        }
        os << " Pa (outside the checked range " << number(lowestCheckable) << " to " << number(highestCheckable)
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

    // The surfaces solved, and the spectrum the laws see.
    const Spectrum given = equivalentSurface(spec.surfaces);
    out.levelsGiven = given.size();
    const bool areal = spec.surfaces.front().kind == SurfaceSpec::Kind::areal;
    std::vector<ArealSurface> solved;
    std::optional<Spectrum> lawSpectrum;
    bool periodic = true;
    bool mirrored = false;
    std::optional<Detrend> detrend = spec.detrend;
    if (areal) {
        for (const SurfaceSpec& s : spec.surfaces) {
            if (s.kind != SurfaceSpec::Kind::areal) {
                throw ParameterError("surfaces", "check two areal maps or two 1-D descriptions, not one of each");
            }
        }
        solved.push_back(arealComposite(spec.surfaces)); // as the boundaryElement model reads it
        periodic = spec.periodic.value_or(false);
        mirrored = spec.mirror.value_or(false);
        lawSpectrum = given;
        std::ostringstream os;
        os << "the map " << solved[0].source() << " (" << solved[0].nx() << " x " << solved[0].ny()
           << (mirrored ? ", mirrored)" : periodic ? ", periodic)" : ", non-periodic)");
        out.surface = os.str();
    } else {
        if (spec.mirror.value_or(false)) {
            throw ParameterError("mirror", "is for areal maps; a surface synthesized from a 1-D description is "
                                           "periodic already");
        }
        const std::size_t n = options.gridSize;
        limits::requireSynthesisSize("check grid", n);
        // The shortest wavelength 8 cells (SurfaceCheck.hpp); the lowest level always stays.
        const double cutoff = std::max(double(n / 8) / given.length(), given.frequencies().front());
        lawSpectrum = given.truncated(cutoff * (1.0 + 1e-12));
        for (std::uint64_t seed : options.seeds) {
            solved.push_back(synthesizeIsotropic(*lawSpectrum, n, seed, "synthesized from " + given.source()));
        }
        std::ostringstream os;
        os << options.seeds.size() << (options.seeds.size() == 1 ? " seed" : " seeds") << " of " << n << " x " << n
           << " synthesized from " << given.source();
        out.surface = os.str();
    }
    out.levelsKept = lawSpectrum->size();
    out.gradient = arealRmsGradient(spectralMoments(*lawSpectrum));

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

    if (!areal) {
        std::size_t light = 0;
        double heaviest = 0.0;
        for (double P : out.pressures) {
            if (P < smallCellLoadPerGradient * Ep * out.gradient) {
                ++light;
                heaviest = P;
            }
        }
        if (light > 0) {
            std::ostringstream os;
            os << "below p/(E' h') = " << smallCellLoadPerGradient << " (" << light << " of the checked pressures, up to "
               << number(heaviest) << " Pa) the exact answer is a periodic cell one scan length on a side, which "
               << "may conduct more than a large joint of this finish (on periods of 8 scan lengths the exact answer "
               << "at p/(E' h') = 1e-4 was down to about a quarter of it where the longest wave holds most of the heights, "
               << "about the same where the spectrum rolls off well below it; less apart by 1e-3): there the exact "
               << "answer below may be too high for a large joint, and the laws' ratios to it too low (the default "
               << "law is fitted on periods of 8 scan lengths; docs/checking.md)";
            out.smallCellNote = os.str();
        }
    }

    // Every law on the checked spectrum: the spec's multi-scale model's area, or the default
    // elasto-plastic (capped) or elastic one.
    const std::string areaModel =
        isMultiscaleModel(spec.model) ? spec.model : (out.hardness ? std::string("jacksonGreen") : std::string("hertz"));
    const MultiscaleModel multiscale(*lawSpectrum, Ep, makeAsperityModel(areaModel, materials));
    ConductanceLawInputs in;
    in.multiscale = &multiscale;
    in.spectrum = &*lawSpectrum;
    in.Eprime = Ep;
    in.roughness = areal ? equivalentRoughness(spec.surfaces) : spectrumRoughness(*lawSpectrum);
    // The surfaces checked on are the map's heights, or Gaussian ones synthesized from a spectrum.
    if (areal) {
        in.skewness = equivalentSkewness(spec.surfaces);
    }
    in.microhardness = spec.microhardness ? spec.microhardness : out.hardness;
    in.hardness = in.microhardness;
    in.vickers = spec.vickers;
    out.chosenLaw = spec.conductanceLaw.empty() ? defaultConductanceLaw() : spec.conductanceLaw;
    if (!isConductanceLaw(out.chosenLaw)) {
        throw ParameterError("conductance", "unknown law '" + out.chosenLaw + "'");
    }
    // Every law built before the minutes of solving (a law that cannot be built here is named
    // then, and the chosen one must be buildable).
    std::vector<std::pair<std::string, std::unique_ptr<ConductanceLaw>>> laws;
    for (const std::string& name : conductanceLawNames()) {
        if (name == "cooperMikicYovanovich" && !in.microhardness && !in.vickers) {
            if (name == out.chosenLaw) {
                throw ParameterError("conductance", "the chosen law cooperMikicYovanovich needs a microhardness "
                                                    "(or Vickers coefficients), and the materials here give no "
                                                    "hardness: give one, or choose another law");
            }
            laws.emplace_back(name, nullptr);
            continue;
        }
        laws.emplace_back(name, makeConductanceLaw(name, in));
    }

    // The exact conductance on every solved surface.
    std::vector<double> loads;
    for (double P : out.pressures) {
        loads.push_back(checkLoad(P / Ep));
    }
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
    log("check: the exact model on " + out.surface + ", " + out.regime + ", at " + std::to_string(count) +
        " pressures from " + number(out.pressures.front()) + " to " + number(out.pressures.back()) + " Pa");
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    for (std::size_t s = 0; s < solved.size(); ++s) {
        const BoundaryElementModel model(solved[s], Ep, bo);
        const std::vector<BoundaryElementPoint> points =
            model.curve(loads, [&](std::size_t done, std::size_t total, const BoundaryElementPoint& p) {
                std::ostringstream os;
                os << "check: surface " << s + 1 << " of " << solved.size() << ", pressure " << done << " of " << total
                   << ": A_r/A_n = " << number(p.areaFraction) << ", h_c/k_s = " << number(p.conductancePerConductivity)
                   << " 1/m; " << number(seconds()) << " s";
                log(os.str());
            });
        if (const std::string warning =
                patchCorrectionWarning(points, Ep, "mirror true; in the contact entry, --mirror with --check, "
                                               "mirror=True in Python");
            !warning.empty()) {
            out.exactWarning = warning + "; nor are the laws' ratios there";
        }
        for (std::size_t i = 0; i < count; ++i) {
            const double h = points[i].conductancePerConductivity;
            if (!(h > 0.0) || !std::isfinite(h)) {
                // A padded map's spots conducting as the bonded map (h infinite below complete
                // contact) is the patch correction's failure, which the warning says.
                const bool patch = points[i].patchCorrectionGain > patchCorrectionGainLimit;
                throw ParameterError("check", "the exact conductance at " + number(out.pressures[i]) + " Pa is " +
                                                  number(h) + " 1/m (" +
                                                  (patch ? out.exactWarning : std::string("no contact, or complete contact")) +
                                                  "): check other pressures");
            }
            logSum[i] += std::log(h);
            areaSum[i] += points[i].areaFraction;
            out.exactHPerKLow[i] = std::min(out.exactHPerKLow[i], h);
            out.exactHPerKHigh[i] = std::max(out.exactHPerKHigh[i], h);
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        out.exactHPerK.push_back(std::exp(logSum[i] / double(solved.size())));
        out.exactArea.push_back(areaSum[i] / double(solved.size()));
    }

    double best = std::numeric_limits<double>::infinity();
    for (const auto& [name, law] : laws) {
        CheckedLaw l;
        l.name = name;
        if (!law) {
            l.unavailable = "needs a microhardness; the surfaces here stay elastic";
            out.laws.push_back(l);
            continue;
        }
        for (std::size_t i = 0; i < count; ++i) {
            const double h = law->perConductivity(out.pressures[i]);
            l.hPerK.push_back(h);
            l.ratio.push_back(h / out.exactHPerK[i]);
            const double factor = l.ratio.back() >= 1.0 ? l.ratio.back() : 1.0 / l.ratio.back();
            l.worstFactor = std::max(l.worstFactor, std::isnan(factor) ? std::numeric_limits<double>::infinity() : factor);
        }
        if (l.worstFactor < best) {
            best = l.worstFactor;
            out.closestLaw = name;
        }
        out.laws.push_back(l);
    }
    out.seconds = seconds();
    return out;
}

} // namespace roughContact
