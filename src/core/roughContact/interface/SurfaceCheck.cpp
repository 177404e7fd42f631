// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/SurfaceCheck.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/InterfaceCurves.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Roughness.hpp"
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

// A surface that holds `kept` of the given spectrum's `given` levels on periods of `periods` scan
// lengths: at least minimumCheckedLevels (or all), else ParameterError naming the options.
void requireLevels(std::size_t kept, std::size_t given, std::size_t periods, const SurfaceCheckOptions::Names& names)
{
    if (kept >= std::min(minimumCheckedLevels, given)) {
        return;
    }
    std::ostringstream os;
    os << "the check's surfaces " << (periods > 1 ? "on periods of " + std::to_string(periods) + " scan lengths " : "")
       << "would hold " << kept << " of the surface's " << given << " levels, fewer than the "
       << minimumCheckedLevels << " a check of this surface needs: give a larger grid (" << names.gridSize << ")"
       << (periods > 1 ? " or a shorter light-load period (" + names.lightLoadPeriods + ")" : std::string());
    throw ParameterError(periods > 1 ? names.lightLoadPeriods : names.gridSize, os.str());
}

} // namespace

double longPeriodWeight(double loadPerGradient)
{
    if (!(loadPerGradient > smallCellLoadPerGradient)) {
        return 1.0;
    }
    if (!(loadPerGradient < checkBlendEnd)) {
        return 0.0;
    }
    const double w = std::log(checkBlendEnd / loadPerGradient) / std::log(checkBlendEnd / smallCellLoadPerGradient);
    // A pressure spaced onto an end (4 across 1e-4 to 1e-1 put two there) is at the end whatever
    // its last digit.
    return w < 1e-9 ? 0.0 : w > 1.0 - 1e-9 ? 1.0 : w;
}

double joinPeriods(double onePeriod, double longPeriod, double weight)
{
    if (!(weight > 0.0)) {
        return onePeriod;
    }
    if (!(weight < 1.0)) {
        return longPeriod;
    }
    const bool logs = std::isfinite(onePeriod) && std::isfinite(longPeriod) && onePeriod > 0.0 && longPeriod > 0.0;
    return logs ? std::exp((1.0 - weight) * std::log(onePeriod) + weight * std::log(longPeriod))
                : (1.0 - weight) * onePeriod + weight * longPeriod;
}

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
        const bool counted = i >= exactTrusted.size() || exactTrusted[i];
        if (counted && !(std::fabs(l.ratio[i] - 1.0) <= checkTolerance)) {
            out.push_back(pressures[i]);
        }
    }
    return out;
}

std::vector<double> SurfaceCheck::chosenUnloadingMisses() const
{
    std::vector<double> out;
    for (std::size_t i = 0; i < chosenUnloadingRatio.size(); ++i) {
        const bool counted = i >= exactTrusted.size() || exactTrusted[i];
        if (counted && !(std::fabs(chosenUnloadingRatio[i] - 1.0) <= checkTolerance)) {
            out.push_back(pressures[i]);
        }
    }
    return out;
}

std::vector<std::string> SurfaceCheck::missWarnings(const std::string& peakName) const
{
    std::vector<std::string> out;
    const int tolerance = int(checkTolerance * 100 + 0.5);
    const std::size_t counted = pressures.size() - untrusted().size();
    const std::vector<double> misses = chosenMisses();
    if (!misses.empty()) {
        std::ostringstream os;
        os << "the conductance law " << chosenLaw
           << " is off the exact conductance of this surface by more than " << tolerance << " % at "
           << misses.size() << " of " << counted << " counted pressures; "
           << (closestHolds() ? "the closest law here is " + closestLaw + " (within " +
                                    std::to_string(tolerance) + " % at every counted pressure)"
                              : std::string("no law holds at every counted pressure: the exact model (model "
                                            "boundaryElement) is the answer to trust here"));
        out.push_back(os.str());
    }
    const std::vector<double> unloading = chosenUnloadingMisses();
    if (unloadFrom && !unloading.empty()) {
        std::ostringstream os;
        os << "unloaded from " << peakName << " " << number(*unloadFrom) << " Pa, the conductance law "
           << chosenLaw << " is off the exact unloading conductance of this surface by more than "
           << tolerance << " % at " << unloading.size() << " of " << counted
           << " counted pressures; model boundaryElement with a cap follows the exact unloading";
        out.push_back(os.str());
    }
    return out;
}

std::vector<double> SurfaceCheck::untrusted() const
{
    std::vector<double> out;
    for (std::size_t i = 0; i < exactTrusted.size() && i < pressures.size(); ++i) {
        if (!exactTrusted[i]) {
            out.push_back(pressures[i]);
        }
    }
    return out;
}

bool SurfaceCheck::closestHolds() const
{
    for (const CheckedLaw& l : laws) {
        if (l.name == closestLaw) {
            // A ratio r holds when |r - 1| <= tolerance; the factor max(r, 1/r) of one that holds is
            // at most 1/(1 - tolerance).
            for (std::size_t i = 0; i < l.ratio.size(); ++i) {
                if ((i >= exactTrusted.size() || exactTrusted[i]) && !(std::fabs(l.ratio[i] - 1.0) <= checkTolerance)) {
                    return false;
                }
            }
            return true;
        }
    }
    return false;
}

std::string SurfaceCheck::report() const
{
    std::ostringstream os;
    os << "check of the surface: " << surface << "; " << regime << ", E' = " << number(reducedModulus)
       << " Pa, h' = " << number(gradient) << "\n";
    if (onePeriodPressures > 0) {
        os << "  the check holds ";
        if (levelsKept < levelsGiven) {
            os << "the surface's " << levelsKept << " longest levels of " << levelsGiven
               << " (the finest a grid resolves with 8 cells a wavelength)";
        } else {
            os << "all the surface's " << levelsGiven << " levels";
        }
        os << "; the laws are held to the exact answer on that surface\n";
    }
    if (lightLevelsOfGiven > 0) {
        os << "  up to p/(E' h') = " << smallCellLoadPerGradient << " the check solves periods of " << lightLoadPeriods
           << " scan lengths on the same grid, which hold the surface's " << lightLevelsOfGiven << " longest levels of "
           << levelsGiven << " (" << lightLevelsKept << " levels on that period, wavelengths down to 8 cells), the laws "
           << "held to them there; from there to p/(E' h') = " << checkBlendEnd
           << " both are solved and joined, the longer period's weight falling from 1 to 0\n";
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
    if (!moved.empty()) {
        os << "  asked for at";
        for (double P : moved) {
            os << " " << number(P);
        }
        os << " Pa, outside the checked range " << number(lowestCheckable) << " to " << number(highestCheckable)
           << " Pa (p/(E' h') within [1e-4, 1e-1]" << (hardness ? ", at most 0.9 H" : "")
           << "): checked at its nearer end instead; what it says holds there, not at those pressures\n";
    }
    const std::size_t width = 13;
    const std::size_t label = 30;
    const auto row = [&](const std::string& name) -> std::ostream& {
        return os << "\n  " << std::left << std::setw(label) << name;
    };
    const auto cell = [&](const std::string& text) { os << std::right << std::setw(width) << text; };
    const auto counted = [&](std::size_t i) { return i >= exactTrusted.size() || exactTrusted[i]; };
    os << "  " << std::left << std::setw(label) << "P [Pa]";
    for (double P : pressures) {
        cell(number(P));
    }
    row("p/(E' h')");
    for (double P : pressures) {
        cell(number(P / (reducedModulus * gradient)));
    }
    // The answer first: the number for the joint (SurfaceCheck.hpp, "The answer").
    if (!answerHPerK.empty()) {
        os << "\n  the answer for your whole surface: the chosen law " << chosenLaw
           << ", and the exact answer it implies (the answer over the law's ratio below, over the seeds)";
        row("  h_c/k_s of the law [1/m]");
        for (double h : answerHPerK) {
            cell(number(h));
        }
        bool oneValue = true; // one seed, or a map: the exact answer it implies is one number
        for (std::size_t i = 0; i < pressures.size(); ++i) {
            oneValue = oneValue && (!counted(i) || answerExactLow[i] == answerExactHigh[i]);
        }
        row(oneValue ? "  exact it implies [1/m]" : "  exact it implies, from");
        for (std::size_t i = 0; i < pressures.size(); ++i) {
            cell(counted(i) ? number(answerExactLow[i]) : std::string("not trusted"));
        }
        if (!oneValue) {
            row("                    to");
            for (std::size_t i = 0; i < pressures.size(); ++i) {
                cell(counted(i) ? number(answerExactHigh[i]) : std::string("-"));
            }
        }
    }
    os << (surface.rfind("the map ", 0) == 0
               ? "\n  the checked surface: the map itself"
               : "\n  the checked surface (synthesized from your surface's spectrum and band-limited: its exact "
                 "answer is not your whole surface's; the laws' ratios to it carry over)");
    row("  exact A_r/A_n");
    for (double a : exactArea) {
        cell(number(a));
    }
    row("  exact h_c/k_s [1/m]");
    for (double h : exactHPerK) {
        cell(number(h));
    }
    row("    seeds' spread");
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        std::ostringstream spread;
        spread << std::fixed << std::setprecision(2) << exactHPerKLow[i] / exactHPerK[i] << "-"
               << exactHPerKHigh[i] / exactHPerK[i];
        cell(exactHPerKLow[i] == exactHPerKHigh[i] ? std::string("-") : spread.str());
    }
    if (!untrusted().empty()) {
        row("  exact answer trusted");
        for (std::size_t i = 0; i < pressures.size(); ++i) {
            cell(counted(i) ? "yes" : "no");
        }
    }
    os << "\n  law / exact:\n";
    for (const CheckedLaw& l : laws) {
        os << "  " << (l.name == chosenLaw ? "* " : "  ") << std::left << std::setw(label - 2) << l.name;
        if (!l.unavailable.empty()) {
            os << "  (not checked: " << l.unavailable << ")\n";
            continue;
        }
        for (std::size_t i = 0; i < l.ratio.size(); ++i) {
            cell(number(l.ratio[i]) + (counted(i) ? "" : "*"));
        }
        os << "\n";
    }
    if (unloadFrom) {
        os << "  unloaded from " << number(*unloadFrom) << " Pa (the joint carried it; docs/theory.md §7.3):";
        row("  exact h_c/k_s [1/m]");
        for (double h : exactUnloadingHPerK) {
            cell(number(h));
        }
        row("  unloading / loading");
        for (std::size_t i = 0; i < pressures.size(); ++i) {
            cell(number(exactUnloadingHPerK[i] / exactHPerK[i]));
        }
        row("  the law / exact unloading");
        for (std::size_t i = 0; i < pressures.size(); ++i) {
            cell(number(chosenUnloadingRatio[i]) + (counted(i) ? "" : "*"));
        }
        os << (chosenUnloads ? "\n  (the law's h on unloading: its unloading branch, docs/theory.md §5.7c)\n"
                             : "\n  (the chosen law has no unloading branch: its h is its loading value)\n");
    }
    const int tolerance = int(checkTolerance * 100 + 0.5);
    const std::vector<double> notTrusted = untrusted();
    if (!notTrusted.empty()) {
        os << "  not counted (*): " << notTrusted.size() << " of " << pressures.size()
           << " pressures, where the exact answer is not to be trusted (below): no law's ratio there counts\n";
    }
    for (const CheckedLaw& l : laws) {
        if (l.name == closestLaw) {
            if (closestHolds()) {
                os << "  closest: " << closestLaw << " (within " << tolerance << " % at every counted pressure; off by a "
                   << "factor of at most " << number(l.worstFactor) << ")\n";
            } else {
                os << "  no law is within " << tolerance << " % of the exact conductance at every counted pressure; "
                   << "the closest, " << closestLaw << ", is off by a factor of up to " << number(l.worstFactor)
                   << ": the exact model (model boundaryElement) is the answer to trust here\n";
            }
        }
    }
    if (closestLaw.empty()) {
        os << "  no pressure is counted: the exact answer is trusted at none, and no law is judged\n";
    }
    const std::vector<double> misses = chosenMisses();
    const std::size_t countedPressures = pressures.size() - notTrusted.size();
    os << "  the chosen law (*) " << chosenLaw;
    if (countedPressures == 0) {
        os << " is not judged";
    } else if (misses.empty()) {
        os << " is within " << tolerance << " % of the exact conductance at every counted pressure";
    } else {
        os << " misses the exact conductance by more than " << tolerance << " % at " << misses.size() << " of "
           << countedPressures << " counted pressures";
    }
    os << " (" << number(seconds) << " s)\n";
    if (unloadFrom && countedPressures > 0) {
        const std::vector<double> unloadingMisses = chosenUnloadingMisses();
        os << "  unloaded from " << number(*unloadFrom) << " Pa, it";
        if (unloadingMisses.empty()) {
            os << " is within " << tolerance
               << " % of the exact unloading conductance at every counted pressure\n";
        } else {
            os << " misses the exact unloading conductance by more than " << tolerance << " % at "
               << unloadingMisses.size() << " of " << countedPressures
               << " counted pressures: for this joint, model boundaryElement with a cap follows the exact "
                  "unloading\n";
        }
    }
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
    os << "nominal_pressure,nominal_pressure_per_Eprime,h_per_k_answer,h_per_k_answer_exact_low,"
          "h_per_k_answer_exact_high,area_checked_surface,h_per_k_checked_surface,h_per_k_checked_surface_min,"
          "h_per_k_checked_surface_max,exact_trusted";
    for (const CheckedLaw& l : laws) {
        if (l.unavailable.empty()) {
            os << ",ratio_" << l.name;
        }
    }
    os << (unloadFrom ? ",h_per_k_checked_surface_unloading,ratio_chosen_unloading" : "") << '\n';
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        const bool trusted = i >= exactTrusted.size() || exactTrusted[i];
        os << formatNumber(pressures[i]) << ',' << formatNumber(pressures[i] / reducedModulus) << ','
           << (i < answerHPerK.size() ? formatNumber(answerHPerK[i]) : std::string()) << ','
           << (i < answerHPerK.size() && trusted ? formatNumber(answerExactLow[i]) : std::string()) << ','
           << (i < answerHPerK.size() && trusted ? formatNumber(answerExactHigh[i]) : std::string()) << ','
           << formatNumber(exactArea[i]) << ',' << formatNumber(exactHPerK[i]) << ','
           << formatNumber(exactHPerKLow[i]) << ',' << formatNumber(exactHPerKHigh[i]) << ',' << (trusted ? 1 : 0);
        for (const CheckedLaw& l : laws) {
            if (l.unavailable.empty()) {
                os << ',' << formatNumber(l.ratio[i]);
            }
        }
        if (unloadFrom) {
            os << ',' << formatNumber(exactUnloadingHPerK[i]) << ',' << formatNumber(chosenUnloadingRatio[i]);
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
    const SurfaceCheckOptions::Names& names = options.names;
    if (options.pressureCount < 1 || options.pressureCount > maximumCheckedPressures) {
        throw ParameterError(names.pressures, "check 1 to " + std::to_string(maximumCheckedPressures) +
                                                  " pressures, not " + std::to_string(options.pressureCount));
    }
    if (options.pressures.size() > maximumCheckedPressures) {
        throw ParameterError(names.pressures, "the check solves at most " + std::to_string(maximumCheckedPressures) +
                                                  " pressures, " + std::to_string(options.pressures.size()) +
                                                  " were given: give at most " +
                                                  std::to_string(maximumCheckedPressures));
    }
    for (double P : options.pressures) {
        if (!std::isfinite(P)) {
            throw ParameterError(names.pressures, "a pressure is " + limits::valueText(P, "Pa") +
                                                      ": give finite pressures in Pa");
        }
    }
    if (options.seeds.empty()) {
        throw ParameterError(names.seeds, "give at least one seed");
    }
    for (std::size_t i = 0; i < options.seeds.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (options.seeds[i] == options.seeds[j]) {
                throw ParameterError(names.seeds, "seed " + std::to_string(options.seeds[i]) +
                                                      " is given twice: the same seed is the same surface, solved "
                                                      "again; give different seeds");
            }
        }
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

    // The surfaces solved, and the spectrum the laws see, in parts: a map's one part; for a 1-D
    // description the surface on one scan length and, where light pressures are checked, on
    // periods of options.lightLoadPeriods scan lengths (SurfaceCheck.hpp, "how the periods join").
    struct Part {
        Spectrum cutSpectrum; // what the surfaces are synthesized from (a map's: its own)
        Spectrum lawSpectrum; // what the laws see
        std::vector<ArealSurface> solved;
        std::vector<std::size_t> at; // indices into out.pressures
    };
    const Spectrum given = equivalentSurface(spec.surfaces);
    const bool areal = spec.surfaces.front().kind == SurfaceSpec::Kind::areal;
    // A finish with a lay (a profile with alongLay): its surfaces are the across spectrum's
    // stretched along y by the lay ratio (synthesizeStretched), and the laws see their rows' and
    // columns' averaged spectrum; the levels counted are the across spectrum's.
    const std::optional<LaySpectra> lay = areal ? std::nullopt : equivalentLay(spec.surfaces);
    out.layStretch = lay ? lay->stretch() : 1.0;
    const Spectrum& base = lay ? lay->across : given;
    const auto partOf = [&](const Spectrum& cutSpectrum) {
        return Part{cutSpectrum,
                    lay ? Spectrum::averaged(cutSpectrum, cutSpectrum.stretched(out.layStretch),
                                             cutSpectrum.source() + " and along the lay")
                        : cutSpectrum,
                    {},
                    {}};
    };
    out.levelsGiven = base.size();
    std::optional<Part> onePart;
    std::optional<Part> longer;
    bool periodic = true;
    bool mirrored = false;
    std::optional<Detrend> detrend = spec.detrend;
    const std::size_t n = options.gridSize;
    // The shortest wavelength 8 cells (SurfaceCheck.hpp); the lowest level always stays.
    const auto cut = [n](const Spectrum& s) {
        return s.truncated(std::max(double(n / 8) / s.length(), s.frequencies().front()) * (1.0 + 1e-12));
    };
    // The given spectrum's levels up to a frequency [1/m].
    const auto levelsUpTo = [&](double f) {
        const std::vector<double>& g = base.frequencies();
        return static_cast<std::size_t>(std::upper_bound(g.begin(), g.end(), f * (1.0 + 1e-12)) - g.begin());
    };
    if (areal) {
        for (const SurfaceSpec& s : spec.surfaces) {
            if (s.kind != SurfaceSpec::Kind::areal) {
                throw ParameterError("surfaces", "check two areal maps or two 1-D descriptions, not one of each");
            }
        }
        onePart = Part{given, given, {arealComposite(spec.surfaces)}, {}}; // as the boundaryElement model reads it
        periodic = spec.periodic.value_or(false);
        mirrored = spec.mirror.value_or(false);
        const ArealSurface& map = onePart->solved[0];
        std::ostringstream os;
        os << "the map " << map.source() << " (" << map.nx() << " x " << map.ny()
           << (mirrored ? ", mirrored)" : periodic ? ", periodic)" : ", non-periodic)");
        out.surface = os.str();
    } else {
        requireMirrorOfMaps(spec.surfaces, spec.mirror.value_or(false));
        limits::requireSynthesisSize(names.gridSize, n);
        requireLightLoadPeriods(options.lightLoadPeriods, names.lightLoadPeriods);
        onePart = partOf(cut(base));
    }
    Part& one = *onePart;
    // A surface too smooth to have contact spots is said as such, before any range is derived
    // from its gradient.
    requireRoughness(one.lawSpectrum);
    out.levelsKept = one.cutSpectrum.size();
    out.gradient = arealRmsGradient(spectralMoments(one.lawSpectrum));

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
            if (P >= lo * (1 - 1e-12) && P <= hi * (1 + 1e-12)) {
                out.pressures.push_back(P);
            } else if (options.movePressuresIntoRange && hi >= lo) {
                out.moved.push_back(P);
                out.pressures.push_back(P < lo ? lo : hi);
            } else {
                out.dropped.push_back(P);
            }
        }
        std::sort(out.pressures.begin(), out.pressures.end());
        out.pressures.erase(std::unique(out.pressures.begin(), out.pressures.end()), out.pressures.end());
        if (out.pressures.empty()) {
            throw ParameterError(names.pressures, "none of the pressures given lies in the checked range: " +
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
    const std::size_t count = out.pressures.size();

    // How the periods join: each pressure's weight of the longer period, 1 up to
    // smallCellLoadPerGradient, 0 from checkBlendEnd on, log-linear in p/(E' h') between
    // (SurfaceCheck.hpp). A map, or a light-load period of one scan length: 0 everywhere.
    const std::size_t periods = areal ? 1 : options.lightLoadPeriods;
    out.longPeriodWeights.assign(count, 0.0);
    if (periods > 1) {
        for (std::size_t i = 0; i < count; ++i) {
            out.longPeriodWeights[i] = longPeriodWeight(out.pressures[i] / (Ep * out.gradient));
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (out.longPeriodWeights[i] < 1.0) {
            one.at.push_back(i);
        }
    }
    std::vector<std::size_t> onLonger;
    for (std::size_t i = 0; i < count; ++i) {
        if (out.longPeriodWeights[i] > 0.0) {
            onLonger.push_back(i);
        }
    }
    out.onePeriodPressures = one.at.size();
    if (!one.at.empty() && !areal) {
        requireLevels(levelsUpTo(double(n / 8) / base.length()), base.size(), 1, names);
    }
    if (!onLonger.empty()) {
        // Only the levels up to the longer period's cut are needed, and three beyond it so that the
        // bins and the interpolation up to the cut are the whole spectrum's (a long profile's
        // spectrum on a longer period would otherwise hold `periods` times all its levels).
        const std::vector<double>& f = base.frequencies();
        const double top = double(n / 8) / (base.length() * double(periods));
        out.lightLevelsOfGiven = levelsUpTo(top);
        requireLevels(out.lightLevelsOfGiven, base.size(), periods, names);
        const std::size_t needed = levelsUpTo(top) + 3;
        const Spectrum levels = needed < f.size() ? base.truncated(f[needed - 1]) : base;
        longer = partOf(cut(levels.onPeriod(periods)));
        longer->at = onLonger;
        out.lightLoadPeriods = periods;
        out.lightLevelsKept = longer->cutSpectrum.size();
    }
    std::vector<Part*> parts;
    if (!one.at.empty()) {
        parts.push_back(&one);
    }
    if (longer) {
        parts.push_back(&*longer);
    }
    if (!areal) {
        for (Part* part : parts) {
            for (std::uint64_t seed : options.seeds) {
                part->solved.push_back(synthesizeStretched(part->cutSpectrum, out.layStretch, n, seed,
                                                           "synthesized from " + given.source()));
            }
        }
        std::ostringstream os;
        os << options.seeds.size() << (options.seeds.size() == 1 ? " seed" : " seeds") << " of " << n << " x " << n
           << " synthesized from " << (lay ? lay->across.source() : given.source());
        if (lay) {
            os << ", stretched " << number(out.layStretch)
               << " times along the lay (the rms slope across over along)";
        }
        if (longer) {
            os << " (up to p/(E' h') = " << smallCellLoadPerGradient << " on periods of " << out.lightLoadPeriods
               << " scan lengths, joining one scan length's by " << checkBlendEnd << ")";
        }
        out.surface = os.str();
    }

    if (longer) {
        double heaviest = 0.0;
        for (std::size_t i : longer->at) {
            if (out.longPeriodWeights[i] >= 1.0) {
                heaviest = std::max(heaviest, out.pressures[i]);
            }
        }
        std::ostringstream os;
        os << "up to p/(E' h') = " << smallCellLoadPerGradient << " the exact answer is a periodic cell "
           << out.lightLoadPeriods
           << " scan lengths on a side, which may conduct more than a large joint of this finish (on periods of 8 "
              "scan lengths the exact answer at p/(E' h') = 1e-4 was down to about a quarter of one scan length's "
              "where the longest wave holds most of the heights, about the same where the spectrum rolls off well "
              "below it; less apart by 1e-3): there the exact answer below may be too high for a large joint, and "
              "the laws' ratios to it too low (the default law is fitted on periods of 8 scan lengths; "
              "docs/checking.md)";
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
        multiscales.push_back(std::make_unique<MultiscaleModel>(parts[k]->lawSpectrum, Ep,
                                                                makeAsperityModel(areaModel, materials)));
        ConductanceLawInputs in;
        in.multiscale = multiscales.back().get();
        in.spectrum = &parts[k]->lawSpectrum;
        in.Eprime = Ep;
        in.roughness = areal ? equivalentRoughness(spec.surfaces) : spectrumRoughness(parts[k]->lawSpectrum);
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

    // The answer's law: the chosen one on the whole surface as given, as the condition builds it
    // (the surfaces' roughness and skewness; SurfaceCheck.hpp, "The answer").
    const MultiscaleModel wholeModel(given, Ep, makeAsperityModel(areaModel, materials));
    const std::unique_ptr<ConductanceLaw> answerLaw = wholeSurfaceLaw(out.chosenLaw, spec, given, wholeModel);

    // The exact conductance on every solved surface: per part and pressure, the log-mean over
    // the seeds, the mean area and the seeds' extremes.
    BoundaryElementOptions bo;
    bo.periodic = periodic;
    bo.mirrored = mirrored;
    bo.hardness = out.hardness;
    bo.detrend = detrend;
    struct Exact {
        std::vector<double> logMean, area, logLow, logHigh, logUnloading;
    };
    // The peak of an unloading check: with the cap, below H (requireUnloadingPeak's rule).
    std::optional<double> peakLoad;
    if (options.unloadFrom) {
        out.unloadFrom = requireUnloadingPeak(*options.unloadFrom, out.hardness, options.names.unloadFrom,
                                              "the hardness (a cap: hardness, hardnessFromYield or the softer "
                                              "solid's S_y)");
        peakLoad = checkLoad(*out.unloadFrom / Ep);
    }
    out.exactTrusted.assign(count, true);
    std::vector<Exact> exact(parts.size(), Exact{std::vector<double>(count, 0.0), std::vector<double>(count, 0.0),
                                                 std::vector<double>(count, std::numeric_limits<double>::infinity()),
                                                 std::vector<double>(count, -std::numeric_limits<double>::infinity()),
                                                 std::vector<double>(count, 0.0)});
    log("check: the exact model on " + out.surface + ", " + out.regime + ", at " +
        (count == 1 ? "1 pressure, " + number(out.pressures.front()) + " Pa"
                    : std::to_string(count) + " pressures from " + number(out.pressures.front()) + " to " +
                          number(out.pressures.back()) + " Pa"));
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    std::size_t surfaces = 0;
    for (const Part* part : parts) {
        surfaces += part->solved.size();
    }
    std::size_t done = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Part& part = *parts[k];
        std::vector<double> loads;
        for (std::size_t i : part.at) {
            loads.push_back(checkLoad(out.pressures[i] / Ep));
        }
        for (const ArealSurface& surface : part.solved) {
            ++done;
            const BoundaryElementModel model(surface, Ep, bo);
            const std::vector<BoundaryElementPoint> points =
                model.curve(loads, [&](std::size_t j, std::size_t total, const BoundaryElementPoint& p) {
                    std::ostringstream os;
                    os << "check: surface " << done << " of " << surfaces << ", pressure " << j << " of " << total
                       << ": A_r/A_n = " << number(p.areaFraction)
                       << ", h_c/k_s = " << number(p.conductancePerConductivity) << " 1/m; " << number(seconds())
                       << " s";
                    log(os.str());
                });
            // Unloaded from the peak at the same loads (each a positive, finite h_c/k_s: the
            // deformed surface keeps at least the contact of the loading solve below the peak).
            std::vector<BoundaryElementPoint> unloaded;
            if (peakLoad) {
                unloaded = model.loadPath(*peakLoad, loads);
                log("check: surface " + std::to_string(done) + " of " + std::to_string(surfaces) +
                    " unloaded from " + number(*out.unloadFrom) + " Pa; " + number(seconds()) + " s");
            }
            if (const std::string warning =
                    patchCorrectionWarning(points, Ep, "mirror true; in the contact entry, --mirror with --check, "
                                                   "mirror=True in Python");
                !warning.empty()) {
                out.exactWarning = warning + "; nor are the laws' ratios there";
            }
            for (std::size_t j = 0; j < part.at.size(); ++j) {
                const std::size_t i = part.at[j];
                if (points[j].patchCorrectionGain > patchCorrectionGainLimit) {
                    out.exactTrusted[i] = false; // the pressures patchCorrectionWarning names
                }
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
                exact[k].logMean[i] += std::log(h) / double(part.solved.size());
                if (peakLoad) {
                    // (After the loading check above: a pressure at complete contact is said as such.)
                    const double hu = unloaded[j].conductancePerConductivity;
                    if (!std::isfinite(hu) || !(hu > 0.0)) {
                        throw ParameterError("check", "the exact conductance unloaded from " + number(*out.unloadFrom) +
                                                          " Pa is " + number(hu) + " 1/m at " + number(out.pressures[i]) +
                                                          " Pa");
                    }
                    exact[k].logUnloading[i] += std::log(unloaded[j].conductancePerConductivity) /
                                                double(part.solved.size());
                }
                exact[k].area[i] += points[j].areaFraction / double(part.solved.size());
                exact[k].logLow[i] = std::min(exact[k].logLow[i], std::log(h));
                exact[k].logHigh[i] = std::max(exact[k].logHigh[i], std::log(h));
            }
        }
    }
    // Each pressure's values from its parts: the longer period's with its weight, one scan
    // length's with the rest (joinPeriods; one part alone where the weight is 0 or 1).
    const Part* longPart = longer ? &*longer : nullptr;
    const auto partIndex = [&](const Part* p) {
        for (std::size_t k = 0; k < parts.size(); ++k) {
            if (parts[k] == p) {
                return k;
            }
        }
        return parts.size();
    };
    const std::size_t kOne = partIndex(&one);
    const std::size_t kLong = partIndex(longPart);
    const auto joined = [&](std::size_t i, const std::function<double(std::size_t k)>& value) {
        const double w = out.longPeriodWeights[i];
        return joinPeriods(w < 1.0 ? value(kOne) : 0.0, w > 0.0 ? value(kLong) : 0.0, w);
    };
    out.exactHPerK.assign(count, 0.0);
    out.exactHPerKLow.assign(count, 0.0);
    out.exactHPerKHigh.assign(count, 0.0);
    out.exactArea.assign(count, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
        out.exactHPerK[i] = joined(i, [&](std::size_t k) { return std::exp(exact[k].logMean[i]); });
        out.exactHPerKLow[i] = joined(i, [&](std::size_t k) { return std::exp(exact[k].logLow[i]); });
        out.exactHPerKHigh[i] = joined(i, [&](std::size_t k) { return std::exp(exact[k].logHigh[i]); });
        out.exactArea[i] = joined(i, [&](std::size_t k) { return exact[k].area[i]; });
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
        for (std::size_t i = 0; i < count; ++i) {
            checked.hPerK[i] =
                joined(i, [&](std::size_t k) { return laws[k][l].second->perConductivity(out.pressures[i]); });
            checked.ratio[i] = checked.hPerK[i] / out.exactHPerK[i];
        }
        bool counted = false;
        for (std::size_t i = 0; i < count; ++i) {
            if (!out.exactTrusted[i]) {
                continue; // reported apart, counted for no law
            }
            counted = true;
            const double r = checked.ratio[i];
            const double factor = r >= 1.0 ? r : 1.0 / r;
            checked.worstFactor =
                std::max(checked.worstFactor, std::isnan(factor) ? std::numeric_limits<double>::infinity() : factor);
        }
        if (counted && checked.worstFactor < best) {
            best = checked.worstFactor;
            out.closestLaw = checked.name;
        }
        out.laws.push_back(checked);
    }
    // The answer, and the exact answer it implies at the seeds' extremes.
    {
        const CheckedLaw& checked = out.chosen();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (std::size_t i = 0; i < count; ++i) {
            const double answer = answerLaw->perConductivity(out.pressures[i]);
            out.answerHPerK.push_back(answer);
            // exact = law / ratio, the ratio at each seed's extreme: law_checked / exact_seed.
            const double scale = answer / checked.hPerK[i];
            out.answerExactLow.push_back(out.exactTrusted[i] ? scale * out.exactHPerKLow[i] : nan);
            out.answerExactHigh.push_back(out.exactTrusted[i] ? scale * out.exactHPerKHigh[i] : nan);
        }
    }
    if (peakLoad) {
        // The chosen law's h on unloading: its unloading branch where it has one (each
        // realization's own law), else its loading value.
        const CheckedLaw& checked = out.chosen(); // names a checked law
        std::size_t l = 0;
        while (laws[0][l].first != out.chosenLaw) {
            ++l;
        }
        out.chosenUnloads = laws[0][l].second && laws[0][l].second->unloads();
        for (std::size_t i = 0; i < count; ++i) {
            const double P = out.pressures[i];
            out.exactUnloadingHPerK.push_back(joined(i, [&](std::size_t k) { return std::exp(exact[k].logUnloading[i]); }));
            const double law = !out.chosenUnloads ? checked.hPerK[i] : joined(i, [&](std::size_t k) {
                const ConductanceLaw& c = *laws[k][l].second;
                return c.perConductivity(P) * c.unloadingFactor(P, *out.unloadFrom);
            });
            out.chosenUnloadingRatio.push_back(law / out.exactUnloadingHPerK[i]);
        }
    }
    out.seconds = seconds();
    return out;
}

} // namespace roughContact
